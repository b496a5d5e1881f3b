#ifndef coaxfit_staggered_coupling_h
#define coaxfit_staggered_coupling_h

#include <coaxfit/alpha_controller.h>
#include <coaxfit/body.h>
#include <coaxfit/contact_interface.h>
#include <coaxfit/interface_solver.h>

#include <ostream>
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
   * returns the reactions F1, F2; the next Neumann step applies
   * F = F1 + alpha (F2 - F1). Both bodies are solved concurrently in every
   * step. With the unilateral pass (UnilateralActiveSet) tensile forces are
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
    StaggeredCoupling(InterfaceOperator         &shaft,
                      InterfaceOperator         &hub,
                      const ContactInterface    &interface,
                      AlphaController           &controller,
                      double                     tolerance,
                      unsigned int               max_steps,
                      const UnilateralActiveSet &active_set,
                      double                     active_set_tolerance);

    /**
     * Run the process; print one line per step to @p progress if not null.
     * Returns whether it converged within the step limit.
     */
    bool
    run(std::ostream *progress) override;

  private:
    /**
     * Relative displacement residual of the current state: |gap| where in
     * contact, penetration where separated.
     */
    double
    relative_gap_residual() const;

    void
    neumann_step();

    void
    dirichlet_step();

    /** Throw a SolverError if the residuals grow or are not finite. */
    void
    check_divergence() const;

    /** Winkler estimate of the convergent alpha range, for messages. */
    std::string
    suggested_alpha_range() const;

    InterfaceOperator      &shaft;
    InterfaceOperator      &hub;
    const ContactInterface &interface;
    AlphaController        &controller;
    const double            tolerance;
    const unsigned int      max_steps;

    std::vector<double> next_force; ///< force for the next Neumann step
    std::vector<double> neumann_force, neumann_u1, neumann_u2;

    const double active_set_tolerance;
    bool         active_set_changed  = false;
    bool         active_set_verified = false;
    unsigned int last_change_step    = 0;
  };
} // namespace coaxfit

#endif
