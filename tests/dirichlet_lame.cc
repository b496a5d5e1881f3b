// Dirichlet mode: a uniform radial displacement u0 prescribed on S (shear
// free) must return, through the consistent nodal reactions (rows of
// K u - f), Lame's pressure
//   hollow cylinder, u0 on r = a:  p = E u0 / (a ((a^2 + b^2)/(b^2 - a^2) +
//   nu)) solid cylinder,  u0 on r = b:  p = -E u0 / (b (1 - nu))
// The pressure at each point is the nodal reaction over its lumped weight.
// Hollow: converges with the mesh; solid: exact (linear field).

#include <coaxfit/fe/lame.h>

#include "test_bodies.h"

namespace
{
  using namespace coaxfit_test;

  void
  check(const std::string  &label,
        const BodyGeometry &geometry,
        const double        u0,
        const double        p_exact,
        const unsigned int  refinements)
  {
    const Material steel;
    std::cout << label << ": exact pressure " << std::fixed
              << std::setprecision(4) << p_exact << " MPa" << std::endl;
    for (unsigned int ref = 0; ref <= refinements; ++ref)
      {
        BodyGeometry g       = geometry;
        g.global_refinements = ref;
        Body body("body", g, steel, 2);
        body.setup_system();
        body.assemble_system();
        std::vector<double> force;
        body.solve_dirichlet(std::vector<double>(body.n_interface_points(), u0),
                             force);
        const std::vector<double> w         = interface_weights(body);
        double                    max_error = 0., total = 0., area = 0.;
        for (unsigned int i = 0; i < force.size(); ++i)
          {
            max_error
              = std::max(max_error, std::abs(force[i] / w[i] / p_exact - 1.));
            total += force[i];
            area += w[i];
          }
        std::cout << "  refinement " << ref << ": max relative error "
                  << std::scientific << std::setprecision(2) << max_error
                  << ", mean pressure relative error "
                  << std::abs(total / area / p_exact - 1.) << std::endl;
      }
  }
} // namespace

int
main()
{
  const double   a = 100., b = 200., u0 = 0.1;
  const Material steel;
  check("hollow cylinder, u0 = 0.1 mm on r = a",
        hollow_cylinder(a, b, 0),
        u0,
        steel.E * u0 / (a * ((a * a + b * b) / (b * b - a * a) + steel.nu)),
        3);

  // Solid: relative errors at round-off are printed as a pass/fail line.
  const double u_solid = -u0;
  const double p_solid = -steel.E * u_solid / (a * (1. - steel.nu));
  for (unsigned int ref = 0; ref < 3; ++ref)
    {
      Body body("shaft", solid_cylinder(a, ref), steel, 2);
      body.setup_system();
      body.assemble_system();
      std::vector<double> force;
      body.solve_dirichlet(std::vector<double>(body.n_interface_points(),
                                               u_solid),
                           force);
      const std::vector<double> w         = interface_weights(body);
      double                    max_error = 0.;
      for (unsigned int i = 0; i < force.size(); ++i)
        max_error
          = std::max(max_error, std::abs(force[i] / w[i] / p_solid - 1.));
      std::cout << "solid cylinder, u0 = -0.1 mm on r = b, refinement " << ref
                << ": pressure " << std::fixed << std::setprecision(4)
                << p_solid << " MPa reproduced to 1e-10: "
                << (max_error < 1e-10 ? "yes" : "NO") << std::endl;
    }
}
