#ifndef coaxfit_block_model_update_h
#define coaxfit_block_model_update_h

#include <coaxfit/coupling/coupling_update.h>
#include <coaxfit/coupling/interface_block_model.h>

#include <string>

namespace coaxfit
{
  /**
   * The interface block quasi-Newton model (Coupling/Accelerator = ibqn) as
   * a CouplingUpdate. Every solve of a body is a sample of its compliance
   * (InterfaceBlockModel); after every step the model's solution of the
   * contact problem sets the contact flags, the force of the next Neumann
   * step and the common displacement the next Dirichlet step prescribes
   * (separated points traction free); alpha plays no part. The model's
   * priors are the coarser mesh's compliances (a coarse model) or Winkler
   * compliances measured in the first step.
   */
  class BlockModelUpdate : public CouplingUpdate
  {
  public:
    /** The model with the history settings of @p parameters. */
    BlockModelUpdate(const CouplingParameters &parameters,
                     const ContactInterface   &interface,
                     UnilateralActiveSet      &active_set);

    std::string
    alpha_rule_name() const override;

    std::string
    accelerator_name() const override;

    std::string
    description() const override;

    std::string
    failure_advice() const override;

    bool
    loaded_start() const override;

    void
    start(bool predicted) override;

    void
    sample_neumann(const InterfaceState &state) override;

    NeumannOutcome
    after_neumann(InterfaceState &state,
                  unsigned int    steps_taken,
                  Vector<double> &next_force,
                  bool           &verified) override;

    void
    dirichlet_data(const InterfaceState &state,
                   Vector<double>       &u_inner,
                   Vector<double>       &u_outer) override;

    double
    after_dirichlet(InterfaceState       &state,
                    bool                  after_zero_start,
                    const Vector<double> &u_inner,
                    const Vector<double> &u_outer,
                    Vector<double>       &f_inner,
                    Vector<double>       &f_outer,
                    Vector<double>       &next_force,
                    bool                 &verified) override;

  private:
    /**
     * Give the model the bodies' answers u1, u2 of @p state to the forces
     * @p f_inner, @p f_outer; without a coarse model the first ones also
     * give its Winkler priors.
     */
    void
    add_samples(const InterfaceState &state,
                const Vector<double> &f_inner,
                const Vector<double> &f_outer);

    /**
     * Let the model's solution of the contact problem set the contact
     * flags, @p next_force and the displacement of the next Dirichlet
     * step. Returns whether the flags stayed and the model's active set
     * iteration settled.
     */
    bool
    predict(Vector<double> &next_force);

    /** The alpha rule's name, reported although alpha plays no part. */
    const std::string   rule_name;
    InterfaceBlockModel model;
    Vector<double>      model_displacement;
  };
} // namespace coaxfit

#endif
