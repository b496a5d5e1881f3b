#include <coaxfit/design/din7190.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace coaxfit
{
  double
  Din7190::CheckPoint::equivalent() const
  {
    return std::sqrt(radial * radial + hoop * hoop - radial * hoop);
  }



  namespace
  {
    /**
     * A plane-stress ring a <= r <= b (a = 0: a solid disc) under the
     * pressures @p p_a at r = a and @p p_b at r = b (compression positive),
     * rotation and a thermal strain: sigma_r = A - B/r^2 - k_r r^2,
     * sigma_t = A + B/r^2 - k_t r^2.
     */
    struct Ring
    {
      Ring(const double    a,
           const double    b,
           const Material &m,
           const double    p_a,
           const double    p_b,
           const double    omega_squared,
           const double    thermal_strain)
        : m(m)
        , thermal_strain(thermal_strain)
      {
        // rho omega^2 in N/mm^4 (density in kg/m^3).
        const double c = 1e-12 * m.density * omega_squared;
        k_r            = (3. + m.nu) / 8. * c;
        k_t            = (1. + 3. * m.nu) / 8. * c;
        if (a == 0.)
          {
            B = 0.;
            A = -p_b + k_r * b * b;
          }
        else
          {
            B = a * a * b * b * ((p_b - p_a) / (a * a - b * b) + k_r);
            A = -p_b + k_r * b * b + B / (b * b);
          }
      }

      double
      sigma_r(const double r) const
      {
        return r == 0. ? A : A - B / (r * r) - k_r * r * r;
      }

      double
      sigma_t(const double r) const
      {
        return r == 0. ? A : A + B / (r * r) - k_t * r * r;
      }

      double
      u(const double r) const
      {
        return r * (sigma_t(r) - m.nu * sigma_r(r)) / m.E + thermal_strain * r;
      }

      Material m;
      double   thermal_strain, k_r, k_t, A, B;
    };
  } // namespace



  Din7190::Din7190(const GeometryParameters &model,
                   const Material           &shaft,
                   const Material           &hub,
                   const Loads              &loads)
    : model(model)
    , shaft(shaft)
    , hub(hub)
    , loads(loads)
    , D_F(2. * model.R1)
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
  Din7190::opening(const double pressure,
                   const double omega_squared,
                   const bool   static_loads) const
  {
    const double s = static_loads ? 1. : 0.;
    const Ring   hub_ring(model.R1,
                        model.R2,
                        hub,
                        pressure,
                        s * loads.hub_outer_pressure,
                        omega_squared,
                        s * loads.hub_thermal_strain);
    const Ring   shaft_ring(model.R0,
                          model.R1,
                          shaft,
                          s * loads.shaft_bore_pressure,
                          pressure,
                          omega_squared,
                          s * loads.shaft_thermal_strain);
    return hub_ring.u(model.R1) - shaft_ring.u(model.R1);
  }



  double
  Din7190::pressure_for(const double U_w) const
  {
    // Linear in the pressure with the slope -R1 K (the compliance of the
    // pair): closing(p) = closing(0) - R1 K p.
    const double left = 0.5 * U_w - opening(0., loads.omega_squared, true);
    return std::max(0., left / (model.R1 * K));
  }



  double
  Din7190::loosening_omega() const
  {
    // The interference left at rest, and what each (rad/s)^2 takes away
    // (rotation alone: no cancellation against the interference).
    const double at_rest           = model.d - opening(0., 0., true);
    const double per_omega_squared = -opening(0., 1., false);
    if (at_rest <= 0.)
      return 0.;
    if (per_omega_squared >= 0.)
      return std::numeric_limits<double>::infinity();
    return std::sqrt(-at_rest / per_omega_squared);
  }



  Din7190::CheckPoint
  Din7190::ring_stress(const bool on_shaft, const double r) const
  {
    const Ring ring = on_shaft ? Ring(model.R0,
                                      model.R1,
                                      shaft,
                                      loads.shaft_bore_pressure,
                                      p,
                                      loads.omega_squared,
                                      loads.shaft_thermal_strain) :
                                 Ring(model.R1,
                                      model.R2,
                                      hub,
                                      p,
                                      loads.hub_outer_pressure,
                                      loads.omega_squared,
                                      loads.hub_thermal_strain);
    return {ring.sigma_r(r), ring.sigma_t(r)};
  }



  Din7190::CheckPoint
  Din7190::hub_bore() const
  {
    return ring_stress(false, model.R1);
  }



  Din7190::CheckPoint
  Din7190::hub_outer() const
  {
    return ring_stress(false, model.R2);
  }



  Din7190::CheckPoint
  Din7190::shaft_inner() const
  {
    return ring_stress(true, model.R0);
  }



  Din7190::CheckPoint
  Din7190::shaft_outer() const
  {
    return ring_stress(true, model.R1);
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



  Din7190::Loads
  operating_loads(const Parameters &parameters)
  {
    const OperationParameters &o = parameters.operation;
    Din7190::Loads             loads;
    loads.shaft_thermal_strain
      = parameters.shaft.thermal_expansion
        * (o.shaft_temperature() - o.assembly_temperature);
    loads.hub_thermal_strain = parameters.hub.thermal_expansion
                               * (o.hub_temperature() - o.assembly_temperature);
    loads.omega_squared       = o.omega() * o.omega();
    loads.shaft_bore_pressure = o.shaft_bore_pressure;
    loads.hub_outer_pressure  = o.hub_outer_pressure;
    return loads;
  }



  double
  joining_temperature(const bool   heat_hub,
                      const double U,
                      const double clearance,
                      const double D_F,
                      const double alpha,
                      const double temperature)
  {
    const double change = (U + clearance) / (alpha * D_F);
    return heat_hub ? temperature + change : temperature - change;
  }
} // namespace coaxfit
