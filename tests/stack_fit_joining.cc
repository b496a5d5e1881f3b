// The fit selection of a stack joins by temperature as the run does, also
// where a joint of the heated part opens as it is heated. Four rings of
// equal length (plane-stress Lame states, frictionless: the compound
// cylinders are exact): a steel shaft D 40, a steel bush D 40-60 (alpha
// 12e-6), a bronze sleeve D 60-90 (18e-6), an aluminium hub D 90-150
// (23e-6), made outside in (the sleeve into the hub, the bush into both,
// the shaft into the three), every body limited to 200 C. The shaft's
// joint is made by heating the bush, sleeve and hub together: the bush
// expands least, so the bush-sleeve joint loosens and opens as they are
// heated and the bush's bore then grows at the bush's own rate.
//
// 1. The selection at two presets of Fit/ISO fit (none, H7/s6): the same
//    fits (the reach is taken at each combination's own interferences,
//    not at the preset's), and each joint of the chosen run joinable by
//    its own figures.
// 2. The shaft's joining temperature of the chosen fits and of H5/s5 +
//    P5/h5 + H7/s6 (which an earlier version chose, promising 200 C)
//    against the closed form: the bush's bore grown by alpha_bush dT r
//    plus the change of the three rings' compound solution as the joints'
//    interferences change by 2 R (alpha_inner - alpha_outer) dT
//    (unilateral: a joint in tension opens), bisected for the temperature
//    at which it opens by the largest interference, what the parts joined
//    before close the bore by, and the joining clearance 0.001 D.
// 3. Three rings made outside in with a sleeve that expands less than its
//    hub: a combination that joins is found, and joins by the run's own
//    figures.

#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/parameters/iso286.h>

#include "run_executable.h"
#include "run_summary.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace coaxfit_test;

namespace
{
  using Ring = coaxfit::CompoundCylinders::Ring;
  /** The bush, sleeve and hub: the part heated to make the shaft's joint. */
  const std::vector<Ring> part     = {{40., 60., 210000., 0.3},
                                      {60., 90., 110000., 0.34},
                                      {90., 150., 70000., 0.33}};
  const double            alpha[3] = {12e-6, 18e-6, 23e-6};

  /** The four rings, selecting; @p extra appended. */
  std::string
  four_rings(const std::string &extra = "")
  {
    std::ostringstream s;
    s << "subsection Assembly\n  set Bodies = Shaft, Bush, Sleeve, Hub\n"
         "  set Order = outside in\nend\nsubsection Geometry\n"
         "  subsection Shaft\n    set Inner diameter = 0\n"
         "    set Outer diameter = 40\n    set Length = 50\n  end\n";
    const char *names[3] = {"Bush", "Sleeve", "Hub"};
    for (unsigned int b = 0; b < 3; ++b)
      s << "  subsection " << names[b]
        << "\n    set Inner diameter = " << part[b].inner_diameter
        << "\n    set Outer diameter = " << part[b].outer_diameter
        << "\n    set Length = 50\n  end\n";
    s << "end\nsubsection Material\n  subsection Shaft\n    set E = 210000\n"
         "    set nu = 0.3\n    set Yield strength = 650\n  end\n";
    const double yield[3] = {500., 300., 250.};
    for (unsigned int b = 0; b < 3; ++b)
      s << "  subsection " << names[b] << "\n    set E = " << part[b].E
        << "\n    set nu = " << part[b].nu
        << "\n    set Yield strength = " << yield[b]
        << "\n    set Thermal expansion = " << alpha[b]
        << "\n    set Temperature limit = 200\n  end\n";
    s << "end\nsubsection Fit\n  set Friction coefficient = 0.12\nend\n"
         "subsection Design\n  set Mode = select\n"
         "  set Required torque = 800\n  set Slip safety = 1.5\n"
         "  set Yield safety = 1.25\nend\n"
         "subsection Mesh\n  set Axial cells = 8\n  set Radial cells = 4\n"
         "  set Global refinements = 0\nend\n"
      << extra;
    return s.str();
  }

