#include <coaxfit/parameters/material_library.h>

namespace coaxfit
{
  const std::vector<MaterialData> &
  material_library()
  {
    // Minimum strengths for the smallest size class of the standard named;
    // elastic and physical constants are the usual room temperature values
    // (the standards' informative annexes or the producers' data sheets).
    static const std::vector<MaterialData> library{
      {"S355",
       210000.,
       0.30,
       355.,
       7850.,
       12.0e-6,
       "EN 10025-2 structural steel S355JR, R_eH for t <= 16 mm"},
      {"C45",
       210000.,
       0.30,
       340.,
       7850.,
       11.5e-6,
       "EN 10083-2 C45+N (normalized), R_eH for d <= 16 mm (305 MPa for "
       "16 < d <= 100 mm)"},
      {"42CrMo4",
       210000.,
       0.30,
       900.,
       7850.,
       11.5e-6,
       "EN 10083-3 42CrMo4+QT, R_e for d <= 16 mm (750 MPa for 16 < d <= "
       "40 mm, 650 MPa for 40 < d <= 100 mm)"},
      {"EN-GJL-250",
       110000.,
       0.26,
       165.,
       7200.,
       10.0e-6,
       "EN 1561 grey cast iron EN-GJL-250, E 103-118 GPa, R_p0.1 165-228 MPa "
       "(lower bound; brittle: DIN 7190 designs it with a larger safety)"},
      {"EN AW-6082 T6",
       70000.,
       0.33,
       250.,
       2700.,
       23.4e-6,
       "EN 755-2 aluminium alloy EN AW-6082 T6, R_p0.2 for extruded bars "
       "and profiles of small section"},
      {"CuSn8",
       115000.,
       0.34,
       170.,
       8800.,
       18.2e-6,
       "EN 12166 tin bronze CuSn8 (CW453K) R390, R_p0.2 about 170 MPa "
       "(indicative)"}};
    return library;
  }



  std::string
  material_names(const std::string &separator)
  {
    std::string names;
    for (const MaterialData &m : material_library())
      names += (names.empty() ? "" : separator) + m.name;
    return names;
  }



  const MaterialData *
  find_material(const std::string &name)
  {
    for (const MaterialData &m : material_library())
      if (m.name == name)
        return &m;
    return nullptr;
  }
} // namespace coaxfit
