#ifndef coaxfit_din7190_h
#define coaxfit_din7190_h

#include <coaxfit/parameters.h>

namespace coaxfit
{
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
   */
  class Din7190
  {
  public:
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
            const Material           &hub);

    /** The joint pressure p (MPa) for the effective interference U_w. */
    double
    pressure() const
    {
      return p;
    }

    /** The pressure for another effective interference @p U_w (mm). */
    double
    pressure_for(double U_w) const;

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
    double D_F, Q_A, Q_I, l_F, K;
    double p;
  };
} // namespace coaxfit

#endif
