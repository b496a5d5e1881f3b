#ifndef coaxfit_staggered_coupling_h
#define coaxfit_staggered_coupling_h

#include <coaxfit/coupling/accelerator.h>
#include <coaxfit/coupling/alpha_rule.h>
#include <coaxfit/coupling/coarse_interface_model.h>
#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_block_model.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/interface_operator.h>

#include <memory>
#include <ostream>
#include <set>
#include <vector>

namespace coaxfit
{
  /**
   * The paper's alternating (staggered Dirichlet-Neumann) process for the
   * shaft D1 and the hub D2.
   *
   * Starting from zero contact pressure, Neumann and Dirichlet steps
   * alternate. In a Neumann step both bodies get the same nodal contact
   * force F and return u1, u2 on S; the displacement mismatch is
   * du = u2 - u1 - d. The Dirichlet step then prescribes
   * u = u1 + (1 - alpha)(u2 - d - u1) to the shaft and u + d to the hub and
   * returns the reactions F1, F2; the blend G = F1 + alpha (F2 - F1) is the
   * image of the applied force under the fixed-point map of one double
   * step, and the Accelerator turns (F, G) into the force of the next
   * Neumann step. The AlphaRule chooses alpha after Neumann steps (with an
   * accelerator only until its first estimate, so that the accelerated map
   * stays the same). Both bodies are solved concurrently in every step.
   * With the unilateral pass (UnilateralActiveSet) tensile forces are
   * set to zero and separated points stay traction free in the Dirichlet
   * step. The iteration has converged when the latest displacement mismatch
   * and the latest traction mismatch are both below the tolerance and the
   * active set was checked in the last Neumann step and did not change. A
   * growing, stalling or non-finite residual stops it with a SolverError
   * that names alpha and suggests a range.
   */
  class StaggeredCoupling : public InterfaceSolver
  {
  public:
    /**
     * The coupling iterates with the operators @p shaft and @p hub (full or
     * condensed); @p shaft_solver and @p hub_solver give the final fields.
     * @p active_set_tolerance is Contact/Active set tolerance (0: auto).
     */
    StaggeredCoupling(BodySolver                &shaft_solver,
                      BodySolver                &hub_solver,
                      InterfaceOperator         &shaft,
                      InterfaceOperator         &hub,
                      const ContactInterface    &interface,
                      const CouplingParameters  &parameters,
                      const UnilateralActiveSet &active_set,
                      double                     active_set_tolerance);

    /**
     * Run the process; print one line per step to @p progress if not null.
     * Returns whether it converged within the step limit.
     */
    bool
    run(std::ostream *progress) override;

    /**
     * Give the accelerator the inverse Jacobian of @p model (the same case
     * one refinement coarser) as its prior, formed for the current alpha
     * and contact points whenever they change (Coupling/Coarse model).
     */
    void
    use_coarse_model(std::unique_ptr<CoarseInterfaceModel> model);

    /**
     * Start from the nodal contact force @p force and the contact flags
     * @p contact (the coarser mesh's solution, which took @p coarse_steps
     * steps) instead of a uniform pressure.
     */
    void
    start_from(const Vector<double>    &force,
               const std::vector<bool> &contact,
               unsigned int             coarse_steps);

    std::pair<Vector<double>, Vector<double>>
    solve_fields() override;

    SolverStatistics
    statistics() const override;

  private:
    void
    neumann_step();

    /**
     * Give the interface block model (Coupling/Accelerator = ibqn) the
     * bodies' latest answers u1, u2 to the forces @p f_shaft, @p f_hub;
     * without a coarse model the first ones also give its Winkler prior.
     */
    void
    add_block_model_samples(const Vector<double> &f_shaft,
                            const Vector<double> &f_hub);

    /**
     * Let the interface block model's solution of the contact problem set
     * the contact flags and the data of the next step (next_force,
     * model_displacement). Returns whether the flags stayed and the
     * model's active set iteration settled.
     */
    bool
    predict_from_block_model();

