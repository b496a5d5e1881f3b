#ifndef coaxfit_fit_selection_study_h
#define coaxfit_fit_selection_study_h

#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/verdict.h>
#include <coaxfit/parameters/parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * A run of `Design/Mode = select`: the FitSelection of the scene (its
   * states solved by one CoaxialFit, set up once and reused for each
   * interference and load), then the first fit checked as with
   * `Fit/Case = all` (its cases min, mean, max in the subdirectories of the
   * output directory). At the top of the output directory:
   * fit_selection.csv, summary.json (the selection and the verdict),
   * report.md (the verdict, the section "Fit selection", the cases' table)
   * and parameters.prm (this run again). A design that no fit satisfies
   * writes the selection and a verdict that names the conflict, and is no
   * error. A taper fit has no ISO fit: its band of push-on distances is
   * checked at both ends and the middle (checking_push_on()). The output
   * directory is staged and replaced as a whole.
   */
  class FitSelectionStudy
  {
  public:
    FitSelectionStudy(const Parameters &parameters,
                      std::ostream     &out     = std::cout,
                      bool              verbose = true);

    /**
     * Select and check; true if every solve of the first fit's cases
     * converged (also when no fit was found). Throws as CoaxialFit::run()
     * does, with the earlier results untouched.
     */
    bool
    run();

    /**
     * Select and check into the existing directory @p directory (no
     * staging, no commit): what run() does between its checks and its
     * commit, for a caller that stages several cases together (a sweep).
     */
    bool
    run_in(const std::string &directory);

    /**
     * The figures of the first fit's mean case in the order of
     * CaseFigures::column_names() (after run(); empty if no fit).
     */
    const std::vector<double> &
    mean_case_values() const
    {
      return mean_values;
    }

    /** The coupling steps of the first fit's mean case (after run()). */
    unsigned int
    mean_case_steps() const
    {
      return mean_steps;
    }

    /**
     * @p parameters checking the ISO fit @p fit as with Fit/Case = all
     * (Design/Mode = check), its parameters.prm saying so.
     */
    static Parameters
    checking(const Parameters &parameters, const std::string &fit);

    /**
     * @p parameters of a taper fit checking the push-on distances of the
     * measured interferences @p U_min to @p U_max (mm) as with Fit/Case =
     * all: its cases min, mean, max are the push-on distances U_min / C,
     * the middle and U_max / C.
     */
    static Parameters
    checking_push_on(const Parameters &parameters, double U_min, double U_max);

    /**
     * The load path of @p parameters (a hub that may yield) followed by
     * PlasticFit without output: the figures a selection takes.
     */
    static FitSelection::PlasticState
    follow_load_path(const Parameters &parameters);

  private:
    /**
     * With a hub that may yield: the first fit @p fit checked on the load
     * paths of its least and largest interference (elastic-plastic runs
     * into the subdirectories min and max of @p directory), the verdict
     * from them (the hub's plastic utilisation at max, the slip safety at
     * min), report.md with the selection's @p section; whether both runs
     * were completed.
     */
    bool
    check_plastic(const FitSelection &selection,
                  const std::string  &fit,
                  const std::string  &directory,
                  const std::string  &section,
                  Verdict            &verdict);

    /**
     * report.md into @p directory (with Output/Write report): the title
     * (with @p title after the diameter), the verdict, then @p body.
     */
    void
    write_report(const std::string &directory,
                 const std::string &title,
                 const Verdict     &verdict,
                 const std::string &body) const;

    const Parameters    parameters;
    std::ostream       &out;
    const bool          verbose;
    std::vector<double> mean_values;
    unsigned int        mean_steps = 0;
  };
} // namespace coaxfit

#endif
