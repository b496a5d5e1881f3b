#ifndef coaxfit_coupling_update_h
#define coaxfit_coupling_update_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/active_set.h>
#include <coaxfit/coupling/coarse_interface_model.h>
#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/parameters/parameters.h>

#include <memory>
#include <string>

namespace coaxfit
{
  using namespace dealii;

  /** What an update reports about a Neumann step, for its history row. */
  struct NeumannOutcome
  {
    /** The alpha that built the step's data (NaN: the method has none). */
    double alpha;
    /** Separated points of the flags the step is judged with. */
    unsigned int n_separated;
    /** An outer active set update begins a new inner iteration. */
    bool new_inner_iteration = false;
  };

  /**
   * How the staggered Dirichlet-Neumann process (StaggeredCoupling) turns
   * the bodies' answers into the data of its next step: the fixed-point
   * map of one double step and its acceleration, behind one interface, one
   * implementation per family of methods (RelaxationUpdate: the paper's
   * relaxation with an AlphaRule and an Accelerator; BlockModelUpdate: the
   * interface block model, ibqn). The coupling does the solves, keeps the
   * history and monitors convergence; an update decides
   * - after a Neumann step (force F applied, answers u1, u2): the contact
   *   flags, the displacement mismatch and, if it predicts it, the force
   *   of the next Neumann step;
   * - before a Dirichlet step: the displacements prescribed to the two
   *   sides at the contact points;
   * - after it (reactions F1, F2): the traction both sides agree on, the
   *   traction mismatch and the force of the next Neumann step.
   * The contact flags are the coupling's UnilateralActiveSet, which the
   * update changes.
   */
  class CouplingUpdate
  {
  public:
    CouplingUpdate(const ContactInterface &interface,
                   UnilateralActiveSet    &active_set);

    virtual ~CouplingUpdate() = default;

    /** The alpha rule's name (SolverStatistics::alpha_rule). */
    virtual std::string
    alpha_rule_name() const = 0;

    /** The accelerator's name (SolverStatistics::accelerator). */
    virtual std::string
    accelerator_name() const = 0;

    /** What ran, as the failure message names it. */
    virtual std::string
    description() const = 0;

    /** Advice for a run that diverged or stalled with this update. */
    virtual std::string
    failure_advice() const = 0;

    /**
     * Whether the first Neumann step applies a uniform pressure (scaled
     * after the step to the one that closes the gap best) instead of the
     * paper's zero force.
     */
    virtual bool
    loaded_start() const = 0;

    /**
     * A run begins; @p predicted: its force and contact flags come from the
     * solution of a coarser mesh.
     */
    virtual void
    start(bool predicted)
      = 0;

    /**
     * The bodies answered the force of a Neumann step in @p state (before
     * the first one is scaled).
     */
    virtual void
    sample_neumann(const InterfaceState &state);

    /**
     * After the Neumann step in @p state, @p steps_taken steps before it:
     * update the flags, set the state's displacement mismatch and, where
     * the update predicts it, @p next_force; set @p verified to whether the
     * flags were checked by this step and stayed.
     */
    virtual NeumannOutcome
    after_neumann(InterfaceState &state,
                  unsigned int    steps_taken,
                  Vector<double> &next_force,
                  bool           &verified)
      = 0;

    /**
     * The displacements @p u_inner, @p u_outer (size n) that the Dirichlet
     * step after @p state prescribes at the contact points.
     */
    virtual void
    dirichlet_data(const InterfaceState &state,
                   Vector<double>       &u_inner,
                   Vector<double>       &u_outer)
      = 0;

    /**
     * After the Dirichlet step that prescribed @p u_inner, @p u_outer and
     * got the reactions @p f_inner, @p f_outer (answers in @p state's u1,
     * u2); @p after_zero_start: it followed the paper's zero Neumann step.
     * Set the state's force and traction mismatch and @p next_force; may
     * clear @p verified. Returns the alpha of the step (NaN: none).
     */
    virtual double
    after_dirichlet(InterfaceState       &state,
                    bool                  after_zero_start,
                    const Vector<double> &u_inner,
                    const Vector<double> &u_outer,
                    Vector<double>       &f_inner,
                    Vector<double>       &f_outer,
                    Vector<double>       &next_force,
                    bool                 &verified)
      = 0;

    /**
     * Form priors from @p model (the same case one refinement coarser);
     * null: none.
     */
    void
    use_coarse_model(CoarseInterfaceModel *model);

    /** How many priors the coarse model gave. */
    unsigned int
    n_coarse_priors() const
    {
      return n_priors;
    }

  protected:
    /**
     * The relative traction mismatch @p mismatch / the largest pressure of
     * @p f_inner and @p f_outer (0 where there is no force; NaN if not
     * finite).
     */
    static double
    relative_to_pressure(double                  mismatch,
                         const Vector<double>   &f_inner,
                         const Vector<double>   &f_outer,
                         const ContactInterface &interface);

    const ContactInterface &interface;
    UnilateralActiveSet    &active_set;
    CoarseInterfaceModel   *coarse_model = nullptr;
    unsigned int            n_priors     = 0;
  };

  /**
   * The energy-weighted Winkler compliance k = sum |u F| / sum F^2/w of a
   * body that answered the nodal forces @p force with @p u (w: the lumped
   * weights @p weights); 0 if there is no load or the sums are not finite.
   */
  double
  winkler_compliance(const Vector<double> &u,
                     const Vector<double> &force,
                     const Vector<double> &weights);

  /**
   * The update Coupling/Accelerator (and Alpha rule) of @p parameters
   * selects, on @p interface with the flags @p active_set;
   * @p active_set_tolerance is Contact/Active set tolerance (0: auto).
   */
  std::unique_ptr<CouplingUpdate>
  make_coupling_update(const CouplingParameters &parameters,
                       const ContactInterface   &interface,
                       UnilateralActiveSet      &active_set,
                       double                    active_set_tolerance);
} // namespace coaxfit

#endif
