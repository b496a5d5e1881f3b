// Variant 5 (solid shaft, L1 = 2 L2): the contact pressure peaks at the hub
// end and is 2 % below the Lame value 187.5 MPa at the mid-plane (the
// long shaft behaves as an infinite one). Compared with the independent
// CalculiX solution (shared/reference: p(0) = 183.82 MPa, mean over
// 0 <= z <= 100 mm 191.55 MPa, p(99 mm) = 322.3 MPa) within 1 %.

#include <coaxfit/app/coaxial_fit.h>

#include <iomanip>
#include <iostream>

int
main()
{
  coaxfit::Parameters p; // variant 5
  p.mesh.global_refinements = 1;
  coaxfit::CoaxialFit fit(p);
  fit.setup_system();
  fit.solve(nullptr);
  const coaxfit::PressureSummary s = fit.pressure_summary();
  const std::vector<double>     &z = fit.get_interface().z();

  // Pressure at z by linear interpolation between interface points.
  const auto at = [&](const double zz) {
    unsigned int i = 0;
    while (i + 2 < z.size() && z[i + 1] < zz)
      ++i;
    const double t = (zz - z[i]) / (z[i + 1] - z[i]);
    return (1. - t) * s.pressure[i] + t * s.pressure[i + 1];
  };

  std::cout << std::fixed << std::setprecision(2);
  std::cout << "z (mm)   pressure (MPa)" << std::endl;
  for (const double zz : {0., 25., 50., 75., 90., 95., 99.})
    std::cout << std::setw(6) << zz << "   " << std::setw(8) << at(zz)
              << std::endl;

  const auto compare = [](const std::string &what, double ours, double ccx) {
    std::cout << what << ": " << ours << " MPa, CalculiX " << ccx
              << " MPa, relative difference " << std::scientific
              << std::setprecision(1) << std::abs(ours / ccx - 1.) << std::fixed
              << std::setprecision(2) << ", within 1 %: "
              << (std::abs(ours / ccx - 1.) < 0.01 ? "yes" : "NO") << std::endl;
  };
  compare("pressure at z = 0", s.at_mid_plane, 183.82);
  compare("mean pressure", s.mean, 191.55);
  compare("pressure at z = 99 mm", at(99.), 322.3);
  std::cout << "maximum at the hub end z = L2: "
            << (s.z_of_max == 100. ? "yes" : "NO")
            << "; minimum between mid-plane and hub end at z = " << s.z_of_min
            << " mm; p(0) / Lame pressure " << s.lame
            << " MPa = " << std::setprecision(4) << s.at_mid_plane / s.lame
            << std::endl;
}
