// The material point of the elastic-plastic bodies (PlasticMaterial): below
// the yield surface Hooke's law (Axisymmetric::stress) to round-off; beyond
// it the returned stress on the yield surface of the hardened state, the
// plastic strain deviatoric (no volume change) and normal to the surface,
// the equivalent plastic strain grown by sqrt(2/3) |de_p|; the consistent
// tangent against central finite differences of the return (1e-6), for
// perfect plasticity and linear hardening, with shear.

#include <coaxfit/fe/plastic_material.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace coaxfit;

namespace
{
  /** The largest difference between the tangent and finite differences. */
  double
  tangent_error(const PlasticMaterial       &m,
                const Axisymmetric::Vector4 &e,
                const PlasticState          &old)
  {
    const PlasticMaterial::Response r     = m.respond(e, old);
    double                          error = 0., scale = 0.;
    const double                    h = 1e-8;
    for (unsigned int j = 0; j < 4; ++j)
      {
        Axisymmetric::Vector4 plus = e, minus = e;
        plus[j] += h;
        minus[j] -= h;
        const auto sp = m.respond(plus, old).stress;
        const auto sm = m.respond(minus, old).stress;
        for (unsigned int i = 0; i < 4; ++i)
          {
            error = std::max(error,
                             std::abs((sp[i] - sm[i]) / (2. * h)
                                      - r.tangent[i][j]));
            scale = std::max(scale, std::abs(r.tangent[i][j]));
          }
      }
    return error / scale;
  }
} // namespace

int
main()
{
  for (const double H : {0., 10000.})
    {
      Material steel;
      steel.E                 = 210000.;
      steel.nu                = 0.3;
      steel.yield_strength    = 300.;
      steel.plastic           = true;
      steel.hardening_modulus = H;
      const PlasticMaterial m(steel);
      std::cout << "hardening modulus " << H << " MPa:\n";

      // Elastic: Hooke's law.
      const Axisymmetric::Vector4 small = {{2e-4, -1e-4, 3e-4, 1e-4}};
      const auto                  r0    = m.respond(small, PlasticState());
      const auto                  hooke = Axisymmetric::stress(steel, small);
      double                      d     = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        d = std::max(d, std::abs(r0.stress[i] - hooke[i]));
      std::cout << "  below yield: plastic " << std::boolalpha << r0.plastic
                << ", Hooke " << (d < 1e-10 ? "to round-off" : "DIFFERS")
                << ", tangent error "
                << (tangent_error(m, small, PlasticState()) < 1e-6 ? "< 1e-6" :
                                                                     "LARGE")
                << '\n';

      // Beyond yield, from a state that yielded before.
      PlasticState old;
      old.plastic_strain              = {{1e-3, -4e-4, -6e-4, 2e-4}};
      old.equivalent_plastic_strain   = 1.5e-3;
      const Axisymmetric::Vector4 big = {{4e-3, -1e-3, 1e-3, 3e-3}};
      const auto                  r   = m.respond(big, old);
      const double                vm  = Axisymmetric::von_mises(r.stress);
      const double sy = m.yield_stress(r.state.equivalent_plastic_strain);
      double       dp[4], norm = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        dp[i] = r.state.plastic_strain[i] - old.plastic_strain[i];
      norm = std::sqrt(dp[0] * dp[0] + dp[1] * dp[1] + dp[2] * dp[2]
                       + 2. * dp[3] * dp[3]);
      const double grown
        = r.state.equivalent_plastic_strain - old.equivalent_plastic_strain;
      // Normality: de_p parallel to the stress deviator.
      const double p = (r.stress[0] + r.stress[1] + r.stress[2]) / 3.;
      const double s[4]
        = {r.stress[0] - p, r.stress[1] - p, r.stress[2] - p, r.stress[3]};
      double s_norm
        = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2. * s[3] * s[3]);
      double normal = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        normal = std::max(normal, std::abs(dp[i] / norm - s[i] / s_norm));
      std::cout
        << "  beyond yield: plastic " << r.plastic << ", on the yield surface "
        << (std::abs(vm / sy - 1.) < 1e-12 ? "to 1e-12" : "NO")
        << ", plastic volume change "
        << (std::abs(dp[0] + dp[1] + dp[2]) < 1e-15 ? "none" : "SOME")
        << ", normal to the surface " << (normal < 1e-10 ? "yes" : "NO")
        << ", equivalent plastic strain grown by sqrt(2/3)|de_p| "
        << (std::abs(grown - std::sqrt(2. / 3.) * norm) < 1e-15 ? "yes" : "NO")
        << ", tangent error "
        << (tangent_error(m, big, old) < 1e-6 ? "< 1e-6" : "LARGE") << '\n';
    }
  return 0;
}
