// The monolithic reference (both bodies in one system, contact points tied,
// primal-dual active set) and the staggered process must give the same
// answer: the contact pressure at every interface point to 1e-8 relative
// to its maximum, and the same separated points, for a full-contact case
// (variant 5) and a separating thin tube (variant 17), paper's coarse mesh.

#include <coaxfit/app/coaxial_fit.h>

#include "coupled_cases.h"

#include <iomanip>
#include <iostream>

namespace
{
  void
  compare(const std::string &label, coaxfit::Parameters p)
  {
    p.coupling.tolerance = 1e-9;
    std::vector<dealii::Vector<double>> pressure;
    std::vector<std::vector<bool>>      contact;
    for (const std::string method : {"staggered", "monolithic"})
      {
        p.set("Solver/Method", method);
        coaxfit::CoaxialFit fit(p);
        fit.setup_system();
        const bool converged = fit.solve(nullptr);
        std::cout << label << ", " << method << ": converged "
                  << (converged ? "yes" : "NO") << " in "
                  << fit.get_coupling().n_steps() << " steps, "
                  << fit.get_coupling().get_active_set().n_separated()
                  << " separated points" << std::endl;
        pressure.push_back(fit.pressure_summary().pressure);
        contact.push_back(fit.get_coupling().get_active_set().in_contact());
      }
    std::cout << "  same pressure to 1e-8 relative: "
              << (coaxfit_test::relative_difference(pressure[0], pressure[1])
                      < 1e-8 ?
                    "yes" :
                    "NO")
              << ", same separated points: "
              << (contact[0] == contact[1] ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main()
{
  compare("variant 5", coaxfit::Parameters());

  compare("variant 17", coaxfit_test::variant_17());
}
