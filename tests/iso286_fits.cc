// The ISO 286 fits a fit selection chooses from, against the standard's
// tables: the transition fits of the hole basis (shafts k, m, n) and the
// shaft basis (shafts h with holes K, M, N, P to ZC, whose deviations
// ISO 286-1 derives from the shaft of the same letter: ES = -ei + Delta up
// to IT7 or IT8, its special cases at 3 mm and below and for N9 and M6).
// The limit deviations below are typed from ISO 286-2's tables, not
// computed; then the candidates at 40 mm are counted and the preferred
// fits named. tests/iso286_table.cc covers the hole-basis interference
// fits. The symmetric classes js and JS (es = +IT/2, ei = -IT/2) are
// checked where ISO 286-2 has half micrometres (js5, js6 with an odd IT)
// and where it rounds an odd IT down to the even value (js7, JS7, JS8).
#include <coaxfit/parameters/iso286.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  struct Tabulated
  {
    std::string fit;
    double      diameter;
    double      ES, EI, es, ei; // micrometres
  };

  // ISO 286-2 limit deviations (hole ES/EI, shaft es/ei) in micrometres.
  const std::vector<Tabulated> tabulated
    = {{"H7/k6", 40, 25, 0, 18, 2},      {"H6/k5", 40, 16, 0, 13, 2},
       {"H8/k8", 40, 39, 0, 39, 0},      {"H8/s7", 40, 39, 0, 68, 43},
       {"K7/h6", 40, 7, -18, 0, -16},    {"K6/h5", 40, 3, -13, 0, -11},
       {"K8/h7", 40, 12, -27, 0, -25},   {"M7/h6", 40, 0, -25, 0, -16},
       {"M8/h7", 40, 5, -34, 0, -25},    {"N7/h6", 40, -8, -33, 0, -16},
       {"N6/h5", 40, -12, -28, 0, -11},  {"N9/h8", 40, 0, -62, 0, -39},
       {"P7/h6", 40, -17, -42, 0, -16},  {"P6/h5", 40, -21, -37, 0, -11},
       {"P8/h7", 40, -26, -65, 0, -25},  {"R7/h6", 40, -25, -50, 0, -16},
       {"S7/h6", 40, -34, -59, 0, -16},  {"S6/h5", 40, -38, -54, 0, -11},
       {"U7/h6", 45, -61, -86, 0, -16},  {"U7/h6", 20, -33, -54, 0, -13},
       {"S7/h6", 100, -58, -93, 0, -22}, {"R7/h6", 190, -60, -106, 0, -29},
       {"N7/h6", 10, -4, -19, 0, -9},    {"K7/h6", 10, 5, -10, 0, -9},
       {"M7/h6", 2, -2, -12, 0, -6},     {"N7/h6", 2, -4, -14, 0, -6},
       {"P7/h6", 2, -6, -16, 0, -6},     {"S7/h6", 2, -14, -24, 0, -6},
       {"M6/h5", 300, -9, -41, 0, -23},  {"M6/h5", 5, -1, -9, 0, -5},
       {"H7/js6", 40, 25, 0, 8, -8},     {"H6/js5", 40, 16, 0, 5.5, -5.5},
       {"H8/js7", 40, 39, 0, 12, -12},   {"JS7/h6", 40, 12, -12, 0, -16},
       {"JS6/h5", 40, 8, -8, 0, -11},    {"H7/js6", 10, 15, 0, 4.5, -4.5},
       {"H8/js7", 10, 22, 0, 7, -7},     {"JS8/h7", 100, 27, -27, 0, -35}};
} // namespace



int
main()
{
  unsigned int mismatches = 0;
  for (const Tabulated &t : tabulated)
    {
      const coaxfit::IsoFit f    = coaxfit::iso_fit(t.fit, t.diameter);
      const bool            same = f.hole_upper == t.ES && f.hole_lower == t.EI
                        && f.shaft_upper == t.es && f.shaft_lower == t.ei
                        && f.min_interference() == t.ei - t.ES
                        && f.max_interference() == t.es - t.EI;
      mismatches += same ? 0 : 1;
      std::cout << f.name << " at " << t.diameter << " mm: hole "
                << f.hole_upper << "/" << f.hole_lower << ", shaft "
                << f.shaft_upper << "/" << f.shaft_lower << " um, interference "
                << f.min_interference() << " to " << f.max_interference()
                << " um: " << (same ? "as tabulated" : "DIFFERS from the table")
                << '\n';
    }
  std::cout << "fits checked: " << tabulated.size()
            << ", differing from ISO 286-2: " << mismatches << '\n';

  const std::vector<coaxfit::IsoFit> candidates = coaxfit::candidate_fits(40.);
  unsigned int                       preferred  = 0;
  std::cout << "candidates at 40 mm: " << candidates.size() << "; preferred:";
  for (const coaxfit::IsoFit &f : candidates)
    if (coaxfit::is_preferred_fit(f.name))
      {
        ++preferred;
        std::cout << ' ' << f.name << " (" << f.min_interference() << " to "
                  << f.max_interference() << ")";
      }
  std::cout << "\npreferred fits among them: " << preferred << '\n'
            << "candidates at 600 mm: " << coaxfit::candidate_fits(600.).size()
            << '\n';
}
