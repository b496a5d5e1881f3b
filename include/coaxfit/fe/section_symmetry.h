#ifndef coaxfit_section_symmetry_h
#define coaxfit_section_symmetry_h

#include <coaxfit/fe/section_outline.h>

#include <optional>
#include <vector>

namespace coaxfit
{
  /**
   * The plane z = z_m about which every outline of @p sections is
   * symmetric, if there is one: z_m is the middle of the first outline's
   * axial extent, and each outline's corners (z, D, R) must have their
   * mirror images (2 z_m - z, D, R) among its corners, within 1e-9 of the
   * largest extent. A scene symmetric about a plane may be modelled as its
   * half z >= z_m with u_z = 0 on the plane; any other is modelled whole.
   */
  std::optional<double>
  mirror_plane(const std::vector<const SectionOutline *> &sections);

  /**
   * The half z >= @p z_m of @p outline, which must be symmetric about it:
   * the corners with z > z_m and the points where the outline crosses the
   * plane, in order, as a new outline (entry name kept). Empty if the half
   * is not one region (the outline crosses the plane more than twice) or a
   * fillet touches the plane: such a scene is modelled whole.
   */
  std::optional<SectionOutline>
  half_outline(const SectionOutline &outline, double z_m);
} // namespace coaxfit

#endif
