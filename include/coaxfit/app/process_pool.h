#ifndef coaxfit_process_pool_h
#define coaxfit_process_pool_h

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace coaxfit
{
  /** One task of a ProcessPool: a case of a batch. */
  struct PoolTask
  {
    std::string label; ///< prefixes the lines it prints to standard error
    /** Non-empty: refused before it runs (exit 1 with this line). */
    std::string refusal;
    /**
     * The output directory whose staging directory (staging_directory_of())
     * a child killed by a signal leaves behind, removed by the parent;
     * empty: none (a case writing into a study's directory).
     */
    std::string output_directory;
  };

  /** How a task of a ProcessPool ended. */
  struct PoolResult
  {
    int         exit_code = -1; ///< as the program's exit codes
    double      wall      = 0.; ///< s, the task's process
    std::string error;          ///< its last line on standard error
    std::string row;            ///< what the task passed back; may be empty
  };

  /**
   * The processes of a batch of cases (CaseBatch, StackBatch): each task
   * runs in a child process of its own (fork), at most `jobs` at a time,
   * each limited to one thread when several run, so that the cores are
   * shared without oversubscription. A child's failure, crash or memory
   * exhaustion ends that task only (exit code 3 for a signal, its staging
   * directory removed). What each task prints is collected and printed as
   * one block, in the order of the tasks (standard output only if
   * verbose; each line of standard error with the task's label).
   *
   * A SIGINT or SIGTERM to this process is passed on to the running tasks
   * (Interruption), which remove their unfinished results as a single run
   * does.
   */
  class ProcessPool
  {
  public:
    /**
     * The work of task @p index in its child: print to std::cout and
     * std::cerr, put the figures to pass back into @p row, return the exit
     * code. It must not throw (wrap it in exit_code_of()).
     */
    using Work = std::function<int(unsigned int index, std::string &row)>;

    ProcessPool(unsigned int  jobs,
                bool          verbose,
                std::ostream &out,
                std::ostream &err);

    /** Run @p tasks with @p work; the results in the same order. */
    std::vector<PoolResult>
    run(const std::vector<PoolTask> &tasks, const Work &work) const;

  private:
    unsigned int  jobs;
    bool          verbose;
    std::ostream &out;
    std::ostream &err;
  };
} // namespace coaxfit

#endif
