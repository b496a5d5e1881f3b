#ifndef coaxfit_stack_mesh_h
#define coaxfit_stack_mesh_h

#include <deal.II/grid/tria.h>

#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The axial cells of a stack of rings of different lengths, all centred
   * (half models, z >= 0): one grid for every body, cut at each body's half
   * length, so that the two bodies of every joint share their joint nodes.
   * The first segment, up to the shortest joint's end, has @p axial_cells
   * cells shrinking by @p ratio towards its end (as a plain body's joint);
   * beyond it, between the breakpoints (the other joints' ends and the
   * bodies' half lengths), cells grow by @p ratio away from a joint's end
   * on both sides of it, from the size of the finest cell.
   *
   * @p half_lengths are the bodies' half lengths, @p joint_ends the joints'
   * contact half lengths (mm). Returns the cell sizes from z = 0 up to the
   * largest half length; every half length and joint end is a node.
   */
  std::vector<double>
  stack_axial_spacing(const std::vector<double> &half_lengths,
                      const std::vector<double> &joint_ends,
                      unsigned int               axial_cells,
                      double                     ratio);

  /** One ring of a stack as stack_ring_mesh() builds it. */
  struct StackRing
  {
    double              r_inner, r_outer, half_length;
    std::vector<double> radial;        ///< cell sizes across the wall
    std::vector<double> axial;         ///< cell sizes up to half_length
    double              inner_contact; ///< joint on the bore up to (0: none)
    double              outer_contact; ///< joint outside up to (0: none)
    unsigned int        global_refinements;
  };

  /**
   * Build the mesh of @p ring into an empty triangulation and tag it: the
   * symmetry plane z = 0, the axis of a solid ring, BoundaryId::joint on the
   * outer surface up to outer_contact, BoundaryId::inner_joint on the bore
   * up to inner_contact, the end face and the free bore and outer surface;
   * then refine globally.
   */
  void
  make_stack_ring_mesh(Triangulation<2> &triangulation, const StackRing &ring);
} // namespace coaxfit

#endif
