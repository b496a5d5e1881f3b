#ifndef coaxfit_radial_plastic_fit_h
#define coaxfit_radial_plastic_fit_h

#include <coaxfit/parameters/parameters.h>

#include <array>
#include <vector>

namespace coaxfit
{
  /**
   * The press fit of two long (or two thin) coaxial cylinders that may yield,
   * as a radial one-dimensional problem: the reference the finite element
   * answer of an elastic-plastic fit is checked against, and the estimate
   * that the summary reports beside it.
   *
   * Each body is a ring a <= r <= b (a = 0: solid) in one of two states,
   * the same at every section: generalized plane strain (a uniform axial
   * strain of each body with zero axial force: the middle of long bodies
   * with free ends) or plane stress (sigma_zz = 0: thin discs). Linear
   * finite elements in r (u_r at the nodes, the hoop strain u_r / r, the
   * axial strain an extra unknown of each body or, in plane stress, found at
   * each Gauss point from sigma_zz = 0); von Mises plasticity with linear
   * isotropic hardening, radial return with its consistent tangent in the
   * principal axes (r, t, z) - written here on their own, apart from the
   * axisymmetric PlasticMaterial of the finite element bodies.
   *
   * The radial interference is applied in equal increments; in each, the
   * hub's bore displacement U is found (bracketed secant on the balance of
   * the two bodies' contact pressures, each body solved by Newton's method
   * with its interface displacement prescribed), so that a hub beyond its
   * limit pressure is still well posed.
   */
  class RadialPlasticFit
  {
  public:
    /** The state through the bodies' length. */
    enum class State
    {
      generalized_plane_strain,
      plane_stress
    };

    /** One body: radii (mm) and material (Plasticity decides yielding). */
    struct Ring
    {
      double   r_inner;
      double   r_outer;
      Material material;
    };

    /**
     * The shaft @p shaft inside the hub @p hub (shaft.r_outer =
     * hub.r_inner = the joint radius), @p elements linear elements per body.
     */
    RadialPlasticFit(const Ring  &shaft,
                     const Ring  &hub,
                     State        state,
                     unsigned int elements = 1000);

    /** The result at the full interference. */
    struct Result
    {
      double pressure = 0.; ///< contact pressure (MPa)
      double shaft_u  = 0.; ///< u_r of the shaft's surface (mm)
      double hub_u    = 0.; ///< u_r of the hub's bore (mm)
      /**
       * Per body (shaft, hub): the diameter (mm) of the plastic zone's
       * outer border (hub) or inner border (shaft), the joint diameter
       * when nothing yields; and whether the whole wall yields.
       */
      std::array<double, 2> plastic_diameter = {{0., 0.}};
      std::array<bool, 2>   fully_plastic    = {{false, false}};
      unsigned int          increments       = 0;
    };

    /**
     * Apply the radial interference @p d (mm, U / 2) in @p increments
     * equal increments from the unloaded state.
     */
    Result
    solve(double d, unsigned int increments = 200);

  private:
    /** One body's discretization and committed state. */
    struct Body
    {
      Ring                               ring;
      std::vector<double>                nodes;
      std::vector<std::array<double, 4>> plastic;   ///< e_p (r, t, z), a
      std::vector<std::array<double, 4>> trial;     ///< of the last solve
      std::vector<double>                u;         ///< nodal u_r
      double                             e_z = 0.;  ///< axial strain (GPS)
      std::vector<double>                point_e_z; ///< plane stress
    };

    /**
     * Solve @p body with u_r = @p u_joint at the joint (from the committed
     * state); returns the contact pressure (compressive positive).
     */
    double
    pressure_for(Body &body, bool joint_at_outer, double u_joint) const;

    const State state;
    Body        bodies[2];
  };

  /**
   * The classical estimate of an elastic-plastic hub (a thick-walled
   * cylinder, von Mises in the plane-strain form 2 R_e / sqrt 3, as DIN
   * 7190-1 builds on it): the joint pressure of a hub of outer diameter
   * @p outer_diameter on the joint diameter @p joint_diameter that is
   * plastic out to the diameter @p plastic_diameter,
   * p = (2 R_e / sqrt 3) (ln(D_p / D_F) + (1 - (D_p / D_aA)^2) / 2).
   * D_p = D_F gives the elastic limit (R_e / sqrt 3)(1 - (D_F/D_aA)^2),
   * D_p = D_aA the fully plastic (2 R_e / sqrt 3) ln(D_aA / D_F).
   */
  double
  elastic_plastic_hub_pressure(double yield_strength,
                               double joint_diameter,
                               double outer_diameter,
                               double plastic_diameter);
} // namespace coaxfit

#endif
