#ifndef coaxfit_staggered_coupling_h
#define coaxfit_staggered_coupling_h

#include <coaxfit/active_set.h>
#include <coaxfit/alpha_controller.h>
#include <coaxfit/body.h>
#include <coaxfit/contact_interface.h>

#include <ostream>
#include <vector>

namespace coaxfit
{
  /** One row of the convergence history. */
  struct CouplingStep
  {
    unsigned int step;
    bool         neumann; ///< Neumann (force) or Dirichlet (displacement)
    double       alpha;   ///< the alpha that built this step's data
    /**
     * max_i |u2_i - u1_i - d| / d of the state after this step (zero by
     * construction after a Dirichlet step).
     */
    double displacement_mismatch;
    /**
     * max_i |p2_i - p1_i| / max_i |p_i| with lumped pressures p = F/w of the
     * state after this step (zero by construction after a Neumann step).
     */
    double traction_mismatch;
    /** Number of separated interface points after this step. */
    unsigned int n_separated;
  };

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
  class StaggeredCoupling
  {
  public:
    StaggeredCoupling(Body                      &shaft,
                      Body                      &hub,
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
    run(std::ostream *progress);

    bool
    converged() const
    {
      return has_converged;
    }

    /** Number of steps taken (each a solve of both bodies). */
    unsigned int
    n_steps() const
    {
      return history_rows.size();
    }

    /**
     * The first step after which the displacement mismatch was below
     * @p criterion (the paper used 1e-2), or 0 if none was.
     */
    unsigned int
    steps_to_displacement_mismatch(double criterion) const;

    const std::vector<CouplingStep> &
    history() const
    {
      return history_rows;
    }

    /** @name The final state on S */
    /** @{ */
    const std::vector<double> &
    contact_force() const
    {
      return force;
    }

    const std::vector<double> &
    u_shaft() const
    {
      return u1;
    }

    const std::vector<double> &
    u_hub() const
    {
      return u2;
    }
    /** @} */

    /** Latest relative displacement mismatch. */
    double
    displacement_residual() const
    {
      return last_displacement_mismatch;
    }

    /** Latest relative traction mismatch. */
    double
    traction_residual() const
    {
      return last_traction_mismatch;
    }

    /** The contact / separated flags of the interface points. */
    const UnilateralActiveSet &
    get_active_set() const
    {
      return active_set;
    }

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

    Body                   &shaft;
    Body                   &hub;
    const ContactInterface &interface;
    AlphaController        &controller;
    const double            tolerance;
    const unsigned int      max_steps;

    std::vector<double> force; ///< nodal contact force of the current state
    std::vector<double> next_force; ///< force for the next Neumann step
    std::vector<double> u1, u2;
    std::vector<double> neumann_force, neumann_u1, neumann_u2;

    std::vector<CouplingStep> history_rows;
    double                    last_displacement_mismatch;
    double                    last_traction_mismatch;
    bool                      has_converged = false;
    UnilateralActiveSet       active_set;
    const double              active_set_tolerance;
    bool                      active_set_changed  = false;
    bool                      active_set_verified = false;
    unsigned int              last_change_step    = 0;
  };
} // namespace coaxfit

#endif
