#ifndef coaxfit_stack_case_study_h
#define coaxfit_stack_case_study_h

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * `Fit/Case = all` of a stack (a file with Assembly/Bodies): the joints'
   * ISO fits checked over their bands. The joints interact (the outer fit
   * squeezes the inner joint, the inner one widens the outer body), so a
   * body's stress may be largest with one joint at its smallest
   * interference and another at its largest: every corner of the bands is
   * run, each ISO joint without its own `Fit/<joint>/Case` at its smallest
   * or largest interference, and the case of the means. Each case is a
   * complete StackFit run into a subdirectory named by its cases, in the
   * order of those joints: `min` (all smallest), `mean`, `max` (all
   * largest), then the mixed corners such as `min-max`; its parameters.prm
   * repeats it (Fit/Case = mean and each joint's `Case`).
   *
   * With Design/Mode = select the selected joints vary too: the case of
   * the means runs first and selects their fits; the other cases run
   * those fits (StackParameters::use_iso_fit(), check mode; their
   * parameters.prm selects again, which gives the same choice), and the
   * selection's fit_selection.csv is put beside fit_cases.csv. If it
   * finds none, the study is the selection's answer as a select run
   * writes it, and no other case runs.
   *
   * The output directory gets fit_cases.csv (a row per case: its exit
   * code, verdict, steps and the figures of stack_column_names()) and
   * report.md (the verdict over every case, a table of each joint's
   * interference and figures and each body's, the links to the cases'
   * reports); the console the same table and verdict. The directory is
   * staged and replaced as a whole: a failed or interrupted study leaves
   * the earlier results untouched. A case that is refused (exit 1: a
   * groove its interference closes) or whose process diverges has its
   * column with its exit code and no subdirectory, a line on the error
   * stream, and the verdict fails; the other cases are written.
   */
  class StackCaseStudy
  {
  public:
    StackCaseStudy(
      const std::string                                      &filename,
      const std::vector<std::pair<std::string, std::string>> &overrides,
      bool                                                    verbose,
      std::ostream                                           &out);

    /**
     * Run every case; the study's exit code: 0 if every case converged,
     * else the largest a case gave (2 not converged, 1 refused). Throws
     * InputError if the file cannot be read, with nothing written.
     */
    int
    run();

  private:
    const std::string                                      filename;
    const std::vector<std::pair<std::string, std::string>> overrides;
    const bool                                             verbose;
    std::ostream                                          &out;
  };
} // namespace coaxfit

#endif
