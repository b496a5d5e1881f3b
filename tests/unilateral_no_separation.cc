// A case without separation (variant 5, solid shaft) must be unchanged by
// the unilateral pass: the same pressures as the bilateral solution, no
// separated point, no active set change, no extra factorization.

#include <coaxfit/app/coaxial_fit.h>

#include <iostream>

int
main()
{
  std::vector<dealii::Vector<double>> pressures;
  for (const bool unilateral : {false, true})
    {
      coaxfit::Parameters p; // variant 5
      p.contact.unilateral = unilateral;
      coaxfit::CoaxialFit fit(p);
      fit.setup_system();
      const bool  converged = fit.solve(nullptr);
      const auto &set       = fit.get_coupling().get_active_set();
      std::cout << (unilateral ? "unilateral" : "bilateral") << ": converged "
                << (converged ? "yes" : "NO") << " in "
                << fit.get_coupling().n_steps() << " steps, separated points "
                << set.n_separated() << ", active set changes "
                << set.n_changes() << std::endl;
      pressures.push_back(fit.pressure_summary().pressure);
    }
  double difference = 0.;
  for (unsigned int i = 0; i < pressures[0].size(); ++i)
    difference
      = std::max(difference, std::abs(pressures[0][i] - pressures[1][i]));
  std::cout << "pressures identical to 1e-12 MPa: "
            << (difference < 1e-12 ? "yes" : "NO") << std::endl;
}
