#ifndef coaxfit_staggered_coupling_h
#define coaxfit_staggered_coupling_h

#include <coaxfit/coupling/coarse_interface_model.h>
#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/convergence_monitor.h>
#include <coaxfit/coupling/coupling_update.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/interface_operator.h>

#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace coaxfit
{
  /**
   * The paper's alternating (staggered Dirichlet-Neumann) process for the
   * shaft D1 and the hub D2.
   *
   * Neumann and Dirichlet steps alternate. In a Neumann step both bodies
   * get the same nodal contact force F and return u1, u2 on S; the
   * displacement mismatch is du = u2 - u1 - d. The Dirichlet step
   * prescribes displacements at the contact points, separated points
   * traction free, and returns the reactions F1, F2. What the steps are
   * given and how the answers become the next step's data (the
   * fixed-point map and its acceleration, the contact flags) is the
   * CouplingUpdate's: the paper's relaxation with an alpha rule and an
   * accelerator, or the interface block model. Both bodies are solved
   * concurrently in every step. The first Neumann step applies the
   * paper's zero force, or a uniform pressure scaled after the step to the
   * one that closes the gap best, or the force of a coarser mesh's
   * solution (start_from()).
   *
   * The iteration has converged when the latest displacement mismatch and
   * the latest traction mismatch are both below the tolerance and the
   * active set was checked in the last Neumann step and did not change.
   * The ConvergenceMonitor judges the history: a growing, stalling or
   * non-finite residual stops it with a SolverError that names what ran
   * and what to try.
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
     * Give the update the model of the same case one refinement coarser
     * (Coupling/Coarse model): the accelerator's prior (the inverse
     * Jacobian for the current alpha and contact points) or the block
     * model's prior compliances.
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

    /**
     * The nodal joint forces of the interface points as forces on the joint
     * points of the shaft (side 0) or the hub (side 1), for the final
     * fields when the sides do not match (Scene::body_forces).
     */
    void
    set_force_transfer(
      const std::function<Vector<double>(unsigned int, const Vector<double> &)>
        &transfer)
    {
      force_to_body = transfer;
    }

    SolverStatistics
    statistics() const override;

  private:
    std::function<Vector<double>(unsigned int, const Vector<double> &)>
      force_to_body;

    void
    neumann_step();

    void
    dirichlet_step();

    /**
     * After the first Neumann step under a uniform unit pressure: scale it
     * (force, u1, u2) to the uniform pressure that closes the gap best.
     */
    void
    scale_first_load();

    BodySolver                     &shaft_solver;
    BodySolver                     &hub_solver;
    InterfaceOperator              &shaft;
    InterfaceOperator              &hub;
    const ContactInterface         &interface;
    std::unique_ptr<CouplingUpdate> update;
    ConvergenceMonitor              monitor;
    const double                    tolerance;
    const unsigned int              max_steps;

    Vector<double> next_force; ///< force for the next Neumann step
    /** Whether the first Neumann step is loaded (scale_first_load()). */
    bool start_loaded        = false;
    bool active_set_verified = false;
    /** The coarse model of the priors; null without one. */
    std::unique_ptr<CoarseInterfaceModel> coarse_model;
    /** Force of a given start (start_from()); empty: uniform pressure. */
    Vector<double> initial_force;
    unsigned int   coarse_start_steps = 0;
  };
} // namespace coaxfit

#endif
