// An elastic-plastic fit against the radial one-dimensional solution
// (RadialPlasticFit: von Mises, linear elements in r, 500 per body, 100
// increments): a long fit (shaft and hub 800 mm, eight outer diameters) at
// its mid-length against generalized plane strain with zero axial force
// (joint pressure and plastic zone diameter within 0.5 %), the same fit
// driven far beyond full plasticity (pressure within 1 % of the 1D limit,
// "fully_plastic" true), and a thin disc (5 mm, a twentieth of the
// diameter) against plane stress: its mean pressure (plane stress is the
// state averaged over the thickness; where the hub yields the 3D state is
// not plane stress exactly, as the plastic axial strain varies with r, and
// the pressure at the mid-plane lies 1.3 % above the mean) and plastic zone
// within 0.5 %. The scene is prm/examples/yielding_hub.prm:
// a solid elastic steel shaft D 50 mm in a hub D 50-100 mm yielding at
// 300 MPa, perfectly plastic.

#include <coaxfit/design/radial_plastic_fit.h>

#include "run_executable.h"
#include "run_summary.h"
#include "yielding_hub_example.h"

#include <filesystem>
#include <iomanip>
#include <iostream>

using namespace coaxfit_test;

namespace
{
  /** Run the example with @p arguments in @p dir; its summary. */
  nlohmann::json
  run_into(const std::string &dir, const std::string &arguments)
  {
    run_example(dir, arguments);
    return read_summary(dir);
  }

  /**
   * Compare a run with the radial model's result: the pressure @p key,
   * with @p zone the plastic zone's diameter at the mid-plane.
   */
  void
  compare(const nlohmann::json                    &s,
          const coaxfit::RadialPlasticFit::Result &exact,
          const double                             tolerance,
          const bool                               zone,
          const std::string                       &key = "at_mid_plane")
  {
    const double p   = s["pressure"][key];
    const auto  &hub = s["plasticity"]["bodies"][1];
    std::cout << std::fixed << std::setprecision(1) << "  pressure (" << key
              << ") " << p << " MPa, radial model " << exact.pressure << ": "
              << agreement(p, exact.pressure, tolerance) << '\n';
    if (zone)
      {
        const double D = hub["plastic_zone"]["diameter_at_mid_plane"];
        std::cout << "  plastic zone diameter " << std::setprecision(2) << D
                  << " mm, radial model " << exact.plastic_diameter[1] << ": "
                  << agreement(D, exact.plastic_diameter[1], tolerance) << '\n';
      }
    std::cout << "  fully plastic: " << std::boolalpha
              << hub["fully_plastic"].get<bool>() << ", radial model "
              << exact.fully_plastic[1] << '\n'
              << std::defaultfloat;
  }
} // namespace

int
main()
{
  const std::string mesh
    = "--set 'Mesh/Radial cells=20' --set 'Mesh/Grading ratio=1' "
      "--set 'Mesh/Axial cells=8' --set 'Load path/Increments=8' ";
  const std::string long_fit
    = mesh
      + "--set 'Geometry/Hub length=800' --set 'Geometry/Shaft length=800' ";

  std::cout << "long fit, U 0.16 mm (the hub plastic to about D 72 mm):\n";
  compare(run_into("long", long_fit),
          radial_model(
            coaxfit::RadialPlasticFit::State::generalized_plane_strain)
            .solve(0.08, 100),
          0.005,
          true);

  std::cout << "long fit, U 0.6 mm (far beyond full plasticity):\n";
  compare(
    run_into("limit", long_fit + "--set 'Fit/Diametral interference=0.6'"),
    radial_model(coaxfit::RadialPlasticFit::State::generalized_plane_strain)
      .solve(0.3, 100),
    0.01,
    false);

  std::cout << "thin disc (5 mm), U 0.16 mm:\n";
  compare(run_into("disc",
                   mesh
                     + "--set 'Geometry/Hub length=5' "
                       "--set 'Geometry/Shaft length=5'"),
          radial_model(coaxfit::RadialPlasticFit::State::plane_stress)
            .solve(0.08, 100),
          0.005,
          true,
          "mean");
  return 0;
}
