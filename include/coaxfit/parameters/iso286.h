#ifndef coaxfit_iso286_h
#define coaxfit_iso286_h

#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * Limit deviations of an ISO 286 fit, in micrometres, for a nominal
   * diameter over 1 up to and including 500 mm: the hole's (ES, EI) and the
   * shaft's (es, ei). Covered are the interference and transition fits
   * (the hole or the shaft system of ISO 286-1):
   * - hole basis `H7/s6`: holes H (EI = 0, ES = IT) in grades 5 to 11,
   *   shafts k, m, n, p, r, s, t, u, v, x, y, z, za, zb, zc in grades 5 to
   *   11 (ei = the fundamental deviation, es = ei + IT), and js in grades
   *   5 to 11 (es = +IT/2, ei = -IT/2; for js7 to js11 an odd IT is first
   *   rounded down to the even value below, as ISO 286-2 does, so that
   *   js5 and js6 alone have half micrometres);
   * - shaft basis `S7/h6`: shafts h (es = 0, ei = -IT) in grades 5 to 11,
   *   holes JS in grades 5 to 11 (ES = +IT/2, EI = -IT/2, rounded as js),
   *   K and M in grades 5 to 8, N in grades 5 to 11 and P to ZC in
   *   grades 5 to 11 (ES = the fundamental deviation, EI = ES - IT), by
   *   ISO 286-1's rules for holes: ES = -ei of the shaft of the same
   *   letter, plus Delta = IT_n - IT_(n-1) for K, M, N up to IT8 and P to
   *   ZC up to IT7 above 3 mm; N above IT8 has ES = 0 (above 3 mm).
   * The tables are those of ISO 286-1 (standard tolerance grades, the
   * fundamental deviations of shafts with their sub-ranges above 10 mm).
   */
  struct IsoFit
  {
    std::string name;                     ///< normalized, e.g. "H7/s6"
    double      hole_upper, hole_lower;   ///< half micrometres for JS5, JS6
    double      shaft_upper, shaft_lower; ///< half micrometres for js5, js6

    /** The largest interference es - EI (micrometres). */
    double
    max_interference() const
    {
      return shaft_upper - hole_lower;
    }

    /** The smallest interference ei - ES (micrometres; < 0: clearance). */
    double
    min_interference() const
    {
      return shaft_lower - hole_upper;
    }
  };

  /**
   * The fit @p designation (`H7/s6`, `S7/h6`, blanks allowed) at the
   * nominal @p diameter (mm). Throws InputError naming `Fit/ISO fit` with
   * what is covered when the designation, the grade or the diameter is not.
   */
  IsoFit
  iso_fit(const std::string &designation, double diameter);

  /** Standard tolerance IT@p grade (4 to 11) at @p diameter, micrometres. */
  int
  standard_tolerance(unsigned int grade, double diameter);

  /**
   * The interference and transition fits a design may choose from at the
   * nominal @p diameter (over 1 up to 500 mm; none outside): shaft grades
   * IT5 to IT8 with the hole one grade coarser or equal, hole basis (H with
   * js, k, m, n, p to zc) and shaft basis (h with JS, K, M, N, P to ZC), each
   * class
   * only in the grades ISO 286-2 tabulates it and where it is defined at
   * this diameter.
   */
  std::vector<IsoFit>
  candidate_fits(double diameter);

  /**
   * Whether @p name (normalized) is one of the preferred interference and
   * transition fits of ISO 286-1 (hole basis and shaft basis): H7/k6,
   * H7/n6, H7/p6, H7/r6, H7/s6, H7/u6 and K7/h6, N7/h6, P7/h6, R7/h6,
   * S7/h6, U7/h6 (sources in iso286.cc).
   */
  bool
  is_preferred_fit(const std::string &name);

  /**
   * How a fit selection ranks fits first (compare with <): the preferred
   * fits, then the widest interference band (the widest tolerances).
   */
  inline std::pair<bool, double>
  preference_key(const IsoFit &fit)
  {
    return {!is_preferred_fit(fit.name),
            fit.min_interference() - fit.max_interference()};
  }
} // namespace coaxfit

#endif
