// The interface compliance of the condensed operator comes from the trailing
// block of the Cholesky factor (interface points eliminated last: the Schur
// complement onto S, inverted densely). It must equal, to round-off, the
// compliance built column by column from Neumann solves with unit nodal
// forces, be symmetric, and its diagonal must have the physical sign: a
// compressive force moves its point away from the partner, inwards on the
// shaft (u_r < 0), outwards on the hub (u_r > 0). Hollow cylinder loaded inside
// and graded solid cylinder loaded outside, FE_Q(1) and FE_Q(2).

#include <deal.II/lac/full_matrix.h>

#include "test_bodies.h"

namespace
{
  void
  check(const std::string &label, coaxfit_test::Body &body)
  {
    body.setup_system();
    body.assemble_system();
    const unsigned int n = body.n_interface_points();

    dealii::FullMatrix<double> schur;
    body.interface_compliance(schur);

    double              difference = 0., magnitude = 0., asymmetry = 0.;
    bool                positive = true;
    std::vector<double> unit(n), u;
    for (unsigned int j = 0; j < n; ++j)
      {
        unit.assign(n, 0.);
        unit[j] = 1.;
        body.solve_neumann(unit, u);
        for (unsigned int i = 0; i < n; ++i)
          {
            difference = std::max(difference, std::abs(schur(i, j) - u[i]));
            magnitude  = std::max(magnitude, std::abs(u[i]));
            asymmetry
              = std::max(asymmetry, std::abs(schur(i, j) - schur(j, i)));
          }
        positive
          = positive
            && -body.discretization.interface_normals()[j][0] * schur(j, j)
                 > 0.;
      }
    std::cout << label << ": " << n << " interface points, "
              << body.n_factorizations() << " factorization" << std::endl
              << "  Schur compliance = solved compliance to 1e-10 relative: "
              << (difference < 1e-10 * magnitude ? "yes" : "NO")
              << ", symmetric to 1e-12: "
              << (asymmetry < 1e-12 * magnitude ? "yes" : "NO")
              << ", diagonal of the physical sign: "
              << (positive ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main()
{
  using namespace coaxfit_test;
  const Material steel;
  for (const unsigned int degree : {1u, 2u})
    {
      Body hub("hub", hollow_cylinder(100., 200., 2), steel, degree);
      check("hollow cylinder, FE_Q(" + std::to_string(degree) + ")", hub);
      Body shaft("shaft", solid_cylinder(100., 2), steel, degree);
      check("solid cylinder, FE_Q(" + std::to_string(degree) + ")", shaft);
    }
}
