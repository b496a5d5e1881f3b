#include <coaxfit/parameters/material_library.h>

namespace coaxfit
{
  std::string
  to_string(const MaterialKind kind)
  {
    switch (kind)
      {
        case MaterialKind::brittle:
          return "brittle";
        case MaterialKind::polymer:
          return "polymer";
        default:
          return "metal";
      }
  }



  std::string
  to_string(const MaterialFamily family)
  {
    switch (family)
      {
        case MaterialFamily::steel:
          return "steel";
        case MaterialFamily::cast_iron:
          return "cast iron";
        case MaterialFamily::light_alloy:
          return "light alloy";
        case MaterialFamily::copper_alloy:
          return "copper alloy";
        default:
          return "unknown";
      }
  }



  const std::vector<MaterialData> &
  material_library()
  {
    // Minimum strengths for the smallest size class of the standard named;
    // elastic and physical constants are the usual room temperature values
    // (the standards' informative annexes or the producers' data sheets).
    // The expansion coefficients for joining are DIN 7190-1's (heating,
    // and the smaller one for undercooling in liquid nitrogen: steel 11 and
    // 8.5, cast iron 10 and 8, bronze 17 and 15, aluminium alloys 23 and 18,
    // in 1e-6/K); the heating coefficients of the entries that existed
    // before the undercooling coefficient are kept.
    // The temperature limit is the one above which heating a hub for
    // joining changes the material (tempering, ageing) or, for steels and
    // irons without such a treatment, the usual limit of 350 C for heating
    // a hub (scaling, structural change).
    const double steel_cooling = 8.5e-6, iron_cooling = 8.0e-6;
    static const std::vector<MaterialData> library{
      {"S355",
       210000.,
       0.30,
       355.,
       470.,
       7850.,
       12.0e-6,
       steel_cooling,
       350.,
       "the usual limit for heating a steel hub (scaling)",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10025-2 structural steel S355JR, R_eH for t <= 16 mm, R_m "
       "470-630 MPa for 3 <= t <= 100 mm"},
      {"C45",
       210000.,
       0.30,
       340.,
       620.,
       7850.,
       11.5e-6,
       steel_cooling,
       350.,
       "the usual limit for heating a steel hub (scaling)",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10083-2 C45+N (normalized), R_eH for d <= 16 mm (305 MPa for "
       "16 < d <= 100 mm), R_m 620 MPa for d <= 16 mm"},
      {"42CrMo4",
       210000.,
       0.30,
       900.,
       1100.,
       7850.,
       11.5e-6,
       steel_cooling,
       540.,
       "the lowest tempering temperature of +QT, 540-680 C",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10083-3 42CrMo4+QT, R_e for d <= 16 mm (750 MPa for 16 < d <= "
       "40 mm, 650 MPa for 40 < d <= 100 mm), R_m 1100-1300 MPa for d <= "
       "16 mm; tempered at 540-680 C"},
      {"34CrNiMo6",
       210000.,
       0.30,
       1000.,
       1200.,
       7850.,
       11.5e-6,
       steel_cooling,
       540.,
       "the lowest tempering temperature of +QT, 540-660 C",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10083-3 34CrNiMo6+QT, R_e for d <= 16 mm (900 MPa for 16 < d <= "
       "40 mm, 800 MPa for 40 < d <= 100 mm), R_m 1200-1400 MPa for d <= "
       "16 mm; tempered at 540-660 C"},
      {"16MnCr5",
       210000.,
       0.30,
       735.,
       1000.,
       7850.,
       11.5e-6,
       steel_cooling,
       150.,
       "the tempering temperature of case-hardened parts, 150-200 C: "
       "the hardened case softens",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10084 case hardening steel 16MnCr5, the core after case "
       "hardening and tempering at 150-200 C: R_m >= 1000 MPa for d <= "
       "16 mm (producer data sheet), R_p0.2 about 735 MPa on the 11 mm test "
       "blank (indicative: EN 10084 specifies hardenability, not "
       "strength)"},
      {"E355",
       210000.,
       0.30,
       355.,
       490.,
       7850.,
       11.5e-6,
       steel_cooling,
       350.,
       "the usual limit for heating a steel hub (scaling)",
       MaterialKind::metal,
       MaterialFamily::steel,
       "EN 10297-1 seamless tube steel E355+N, R_eH for T <= 16 mm, R_m "
       "490-630 MPa"},
      {"EN-GJL-250",
       110000.,
       0.26,
       165.,
       250.,
       7200.,
       10.0e-6,
       iron_cooling,
       350.,
       "the usual limit for heating a cast iron hub",
       MaterialKind::brittle,
       MaterialFamily::cast_iron,
       "EN 1561 grey cast iron EN-GJL-250, E 103-118 GPa, R_p0.1 165-228 MPa "
       "(lower bound), R_m 250 MPa (separately cast sample); brittle: "
       "DIN 7190 assesses it by the hoop stress against R_m"},
      {"EN-GJS-400-15",
       169000.,
       0.275,
       250.,
       400.,
       7100.,
       10.0e-6,
       iron_cooling,
       350.,
       "the usual limit for heating a cast iron hub",
       MaterialKind::metal,
       MaterialFamily::cast_iron,
       "EN 1563 spheroidal graphite cast iron EN-GJS-400-15 (ferritic, "
       "ductile: elongation 15 %), R_p0.2 250 MPa, R_m 400 MPa for wall "
       "thicknesses t <= 30 mm, E 169 GPa and nu 0.275 from the standard's "
       "informative annex"},
      {"EN AW-6082 T6",
       70000.,
       0.33,
       250.,
       295.,
       2700.,
       23.4e-6,
       18.0e-6,
       160.,
       "the artificial ageing temperature of T6, 160-180 C: the alloy "
       "over-ages and loses strength",
       MaterialKind::metal,
       MaterialFamily::light_alloy,
       "EN 755-2 aluminium alloy EN AW-6082 T6, R_p0.2 250 MPa and R_m "
       "295 MPa for extruded bars of small section (D <= 20 mm)"},
      {"EN AW-7075 T6",
       72000.,
       0.33,
       480.,
       540.,
       2810.,
       23.4e-6,
       18.0e-6,
       120.,
       "the artificial ageing temperature of T6, about 120 C: the alloy "
       "over-ages and loses strength",
       MaterialKind::metal,
       MaterialFamily::light_alloy,
       "EN 755-2 aluminium alloy EN AW-7075 T6, R_p0.2 480 MPa and R_m "
       "540 MPa for extruded bars D <= 25 mm"},
      {"CuSn8",
       115000.,
       0.34,
       170.,
       390.,
       8800.,
       18.2e-6,
       15.0e-6,
       200.,
       "about where stress relieving of the cold-worked state begins",
       MaterialKind::metal,
       MaterialFamily::copper_alloy,
       "EN 12166 tin bronze CuSn8 (CW453K) R390, R_m 390 MPa, R_p0.2 about "
       "170 MPa (indicative)"}};
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
