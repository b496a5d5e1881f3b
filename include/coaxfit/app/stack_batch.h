#ifndef coaxfit_stack_batch_h
#define coaxfit_stack_batch_h

#include <coaxfit/app/stack_fit.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /** A stack file of a batch: its parameters, or why they were refused. */
  struct StackCase
  {
    std::string                            label; ///< the file as given
    std::shared_ptr<const StackParameters> parameters;
    std::string                            input_error;
  };

  /** How a stack case of a batch ended, and its figures. */
  struct StackCaseOutcome
  {
    int                       exit_code = -1; ///< as the program's
    double                    wall      = 0.; ///< s
    std::string               error;          ///< its last error line
    std::string               verdict;        ///< OK, FAILED; empty: none
    unsigned int              steps = 0;
    std::vector<JointFigures> joints;     ///< empty: nothing computed
    std::string               fits;       ///< a selection's chosen fits
    std::vector<std::string>  joint_fits; ///< where each joint's fit is from

    /**
     * The figures of the table as one line of text (JSON), passed from a
     * case's process to the batch's; read back by parse().
     */
    std::string
    serialize() const;
    void
    parse(const std::string &text);
  };

  /**
   * Several stack files (Assembly/Bodies) in one command: `coaxfit A.prm
   * B.prm`. Each file runs as it would on its own, into its own
   * Output/Directory, in a process of its own (ProcessPool, as the cases
   * of two bodies), at most `--jobs` at a time. A case that fails (bad
   * input, not converged, out of memory, disk full, a crash) ends alone:
   * its row says how, the others run on; an interrupt ends the batch with
   * the cases done in place and the running ones' results not written.
   * The table has one row per joint of each case (the cases' body lists
   * differ).
   */
  class StackBatch
  {
  public:
    StackBatch(unsigned int  jobs,
               bool          verbose,
               std::ostream &out,
               std::ostream &err);

    /** Run every case; their outcomes in the same order. */
    std::vector<StackCaseOutcome>
    run(const std::vector<StackCase> &cases) const;

    /** The console table. */
    static void
    print_table(std::ostream                        &out,
                const std::vector<StackCase>        &cases,
                const std::vector<StackCaseOutcome> &outcomes);

    /** The CSV table: a row per joint of each case (a case without: one). */
    static std::string
    table_csv(const std::vector<StackCase>        &cases,
              const std::vector<StackCaseOutcome> &outcomes);

    /**
     * The batch's exit code: 0 if every case gave 0, else the largest of
     * 1, 2, 3 a case gave (any other: 3).
     */
    static int
    exit_code(const std::vector<StackCaseOutcome> &outcomes);

  private:
    const unsigned int jobs;
    const bool         verbose;
    std::ostream      &out, &err;
  };
} // namespace coaxfit

#endif
