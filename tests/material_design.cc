// Materials in the design figures (issue 31), each against a hand
// calculation, through the executable as a user runs it:
//
// 1. A grey cast iron hub (EN-GJL-250: E 110000 MPa, nu 0.26, R_m 250 MPa,
//    brittle) on a solid 42CrMo4 shaft (E 210000, nu 0.30; DIN 7190's
//    undercooling coefficient 8.5e-6 1/K), D_F = 40 mm, D_aA = 80 mm, hub
//    and shaft 40 mm long (Lame's case), U = 0.04 mm, no roughness.
//    By hand, with Q_A = 0.5:
//      K = ((1 + 0.25)/(1 - 0.25) + 0.26)/110000 + (1 - 0.30)/210000
//        = 1.926667/110000 + 0.7/210000 = 2.084848e-5 1/MPa,
//      p = U/(D_F K) = 0.04/(40 * 2.084848e-5) = 47.9651 MPa,
//      sigma_t at the bore = p (1 + Q^2)/(1 - Q^2) = 5/3 p = 79.9419 MPa,
//      safety against fracture = R_m/sigma_t = 250/79.9419 = 3.12727.
//    The FE hoop stress (largest at the mid-plane check points and along
//    the bore away from the ends) must be within 3 % of Lame's; the hub's
//    yield safety is not given (brittle: not assessed by yield).
//    Joining (DIN 7190), clearance 0.001 D_F = 0.04 mm:
//      cool the shaft by (U + clearance)/(alpha_K D_F)
//        = 0.08/(8.5e-6 * 40) = 235.294 K, to 20 - 235.294 = -215.294 C:
//      below liquid nitrogen (-196 C), not reachable (with the heating
//      coefficient 11.5e-6 it would have been -153.913 C, "reachable");
//      heat the hub by 0.08/(10e-6 * 40) = 200 K to 220 C, below the
//      limit of 350 C: no caution.
// 2. E typed in GPa: both bodies custom with E = 210: one warning line
//    naming both; none when both are declared Kind = polymer.
// 3. A named metal given another E: 42CrMo4 with E = 70000 (a factor 3
//    from 210000): a warning; with E = 150000 (factor 1.4): none.
// 4. A hub of EN AW-7075 T6 (alpha 23.4e-6, limit 120 C, the ageing
//    temperature) with U = 0.08 mm: heated by 0.12/(23.4e-6 * 40) =
//    128.205 K to 148.205 C > 120 C: a caution, which also says that
//    cooling the 42CrMo4 shaft instead, to 20 - 0.12/(8.5e-6 * 40) =
//    -332.941 C, is not reachable, and that both at once suffice: the hub
//    at 120 C and the shaft at -196 C open 40 (23.4e-6 * 100 + 8.5e-6 *
//    216) = 0.16704 mm of the 0.12 mm needed.

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace
{
  const std::string common = "subsection Geometry\n"
                             "  set Joint diameter      = 40\n"
                             "  set Shaft bore diameter = 0\n"
                             "  set Hub outer diameter  = 80\n"
                             "  set Hub length          = 40\n"
                             "  set Shaft length        = 40\n"
                             "end\n"
                             "subsection Mesh\n"
                             "  set Axial cells  = 8\n"
                             "  set Radial cells = 6\n"
                             "end\n"
                             "subsection Output\n"
                             "  set Print timing = false\n"
                             "  set Write vtu    = false\n"
                             "  set Write plots  = false\n"
                             "  set Write report = false\n"
                             "end\n";

  /** Write @p name.prm with the common part and @p scene. */
  std::string
  prm_file(const std::string &name, const std::string &scene)
  {
    std::ofstream(name + ".prm") << common << scene;
    return name + ".prm";
  }

  struct Run
  {
    int                    exit_code;
    std::string            console;
    nlohmann::ordered_json summary;
  };

  /** Run coaxfit on @p file with @p options into the directory @p name. */
  Run
  run(const std::string &name,
      const std::string &file,
      const std::string &options = "")
  {
    std::filesystem::remove_all(name);
    const auto r = coaxfit_test::run_command(
      "timeout 120 " + std::string(coaxfit_test::coaxfit_executable)
      + " --set Output/Directory=" + name + " " + options + " " + file
      + " 2>&1");
    Run           result{r.exit_code, r.message, nullptr};
    std::ifstream in(name + "/summary.json");
    if (in)
      result.summary = nlohmann::ordered_json::parse(in);
    return result;
  }

  /** The warnings of summary.json that contain @p part. */
  unsigned int
  warnings_with(const Run &r, const std::string &part)
  {
    unsigned int n = 0;
    for (const auto &w : r.summary["warnings"])
      n += w.get<std::string>().find(part) != std::string::npos;
    return n;
  }

  void
  compare(const std::string &what,
          const double       program,
          const double       hand,
          const double       tolerance)
  {
    std::cout << "  " << std::left << std::setw(44) << what << std::right
              << std::setprecision(6) << std::setw(12) << program << "  hand "
              << std::setw(12) << hand << "  "
              << (std::abs(program - hand) <= tolerance * std::abs(hand) ?
                    "within " :
                    "DIFFERS beyond ")
              << std::setprecision(1) << tolerance << '\n';
  }

  std::string
  yes(const bool b)
  {
    return b ? "yes" : "NO";
  }
} // namespace



