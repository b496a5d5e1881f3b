#include <coaxfit/fe/plastic_material.h>

#include <cmath>

namespace coaxfit
{
  PlasticMaterial::PlasticMaterial(const Material &material)
    : bulk(material.E / (3. * (1. - 2. * material.nu)))
    , mu(material.mu())
    , yield_strength(material.yield_strength)
    , hardening(material.hardening_modulus)
  {}



  PlasticMaterial::Response
  PlasticMaterial::respond_elastic(const Axisymmetric::Vector4 &strain) const
  {
    // No yield surface: the return never starts.
    return respond_to(strain, PlasticState(), false);
  }



  PlasticMaterial::Response
  PlasticMaterial::respond(const Axisymmetric::Vector4 &strain,
                           const PlasticState          &old) const
  {
    return respond_to(strain, old, true);
  }



  PlasticMaterial::Response
  PlasticMaterial::respond_to(const Axisymmetric::Vector4 &strain,
                              const PlasticState          &old,
                              const bool                   may_yield) const
  {
    // Mandel components (rr, zz, tt, sqrt2 rz): tensor products are plain
    // dot products there.
    const double root2      = std::sqrt(2.);
    const double e[4]       = {strain[0] - old.plastic_strain[0],
                               strain[1] - old.plastic_strain[1],
                               strain[2] - old.plastic_strain[2],
                               strain[3] / root2 - root2 * old.plastic_strain[3]};
    const double volumetric = e[0] + e[1] + e[2];
    double       deviator[4];
    for (unsigned int i = 0; i < 3; ++i)
      deviator[i] = 2. * mu * (e[i] - volumetric / 3.);
    deviator[3] = 2. * mu * e[3];
    double norm = 0.;
    for (const double s : deviator)
      norm += s * s;
    norm = std::sqrt(norm);

    const double radius
      = std::sqrt(2. / 3.) * yield_stress(old.equivalent_plastic_strain);
    Response response;
    response.state = old;
    double theta = 1., theta_bar = 0.;
    double n[4] = {0., 0., 0., 0.};
    if (may_yield && norm > radius)
      {
        response.plastic = true;
        const double dl  = (norm - radius) / (2. * mu + 2. * hardening / 3.);
        for (unsigned int i = 0; i < 4; ++i)
          n[i] = deviator[i] / norm;
        theta     = 1. - 2. * mu * dl / norm;
        theta_bar = 1. / (1. + hardening / (3. * mu)) - (1. - theta);
        for (unsigned int i = 0; i < 3; ++i)
          response.state.plastic_strain[i] += dl * n[i];
        response.state.plastic_strain[3] += dl * n[3] / root2;
        response.state.equivalent_plastic_strain += std::sqrt(2. / 3.) * dl;
      }

    // The stress: the volumetric part and the returned deviator.
    double sigma[4];
    for (unsigned int i = 0; i < 3; ++i)
      sigma[i] = bulk * volumetric + theta * deviator[i];
    sigma[3]        = theta * deviator[3];
    response.stress = {{sigma[0], sigma[1], sigma[2], sigma[3] / root2}};

    // The tangent in Mandel components, then to (engineering strain ->
    // stress): the shear row and column each carry a factor 1 / sqrt 2.
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        {
          const double one   = (i < 3 && j < 3) ? 1. : 0.;
          const double delta = (i == j) ? 1. : 0.;
          double       c     = bulk * one + 2. * mu * theta * (delta - one / 3.)
                     - 2. * mu * theta_bar * n[i] * n[j];
          if (i == 3)
            c /= root2;
          if (j == 3)
            c /= root2;
          response.tangent[i][j] = c;
        }
    return response;
  }
} // namespace coaxfit
