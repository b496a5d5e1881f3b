#ifndef coaxfit_parameter_sweep_h
#define coaxfit_parameter_sweep_h

#include <iosfwd>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * `--sweep Section/Name=v1,v2,...` or `--sweep Section/Name=from:to:count`
   * (count values evenly spaced from from to to, both included), or
   * `v1;v2;...` for values that contain commas (Assembly/Order's lists of
   * joints).
   */
  struct SweepSpec
  {
    std::string              entry;  ///< Section/Name
    std::vector<std::string> values; ///< as given to ParameterHandler

    /** Parse the argument of --sweep; InputError on a malformed one. */
    static SweepSpec
    parse(const std::string &argument);

    /**
     * The subdirectory of value @p index in a study: `NN_value`, the value
     * in letters, digits and . + - = only.
     */
    std::string
    directory_name(unsigned int index) const;
    /**
     * What the study directory @p study may hold directly: the table and
     * plot, the value subdirectories of this study and of an earlier one
     * (recognized by its sweep.csv). The value subdirectories hold a
     * run's files.
     */
    std::set<std::string>
    study_entries(const std::string &study) const;
    /**
     * Write sweep.gp (the terminal of @p size, sweep.csv as data, this
     * entry on the x axis, then @p plots) into @p directory and draw
     * sweep.png with it; what was drawn (@p what against the entry) or
     * why it was skipped.
     */
    std::string
    draw(const std::string &directory,
         const std::string &size,
         const std::string &plots,
         const std::string &what) const;
    /** Whether every value is a number (the plot's axis is then a scale). */
    bool
    numeric() const;
  };

  /**
   * A study of one parameter file over the values of one parameter. Each
   * value is a complete case (its own results in a subdirectory
   * `NN_value/` of the study), run by a CaseBatch, several at a time, with
   * the file's other settings; the study directory also gets sweep.csv
   * (the swept value and each case's figures, steps, exit code and wall
   * time), sweep.png (pressures and torque capacity against the value,
   * FE next to DIN 7190) and sweep.gp, the gnuplot script that draws it.
   *
   * The study directory is the file's output directory with `_sweep`
   * appended (output/variant_05_sweep for prm/variant_05.prm), staged and
   * replaced as a whole, as one run's is: a failed or interrupted study
   * leaves the earlier one untouched. A value whose case fails (bad value,
   * diverged, out of memory) has its row in the table with its exit code
   * and error, and no subdirectory; the others are written.
   */
  class ParameterSweep
  {
  public:
    ParameterSweep(
      const std::string                                      &filename,
      const std::vector<std::pair<std::string, std::string>> &overrides,
      const SweepSpec                                        &sweep,
      unsigned int                                            jobs,
      bool                                                    verbose,
      std::ostream                                           &out,
      std::ostream                                           &err);

    /** Run the study; its exit code (CaseBatch::exit_code()). */
    int
    run();

  private:
    /** Write sweep.gp and draw sweep.png in @p directory. */
    std::string
    plot(const std::string &directory) const;

    const std::string                                      filename;
    const std::vector<std::pair<std::string, std::string>> overrides;
    const SweepSpec                                        sweep;
    const unsigned int                                     jobs;
    const bool                                             verbose;
    std::ostream                                          &out;
    std::ostream                                          &err;
  };
} // namespace coaxfit

#endif
