#ifndef coaxfit_section_mesh_h
#define coaxfit_section_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_outline.h>

#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Boundary and manifold ids of sections (outlines and gmsh files) beyond
   * those of BoundaryId.
   */
  namespace SectionId
  {
    /** A free surface of a section that no one has named or tagged. */
    constexpr types::boundary_id free = 6;
    /** The first id given to the other names of a gmsh file's curves. */
    constexpr types::boundary_id first_named = 10;
    /**
     * The manifold id of the k-th arc of a section is first_arc + k (a
     * PolarManifold<2> about its centre); every other face and every cell
     * is flat.
     */
    constexpr types::manifold_id first_arc = 1;
  } // namespace SectionId

  static_assert(SectionId::free != BoundaryId::held
                  && SectionId::free > BoundaryId::end
                  && SectionId::first_named > BoundaryId::held,
                "the ids of a section's faces must differ from BoundaryId's");

  /**
   * A part of a section's boundary that gets its own boundary id, for
   * instance the joint: the outline between two points on it (r, z, mm),
   * along the shorter of the two ways round. The mesher places a vertex at
   * both points, so that the part begins and ends at a vertex.
   */
  struct TaggedSegment
  {
    Point<2>           start; ///< (r, z) on the outline, mm
    Point<2>           end;   ///< (r, z) on the outline, mm
    types::boundary_id boundary_id = 0;
    /**
     * If not empty: the segment's cells are fixed, one between each two
     * consecutive points of start, these vertices (on the outline, in
     * order) and end, whatever the cell size says. Two bodies meshed
     * with the same vertices on their joint get coinciding nodes there.
     */
    std::vector<Point<2>> vertices = {};
    /**
     * Whether the mesh is refined towards both ends (false for a segment
     * that ends on a symmetry plane: give its other end as a refinement
     * point).
     */
    bool refine_ends = true;

    /** The segment from (z, D) to (z, D) in drawing coordinates. */
    static TaggedSegment
    from_drawing(double             z_start,
                 double             diameter_start,
                 double             z_end,
                 double             diameter_end,
                 types::boundary_id boundary_id);
  };

  /**
   * The boundary ids of an outline's mesh. Every face gets, in order of
   * precedence: the id of the tagged segment it lies on; else the id of its
   * outline edge in edge_ids (indexed like SectionOutline::edges(); an empty
   * vector gives no edge ids); else BoundaryId::axis on r = 0 and
   * SectionId::free elsewhere.
   */
  struct SectionBoundary
  {
    std::vector<types::boundary_id> edge_ids;
    std::vector<TaggedSegment>      segments;
  };

  /**
   * How an outline is meshed. The cells have size cell_size (mm) at the
   * refinement points: the points given here, every end of a tagged
   * segment (where a joint or a load begins or ends), every sharp
   * re-entrant corner and every fillet of a re-entrant corner. Away from
   * them, the size grows by the factor grading_ratio from one cell to the
   * next, that is linearly with the distance d, h = cell_size +
   * (grading_ratio - 1) d, up to max_cell_size. A fillet's arc has at
   * least 6 cells per quarter circle.
   */
  struct SectionMeshSettings
  {
    double cell_size     = 1.;  ///< mm, > 0, at the refinement points
    double grading_ratio = 1.2; ///< >= 1; 1 gives cell_size everywhere
    double max_cell_size = 0.;  ///< mm; 0: 8 cell_size
    std::vector<Point<2>> refinement_points; ///< (r, z), mm
    unsigned int          global_refinements = 0;
    /**
     * Split every cell of gmsh's recombined mesh into quadrilaterals
     * (gmsh's full-quad variant, or its subdivision where tagged segments
     * have fixed vertices), which halves every boundary cell, whether or
     * not the Blossom recombination alone leaves a triangle.
     */
    bool full_quad = false;
  };

  /**
   * Mesh @p outline into @p triangulation (which must be empty) with
   * quadrilaterals by gmsh (frontal-Delaunay triangles recombined by the
   * Blossom algorithm; if that leaves a triangle, the full-quad variant),
   * tag its boundary as @p boundary says, attach a PolarManifold<2> to the
   * faces on each arc (manifold id SectionId::first_arc + k for the k-th
   * arc of outline.edges()), so that refinement keeps new vertices on the
   * arc, and refine globally settings.global_refinements times.
   *
   * @throws InputError naming outline.entry() if a tagged segment does not
   * lie on the outline, the settings are out of range, gmsh fails or the
   * mesh is not all quadrilaterals.
   *
   * @return whether every cell was split (asked for, or because Blossom
   * left a triangle): then every boundary cell, also of a segment with
   * fixed vertices, was halved at its middle, so that two sections with
   * the same fixed vertices match only if both were split.
   */
  bool
  make_section_mesh(Triangulation<2>          &triangulation,
                    const SectionOutline      &outline,
                    const SectionBoundary     &boundary,
                    const SectionMeshSettings &settings);
} // namespace coaxfit

#endif
