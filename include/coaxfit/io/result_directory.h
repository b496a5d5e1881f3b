#ifndef coaxfit_result_directory_h
#define coaxfit_result_directory_h

#include <ostream>
#include <set>
#include <string>

namespace coaxfit
{
  /**
   * @p path without trailing slashes, `.` and `..` parts resolved (a path
   * that ends in one is made absolute): `out/` and `out/./` are `out`, and
   * a name can be appended to the directory's own name.
   */
  std::string
  normalized_directory(const std::string &path);

  /** The staging directory a run of process @p pid makes for @p target. */
  std::string
  staging_directory_of(const std::string &target, int pid);

  /**
   * The output directory of one run, replaced as a whole or not at all.
   *
   * The constructor checks the target (Output/Directory) before any work:
   * the path must be creatable and writable, and an existing directory may
   * contain only files that coaxfit writes (@p result_files), since the
   * whole directory is replaced. It then creates a staging directory
   * beside the target (same file system), `.NAME.partial-PID`, into which
   * the writers write. commit() flushes every file to disk and swaps the
   * staging directory into place with one atomic rename (Linux
   * renameat2(RENAME_EXCHANGE) when a previous result is there), then
   * removes the previous result. Until commit() returns, the previous
   * result is untouched: a run that fails, is interrupted (see
   * Interruption) or runs out of disk leaves it as it was and removes its
   * staging directory. Of two runs into one directory, the one that
   * commits last wins, each leaving a complete set.
   *
   * Staging directories of runs killed without a chance to clean up
   * (SIGKILL, power loss) are removed by the next run into the same target
   * once their process no longer exists.
   */
  class ResultDirectory
  {
  public:
    /**
     * Check @p target and create the staging directory; throws InputError
     * naming Output/Directory if the target cannot be used. Everything in
     * it must be a file coaxfit writes (@p result_files, at any depth);
     * with @p top_level (a study), what lies directly in it must be one
     * of those names instead (its table, plot and value directories).
     */
    ResultDirectory(const std::string           &target,
                    const std::set<std::string> &result_files,
                    const std::set<std::string> &top_level = {});

    /** Removes the staging directory unless committed. */
    ~ResultDirectory();

    ResultDirectory(const ResultDirectory &) = delete;
    ResultDirectory &
    operator=(const ResultDirectory &)
      = delete;

    /** Where the writers write until commit(). */
    const std::string &
    staging_path() const;

    /**
     * Flush every staged file to disk and put the staging directory in the
     * target's place; throws (with the previous result untouched) if that
     * cannot be done. The @p console must have taken everything printed to
     * it so far (it is flushed and checked first): a run whose report could
     * not be shown ends with exit 3 and leaves the previous result as it
     * was.
     */
    void
    commit(std::ostream &console);

  private:
    /** Remove staging directories of dead runs into the same target. */
    void
    remove_stale_staging() const;

    /** Swap (or move) the staging directory into the target's place. */
    void
    swap_into_place() const;

    std::string target;
    std::string staging;
    bool        committed = false;
  };
} // namespace coaxfit

#endif
