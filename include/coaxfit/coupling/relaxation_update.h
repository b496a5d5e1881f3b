#ifndef coaxfit_relaxation_update_h
#define coaxfit_relaxation_update_h

#include <coaxfit/coupling/accelerator.h>
#include <coaxfit/coupling/alpha_rule.h>
#include <coaxfit/coupling/coupling_update.h>

#include <memory>
#include <set>
#include <vector>

namespace coaxfit
{
  /**
   * The paper's relaxation as a CouplingUpdate: the Dirichlet step
   * prescribes u = u1 + (1 - alpha)(u2 - d - u1) to the inner side and
   * u + d to the outer one; the blend G = F1 + alpha (F2 - F1) of the
   * reactions is the image of the applied force under the fixed-point map
   * of one double step, and the Accelerator turns (F, G) into the force of
   * the next Neumann step. The AlphaRule chooses alpha after Neumann steps
   * (with an accelerator only until its first estimate, so that the
   * accelerated map stays the same); an adaptive rule's first alpha is the
   * Winkler alpha of the bodies' first answers. The contact flags are
   * updated after Neumann steps, every step (the paper) or once the
   * iteration converged for the current flags to the active set tolerance
   * (outer, primal-dual); a change restarts, filters or keeps the
   * accelerator's history (Coupling/Active set change). With a coarse
   * model the accelerator's prior is the inverse Jacobian of the coarser
   * mesh for the current alpha and flags.
   */
  class RelaxationUpdate : public CouplingUpdate
  {
  public:
    /**
     * The rule and accelerator of @p parameters; @p active_set_tolerance
     * is Contact/Active set tolerance (0: auto).
     */
    RelaxationUpdate(const CouplingParameters &parameters,
                     const ContactInterface   &interface,
                     UnilateralActiveSet      &active_set,
                     double                    active_set_tolerance);

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
     * Update the flags from the Neumann step in @p state; returns whether
     * they changed and set @p verified to whether they were checked and
     * stayed.
     */
    bool
    update_active_set(const InterfaceState &state, bool &verified);

    /**
     * After the first Dirichlet step, which followed a zero Neumann step
     * (prescribed @p u_inner, @p u_outer, reactions @p f_inner, @p f_outer):
     * measure the bodies' compliances, replace an adaptive rule's initial
     * alpha by the Winkler alpha, and rescale the step's answers (the
     * state's u1, u2, @p f_inner, @p f_outer) to that alpha.
     */
    void
    seed_alpha(InterfaceState       &state,
               const Vector<double> &u_inner,
               const Vector<double> &u_outer,
               Vector<double>       &f_inner,
               Vector<double>       &f_outer);

    /**
     * Form the coarse model's prior for the current alpha and contact
     * points if they differ from those of the prior in use.
     */
    void
    update_prior();

    /** Winkler estimate of the convergent alpha range, for messages. */
    std::string
    suggested_alpha_range() const;

    std::unique_ptr<AlphaRule>   rule;
    std::unique_ptr<Accelerator> accelerator;
    const bool                   accelerated;
    /** What the accelerator keeps when the contact points change. */
    const HistoryOnChange history_on_change;

    /**
     * The outer mode's tolerance for updating the flags; divided by 100
     * (down to Coupling/Tolerance) whenever an update returns to a set of
     * flags seen before: updates from states that are too rough can cycle
     * between zones.
     */
    double active_set_tolerance;
    /** Its start: Contact/Active set tolerance, or 0.1 for auto. */
    const double initial_active_set_tolerance;
    /** Contact/Active set tolerance = auto: 0.1, 1e-2 from a coarse start. */
    const bool   automatic_active_set_tolerance;
    const double tolerance_floor;
    /** Every set of flags the iteration has had. */
    std::set<std::vector<bool>> visited_sets;

    /** The latest Neumann step's force and answers (for messages). */
    Vector<double> neumann_force, neumann_u1, neumann_u2;
    /** Alpha and contact points of the prior in use. */
    std::vector<double> prior_alpha;
    std::vector<bool>   prior_contact;
  };
} // namespace coaxfit

#endif