    /** Update the active set from the state of a Neumann step. */
    void
    update_active_set();

    void
    dirichlet_step();

    /**
     * After the first Dirichlet step (prescribed @p u_shaft, @p u_hub,
     * reactions @p f1, @p f2): measure the bodies' compliances, replace an
     * adaptive rule's initial alpha by the Winkler alpha, and rescale the
     * step's answers (u1, u2, @p f1, @p f2) to that alpha.
     */
    void
    seed_alpha(const Vector<double> &u_shaft,
               const Vector<double> &u_hub,
               Vector<double>       &f1,
               Vector<double>       &f2);

    /**
     * After the first Neumann step under a uniform unit pressure: scale it
     * (force, u1, u2) to the uniform pressure that closes the gap best.
     */
    void
    scale_first_load();

    /**
     * Form the coarse model's prior for the current alpha and contact
     * points if they differ from those of the prior in use.
     */
    void
    update_prior();

    /** Throw a SolverError if the residuals grow or are not finite. */
    void
    check_divergence() const;

    /**
     * The mismatches of the latest @p count Neumann (@p neumann) or
     * Dirichlet steps, newest first (fewer if there are fewer).
     */
    std::vector<double>
    latest_mismatches(bool neumann, unsigned int count) const;

    /**
     * Whether the mismatch of the Neumann (@p neumann) or Dirichlet steps
     * grew in each of the last @p window steps of that kind.
     */
    bool
    grew(bool neumann, unsigned int window) const;

    /** Why the residuals look divergent or stalled; empty if they do not. */
    std::string
    divergence_reason() const;

    /** Winkler estimate of the convergent alpha range, for messages. */
    std::string
    suggested_alpha_range() const;

    /** One progress line for the latest step. */
    void
    print_step(std::ostream &out) const;

    BodySolver                  &shaft_solver;
    BodySolver                  &hub_solver;
    InterfaceOperator           &shaft;
    InterfaceOperator           &hub;
    const ContactInterface      &interface;
    std::unique_ptr<AlphaRule>   rule;
    std::unique_ptr<Accelerator> accelerator;
    const bool                   accelerated;
    const double                 tolerance;
    const unsigned int           max_steps;

    Vector<double> next_force; ///< force for the next Neumann step
    Vector<double> neumann_force, neumann_u1, neumann_u2;

    /** Whether the first Neumann step is loaded (scale_first_load()). */
    bool start_loaded = false;
    /**
     * The when-converged mode's tolerance for updating the flags; divided
     * by 100 (down to Coupling/Tolerance) whenever an update returns to a
     * set of flags seen before: updates from states that are too rough
     * can cycle between zones.
     */
    double active_set_tolerance;
    double initial_active_set_tolerance;
    /** Contact/Active set tolerance = auto: 0.1, 1e-2 from a coarse start. */
    const bool   automatic_active_set_tolerance;
    const double tolerance_floor;
    /** Every set of flags the iteration has had. */
    std::set<std::vector<bool>> visited_sets;
    /** What the accelerator keeps when the contact points change. */
    const HistoryOnChange history_on_change;
    /**
     * The interface block model (Coupling/Accelerator = ibqn); null for the
     * other accelerators. Its prediction gives the Neumann steps' forces
     * and the Dirichlet steps' displacement (model_displacement), alpha
     * plays no part.
     */
    std::unique_ptr<InterfaceBlockModel> block_model;
    Vector<double>                       model_displacement;
    /** The coarse model of the prior; null without one. */
    std::unique_ptr<CoarseInterfaceModel> coarse_model;
    /** Alpha and contact points of the prior in use. */
    std::vector<double> prior_alpha;
    std::vector<bool>   prior_contact;
    unsigned int        n_coarse_priors = 0;
    /** Force of a given start (start_from()); empty: uniform pressure. */
    Vector<double> initial_force;
    unsigned int   coarse_start_steps  = 0;
    bool           active_set_verified = false;
    unsigned int   last_change_step    = 0;
  };
} // namespace coaxfit

#endif
