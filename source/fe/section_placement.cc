#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_placement.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  SectionOutline
  shifted(const SectionOutline &outline, const double dz)
  {
    std::vector<OutlineCorner> corners = outline.corners();
    for (OutlineCorner &c : corners)
      c.z += dz;
    corners.push_back(corners.front()); // closed explicitly
    return SectionOutline(corners, outline.entry());
  }



  SectionOutline
  snapped(const SectionOutline &outline,
          const Point<2>       &a,
          const Point<2>       &b,
          const double          tol)
  {
    const Tensor<1, 2>         along   = (b - a) / (b - a).norm();
    std::vector<OutlineCorner> corners = outline.corners();
    for (OutlineCorner &c : corners)
      {
        const Point<2> p(0.5 * c.diameter, c.z);
        if (std::abs(along[0] * (p - a)[1] - along[1] * (p - a)[0]) > tol)
          continue;
        // The line's r at this z (a cylinder: its radius).
        const double r = std::abs(b[1] - a[1]) > 0. ?
                           a[0] + (c.z - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) :
                           a[0];
        c.diameter     = 2. * r;
      }
    corners.push_back(corners.front()); // closed explicitly
    return SectionOutline(corners, outline.entry());
  }



  std::vector<JointPiece>
  merged(std::vector<JointPiece> pieces, const double tol)
  {
    std::sort(pieces.begin(),
              pieces.end(),
              [](const JointPiece &a, const JointPiece &b) {
                return std::min(a.start[1], a.end[1])
                       < std::min(b.start[1], b.end[1]);
              });
    std::vector<JointPiece> result;
    for (JointPiece piece : pieces)
      {
        if (piece.start[1] > piece.end[1])
          std::swap(piece.start, piece.end);
        if (!result.empty() && result.back().end.distance(piece.start) <= tol
            && (result.back().normal - piece.normal).norm() <= 1e-9
            && std::abs(result.back().start[0] - piece.end[0]) <= tol)
          result.back().end = piece.end;
        else
          result.push_back(piece);
      }
    return result;
  }



  std::pair<double, double>
  axial_range(const SectionOutline &outline)
  {
    double lo = outline.corners().front().z, hi = lo;
    for (const OutlineCorner &c : outline.corners())
      {
        lo = std::min(lo, c.z);
        hi = std::max(hi, c.z);
      }
    return {lo, hi};
  }



  std::vector<double>
  joint_offsets(const double half_length,
                const double cell_size,
                const double grading_ratio,
                const double max_cell_size)
  {
    // Sizes from the end of the joint towards its middle.
    std::vector<double> sizes;
    double              sum = 0., h = cell_size;
    while (sum < half_length * (1. - 1e-9) && sizes.size() < 100000)
      {
        sizes.push_back(h);
        sum += h;
        h = std::min(h * grading_ratio, max_cell_size);
      }
    // The last cell overshoots: shrink all in proportion.
    const double        scale = half_length / sum;
    std::vector<double> from_middle;
    double              d = half_length;
    for (unsigned int k = 0; k + 1 < sizes.size(); ++k)
      {
        d -= sizes[k] * scale;
        from_middle.push_back(d);
      }
    return from_middle;
  }



  std::vector<double>
  with_corners(std::vector<double>                        z,
               const std::vector<const SectionOutline *> &outlines,
               const std::function<double(double)>       &radius_at,
               const double                               z_start,
               const double                               z_end)
  {
    double extent = 0.;
    for (const SectionOutline *outline : outlines)
      extent = std::max(extent, outline->extent());
    const double tol = 1e-9 * extent;
    for (const SectionOutline *outline : outlines)
      for (const OutlineCorner &c : outline->corners())
        if (std::abs(0.5 * c.diameter - radius_at(c.z)) <= tol
            && c.z > z_start + tol && c.z < z_end - tol)
          {
            std::vector<double> all = {z_start};
            all.insert(all.end(), z.begin(), z.end());
            all.push_back(z_end);
            const auto   next = std::lower_bound(all.begin(), all.end(), c.z);
            const double cell = *next - *(next - 1);
            auto         near
              = std::min_element(z.begin(),
                                 z.end(),
                                 [&](const double a, const double b) {
                                   return std::abs(a - c.z) < std::abs(b - c.z);
                                 });
            if (near != z.end() && std::abs(*near - c.z) < 0.3 * cell)
              *near = c.z;
            else
              z.insert(std::lower_bound(z.begin(), z.end(), c.z), c.z);
          }
    std::sort(z.begin(), z.end());
    return z;
  }



  std::vector<TaggedSegment>
  symmetry_segments(const SectionOutline &outline)
  {
    std::vector<TaggedSegment> segments;
    const double               tol = 1e-9 * outline.extent();
    for (const OutlineEdge &edge : outline.edges())
      if (!edge.is_arc() && std::abs(edge.start[1]) <= tol
          && std::abs(edge.end[1]) <= tol)
        {
          TaggedSegment plane{edge.start, edge.end, BoundaryId::symmetry};
          plane.refine_ends = false;
          segments.push_back(plane);
        }
    return segments;
  }



  void
  tag_free_faces_at_radius(Triangulation<2>        &mesh,
                           const double             r,
                           const double             extent,
                           const types::boundary_id id)
  {
    const double tol = 1e-9 * extent;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == SectionId::free
            && std::abs(face->vertex(0)[0] - r) <= tol
            && std::abs(face->vertex(1)[0] - r) <= tol)
          face->set_boundary_id(id);
  }
} // namespace coaxfit
