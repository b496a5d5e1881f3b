#ifndef coaxfit_section_file_h
#define coaxfit_section_file_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <coaxfit/fe/section_outline.h>

#include <map>
#include <string>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Read the section of a body from the gmsh file @p filename into
   * @p triangulation (which must be empty) and return the boundary id of
   * every named physical curve, so that loads can refer to faces by name.
   *
   * <h3>The file</h3>
   * - Coordinates: gmsh's x is the radius r >= 0 and its y the axial
   *   position z, in mm (as in coaxfit's meshes and VTU output: x = r,
   *   y = z); its z must be 0.
   * - A `.msh` file is read as it is; a `.geo` file is meshed in 2D with
   *   the sizes it sets itself, recombined into quadrilaterals
   *   (frontal-Delaunay and Blossom unless the file chooses otherwise). A
   *   mesh with any element that is not a first-order quadrilateral is
   *   refused.
   * - Physical curves give the boundary ids by name: `joint` gets
   *   BoundaryId::joint, `axis` BoundaryId::axis, every other name a new id
   *   from SectionId::first_named on, in the order of the groups' tags. A
   *   boundary face on no physical curve is BoundaryId::axis on r = 0 and
   *   SectionId::free elsewhere. A file without a `joint` curve is refused
   *   if @p joint_required (a body of two; a stack finds its joints where
   *   the sections meet).
   * - Curves of a `.geo` that are circle arcs get a PolarManifold<2> about
   *   their centre (manifold ids from SectionId::first_arc), so that global
   *   refinement keeps new vertices on them; a `.msh` file holds no
   *   geometry, its curves are refined as straight faces.
   *
   * Then the mesh is refined @p global_refinements times.
   *
   * @throws InputError "parameter @p entry = '@p filename': ..." if the
   * file does not exist, gmsh cannot read or mesh it, or it breaks a rule
   * above.
   */
  std::map<std::string, types::boundary_id>
  read_section_file(Triangulation<2>  &triangulation,
                    const std::string &filename,
                    const std::string &entry,
                    unsigned int       global_refinements = 0,
                    bool               joint_required     = true);

  /**
   * Whether the value @p text of `Geometry/Shaft section` or `Hub section`
   * names a gmsh file rather than an outline: one word (no ';') ending in
   * `.geo` or `.msh` (in any case).
   */
  bool
  is_section_file_name(const std::string &text);

  /**
   * The section file @p text (is_section_file_name()) of the parameter file
   * @p parameter_file: relative to that file's directory unless absolute,
   * written absolute and normal, so that a run's parameters.prm repeats it
   * from anywhere.
   * @throws InputError naming @p entry if the name has a '#' (a comment
   * in a parameter file).
   */
  std::string
  resolved_section_file(const std::string &text,
                        const std::string &parameter_file,
                        const std::string &entry);

  /**
   * The boundary of the section mesh @p triangulation (as read by
   * read_section_file(), before refinement) as an outline in drawing
   * coordinates (z, D): its boundary vertices in order, neighbours on one
   * straight line merged, so that a straight surface is one edge and a
   * circle arc its chords. The outline is what SectionScene finds the
   * joint, the plane of symmetry and D_aA from.
   *
   * @throws InputError "parameter @p entry = '@p filename': ..." if the
   * boundary is not one closed loop (a section with a hole, or two pieces).
   */
  SectionOutline
  outline_of_mesh(const Triangulation<2> &triangulation,
                  const std::string      &entry,
                  const std::string      &filename);
} // namespace coaxfit

#endif
