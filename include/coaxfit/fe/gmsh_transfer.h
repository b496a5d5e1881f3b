#ifndef coaxfit_gmsh_transfer_h
#define coaxfit_gmsh_transfer_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>

namespace coaxfit
{
  using namespace dealii;

  /** What the faces on one gmsh curve get in the deal.II mesh. */
  struct CurveTag
  {
    types::boundary_id boundary_id = 0;
    /** The manifold of the faces (flat unless the curve is an arc). */
    types::manifold_id manifold_id = numbers::flat_manifold_id;
  };

  /**
   * Copy the 2D mesh of gmsh's current model (inside a run_gmsh_session())
   * into @p triangulation, which must be empty: gmsh's x is r, its y is z
   * (mm), its z must be 0.
   *
   * Only first-order quadrilaterals are accepted: triangles, second-order
   * or other elements, no 2D elements at all, a node at r < 0 or off the
   * plane, or a quadrilateral that is degenerate or not convex throw an
   * InputError "@p context: ..." that says which. Quadrilaterals are
   * oriented counter-clockwise and consistently ordered for deal.II.
   *
   * Each boundary face on the gmsh curve with tag t of @p curves gets the
   * boundary and manifold ids of curves.at(t); a boundary face on no listed
   * curve gets BoundaryId::axis if it lies on r = 0 and @p untagged_id
   * otherwise. For every entry of @p arc_centres a PolarManifold<2> about
   * that centre is attached to the triangulation under that manifold id.
   */
  void
  transfer_gmsh_mesh(Triangulation<2>              &triangulation,
                     const std::map<int, CurveTag> &curves,
                     const std::map<types::manifold_id, Point<2>> &arc_centres,
                     types::boundary_id                            untagged_id,
                     const std::string                            &context);
} // namespace coaxfit

#endif
