#ifndef coaxfit_interface_solver_h
#define coaxfit_interface_solver_h

#include <coaxfit/active_set.h>

#include <limits>
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
   * What every method that solves the contact problem on S delivers: the
   * final nodal contact force and radial displacements of both bodies at
   * the interface points, the contact / separated flags, the convergence
   * history and residuals. The staggered coupling (the paper's method) and
   * the monolithic reference solver derive from it, so results are written
   * the same way for both.
   */
  class InterfaceSolver
  {
  public:
    explicit InterfaceSolver(const UnilateralActiveSet &active_set)
      : last_displacement_mismatch(std::numeric_limits<double>::infinity())
      , last_traction_mismatch(std::numeric_limits<double>::infinity())
      , active_set(active_set)
    {}

    virtual ~InterfaceSolver() = default;

    /**
     * Solve; print one line per step to @p progress if not null. Returns
     * whether it converged.
     */
    virtual bool
    run(std::ostream *progress)
      = 0;

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
     * The first Neumann step after which the displacement mismatch was
     * below @p criterion (the paper used 1e-2), or 0 if none was.
     */
    unsigned int
    steps_to_displacement_mismatch(const double criterion) const
    {
      for (const CouplingStep &s : history_rows)
        if (s.neumann && s.displacement_mismatch < criterion)
          return s.step;
      return 0;
    }

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

  protected:
    std::vector<double>       force;  ///< nodal contact force (compression +)
    std::vector<double>       u1, u2; ///< u_r of shaft and hub on S
    std::vector<CouplingStep> history_rows;
    double                    last_displacement_mismatch;
    double                    last_traction_mismatch;
    bool                      has_converged = false;
    UnilateralActiveSet       active_set;
  };
} // namespace coaxfit

#endif
