// The Lame case of the staggered coupling: shaft and hub of equal length
// (L1 = L2) with free ends have the uniform contact pressure of Lame's
// formula; the converged staggered answer must reproduce it at every
// interface point (relative error far below 1e-3 on the default mesh), for
// the paper's material and for two different materials.

#include <coaxfit/app/coaxial_fit.h>

#include <iomanip>
#include <iostream>

namespace
{
  void
  check(const std::string &label, coaxfit::Parameters p)
  {
    p.geometry.L1 = p.geometry.L2 = 100.;
    coaxfit::CoaxialFit fit(p);
    fit.setup_system();
    const bool                     converged = fit.solve(nullptr);
    const coaxfit::PressureSummary s         = fit.pressure_summary();
    double                         max_error = 0.;
    for (const double x : s.pressure)
      max_error = std::max(max_error, std::abs(x / s.lame - 1.));
    std::cout << label << ": Lame pressure " << std::fixed
              << std::setprecision(3) << s.lame << " MPa, converged "
              << (converged ? "yes" : "NO") << " in "
              << fit.get_coupling().n_steps() << " steps" << std::endl
              << "  max relative error over S " << std::scientific
              << std::setprecision(2) << max_error
              << ", mean pressure relative error "
              << std::abs(s.mean / s.lame - 1.) << std::endl
              << "  max relative error below 1e-3: "
              << (max_error < 1e-3 ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main()
{
  coaxfit::Parameters paper; // R0 = 0, R1 = 100, R2 = 200, d = 0.25, steel
  check("solid steel shaft, steel hub (paper)", paper);

  coaxfit::Parameters two = paper;
  two.shaft.E             = 2.1e5; // steel shaft
  two.shaft.nu            = 0.30;
  two.hub.E               = 7.0e4; // aluminium hub
  two.hub.nu              = 0.33;
  two.coupling.alpha      = 0.85;
  check("solid steel shaft (E 2.1e5, nu 0.30), aluminium hub (7e4, 0.33)", two);

  coaxfit::Parameters tube = two;
  tube.geometry.R0         = 60.; // hollow shaft: the R0 terms of the formula
  tube.coupling.alpha      = 0.6;
  check("steel tube R0 = 60 mm, aluminium hub", tube);
}
