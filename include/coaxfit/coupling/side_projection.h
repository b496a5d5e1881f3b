#ifndef coaxfit_side_projection_h
#define coaxfit_side_projection_h

#include <deal.II/base/point.h>

#include <coaxfit/coupling/interface_side.h>

#include <vector>

namespace coaxfit
{
  /**
   * The closest point of an InterfaceSide (the polyline of its straight
   * faces) to a point x, and where it lies.
   */
  struct SideProjection
  {
    unsigned int face = 0;      ///< the face it lies on
    double       t    = 0.;     ///< its face parameter, in [0, 1]
    Point<2>     point;         ///< the closest point (mm)
    double       distance = 0.; ///< |x - point| (mm)
    /**
     * How far x lies beyond an end of the side, measured along the end
     * face (mm); 0 if its projection falls on the side.
     */
    double overshoot = 0.;
  };

  /**
   * The closest point of @p side to @p x. For x near the side it is the
   * projection along the normal of the face it falls on (or a vertex, for x
   * in the wedge outside a convex corner). Costs O(n_faces).
   */
  SideProjection
  closest_point(const InterfaceSide &side, const Point<2> &x);

  /**
   * The parameters t in [0, 1] of the segment from @p start to @p end
   * where the closest point on @p side can change its face: where the
   * segment crosses the normal lines of the side's faces through their end
   * points, and the mean-normal lines (the bisectors) through the vertices
   * where two faces meet. Between two consecutive values, closest_point()
   * moves affinely along one face or stays at one vertex, so a function
   * that is polynomial on each face of @p side is polynomial in t there.
   * Sorted, starting with 0 and ending with 1. Vertices of @p side farther
   * from the segment than its length plus the longest face are skipped.
   */
  std::vector<double>
  projection_breakpoints(const InterfaceSide &side,
                         const Point<2>      &start,
                         const Point<2>      &end);
} // namespace coaxfit

#endif
