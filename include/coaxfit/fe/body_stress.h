#ifndef coaxfit_body_stress_h
#define coaxfit_body_stress_h

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/fe/body_discretization.h>

#include <functional>
#include <vector>

namespace coaxfit
{
  /**
   * The stress at one point of a body (MPa): sigma_rr, sigma_zz, sigma_tt
   * (hoop) and sigma_rz, with the equivalent stresses of the strength
   * checks.
   */
  struct StressState
  {
    double                z = 0.; ///< axial position (mm)
    double                r = 0.; ///< radius (mm)
    Axisymmetric::Vector4 sigma{{0., 0., 0., 0.}};

    double
    radial() const
    {
      return sigma[0];
    }

    double
    hoop() const
    {
      return sigma[2];
    }

    /** Von Mises of the full axisymmetric state. */
    double
    von_mises() const
    {
      return Axisymmetric::von_mises(sigma);
    }
  };

  /**
   * The stress of @p solution at @p point of @p body, from the cell that
   * contains it (on a cell boundary: one of them).
   */
  StressState
  stress_at(const BodyDiscretization &body,
            const Vector<double>     &solution,
            const Point<2>           &point);

  /**
   * The displacement (u_r, u_z) of @p solution at @p point of @p body (mm),
   * from the cell that contains it; a point of a surface drawn with arcs
   * may lie a little outside the mesh: then on the nearest cell.
   */
  Tensor<1, 2>
  displacement_at(const BodyDiscretization &body,
                  const Vector<double>     &solution,
                  const Point<2>           &point);

  /**
   * The stresses of @p solution at the support points of the boundary faces
   * of @p body at the radius @p r (a surface r = const), ordered by z; the
   * values of the two cells at a shared vertex are averaged.
   */
  std::vector<StressState>
  stresses_along_radius(const BodyDiscretization &body,
                        const Vector<double>     &solution,
                        double                    r);

  /**
   * The same on the boundary faces of @p body with the id @p id (a cone's
   * joint, BoundaryId::joint).
   */
  std::vector<StressState>
  stresses_along_boundary(const BodyDiscretization &body,
                          const Vector<double>     &solution,
                          types::boundary_id        id);

  /**
   * The stresses of @p solution at the support points of the faces of
   * @p body for which @p on_surface (cell, face index) is true, ordered by
   * z (and r); the values of the cells at a shared point averaged.
   */
  std::vector<StressState>
  stresses_on_faces(
    const BodyDiscretization                &body,
    const Vector<double>                    &solution,
    const std::function<bool(const DoFHandler<2>::active_cell_iterator &,
                             unsigned int)> &on_surface);
} // namespace coaxfit

#endif
