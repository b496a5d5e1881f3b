#ifndef coaxfit_mesh_h
#define coaxfit_mesh_h

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Boundary ids of a body's (r, z) half section, set by the mesh builder
   * (make_body_mesh) and nowhere else: constraints, loads, the joint and the
   * output select faces by these ids and take directions from the face
   * normals, never from coordinates.
   */
  namespace BoundaryId
  {
    constexpr types::boundary_id axis     = 0; ///< r = 0: u_r = 0
    constexpr types::boundary_id symmetry = 1; ///< z = 0: u_z = 0
    constexpr types::boundary_id joint    = 2; ///< S: meets the other body
    constexpr types::boundary_id bore     = 3; ///< free inner surface
    constexpr types::boundary_id outer    = 4; ///< free outer surface
    constexpr types::boundary_id end      = 5; ///< free end face
    /**
     * An end face held axially (u_z = 0): a taper fit's supports (7: 6 is
     * SectionId::free, a section's untagged surface).
     */
    constexpr types::boundary_id held = 7;
    /**
     * The bore of a ring in the middle of a stack of several bodies where it
     * meets the body inside it: its second joint (the first, `joint`, is
     * its outer surface).
     */
    constexpr types::boundary_id inner_joint = 8;

    /** The name of @p id for messages and output ("joint", "bore", ...). */
    const char *
    name(types::boundary_id id);
  } // namespace BoundaryId

  /**
   * The (r, z) half section of one cylinder, z >= 0, and how to mesh it.
   *
   * The contact surface S is the part 0 <= z <= contact_length of the
   * cylindrical surface r = contact_radius, which is either the inner or the
   * outer radius. Two bodies that share S and the mesh settings get
   * coinciding vertices and FE support points on S.
   */
  struct BodyGeometry
  {
    double r_inner        = 0.; ///< mm; 0 gives a solid cylinder with an axis
    double r_outer        = 1.; ///< mm
    double length         = 1.; ///< half length (mm)
    double contact_length = 1.; ///< 0 < contact_length <= length (mm)
    bool   contact_at_outer_radius = true;
    /**
     * A ring in the middle of a stack: a joint on its outer radius
     * (contact_at_outer_radius) and another, BoundaryId::inner_joint, on
     * its bore over the same contact length.
     */
    bool inner_joint = false;

    unsigned int axial_cells        = 12;  ///< over the contact length
    unsigned int radial_cells       = 10;  ///< across the wall
    double       grading_ratio      = 1.4; ///< neighbouring cell size ratio
    unsigned int global_refinements = 0;

    /** Radius of the contact surface. */
    double
    contact_radius() const
    {
      return contact_at_outer_radius ? r_outer : r_inner;
    }
  };

  /**
   * Cell sizes of a geometric progression with @p n cells over @p length,
   * neighbouring sizes differing by the factor @p ratio, the smallest cell at
   * the end (fine_at_end) or at the start.
   */
  std::vector<double>
  graded_spacing(double length, unsigned int n, double ratio, bool fine_at_end);

  /**
   * Cells that continue a progression beyond a point where the neighbouring
   * cell has size @p first_size: sizes grow by @p ratio away from it and are
   * scaled to fill @p length exactly.
   */
  std::vector<double>
  growing_spacing(double length, double first_size, double ratio);

  /**
   * The cell sizes of the coarse mesh of a body before refinement: across
   * the wall (r) and along the axis (z), graded towards the contact surface
   * and the end of contact.
   */
  std::pair<std::vector<double>, std::vector<double>>
  body_spacing(const BodyGeometry &geometry);

  /**
   * The number of DoFs of the refined mesh of a body with FE_Q(@p degree)
   * (two components), known before any mesh is built.
   */
  std::size_t
  predicted_dofs(const BodyGeometry &geometry, unsigned int degree);

  /**
   * The number of points along the axis of the refined mesh of a body with
   * FE_Q(@p degree): for the hub, its interface points.
   */
  double
  predicted_axial_points(const BodyGeometry &geometry, unsigned int degree);

  /**
   * The outward unit normal of the straight face @p face of @p cell: the
   * face's direction turned by 90 degrees, pointing away from the cell's
   * centre. Exact for faces along r or z (+-1 and 0, where a mapping's
   * normal carries round-off).
   */
  Tensor<1, 2>
  outward_normal(const Triangulation<2>::cell_iterator &cell,
                 unsigned int                           face);

  /**
   * Build the graded rectangular mesh of one body, tag its boundary with
   * the ids of BoundaryId (the axis of a solid body, the symmetry plane, the
   * joint S, the free bore, outer surface and end face; the part of the
   * joint radius beyond the end of contact is free bore or outer surface),
   * then refine globally (children inherit the ids).
   */
  void
  make_body_mesh(Triangulation<2> &triangulation, const BodyGeometry &geometry);
} // namespace coaxfit

#endif
