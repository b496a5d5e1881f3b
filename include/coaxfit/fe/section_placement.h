#ifndef coaxfit_section_placement_h
#define coaxfit_section_placement_h

#include <deal.II/grid/tria.h>

#include <coaxfit/fe/section_joint.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/fe/section_outline.h>

#include <functional>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * @name Placing sections against each other
   * What a scene of sections (two bodies, or a stack) does with its
   * outlines before meshing them: move them along the axis, snap corners
   * that lie on a joint within the drawing tolerance onto it, join the
   * pieces of a joint split by a corner, find their axial extent.
   */
  /** @{ */

  /** @p outline moved by @p dz along the axis (same entry). */
  SectionOutline
  shifted(const SectionOutline &outline, double dz);

  /**
   * @p outline with every corner within @p tol of the line through @p a
   * and @p b (a cylinder or a cone in (r, z)) moved radially onto it.
   */
  SectionOutline
  snapped(const SectionOutline &outline,
          const Point<2>       &a,
          const Point<2>       &b,
          double                tol);

  /**
   * @p pieces with neighbours on one straight line joined (a corner of
   * an outline on the joint splits it without changing it), sorted along
   * the axis, each from its smaller z to its larger.
   */
  std::vector<JointPiece>
  merged(std::vector<JointPiece> pieces, double tol);

  /** Smallest and largest z of the corners of @p outline. */
  std::pair<double, double>
  axial_range(const SectionOutline &outline);

  /**
   * The distances from the middle of a joint of half length @p half_length
   * of its vertices between the middle and the end, descending (the
   * middle and the end not included): the first cell at the end has size
   * @p cell_size, sizes grow by @p grading_ratio towards the middle up to
   * @p max_cell_size, the half filled exactly.
   */
  std::vector<double>
  joint_offsets(double half_length,
                double cell_size,
                double grading_ratio,
                double max_cell_size);

  /**
   * The joint vertices @p z (model z, ascending, between @p z_start and
   * @p z_end) with every corner of @p outlines that lies on the joint
   * (r = @p radius_at(z) within 1e-9 of the outlines' extent) strictly
   * between its ends made one of them: replacing the nearest vertex if
   * that is closer than 0.3 of its cell, else inserted. Both bodies of a
   * joint then have the same vertices on it.
   */
  std::vector<double>
  with_corners(std::vector<double>                        z,
               const std::vector<const SectionOutline *> &outlines,
               const std::function<double(double)>       &radius_at,
               double                                     z_start,
               double                                     z_end);

  /**
   * The straight edges of @p outline on the plane z = 0 of a half model,
   * each a segment tagged BoundaryId::symmetry (its ends not refined).
   */
  std::vector<TaggedSegment>
  symmetry_segments(const SectionOutline &outline);

  /**
   * Give the free faces (SectionId::free) of @p mesh that lie on the
   * cylinder r = @p r (within 1e-9 of @p extent) the boundary id @p id:
   * a bore or an outer surface that Operation's pressures load.
   */
  void
  tag_free_faces_at_radius(Triangulation<2>  &mesh,
                           double             r,
                           double             extent,
                           types::boundary_id id);
  /** @} */
} // namespace coaxfit

#endif
