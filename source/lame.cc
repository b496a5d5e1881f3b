#include <coaxfit/lame.h>

namespace coaxfit
{
  LameCylinder::LameCylinder(const double    a,
                             const double    b,
                             const Material &material,
                             const double    p_in,
                             const double    p_out)
    : A((p_in * a * a - p_out * b * b) / (b * b - a * a))
    , B((p_in - p_out) * a * a * b * b / (b * b - a * a))
    , material(material)
  {}



  double
  LameCylinder::u_r(const double r) const
  {
    const double nu = material.nu;
    return ((1. - nu) * A * r + (r > 0. ? (1. + nu) * B / r : 0.)) /
           material.E;
  }



  double
  LameCylinder::u_z(const double z) const
  {
    return -2. * material.nu * A * z / material.E;
  }



  double
  LameCylinder::sigma_rr(const double r) const
  {
    return A - (r > 0. ? B / (r * r) : 0.);
  }



  double
  LameCylinder::sigma_tt(const double r) const
  {
    return A + (r > 0. ? B / (r * r) : 0.);
  }



  double
  lame_pressure(const double    R0,
                const double    R1,
                const double    R2,
                const double    d,
                const Material &shaft,
                const Material &hub)
  {
    const double hub_compliance =
      ((R2 * R2 + R1 * R1) / (R2 * R2 - R1 * R1) + hub.nu) / hub.E;
    const double shaft_compliance =
      ((R1 * R1 + R0 * R0) / (R1 * R1 - R0 * R0) - shaft.nu) / shaft.E;
    return d / (R1 * (hub_compliance + shaft_compliance));
  }
} // namespace coaxfit
