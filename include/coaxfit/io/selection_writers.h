#ifndef coaxfit_selection_writers_h
#define coaxfit_selection_writers_h

#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/verdict.h>

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The result files of `Design/Mode = select` at the top of the output
   * directory (the first fit's cases have their own files below it):
   * fit_selection.csv, the ranked fits; summary.json, the band, what
   * governs its ends, the fits and the verdict. Each writes its file with
   * open_result_file() (into the staged directory) and returns one line
   * for the console.
   */
  namespace selection_files
  {
    /**
     * fit_selection.csv: one row per fit inside the band, ranked: rank,
     * fit, system (hole or shaft basis), preferred (1/0), the deviations
     * ES, EI, es, ei and the interferences U_min, U_max (micrometres).
     */
    std::string
    write_csv(const FitSelection &selection, const std::string &directory);

    /**
     * summary.json: `case` (@p case_name), `mode` select, `selection` {U_min,
     * U_max, U_min_din, U_max_din (mm, measured, smoothing loss included),
     * governing {U_min, U_max, U_min_din, U_max_din: state and criterion},
     * checks, notes, fits: [{fit, U_min, U_max} in mm]}, and `verdict` {ok,
     * failed}.
     */
    std::string
    write_summary(const std::string  &case_name,
                  const FitSelection &selection,
                  const Verdict      &verdict,
                  const std::string  &first_fit,
                  const std::string  &directory);

    /** The names of the files above. */
    std::vector<std::string>
    file_names();
  } // namespace selection_files
} // namespace coaxfit

#endif
