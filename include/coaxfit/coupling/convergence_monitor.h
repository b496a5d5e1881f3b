#ifndef coaxfit_convergence_monitor_h
#define coaxfit_convergence_monitor_h

#include <coaxfit/coupling/interface_solver.h>

#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The convergence measures of an iteration on the interface, apart from
   * the iteration that produces them: it reads the history of steps (one
   * CouplingStep per step, with the relative displacement and traction
   * mismatches), prints a step as a line, and judges whether the residuals
   * diverge or stall.
   *
   * Divergence: a residual that is not finite or above 1e3; above ten times
   * the tolerance, the same kind of mismatch growing in each of the last
   * four steps of its kind (for an accelerated iteration, both kinds). A
   * stall: since the start of the current inner iteration (an outer active
   * set update begins a new one) at least 60 steps and no progress of the
   * best mismatch in the last 30. Growth or a stall below 1e-4 is the
   * round-off floor of the problem and is reported as such.
   */
  class ConvergenceMonitor
  {
  public:
    /**
     * A monitor for the mismatch tolerance @p tolerance; @p judge_both
     * asks both kinds of mismatch to grow before calling it divergence (an
     * accelerated iteration may trade one for the other after a restart).
     */
    ConvergenceMonitor(double tolerance, bool judge_both);

    /** Forget the inner iteration (a new run). */
    void
    start();

    /** A new inner iteration begins with the step @p step. */
    void
    new_inner_iteration(unsigned int step);

    /**
     * Why the residuals of @p history look divergent or stalled; empty if
     * they do not.
     */
    std::string
    divergence_reason(const std::vector<CouplingStep> &history) const;

    /**
     * Throw the SolverError for the residuals of @p history, which diverge
     * or stall for @p reason (from divergence_reason()): at the round-off
     * level with advice on the tolerance and the mesh, else naming the
     * method @p method that ran and giving @p advice.
     */
    [[noreturn]] void
    fail(const std::vector<CouplingStep> &history,
         const std::string               &reason,
         const std::string               &method,
         const std::string               &advice) const;

    /**
     * The header of the progress lines; @p separated adds the column of
     * separated points.
     */
    static void
    print_header(std::ostream &out, bool separated);

    /** One progress line for the step @p step. */
    static void
    print_step(std::ostream &out, const CouplingStep &step, bool separated);

  private:
    /**
     * The mismatches of the latest @p count Neumann (@p neumann) or
     * Dirichlet steps of @p history, newest first (fewer if there are
     * fewer).
     */
    static std::vector<double>
    latest_mismatches(const std::vector<CouplingStep> &history,
                      bool                             neumann,
                      unsigned int                     count);

    /**
     * Whether the mismatch of the Neumann (@p neumann) or Dirichlet steps
     * grew in each of the last @p window steps of that kind.
     */
    static bool
    grew(const std::vector<CouplingStep> &history,
         bool                             neumann,
         unsigned int                     window);

    const double tolerance;
    const bool   judge_both;
    /** The step before the first of the current inner iteration. */
    unsigned int last_change_step = 0;
  };
} // namespace coaxfit

#endif