int
main()
{
  const std::string materials_gjl = "subsection Fit\n"
                                    "  set Diametral interference = 0.04\n"
                                    "end\n"
                                    "subsection Material\n"
                                    "  subsection Shaft\n"
                                    "    set Name = 42CrMo4\n"
                                    "  end\n"
                                    "  subsection Hub\n"
                                    "    set Name = EN-GJL-250\n"
                                    "  end\n"
                                    "end\n";

  std::cout << "1. brittle hub EN-GJL-250 on 42CrMo4, U = 0.04 mm\n";
  {
    const Run r = run("gjl", prm_file("gjl", materials_gjl));
    std::cout << "  exit code " << r.exit_code << '\n';
    const auto  &design  = r.summary["design"];
    const auto  &joining = r.summary["operation"]["joining"];
    const double p_hand
      = 0.04 / (40. * (1.926666666666667 / 110000. + 0.7 / 210000.));
    const double hoop_hand = 5. / 3. * p_hand;
    compare("DIN 7190 pressure (MPa)",
            design["pressure_din"].get<double>(),
            p_hand,
            1e-12);
    compare("DIN 7190 hoop stress at the bore (MPa)",
            design["hoop_stress_max_hub_din"].get<double>(),
            hoop_hand,
            1e-12);
    compare("DIN 7190 safety against fracture",
            design["safety_fracture_hub_din"].get<double>(),
            250. / hoop_hand,
            1e-12);
    compare("FE largest hoop stress at the bore (MPa)",
            design["hoop_stress_max_hub"].get<double>(),
            hoop_hand,
            3e-2);
    compare("FE safety against fracture",
            design["safety_fracture_hub"].get<double>(),
            250. / hoop_hand,
            3e-2);
    std::cout << "  hub yield safety not given (null): "
              << yes(design["safety_yield_hub"].is_null()
                     && design["safety_yield_hub_din"].is_null())
              << "\n  console labels 'safety against fracture (brittle, "
                 "sigma_t vs R_m)': "
              << yes(r.console.find(
                       "safety against fracture (brittle, sigma_t vs R_m)")
                     != std::string::npos)
              << "\n  hub kind in summary.json: "
              << r.summary["material"]["hub"]["kind"].get<std::string>()
              << ", R_m " << r.summary["material"]["hub"]["tensile_strength"]
              << " MPa\n";
    compare("shaft cooled to (C), alpha_K 8.5e-6",
            joining["shaft_temperature"].get<double>(),
            20. - 0.08 / (8.5e-6 * 40.),
            1e-12);
    compare("hub heated to (C), alpha 10e-6",
            joining["hub_temperature"].get<double>(),
            20. + 0.08 / (10e-6 * 40.),
            1e-12);
    std::cout << "  cooling coefficient used " << std::setprecision(3)
              << joining["shaft_cooling_expansion"].get<double>()
              << " 1/K, reachable: "
              << (joining["shaft_cooling_reachable"].get<bool>() ? "yes" : "no")
              << ", console says 'not reachable': "
              << yes(r.console.find("not reachable: below liquid nitrogen")
                     != std::string::npos)
              << "\n  hub above its limit: "
              << (joining["hub_above_temperature_limit"].get<bool>() ? "yes" :
                                                                       "no")
              << ", warnings: " << r.summary["warnings"].size() << '\n';
  }

  std::cout << "2. E typed in GPa (E = 210 for both bodies)\n";
  {
    const std::string custom = "subsection Fit\n"
                               "  set Diametral interference = 0.04\n"
                               "end\n"
                               "subsection Material\n"
                               "  subsection Shaft\n"
                               "    set E  = 210\n"
                               "    set nu = 0.3\n"
                               "  end\n"
                               "  subsection Hub\n"
                               "    set E  = 210\n"
                               "    set nu = 0.3\n"
                               "  end\n"
                               "end\n";
    const std::string file   = prm_file("gpa", custom);
    const Run         r      = run("gpa", file);
    std::cout << "  exit code " << r.exit_code << ", warning lines "
              << warnings_with(r, "below 1000 MPa") << ", naming both bodies: "
              << yes(warnings_with(r,
                                   "Material/Shaft/E = 210, "
                                   "Material/Hub/E = 210 MPa")
                     == 1)
              << ", on the console: "
              << yes(r.console.find("warning: Material/Shaft/E = 210")
                     != std::string::npos)
              << '\n';
    const Run p = run("polymer",
                      file,
                      "--set Material/Shaft/Kind=polymer --set "
                      "Material/Hub/Kind=polymer");
    std::cout << "  declared polymer: exit code " << p.exit_code
              << ", warning lines " << warnings_with(p, "below 1000 MPa")
              << '\n';
  }

  std::cout << "3. 42CrMo4 given another E\n";
  {
    const std::string file = prm_file("named_E", materials_gjl);
    for (const std::string E : {"70000", "150000"})
      {
        const Run r = run("named_E_" + E, file, "--set Material/Shaft/E=" + E);
        std::cout << "  E = " << E << ": exit code " << r.exit_code
                  << ", warning lines "
                  << warnings_with(r, "more than a factor 2 from the library")
                  << '\n';
      }
  }

  std::cout << "4. hub EN AW-7075 T6 heated above its ageing temperature\n";
  {
    const Run   r       = run("aw7075",
                      prm_file("aw7075", materials_gjl),
                      "--set Material/Hub/Name='EN AW-7075 T6' --set "
                              "'Fit/Diametral interference=0.08'");
    const auto &joining = r.summary["operation"]["joining"];
    std::cout << "  exit code " << r.exit_code << '\n';
    compare("hub heated to (C), alpha 23.4e-6",
            joining["hub_temperature"].get<double>(),
            20. + 0.12 / (23.4e-6 * 40.),
            1e-12);
    compare("shaft cooled to (C), alpha_K 8.5e-6",
            joining["shaft_temperature"].get<double>(),
            20. - 0.12 / (8.5e-6 * 40.),
            1e-12);
    std::cout << "  limit " << joining["hub_temperature_limit"]
              << " C, above: " << joining["hub_above_temperature_limit"]
              << ", caution lines "
              << warnings_with(r, "exceeds its temperature limit 120.0 C")
              << ", naming cooling as not reachable: "
              << yes(warnings_with(r,
                                   "cooling the shaft instead is not "
                                   "reachable (-332.9 C")
                     == 1)
              << '\n';
    for (const auto &w : r.summary["warnings"])
      std::cout << "  warning: " << w.get<std::string>() << '\n';
  }
}
