// Neumann mode with the axis boundary: a solid cylinder (radius 100 mm, free
// ends, graded mesh) under external pressure 100 MPa. Lame's solution is
// u_r = -(1 - nu) p r / E, u_z = 2 nu p z / E, sigma_rr = sigma_tt = -p:
// linear, so every FE space here contains it and the error must be at
// round-off on every mesh (a patch test of the hoop term u_r/r, the axis
// condition u_r = 0 and the consistent surface load), for several
// materials including a nearly incompressible one.

#include <coaxfit/fe/lame.h>

#include "test_bodies.h"

int
main()
{
  using namespace coaxfit_test;
  const double b = 100., p = 100.;
  for (const double nu : {0., 0.33, 0.49})
    for (const unsigned int degree : {1u, 2u, 3u})
      {
        Material material;
        material.nu = nu;
        const LameCylinder exact(0., b, material, 0., p);
        double             worst_u = 0., worst_s = 0.;
        for (unsigned int ref = 0; ref < 3; ++ref)
          {
            Body body("shaft", solid_cylinder(b, ref), material, degree);
            body.setup_system();
            body.assemble_system();
            std::vector<double> u_r;
            body.solve_neumann(uniform_pressure_forces(body, p), u_r);
            const LameErrors e = body.errors(exact);
            worst_u            = std::max(worst_u, e.displacement_L2);
            worst_s = std::max({worst_s, e.hoop_stress_L2, e.radial_stress_L2});
          }
        std::cout << "nu = " << nu << ", FE_Q(" << degree
                  << "), refinements 0-2: displacement error below 1e-10: "
                  << (worst_u < 1e-10 ? "yes" : "NO")
                  << ", stress error below 1e-10: "
                  << (worst_s < 1e-10 ? "yes" : "NO") << std::endl;
      }
}
