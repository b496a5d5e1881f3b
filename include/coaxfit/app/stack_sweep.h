#ifndef coaxfit_stack_sweep_h
#define coaxfit_stack_sweep_h

#include <coaxfit/app/parameter_sweep.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * `--sweep Section/Name=...` of a stack (a file with Assembly/Bodies):
   * each value a complete run of StackFit with the file's other settings,
   * one after the other in this process (a stack's run takes a second or
   * less), its results in a subdirectory `NN_value/` of the study
   * `<Output/Directory>_sweep`. The study directory also gets sweep.csv
   * (the value, the run's exit code, convergence, steps and verdict, each
   * joint's pressures, contact, slip safety, press-in force and joining
   * temperatures, each
   * body's von Mises stress and safety) and, for numeric values, sweep.png
   * (each joint's mean pressure against the value) with sweep.gp.
   *
   * The study is staged and replaced as a whole: a failed or interrupted
   * study leaves the earlier one untouched. A value that is refused (bad
   * input, exit 1) or whose process diverges (exit 2, nothing written)
   * has its row with its exit code and no subdirectory; a value that did
   * not converge is written with converged false (exit 2), as a single
   * run writes it. The bodies (Assembly/Bodies) and Output/Directory
   * cannot be swept.
   */
  class StackSweep
  {
  public:
    StackSweep(
      const std::string                                      &filename,
      const std::vector<std::pair<std::string, std::string>> &overrides,
      const SweepSpec                                        &sweep,
      bool                                                    verbose,
      std::ostream                                           &out);

    /**
     * Run the study; its exit code: 0 if every value converged, else 2 if
     * one did not, else 1 (a value refused).
     */
    int
    run();

  private:
    /** Write sweep.gp and draw sweep.png in @p directory; what it did. */
    std::string
    plot(const std::string &directory, unsigned int n_joints) const;

    const std::string                                      filename;
    const std::vector<std::pair<std::string, std::string>> overrides;
    const SweepSpec                                        sweep;
    const bool                                             verbose;
    std::ostream                                          &out;
  };
} // namespace coaxfit

#endif
