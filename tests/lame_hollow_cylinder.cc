// Neumann mode of one body against Lame's exact solution: a thick hollow
// cylinder (a = 100 mm, b = 200 mm, free ends) under internal pressure
// 100 MPa applied as consistent nodal forces on S. The exact field has
// u_r = c1 r + c2 / r, so the FE error is pure discretization error: in the
// r-weighted L2 norm it must fall as h^(p+1) for the displacement and h^p
// for the hoop stress.

#include <coaxfit/fe/lame.h>

#include "test_bodies.h"

int
main()
{
  using namespace coaxfit_test;
  const double       a = 100., b = 200., p = 100.;
  const Material     steel;
  const LameCylinder exact(a, b, steel, p, 0.);

  for (const unsigned int degree : {1u, 2u})
    {
      std::cout << "FE_Q(" << degree << "): refinement, DoFs, "
                << "|u - u_h|/|u|, order, |s_tt - s_tt,h|/|s_tt|, order, "
                << "max rel. error of u_r on S" << std::endl;
      double last_u = 0, last_s = 0;
      for (unsigned int ref = 0; ref < 5; ++ref)
        {
          Body body("cylinder", hollow_cylinder(a, b, ref), steel, degree);
          body.setup_system();
          body.assemble_system();
          std::vector<double> u_r;
          body.solve_neumann(uniform_pressure_forces(body, p), u_r);
          const LameErrors e           = body.errors(exact);
          double           max_surface = 0.;
          for (const double u : u_r)
            max_surface
              = std::max(max_surface, std::abs(u / exact.u_r(a) - 1.));

          std::cout << std::setw(3) << ref << std::setw(8) << body.n_dofs()
                    << std::scientific << std::setprecision(3) << "  "
                    << e.displacement_L2 << "  " << std::fixed
                    << std::setprecision(2)
                    << (ref ? order(last_u, e.displacement_L2) : 0.) << "  "
                    << std::scientific << std::setprecision(3)
                    << e.hoop_stress_L2 << "  " << std::fixed
                    << std::setprecision(2)
                    << (ref ? order(last_s, e.hoop_stress_L2) : 0.) << "  "
                    << std::scientific << std::setprecision(3) << max_surface
                    << std::endl;
          last_u = e.displacement_L2;
          last_s = e.hoop_stress_L2;
        }
    }
}
