// Unilateral contact of a thin tube (variant 17: beta1 = 0.988, beta2 = 2,
// l1 = 3, l2 = 2, delta = 0.005) on the paper's coarse mesh. The bilateral
// solution has tensile contact pressure near the hub end; with the
// unilateral pass the converged state must satisfy the complementarity
// conditions (1.2)-(1.3) to the tolerance: no tension, no penetration, no
// pressure on an open gap. The separated zone must not depend on the
// controller or the first alpha.

#include <coaxfit/app/coaxial_fit.h>

#include "coupled_cases.h"

#include <iomanip>
#include <iostream>

using coaxfit_test::variant_17;

int
main()
{
  {
    coaxfit::Parameters p = variant_17();
    p.contact.unilateral  = false;
    coaxfit::CoaxialFit fit(p);
    fit.setup_system();
    fit.solve(nullptr);
    const coaxfit::PressureSummary s = fit.pressure_summary();
    std::cout << "bilateral: min pressure " << std::fixed
              << std::setprecision(2) << s.min << " MPa at z = " << s.z_of_min
              << " mm (tensile: " << (s.min < 0. ? "yes" : "no") << ")"
              << std::endl;
  }

  std::vector<std::vector<std::pair<double, double>>> all_zones;
  for (const auto &[controller, alpha] :
       std::vector<std::pair<std::string, double>>{{"iqn-ils", 0.017},
                                                   {"iqn-ils", 0.3},
                                                   {"aitken", 0.017}})
    {
      coaxfit::Parameters p = variant_17();
      p.set("Coupling/Alpha controller", controller);
      p.coupling.alpha = alpha;
      coaxfit::CoaxialFit fit(p);
      fit.setup_system();
      const bool                      converged = fit.solve(nullptr);
      const coaxfit::InterfaceSolver &c         = fit.get_coupling();
      const coaxfit::Complementarity  comp(fit.get_interface(), c);
      const auto                      zones
        = c.get_active_set().separated_zones(fit.get_interface().z(),
                                             p.geometry.contact_length());
      all_zones.push_back(zones);

      std::cout << std::defaultfloat << std::setprecision(4) << controller
                << ", alpha0 = " << alpha << ": converged "
                << (converged ? "yes" : "NO") << " in " << c.n_steps()
                << " steps, " << c.get_active_set().n_changes()
                << " active set changes" << std::endl
                << "  separated zones (mm):" << std::fixed
                << std::setprecision(3);
      for (const auto &zone : zones)
        std::cout << " [" << zone.first << ", " << zone.second << "]";
      std::cout << std::endl
                << "  no tension: "
                << (comp.max_tension_relative == 0. ? "yes" : "NO")
                << ", penetration below 1e-8 d: "
                << (comp.max_penetration_relative < 1e-8 ? "yes" : "NO")
                << ", |p gap| below 1e-8 max(p) d: "
                << (comp.max_pressure_gap_relative < 1e-8 ? "yes" : "NO")
                << std::endl;
    }
  std::cout << "same separated zones for every run: "
            << (all_zones[0] == all_zones[1] && all_zones[0] == all_zones[2] ?
                  "yes" :
                  "NO")
            << std::endl;
}
