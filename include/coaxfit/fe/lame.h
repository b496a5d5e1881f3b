#ifndef coaxfit_lame_h
#define coaxfit_lame_h

#include <deal.II/lac/vector.h>

#include <coaxfit/parameters/parameters.h>

namespace coaxfit
{
  class BodyDiscretization;
}

namespace coaxfit
{
  /**
   * Lame's exact solution for a thick-walled cylinder a <= r <= b (a = 0:
   * solid) with free (open) ends: sigma_zz = sigma_rz = 0, internal
   * pressure p_in at r = a, external pressure p_out at r = b (compression
   * positive). With u_z = 0 on z = 0 it is the exact solution of the
   * finite cylinder modelled by coaxfit:
   * sigma_rr = A - B/r^2, sigma_tt = A + B/r^2,
   * u_r = ((1 - nu) A r + (1 + nu) B / r) / E, u_z = -2 nu A z / E.
   */
  class LameCylinder
  {
  public:
    LameCylinder(double          a,
                 double          b,
                 const Material &material,
                 double          p_in,
                 double          p_out);

    double
    u_r(double r) const;
    double
    u_z(double z) const;
    double
    sigma_rr(double r) const;
    double
    sigma_tt(double r) const;

  private:
    double   A, B;
    Material material;
  };

  /** Relative errors of a body's solution against a Lame solution. */
  struct LameErrors
  {
    double displacement_L2;  ///< ||u - u_h|| / ||u||, r-weighted L2 norm
    double hoop_stress_L2;   ///< ||sigma_tt - sigma_tt,h|| / ||sigma_tt||
    double radial_stress_L2; ///< ||sigma_rr - sigma_rr,h|| / ||sigma_rr||
  };

  /**
   * Errors of @p solution of @p body against @p exact, integrated
   * with the axisymmetric weight r by a Gauss rule of degree + 3 points.
   */
  LameErrors
  lame_errors(const BodyDiscretization &body,
              const Vector<double>     &solution,
              const LameCylinder       &exact);
} // namespace coaxfit

#endif
