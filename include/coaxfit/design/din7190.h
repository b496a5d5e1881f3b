#ifndef coaxfit_din7190_h
#define coaxfit_din7190_h

#include <coaxfit/parameters/parameters.h>

namespace coaxfit
{
  /** Loads of operation for Din7190, all zero at assembly. */
  struct Din7190Loads
  {
    double shaft_thermal_strain = 0.; ///< alpha_I (T_I - T_assembly)
    double hub_thermal_strain   = 0.; ///< alpha_A (T_A - T_assembly)
    double omega_squared        = 0.; ///< (rad/s)^2
    double shaft_bore_pressure  = 0.; ///< MPa
    double hub_outer_pressure   = 0.; ///< MPa
  };

  /**
   * The elastic design of a cylindrical press fit by DIN 7190-1: the joint
   * pressure of Lame's thick-walled cylinders of equal length (plane
   * stress), the stresses at the standard's check points, the transmissible
   * torque and axial force, the press-in force. Inputs in mm and MPa,
   * forces in N, torques in N m.
   *
   * With Q_A = D_F/D_aA and Q_I = D_iI/D_F:
   *   p = U_w / (D_F [ (1/E_A)((1 + Q_A^2)/(1 - Q_A^2) + nu_A)
   *                  + (1/E_I)((1 + Q_I^2)/(1 - Q_I^2) - nu_I) ]),
   *   M = p pi D_F^2 l_F mu / 2,  F_ax = p pi D_F l_F mu.
   *
   * In operation each part is a plane-stress ring a <= r <= b under the
   * joint pressure, its own pressures, rotation and a uniform temperature:
   *   sigma_r = A - B/r^2 - (3 + nu)/8 rho omega^2 r^2,
   *   sigma_t = A + B/r^2 - (1 + 3 nu)/8 rho omega^2 r^2,
   *   u = r (sigma_t - nu sigma_r)/E + alpha dT r
   * (B = 0 for a solid shaft); the joint pressure closes the radial
   * interference d = U_w/2 between the two rings' u at D_F/2 and is 0 where
   * that gives tension (the joint has opened). Without loads these are the
   * formulas above.
   */
  class Din7190
  {
  public:
    /** Loads of operation, all zero at assembly. */
    using Loads = Din7190Loads;
    /** Radial and hoop stress of a check point and its equivalent stress. */
    struct CheckPoint
    {
      double radial, hoop;

      /**
       * Von Mises of the plane stress state (sigma_z = 0): at the hub bore
       * sqrt(s_t^2 + s_r^2 - s_t s_r), at a free surface |s_t|, in a solid
       * shaft p, at a hollow shaft's bore 2p/(1 - Q_I^2).
       */
      double
      equivalent() const;
    };

    /**
     * For the joint of @p model (radii, half lengths, d = U_w/2) and the
     * materials @p shaft and @p hub.
     */
    Din7190(const GeometryParameters &model,
            const Material           &shaft,
            const Material           &hub,
            const Loads              &loads = Loads());

    /** The joint pressure p (MPa) for the effective interference U_w. */
    double
    pressure() const
    {
      return p;
    }

    /**
     * The pressure for another effective interference @p U_w (mm), the
     * same loads; 0 if the joint opens.
     */
    double
    pressure_for(double U_w) const;

    /**
     * The speed (rad/s) at which the joint pressure of the loads without
     * rotation falls to zero (plane stress: the whole joint at once); 0 if
     * it has no pressure at rest, infinite if rotation does not reduce it.
     */
    double
    loosening_omega() const;

    /** Hub at its bore r = D_F/2: sigma_r = -p, sigma_t = p (1+Q^2)/(1-Q^2). */
    CheckPoint
    hub_bore() const;

    /** Hub at its outer surface: sigma_r = 0, sigma_t = 2 p Q^2/(1-Q^2). */
    CheckPoint
    hub_outer() const;

    /**
     * Shaft at its bore (sigma_r = 0, sigma_t = -2p/(1-Q_I^2)) or, solid,
     * at its axis (sigma_r = sigma_t = -p).
     */
    CheckPoint
    shaft_inner() const;

    /** Shaft at its surface: sigma_r = -p, sigma_t = -p (1+Q^2)/(1-Q^2). */
    CheckPoint
    shaft_outer() const;

    /** Torque (N m) that a pressure @p pressure transmits with @p mu. */
    double
    torque(double pressure, double mu) const;

    /** Axial force (N) that a pressure @p pressure transmits with @p mu. */
    double
    axial_force(double pressure, double mu) const;

    /** Joint length l_F (mm): the hub's or the shaft's, the shorter. */
    double
    joint_length() const
    {
      return l_F;
    }

  private:
    /**
     * How far the rings' surfaces at D_F/2 move apart, u_hub - u_shaft
     * (mm), under the joint pressure @p pressure, rotation
     * @p omega_squared and, if @p static_loads, the temperatures and
     * pressures of operation; linear in each.
     */
    double
    opening(double pressure, double omega_squared, bool static_loads) const;

    /** Radial and hoop stress of the shaft (or hub) ring at @p r. */
    CheckPoint
    ring_stress(bool shaft, double r) const;

    GeometryParameters model;
    Material           shaft, hub;
    Loads              loads;
    double             D_F, Q_A, Q_I, l_F, K;
    double             p;
  };

  /** The loads of operation of @p parameters for Din7190. */
  Din7190::Loads
  operating_loads(const Parameters &parameters);

  /**
   * DIN 7190's joining temperature (degrees C): heat the hub
   * (@p heat_hub) by (U + clearance)/(alpha D_F) above @p temperature, or
   * cool the shaft by as much below it, with the thermal expansion
   * @p alpha of the part that changes temperature; U the largest
   * interference and the clearance diametral (mm).
   */
  double
  joining_temperature(bool   heat_hub,
                      double U,
                      double clearance,
                      double D_F,
                      double alpha,
                      double temperature);
} // namespace coaxfit

#endif