  /**
   * The closed form's temperature (C) to which the bush, sleeve and hub,
   * with the bush-sleeve and sleeve-hub joints at @p U (mm, diametral),
   * are heated from 20 C to open the shaft's joint by @p U_shaft plus
   * what the part's joints close the bush's bore by, plus 0.04 mm.
   */
  double
  shaft_joining_temperature(const double U_shaft, const std::vector<double> &U)
  {
    const auto bore = [&](const double dT) {
      // Heated by dT: each joint's interference changes by the bodies'
      // different growth, 2 R (alpha_inner - alpha_outer) dT.
      const std::vector<double> heated
        = {U[0] + 60. * (alpha[0] - alpha[1]) * dT,
           U[1] + 90. * (alpha[1] - alpha[2]) * dT};
      const coaxfit::CompoundCylinders cc(part, heated, 0., 0., true);
      return alpha[0] * dT * 20. + cc.radial_displacement(0, 20.);
    };
    const double closed = -2. * bore(0.); // the bore closed by the part
    const double need   = U_shaft + closed + 0.04;
    double       lo = 0., hi = 2000.;
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double mid                               = 0.5 * (lo + hi);
        (2. * (bore(mid) - bore(0.)) < need ? lo : hi) = mid;
      }
    return 20. + 0.5 * (lo + hi);
  }

  /** Each joint's joining as the run gives it, and whether it joins. */
  void
  print_joining(const nlohmann::json &j)
  {
    for (const auto &joint : j["joints"])
      {
        const auto &f  = joint["joining"];
        const bool  ok = !f["heat_above_limit"].get<bool>()
                        || (f["cool_reachable"].is_boolean()
                            && f["cool_reachable"].get<bool>())
                        || (f["both_cool_inner_to"].is_number()
                            && f["both_cool_inner_to"].get<double>() >= -196.);
        std::cout << "  " << joint["name"].get<std::string>() << ": heat to "
                  << std::setprecision(5) << f["heat_outer_to"].get<double>()
                  << " C, joins: " << (ok ? "yes" : "NO") << '\n';
      }
  }
} // namespace


int
main()
{
  std::cout << std::setprecision(6);
  std::cout << "1. The choice and its joining\n";
  std::ofstream("four.prm") << four_rings();
  std::filesystem::remove_all("plain");
  std::filesystem::remove_all("preset");
  RunResult            r = run_coaxfit("plain", quiet + "four.prm");
  const nlohmann::json a = read_summary("plain");
  std::cout << "no preset: exit " << r.exit_code << ", " << fits_of(a)
            << ", notes " << a["selection"]["notes"].size() << '\n';
  print_joining(a);
  r = run_coaxfit("preset", quiet + "--set 'Fit/ISO fit=H7/s6' four.prm");
  const nlohmann::json b = read_summary("preset");
  std::cout << "Fit/ISO fit = H7/s6: exit " << r.exit_code << ", " << fits_of(b)
            << (fits_of(b) == fits_of(a) ? " (the same)" : " (DIFFERS)")
            << '\n';

  std::cout << "\n2. The shaft's joining temperature against the closed "
               "form\n";
  const auto check = [&](const std::string &label, const nlohmann::json &j) {
    std::vector<double> U_max;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const std::string fit = j["joints"][k]["fit"].get<std::string>();
        // "[Fit/<joint>/]ISO fit H7/s6, ..." as the run names it.
        const std::size_t at   = fit.find("ISO fit ") + 8;
        const std::string name = fit.substr(at, fit.find(',', at) - at);
        U_max.push_back(
          1e-3
          * coaxfit::iso_fit(name, j["joints"][k]["diameter"].get<double>())
              .max_interference());
      }
    const double exact
      = shaft_joining_temperature(U_max[0], {U_max[1], U_max[2]});
    const double run = j["joints"][0]["joining"]["heat_outer_to"].get<double>();
    std::cout << label << ": the run " << std::setprecision(6) << run
              << " C, the closed form " << exact
              << " C: " << agreement(run, exact, 1e-4) << '\n';
  };
  check(fits_of(a), a);
  std::filesystem::remove_all("earlier");
  r                      = run_coaxfit("earlier",
                  quiet
                    + "--set Design/Mode=check --set 'Fit/Shaft-Bush/ISO "
                                           "fit=H5/s5' --set 'Fit/Bush-Sleeve/ISO fit=P5/h5' "
                                           "--set 'Fit/Sleeve-Hub/ISO fit=H7/s6' --set "
                                           "Fit/Case=max four.prm");
  const nlohmann::json c = read_summary("earlier");
  check("H5/s5 + P5/h5 + H7/s6 (exit " + std::to_string(r.exit_code) + ")", c);
  std::cout << "  above the limit: "
            << c["joints"][0]["joining"]["heat_above_limit"] << '\n';

  // 3. The three rings of select_three_ring_fits.prm made outside in, the
  // sleeve expanding less (11.5e-6) than the hub it is heated with: the
  // shaft's joint is reached at each combination's own interferences (at
  // one interference for all, an earlier version found none to join and
  // chose one needing 211 C); the chosen fits join by the run's figures.
  std::cout << "\n3. Three rings made outside in, the hub limited to 200 "
               "C\n";
  std::filesystem::remove_all("three");
  r                      = run_coaxfit("three",
                  quiet
                    + "--set 'Assembly/Order=outside in' --set "
                                           "'Material/Sleeve/Thermal expansion=11.5e-6' --set "
                                           "'Material/Hub/Temperature limit=200' "
                    + std::string(COAXFIT_SOURCE_DIR)
                    + "/prm/examples/select_three_ring_fits.prm");
  const nlohmann::json t = read_summary("three");
  std::cout << "exit " << r.exit_code << ", " << fits_of(t) << ", notes "
            << t["selection"]["notes"].size() << '\n';
  print_joining(t);
  return 0;
}
