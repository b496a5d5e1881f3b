#ifndef coaxfit_axisymmetric_h
#define coaxfit_axisymmetric_h

#include <deal.II/base/tensor.h>

#include <coaxfit/parameters/parameters.h>

#include <array>
#include <cmath>

namespace coaxfit
{
  /**
   * Kinematics and Hooke's law of axisymmetric linear elasticity in the
   * (r, z) half plane (x = r, y = z), written out once for assembly and
   * post-processing alike.
   *
   * Strains are ordered (e_rr, e_zz, e_tt, g_rz) with e_tt = u_r / r the hoop
   * strain and g_rz = du_r/dz + du_z/dr the engineering shear strain. Stresses
   * are ordered (sigma_rr, sigma_zz, sigma_tt, sigma_rz).
   */
  namespace Axisymmetric
  {
    using Vector4 = std::array<double, 4>;

    /**
     * Strain of a displacement with radial value @p u_r and gradients of
     * both components at radius @p r. On the axis (r = 0) the hoop strain is
     * its limit du_r/dr.
     */
    inline Vector4
    strain(const double        u_r,
           const Tensor<1, 2> &grad_u_r,
           const Tensor<1, 2> &grad_u_z,
           const double        r)
    {
      const double e_tt = (r > 0.) ? u_r / r : grad_u_r[0];
      return {{grad_u_r[0], grad_u_z[1], e_tt, grad_u_r[1] + grad_u_z[0]}};
    }

    /**
     * The mechanical part of the strain @p e: without the thermal
     * eigenstrain @p thermal_strain on its normal components.
     */
    inline Vector4
    mechanical(const Vector4 &e, const double thermal_strain)
    {
      return {{e[0] - thermal_strain,
               e[1] - thermal_strain,
               e[2] - thermal_strain,
               e[3]}};
    }

    /** Volumetric strain e_rr + e_zz + e_tt. */
    inline double
    trace(const Vector4 &e)
    {
      return e[0] + e[1] + e[2];
    }

    /** Hooke's law: stress of a strain for an isotropic material. */
    inline Vector4
    stress(const Material &material, const Vector4 &e)
    {
      const double lambda = material.lambda();
      const double mu     = material.mu();
      const double trace  = Axisymmetric::trace(e);
      return {{lambda * trace + 2. * mu * e[0],
               lambda * trace + 2. * mu * e[1],
               lambda * trace + 2. * mu * e[2],
               mu * e[3]}};
    }

    /** Von Mises equivalent stress of an axisymmetric stress state. */
    inline double
    von_mises(const Vector4 &s)
    {
      const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
      return std::sqrt(0.5 * (a * a + b * b + c * c) + 3. * s[3] * s[3]);
    }
  } // namespace Axisymmetric
} // namespace coaxfit

#endif
