// ISO 286 fits against the standard's tables: the limit deviations of holes
// and shafts below are typed from ISO 286-2 (tables of limit deviations for
// holes H and shafts m to zc), not computed; coaxfit's tables (ISO 286-1
// standard tolerances and fundamental deviations) must give the same, for
// every grade 5 to 11, both ends of the diameter range, the sub-ranges
// above 10 mm and letters that start above a diameter (t, v, y). The
// interference limits follow as U_min = ei - ES and U_max = es - EI.

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
    int         ES, EI, es, ei; // micrometres
  };

  // ISO 286-2 limit deviations (hole ES/EI, shaft es/ei) in micrometres.
  const std::vector<Tabulated> tabulated
    = {{"H7/s6", 3, 10, 0, 20, 14},     {"H7/m6", 6, 12, 0, 12, 4},
       {"H7/n6", 10, 15, 0, 19, 10},    {"H7/z7", 12, 18, 0, 68, 50},
       {"H7/v6", 16, 18, 0, 50, 39},    {"H6/s5", 18, 11, 0, 36, 28},
       {"H7/y6", 20, 21, 0, 76, 63},    {"H7/u6", 25, 21, 0, 61, 48},
       {"H7/t6", 30, 21, 0, 54, 41},    {"H7/s6", 40, 25, 0, 59, 43},
       {"H7/p6", 50, 25, 0, 42, 26},    {"H9/za9", 60, 74, 0, 300, 226},
       {"H7/s6", 65, 30, 0, 72, 53},    {"H7/r6", 80, 30, 0, 62, 43},
       {"H7/r6", 100, 35, 0, 73, 51},   {"H10/zb10", 120, 140, 0, 665, 525},
       {"H8/u7", 150, 63, 0, 230, 190}, {"H5/p5", 200, 20, 0, 70, 50},
       {"H7/s6", 300, 52, 0, 202, 170}, {"H11/zc11", 450, 400, 0, 2800, 2400},
       {"H7/x6", 500, 63, 0, 860, 820}};
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
      std::cout << f.name << " at " << t.diameter << " mm: hole +"
                << f.hole_upper << "/" << f.hole_lower << ", shaft +"
                << f.shaft_upper << "/+" << f.shaft_lower
                << " um, interference " << f.min_interference() << " to "
                << f.max_interference()
                << " um: " << (same ? "as tabulated" : "DIFFERS from the table")
                << '\n';
    }
  std::cout << "fits checked: " << tabulated.size()
            << ", differing from ISO 286-2: " << mismatches << '\n';
}
