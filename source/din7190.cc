#include <coaxfit/din7190.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  double
  Din7190::CheckPoint::equivalent() const
  {
    return std::sqrt(radial * radial + hoop * hoop - radial * hoop);
  }



  Din7190::Din7190(const GeometryParameters &model,
                   const Material           &shaft,
                   const Material           &hub)
    : D_F(2. * model.R1)
    , Q_A(model.R1 / model.R2)
    , Q_I(model.R0 / model.R1)
    , l_F(2. * std::min(model.L1, model.L2))
  {
    const double A2 = Q_A * Q_A, I2 = Q_I * Q_I;
    K = ((1. + A2) / (1. - A2) + hub.nu) / hub.E
        + ((1. + I2) / (1. - I2) - shaft.nu) / shaft.E;
    p = pressure_for(2. * model.d);
  }



  double
  Din7190::pressure_for(const double U_w) const
  {
    return U_w / (D_F * K);
  }



  Din7190::CheckPoint
  Din7190::hub_bore() const
  {
    const double A2 = Q_A * Q_A;
    return {-p, p * (1. + A2) / (1. - A2)};
  }



  Din7190::CheckPoint
  Din7190::hub_outer() const
  {
    const double A2 = Q_A * Q_A;
    return {0., 2. * p * A2 / (1. - A2)};
  }



  Din7190::CheckPoint
  Din7190::shaft_inner() const
  {
    if (Q_I == 0.)
      return {-p, -p};
    return {0., -2. * p / (1. - Q_I * Q_I)};
  }



  Din7190::CheckPoint
  Din7190::shaft_outer() const
  {
    const double I2 = Q_I * Q_I;
    return {-p, -p * (1. + I2) / (1. - I2)};
  }



  double
  Din7190::torque(const double pressure, const double mu) const
  {
    return 1e-3 * pressure * M_PI * D_F * D_F * l_F * mu / 2.;
  }



  double
  Din7190::axial_force(const double pressure, const double mu) const
  {
    return pressure * M_PI * D_F * l_F * mu;
  }
} // namespace coaxfit
