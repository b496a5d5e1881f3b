#ifndef coaxfit_interface_solver_h
#define coaxfit_interface_solver_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/active_set.h>

#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <utility>
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
   * The state of the interface after a step of a solver: the nodal contact
   * force, the radial displacements of the two sides on S and the latest
   * relative mismatches (those of the last step of each kind).
   */
  struct InterfaceState
  {
    Vector<double> force;  ///< nodal contact force (compression +)
    Vector<double> u1, u2; ///< u_r of the inner and the outer side on S
    double displacement_mismatch = std::numeric_limits<double>::infinity();
    double traction_mismatch     = std::numeric_limits<double>::infinity();
  };

  /**
   * What a solver reports about itself: its method and controller, and
   * counts of its work (factorizations, solves) by name.
   */
  struct SolverStatistics
  {
    std::string method;
    std::string linear_solver = "direct"; ///< or amg
    std::string alpha_rule;
    std::string accelerator;
    /**
     * Points of the coarse model whose Jacobian is the quasi-Newton prior
     * (0: none), and how many priors it formed.
     */
    unsigned int coarse_model_points = 0;
    unsigned int coarse_priors       = 0;
    /** Steps of the coarser mesh's solution the run started from. */
    unsigned int                        coarse_start_steps = 0;
    std::map<std::string, unsigned int> factorizations;
    std::map<std::string, unsigned int> solves;
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
      : active_set(active_set)
    {}

    virtual ~InterfaceSolver() = default;

    /**
     * Solve; print one line per step to @p progress if not null. Returns
     * whether it converged.
     */
    virtual bool
    run(std::ostream *progress)
      = 0;

    /**
     * The displacement fields of shaft and hub for the final state on S
     * (an explicit, full solve of each body where the method iterated on
     * the interface only).
     */
    virtual std::pair<Vector<double>, Vector<double>>
    solve_fields() = 0;

    /** What the solver reports about itself. */
    virtual SolverStatistics
    statistics() const = 0;

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
    const Vector<double> &
    contact_force() const
    {
      return state.force;
    }

    const Vector<double> &
    u_shaft() const
    {
      return state.u1;
    }

    const Vector<double> &
    u_hub() const
    {
      return state.u2;
    }
    /** @} */

    /** Latest relative displacement mismatch. */
    double
    displacement_residual() const
    {
      return state.displacement_mismatch;
    }

    /** Latest relative traction mismatch. */
    double
    traction_residual() const
    {
      return state.traction_mismatch;
    }

    /** The contact / separated flags of the interface points. */
    const UnilateralActiveSet &
    get_active_set() const
    {
      return active_set;
    }

  protected:
    InterfaceState            state;
    std::vector<CouplingStep> history_rows;
    bool                      has_converged = false;
    UnilateralActiveSet       active_set;
  };
} // namespace coaxfit

#endif
