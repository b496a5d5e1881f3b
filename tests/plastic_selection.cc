// Design/Mode = select with a hub that may yield (Design/Plastic
// utilisation). The scene is prm/examples/yielding_hub.prm made a thin disc
// (shaft and hub 5 mm long, a twentieth of the hub's diameter), whose
// elastic-plastic state is the plane-stress one (test plastic_long_hub:
// mean pressure and plastic zone within 0.5 %), so that the band the
// selection finds can be checked against the plane-stress radial model
// (RadialPlasticFit, von Mises, 500 elements per body), independent of the
// finite elements:
// - U_max at the allowed utilisation 0.5 (the hub plastic to D_p = 75 mm):
//   the radial model's interference for D_p = 75 mm, within 1 % (the
//   disc's plastic zone is within 0.5 % of the model's, and U grows about
//   with D_p^2);
// - U_min for a torque of 400 N m (mu 0.15: a mean pressure of 135.8 MPa,
//   above the disc's elastic limit of 128.6 MPa, so the hub yields there):
//   the radial model's interference for that pressure, within 1 %; the
//   elastic model would put U_min lower (it overstates the pressure of a
//   yielding hub);
// - the first fit checked on its load paths: the verdict OK, the hub's
//   utilisation at the fit's largest interference not above 0.5;
// - Plastic utilisation = 0 with a plastic hub: the elastic selection,
//   the same band as with Plasticity = none (to 1e-12);
// - check mode beyond the allowed utilisation: the slip safety with K_A
//   and the axial force against the hand formula, the verdict failed;
// - bad input: a utilisation without a plastic hub, a utilisation beyond
//   0.9 (exit 1, one line naming the entry).

#include <coaxfit/design/radial_plastic_fit.h>

#include "run_executable.h"
#include "run_summary.h"
#include "yielding_hub_example.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>

using namespace coaxfit_test;

namespace
{
  /** The disc of the example, selecting for 400 N m. */
  const std::string disc
    = "--set 'Geometry/Hub length=5' --set 'Geometry/Shaft length=5' "
      "--set 'Mesh/Radial cells=20' --set 'Mesh/Grading ratio=1' "
      "--set 'Mesh/Axial cells=4' --set 'Load path/Increments=8' "
      "--set 'Design/Mode=select' --set 'Design/Required torque=400' "
      "--set 'Output/Write vtu=false' ";

  /**
   * The diametral interference (mm) at which @p figure of the radial
   * model's result reaches @p target (it grows with the interference).
   */
  double
  interference_for(
    const std::function<double(const coaxfit::RadialPlasticFit::Result &)>
                &figure,
    const double target)
  {
    double lo = 0.04, hi = 0.1; // radial interference d = U / 2 (mm)
    for (unsigned int i = 0; i < 20; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (figure(radial_model(coaxfit::RadialPlasticFit::State::plane_stress)
                  .solve(mid, 100))
             < target ?
           lo :
           hi)
          = mid;
      }
    return lo + hi;
  }
} // namespace

