#include <deal.II/grid/grid_generator.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/mesh.h>

#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream text;
      text << x;
      return text.str();
    }
  } // namespace


  std::vector<double>
  graded_spacing(const double       length,
                 const unsigned int n,
                 const double       ratio,
                 const bool         fine_at_end)
  {
    std::vector<double> sizes(n);
    double              size = 1.;
    for (unsigned int i = 0; i < n; ++i, size *= ratio)
      sizes[i] = size; // growing from the start
    const double sum = std::accumulate(sizes.begin(), sizes.end(), 0.);
    for (double &s : sizes)
      s *= length / sum;
    if (fine_at_end)
      std::reverse(sizes.begin(), sizes.end());
    return sizes;
  }



  std::vector<double>
  growing_spacing(const double length,
                  const double first_size,
                  const double ratio)
  {
    // Smallest n for which first_size (1 + r + ... + r^(n-1)) >= length.
    unsigned int n   = 0;
    double       sum = 0., size = first_size;
    // MeshParameters::validate() bounds the grading; a cell this small or a
    // count this large can only come from a defect.
    if (!(first_size > 1e-12 * length) || !(ratio >= 1.))
      throw std::logic_error("growing_spacing: first cell "
                             + std::to_string(first_size) + " of "
                             + std::to_string(length));
    while (sum < length * (1. - 1e-12))
      {
        if (n >= 100000)
          throw InputError(
            "parameter Mesh/Grading ratio = " + number(ratio)
            + ": the longer body needs more than 100000 cells beyond the "
              "end of contact; use a larger Mesh/Grading ratio or "
              "Geometry/Shaft length and Hub length closer to each other");
        sum += size;
        size *= ratio;
        ++n;
      }
    // Rather one cell fewer and slightly larger ones than a sliver at the end.
    if (n > 1)
      {
        const double sum_without_last = sum - size / ratio;
        if (length - sum_without_last < 0.5 * size / ratio)
          --n;
      }
    return graded_spacing(length, n, ratio, false);
  }



  std::pair<std::vector<double>, std::vector<double>>
  body_spacing(const BodyGeometry &geometry)
  {
    const double wall = geometry.r_outer - geometry.r_inner;

    // Radial: smallest cells at the contact surface (equal cells in a
    // ring with joints at both radii).
    const std::vector<double> radial
      = graded_spacing(wall,
                       geometry.radial_cells,
                       geometry.inner_joint ? 1. : geometry.grading_ratio,
                       geometry.contact_at_outer_radius);

    // Axial: over the contact, smallest cells at the end of contact; beyond
    // it (the longer body) cells grow away from the end of contact.
    std::vector<double> axial  = graded_spacing(geometry.contact_length,
                                               geometry.axial_cells,
                                               geometry.grading_ratio,
                                               true);
    const double        beyond = geometry.length - geometry.contact_length;
    if (beyond > 1e-12 * geometry.length)
      {
        const std::vector<double> extra
          = growing_spacing(beyond, axial.back(), geometry.grading_ratio);
        axial.insert(axial.end(), extra.begin(), extra.end());
      }

    return {radial, axial};
  }



  std::size_t
  predicted_dofs(const BodyGeometry &geometry, const unsigned int degree)
  {
    const auto [radial, axial]  = body_spacing(geometry);
    const double cells_per_line = std::pow(2., geometry.global_refinements);
    const double n_r            = degree * radial.size() * cells_per_line + 1.;
    const double n_z            = degree * axial.size() * cells_per_line + 1.;
    return static_cast<std::size_t>(std::min(2. * n_r * n_z, 1e18));
  }



  double
  predicted_axial_points(const BodyGeometry &geometry,
                         const unsigned int  degree)
  {
    const double cells_per_line = std::pow(2., geometry.global_refinements);
    return std::min(degree * body_spacing(geometry).second.size()
                        * cells_per_line
                      + 1.,
                    1e18);
  }



  const char *
  BoundaryId::name(const types::boundary_id id)
  {
    switch (id)
      {
        case axis:
          return "axis";
        case symmetry:
          return "symmetry";
        case joint:
          return "joint";
        case bore:
          return "bore";
        case outer:
          return "outer";
        case end:
          return "end";
        case held:
          return "held";
        case inner_joint:
          return "inner joint";
        default:
          return "untagged";
      }
  }



  Tensor<1, 2>
  outward_normal(const Triangulation<2>::cell_iterator &cell,
                 const unsigned int                     face)
  {
    const Tensor<1, 2> t
      = cell->face(face)->vertex(1) - cell->face(face)->vertex(0);
    // Component by component (Tensor's /= multiplies by the reciprocal,
    // which leaves h * (1/h) != 1).
    const double length = std::sqrt(t[0] * t[0] + t[1] * t[1]);
    Tensor<1, 2> n;
    n[0] = t[1] / length;
    n[1] = -t[0] / length;
    if (n * (cell->face(face)->center() - cell->center()) < 0.)
      n *= -1.;
    return n;
  }



  void
  make_body_mesh(Triangulation<2> &triangulation, const BodyGeometry &geometry)
  {
    const auto [radial, axial] = body_spacing(geometry);
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {radial, axial},
                                              Point<2>(geometry.r_inner, 0.),
                                              Point<2>(geometry.r_outer,
                                                       geometry.length),
                                              false);

    // The only place that tells faces apart by their coordinates.
    const double tol = 1e-10 * std::max(geometry.r_outer, geometry.length);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            if (std::abs(c[1]) < tol)
              face->set_boundary_id(BoundaryId::symmetry);
            else if (geometry.r_inner == 0. && std::abs(c[0]) < tol)
              face->set_boundary_id(BoundaryId::axis);
            else if (std::abs(c[0] - geometry.contact_radius()) < tol
                     && c[1] < geometry.contact_length)
              face->set_boundary_id(BoundaryId::joint);
            else if (geometry.inner_joint
                     && std::abs(c[0] - geometry.r_inner) < tol
                     && c[1] < geometry.contact_length)
              face->set_boundary_id(BoundaryId::inner_joint);
            else if (std::abs(c[1] - geometry.length) < tol)
              face->set_boundary_id(BoundaryId::end);
            else if (std::abs(c[0] - geometry.r_inner) < tol)
              face->set_boundary_id(BoundaryId::bore);
            else
              face->set_boundary_id(BoundaryId::outer);
          }

    triangulation.refine_global(geometry.global_refinements);
  }
} // namespace coaxfit
