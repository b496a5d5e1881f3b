#ifndef coaxfit_case_batch_h
#define coaxfit_case_batch_h

#include <coaxfit/parameters/parameters.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace coaxfit
{
  class CoaxialFit;

  /** The figures of one finished case, one row of a batch's table. */
  struct CaseFigures
  {
    bool         converged = false;
    unsigned int steps     = 0;
    /** A selection that found no fit (its figures NaN; not an error). */
    bool no_fit = false;
    /** In the order of column_names(); NaN where the case has none. */
    std::vector<double> values;

    /** Names (with units) of the values. */
    static std::vector<std::string>
    column_names();

    /** One line of text, read back by parse() in the parent process. */
    std::string
    serialize() const;

    static CaseFigures
    parse(const std::string &text);
  };

  /**
   * Run one case the way `coaxfit FILE.prm` does (one fit case, or the
   * three of `Fit/Case = all`, whose mean case gives the figures), into
   * its own output directory, staged and replaced as a whole; or, with a
   * non-empty @p directory, straight into that existing directory (a case
   * of a study that is staged as a whole). With @p prepared (a set-up case
   * that differs only in entries that CoaxialFit::reusable_across()), that
   * case is made this one and run without a new setup. Returns the
   * figures; throws as CoaxialFit::run() does.
   */
  CaseFigures
  run_case(const Parameters  &parameters,
           std::ostream      &out,
           bool               verbose,
           const std::string &directory = "",
           CoaxialFit        *prepared  = nullptr);

  /** One case of a batch. */
  struct BatchCase
  {
    std::string label; ///< the file name, or Name=value of a sweep
    /** The case's parameters; null when they could not be read. */
    std::shared_ptr<const Parameters> parameters;
    /** Why the parameters could not be read (exit code 1). */
    std::string input_error;
    /** Run into this existing directory (empty: its own, staged). */
    std::string directory;
    /** A set-up case to make this one (see run_case()); may be null. */
    CoaxialFit *prepared = nullptr;
  };

  /** How a case of a batch ended. */
  struct CaseOutcome
  {
    int         exit_code = -1; ///< as the program's exit codes
    double      wall      = 0.; ///< s, the case's process
    std::string error;          ///< its last error line, if any
    CaseFigures figures;        ///< when it wrote results
  };

  /**
   * Several cases in one command: `coaxfit A.prm B.prm ...` and the values
   * of a `--sweep`. The libraries are loaded and the parameters read once,
   * by this process; each case then runs in a child process of its own
   * (fork), at most `jobs` at a time, each limited to one thread when
   * several run (one BLAS thread each, no thread pool), so that the cores
   * are shared without oversubscription. A child's failure, crash or
   * memory exhaustion ends that case only: it is reported in the table
   * with its exit code, the others run on. What each case prints is
   * collected and printed as one block, in the order of the cases.
   *
   * A SIGINT or SIGTERM to this process is passed on to the running cases,
   * which remove their unfinished results as a single run does.
   */
  class CaseBatch
  {
  public:
    /**
     * @p verbose: each case's progress and report (otherwise only errors
     * and the table).
     */
    CaseBatch(unsigned int  jobs,
              bool          verbose,
              std::ostream &out,
              std::ostream &err);

    /** Run @p cases; the outcomes in the same order. */
    std::vector<CaseOutcome>
    run(const std::vector<BatchCase> &cases);

    /**
     * The exit code of a batch: 0 if every case converged, otherwise the
     * gravest of the cases' codes (3 internal or system error, then 2 not
     * converged or diverged, then 1 bad input).
     */
    static int
    exit_code(const std::vector<CaseOutcome> &outcomes);

    /**
     * The table of a batch as CSV text, a column @p key_name (the swept
     * parameter; none if empty) with @p keys first.
     */
    static std::string
    table_csv(const std::vector<BatchCase>   &cases,
              const std::vector<CaseOutcome> &outcomes,
              const std::string              &key_name = "",
              const std::vector<std::string> &keys     = {});

    /** Print the table of a batch for the console. */
    static void
    print_table(std::ostream                   &out,
                const std::vector<BatchCase>   &cases,
                const std::vector<CaseOutcome> &outcomes);

  private:
    unsigned int  jobs;
    bool          verbose;
    std::ostream &out;
    std::ostream &err;
  };

  /** The number of processors this process may run on. */
  unsigned int
  available_cores();

  /**
   * Write @p text to @p filename atomically: into a temporary file beside
   * it, flushed, then renamed over it; throws ResourceError if that fails
   * (the earlier file is untouched).
   */
  void
  write_file_atomically(const std::string &filename, const std::string &text);
} // namespace coaxfit

#endif
