#include <deal.II/grid/grid_generator.h>

#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/stack_mesh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coaxfit
{
  std::vector<double>
  stack_axial_spacing(const std::vector<double> &half_lengths,
                      const std::vector<double> &joint_ends,
                      const unsigned int         axial_cells,
                      const double               ratio)
  {
    if (joint_ends.empty() || half_lengths.empty())
      throw std::logic_error("a stack without joints");
    // Breakpoints: the joints' ends and the bodies' half lengths.
    std::vector<double> points = half_lengths;
    points.insert(points.end(), joint_ends.begin(), joint_ends.end());
    std::sort(points.begin(), points.end());
    const double        top = points.back();
    std::vector<double> breaks;
    for (const double p : points)
      if (breaks.empty() || p - breaks.back() > 1e-9 * top)
        breaks.push_back(p);
    const auto is_joint_end = [&](const double z) {
      for (const double e : joint_ends)
        if (std::abs(e - z) <= 1e-9 * top)
          return true;
      return false;
    };

    // Up to the first breakpoint (the shortest joint's end, or a shorter
    // body's): graded towards it.
    std::vector<double> cells
      = graded_spacing(breaks[0], axial_cells, ratio, true);
    const double fine = cells.back();
    for (unsigned int i = 1; i < breaks.size(); ++i)
      {
        const double        length = breaks[i] - breaks[i - 1];
        const bool          from   = is_joint_end(breaks[i - 1]);
        const bool          to     = is_joint_end(breaks[i]);
        std::vector<double> part;
        if (from && to)
          {
            // Growing from both ends, meeting in the middle.
            part = growing_spacing(length / 2., fine, ratio);
            std::vector<double> back
              = growing_spacing(length / 2., fine, ratio);
            std::reverse(back.begin(), back.end());
            part.insert(part.end(), back.begin(), back.end());
          }
        else if (to)
          {
            part = growing_spacing(length, fine, ratio);
            std::reverse(part.begin(), part.end());
          }
        else
          part = growing_spacing(length, from ? fine : cells.back(), ratio);
        cells.insert(cells.end(), part.begin(), part.end());
      }
    return cells;
  }



  void
  make_stack_ring_mesh(Triangulation<2> &triangulation, const StackRing &ring)
  {
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {ring.radial, ring.axial},
                                              Point<2>(ring.r_inner, 0.),
                                              Point<2>(ring.r_outer,
                                                       ring.half_length),
                                              false);
    const double tol = 1e-10 * std::max(ring.r_outer, ring.half_length);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            if (std::abs(c[1]) < tol)
              face->set_boundary_id(BoundaryId::symmetry);
            else if (ring.r_inner == 0. && std::abs(c[0]) < tol)
              face->set_boundary_id(BoundaryId::axis);
            else if (std::abs(c[1] - ring.half_length) < tol)
              face->set_boundary_id(BoundaryId::end);
            else if (std::abs(c[0] - ring.r_outer) < tol)
              face->set_boundary_id(c[1] < ring.outer_contact ?
                                      BoundaryId::joint :
                                      BoundaryId::outer);
            else
              face->set_boundary_id(c[1] < ring.inner_contact ?
                                      BoundaryId::inner_joint :
                                      BoundaryId::bore);
          }
    triangulation.refine_global(ring.global_refinements);
  }
} // namespace coaxfit
