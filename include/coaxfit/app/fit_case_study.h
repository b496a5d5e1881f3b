#ifndef coaxfit_fit_case_study_h
#define coaxfit_fit_case_study_h

#include <coaxfit/parameters/parameters.h>

#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * `Fit/Case = all`: the smallest, mean and largest interference of the
   * ISO fit in one run. Each case is a complete CoaxialFit run into the
   * subdirectory min, mean or max of the output directory; fit_cases.csv
   * and the console get one table of the design figures of the three. The
   * output directory is staged and replaced as a whole, as for one case.
   */
  class FitCaseStudy
  {
  public:
    FitCaseStudy(const Parameters &parameters,
                 std::ostream     &out     = std::cout,
                 bool              verbose = true);

    /**
     * Run the three cases; true if all converged (the others are written,
     * marked not converged). Throws as CoaxialFit::run() does, with the
     * earlier results untouched.
     */
    bool
    run();

    /**
     * Run the three cases into the existing directory @p directory (no
     * staging, no commit): what run() does between its checks and its
     * commit, for a caller that stages the directory (Design/Mode =
     * select).
     */
    bool
    run_in(const std::string &directory);

    /**
     * A section (Markdown, with its heading) that report.md gives after
     * the verdict (the fit selection that chose the fit).
     */
    void
    set_report_section(const std::string &markdown)
    {
      report_section = markdown;
    }

    /** The verdict of the three cases (after run()). */
    std::string
    verdict_line() const;

    /** The names of the entries a study writes into its directory. */
    static std::vector<std::string>
    file_names();

    /** One line of the table. */
    struct Row
    {
      FitCase                  fit_case;
      bool                     converged;
      unsigned int             steps;
      std::vector<double>      values; ///< in the order of column_names()
      std::vector<std::string> failed; ///< the case's failed criteria
    };

    /** The names (with units) of the figures of a Row. */
    static std::vector<std::string>
    column_names();

    /**
     * The figures of @p row named @p names (a subset of column_names(),
     * as CaseFigures takes them), in that order; NaN for a name the table
     * does not have.
     */
    static std::vector<double>
    values_of(const Row &row, const std::vector<std::string> &names);

    /** The table of the cases (after run()). */
    const std::vector<Row> &
    get_rows() const
    {
      return rows;
    }

  private:
    /**
     * Write fit_cases.csv and report.md (the verdict and the table, with
     * links to each case's report) into @p directory and print the table
     * and the verdict.
     */
    void
    output_results(const std::string &directory) const;

    const Parameters parameters;
    std::ostream    &out;
    const bool       verbose;
    std::vector<Row> rows;
    std::string      report_section;
  };
  /**
   * The name of every file any run may write (all writers, summary.json
   * and the files of a Fit/Case = all study included): what an existing
   * result directory may contain.
   */
  std::set<std::string>
  all_result_file_names();
} // namespace coaxfit

#endif