int
main()
{
  std::cout << std::unitbuf;
  std::cout << "thin disc, Plastic utilisation 0.5, required torque 400 N m:\n";
  run_example("plastic", disc + "--set 'Design/Plastic utilisation=0.5'");
  const nlohmann::json s         = read_summary("plastic");
  const nlohmann::json selection = s["selection"];
  const double         U_max     = selection["U_max"];
  const double         U_min     = selection["U_min"];

  const double U_max_model
    = interference_for([](const auto &r) { return r.plastic_diameter[1]; },
                       75.);
  std::cout << std::fixed << std::setprecision(5) << "  U_max " << U_max
            << " mm ("
            << selection["governing"]["U_max"]["criterion"].get<std::string>()
            << "), radial model (D_p 75 mm) " << U_max_model << ": "
            << agreement(U_max, U_max_model, 0.01) << '\n';
  const double p_needed
    = 400. * 2000. / 50. / (0.15 * M_PI * 50. * 5.); // MPa, mean
  const double U_min_model
    = interference_for([](const auto &r) { return r.pressure; }, p_needed);
  std::cout << "  U_min " << U_min << " mm ("
            << selection["governing"]["U_min"]["criterion"].get<std::string>()
            << "), radial model (p " << std::setprecision(2) << p_needed
            << " MPa) " << std::setprecision(5) << U_min_model << ": "
            << agreement(U_min, U_min_model, 0.01) << '\n';
  for (const auto &c : selection["plastic"]["checks"])
    std::cout << "  " << c["end"].get<std::string>()
              << " on its load path: hub utilisation " << std::setprecision(3)
              << c["hub_utilisation"].get<double>() << ", slip safety "
              << c["safety_slip"].get<double>() << ", completed "
              << std::boolalpha << c["completed"].get<bool>() << '\n';
  const double u_end = selection["plastic"]["checks"][1]["hub_utilisation"];
  const double s_end = selection["plastic"]["checks"][0]["safety_slip"];
  std::cout << "  the utilisation at U_max within 0.5 % below 0.5: "
            << (u_end <= 0.5 && u_end >= 0.4975 ? "yes" : "NO") << '\n'
            << "  the slip safety at U_min within 0.1 % above 1: "
            << (s_end >= 1. && s_end <= 1.001 ? "yes" : "NO") << '\n';
  std::cout << "  DIN 7190 (thick-walled cylinder): U_min "
            << selection["U_min_din"].get<double>() << ", U_max "
            << selection["U_max_din"].get<double>() << " mm\n";
  std::cout << "  first fit " << selection["first_fit"].get<std::string>()
            << ", verdict ok " << s["verdict"]["ok"].get<bool>() << '\n';
  const nlohmann::json max_case = read_summary("plastic/max");
  const double         used
    = max_case["plasticity"]["bodies"][1]["plastic_zone"]["utilisation"];
  std::cout << "  its case max: hub utilisation " << std::setprecision(3)
            << used << " (not above 0.5: " << (used <= 0.5 ? "yes" : "NO")
            << ")\n";

  std::cout << "Plastic utilisation 0 with the plastic hub, against "
               "Plasticity = none:\n";
  run_example("elastic_selection",
              disc + "--set 'Design/Plastic utilisation=0'");
  run_example("no_plasticity",
              disc
                + "--set 'Design/Plastic utilisation=0' "
                  "--set 'Material/Hub/Plasticity=none'");
  const nlohmann::json a = read_summary("elastic_selection")["selection"];
  const nlohmann::json b = read_summary("no_plasticity")["selection"];
  std::cout
    << std::setprecision(5) << "  U_min " << a["U_min"].get<double>()
    << ", U_max " << a["U_max"].get<double>() << " mm ("
    << a["governing"]["U_max"]["criterion"].get<std::string>()
    << "); the same: "
    << (std::abs(a["U_min"].get<double>() - b["U_min"].get<double>()) <= 1e-12
            && std::abs(a["U_max"].get<double>() - b["U_max"].get<double>())
                 <= 1e-12 ?
          "yes" :
          "NO")
    << '\n';

  std::cout << "check mode, U 0.2 mm, 400 N m and 20000 N times K_A 1.25:\n";
  run_example("check",
              disc
                + "--set 'Design/Mode=check' "
                  "--set 'Fit/Diametral interference=0.2' "
                  "--set 'Design/Required axial force=20000' "
                  "--set 'Design/Application factor=1.25'");
  {
    // The slip safety by hand from the mean pressure: mu p pi D_F l_F over
    // K_A times the resultant of the required loads.
    const nlohmann::json c       = read_summary("check");
    const double         mean    = c["pressure"]["mean"];
    const double         by_hand = 0.15 * mean * M_PI * 50. * 5.
                           / (1.25 * std::hypot(400. * 2000. / 50., 20000.));
    std::cout << "  slip safety " << std::setprecision(4)
              << c["design"]["safety_slip"].get<double>() << ", by hand "
              << by_hand << ": "
              << agreement(c["design"]["safety_slip"], by_hand, 1e-9) << '\n'
              << "  hub utilisation "
              << c["design"]["plastic_utilisation"]["hub"].get<double>()
              << ", verdict ok " << c["verdict"]["ok"].get<bool>() << ": ";
    for (const auto &f : c["verdict"]["failed"])
      std::cout << f.get<std::string>() << "; ";
    std::cout << '\n';
  }

  std::cout << "bad input:\n";
  run_example("bad",
              disc
                + "--set 'Design/Plastic utilisation=0.5' "
                  "--set 'Material/Hub/Plasticity=none'");
  run_example("bad", disc + "--set 'Design/Plastic utilisation=0.95'");
  std::cout << "  nothing written: " << std::boolalpha
            << !std::filesystem::exists("bad") << '\n';
  return 0;
}
