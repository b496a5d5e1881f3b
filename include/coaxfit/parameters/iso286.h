#ifndef coaxfit_iso286_h
#define coaxfit_iso286_h

#include <string>

namespace coaxfit
{
  /**
   * Limit deviations of a hole-basis fit of ISO 286 (`H7/s6`): the hole's
   * (EI = 0, ES = IT) and the shaft's (ei = fundamental deviation,
   * es = ei + IT), in micrometres, for a nominal diameter over 1 up to and
   * including 500 mm. Covered: holes H5 to H11, shafts m, n, p, r, s, t, u,
   * v, x, y, z, za, zb, zc in grades 5 to 11 (the interference fits; the
   * tables are those of ISO 286-1, standard tolerance grades and the
   * fundamental deviations of shafts, with their sub-ranges above 10 mm).
   */
  struct IsoFit
  {
    std::string name; ///< normalized, e.g. "H7/s6"
    int         hole_upper, hole_lower;
    int         shaft_upper, shaft_lower;

    /** The largest interference es - EI (micrometres). */
    int
    max_interference() const
    {
      return shaft_upper - hole_lower;
    }

    /** The smallest interference ei - ES (micrometres; < 0: clearance). */
    int
    min_interference() const
    {
      return shaft_lower - hole_upper;
    }
  };

  /**
   * The fit @p designation (`H7/s6`, blanks allowed) at the nominal
   * @p diameter (mm). Throws InputError naming `Fit/ISO fit` with what is
   * covered when the designation, the grade or the diameter is not.
   */
  IsoFit
  iso_fit(const std::string &designation, double diameter);

  /** Standard tolerance IT@p grade (5 to 11) at @p diameter, micrometres. */
  int
  standard_tolerance(unsigned int grade, double diameter);
} // namespace coaxfit

#endif
