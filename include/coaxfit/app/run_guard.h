#ifndef coaxfit_run_guard_h
#define coaxfit_run_guard_h

#include <coaxfit/parameters/parameters.h>

#include <functional>
#include <ostream>
#include <string>

namespace coaxfit
{
  /**
   * Run @p job and turn its outcome into coaxfit's exit code: the job's own
   * code when it returns, otherwise 1 for an InputError (bad input, a run
   * refused for its resources), 2 for a SolverError (diverged), 3 for a
   * ResourceError, std::bad_alloc or any other exception (internal or
   * system error). Each caught error is printed to @p err as one line
   * "coaxfit: error: ..." (or "coaxfit: internal error: ..."); none is
   * swallowed. The one place where exceptions become exit codes, for the
   * program and for each case of a batch.
   */
  int
  exit_code_of(const std::function<int()> &job, std::ostream &err);

  /**
   * The one line that says a case stopped at Coupling/Max steps (exit
   * code 2, its state written, marked not converged).
   */
  std::string
  not_converged_message(const Parameters &parameters);
} // namespace coaxfit

#endif
