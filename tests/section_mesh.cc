// Outlines meshed into quadrilaterals by gmsh: (a) the plain hub D 50-100,
// z -20..20, (b) the gear hub of boss, web and rim, (c) a solid shaft with
// a shoulder and a fillet R 2 at its re-entrant corner, (d) a hub with a
// tapered bore D 50-52 over z 0..40. For each: the section's area and
// Pappus volume 2 pi int r dA of the mesh (MappingQ(2), which follows the
// fillet's manifold) against the exact figures of the outline (worked out
// by hand in tests/section_outline.cc), the boundary length per id
// (MappingQ(3)) against the exact one, that every cell is a quadrilateral, the
// ends of the joint as vertices, the grading (small faces at the ends of the
// joint, large ones in its middle) and the cell quality. For the fillet: the
// area of the straight-sided (MappingQ1) mesh under 0, 1, 2 global refinements,
// whose error falls about 4 times per refinement because new vertices land on
// the arc, and stays put without the manifold. Last, bad settings and tags.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_mesh.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

namespace
{
  using namespace coaxfit;

  constexpr double pi = numbers::PI;

  /** Area and int r dA of the mesh with a MappingQ of @p degree. */
  std::pair<double, double>
  measures(const Triangulation<2> &triangulation, const unsigned int degree)
  {
    const MappingQ<2>   mapping(degree);
    const QGauss<2>     quadrature(degree + 2);
    const FE_Nothing<2> fe;
    FEValues<2>         values(mapping,
                       fe,
                       quadrature,
                       update_quadrature_points | update_JxW_values);
    double              area = 0., moment = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        values.reinit(cell);
        for (const unsigned int q : values.quadrature_point_indices())
          {
            area += values.JxW(q);
            moment += values.quadrature_point(q)[0] * values.JxW(q);
          }
      }
    return {area, moment};
  }

  /** The boundary length per id, MappingQ(3). */
  std::map<types::boundary_id, double>
  lengths(const Triangulation<2> &triangulation)
  {
    const MappingQ<2>   mapping(3);
    const QGauss<1>     quadrature(4);
    const FE_Nothing<2> fe;
    FEFaceValues<2>     values(mapping, fe, quadrature, update_JxW_values);
    std::map<types::boundary_id, double> length;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            values.reinit(cell, f);
            for (const unsigned int q : values.quadrature_point_indices())
              length[cell->face(f)->boundary_id()] += values.JxW(q);
          }
    return length;
  }

  std::string
  id_name(const types::boundary_id id)
  {
    return id == SectionId::free ? "free" : BoundaryId::name(id);
  }

  void
  check(const std::string &label,
        const double       value,
        const double       exact,
        const double       tolerance)
  {
    const double error = std::abs(value - exact) / std::abs(exact);
    std::cout << "  " << std::left << std::setw(16) << label << std::right
              << std::setprecision(9) << std::setw(14) << value << "  exact "
              << std::setw(14) << exact << "  rel. error < " << std::setw(5)
              << std::setprecision(0) << std::scientific << tolerance
              << std::defaultfloat << ": " << (error < tolerance ? "yes" : "NO")
              << '\n';
  }

  /** Smallest and largest corner angle of the cells (degrees). */
  std::pair<double, double>
  corner_angles(const Triangulation<2> &triangulation)
  {
    double smallest = 180., largest = 0.;
    // Vertices of a deal.II quadrilateral, going round it.
    const unsigned int round[4] = {0, 1, 3, 2};
    for (const auto &cell : triangulation.active_cell_iterators())
      for (unsigned int v = 0; v < 4; ++v)
        {
          const Point<2> p     = cell->vertex(round[v]),
                         a     = cell->vertex(round[(v + 1) % 4]),
                         b     = cell->vertex(round[(v + 3) % 4]);
          const Tensor<1, 2> u = a - p, w = b - p;
          const double       angle
            = std::acos(u * w / (u.norm() * w.norm())) * 180. / pi;
          smallest = std::min(smallest, angle);
          largest  = std::max(largest, angle);
        }
    return {smallest, largest};
  }

  bool
  has_vertex(const Triangulation<2> &triangulation, const Point<2> &p)
  {
    for (const Point<2> &v : triangulation.get_vertices())
      if (v.distance(p) < 1e-12 * (1. + p.norm()))
        return true;
    return false;
  }

  /** The longest and shortest joint face within @p d of the points @p ends. */
  std::pair<double, double>
  joint_faces(const Triangulation<2>      &triangulation,
              const std::vector<Point<2>> &ends,
              const double                 d)
  {
    double near = 0., far = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == BoundaryId::joint)
          {
            double distance = 1e300;
            for (const Point<2> &e : ends)
              distance = std::min(distance, face->center().distance(e));
            const double size = face->vertex(0).distance(face->vertex(1));
            (distance < d ? near : far)
              = std::max(distance < d ? near : far, size);
          }
    return {near, far};
  }

  void
  run(const std::string                          &title,
      const std::string                          &text,
      const TaggedSegment                        &joint,
      const SectionMeshSettings                  &settings,
      const std::map<types::boundary_id, double> &exact_lengths)
  {
    std::cout << title << "\n";
    const SectionOutline outline
      = SectionOutline::parse(text, "Geometry/Hub section");
    Triangulation<2> triangulation;
    make_section_mesh(triangulation, outline, {{}, {joint}}, settings);

    bool all_quads = true;
    for (const auto &cell : triangulation.active_cell_iterators())
      all_quads
        = all_quads && cell->reference_cell() == ReferenceCells::Quadrilateral;
    std::cout << "  " << triangulation.n_active_cells()
              << " cells, all quadrilaterals: " << (all_quads ? "yes" : "NO")
              << ", joint ends are vertices: "
              << (has_vertex(triangulation, joint.start)
                      && has_vertex(triangulation, joint.end) ?
                    "yes" :
                    "NO")
              << '\n';

    const auto [area, moment] = measures(triangulation, 2);
    check("area", area, outline.area(), 1e-6);
    check("volume", 2. * pi * moment, outline.volume(), 1e-6);
    for (const auto &[id, length] : lengths(triangulation))
      check("length " + id_name(id),
            length,
            exact_lengths.count(id) ? exact_lengths.at(id) : -1.,
            1e-6);

    const auto [near, far]
      = joint_faces(triangulation, {joint.start, joint.end}, 2.);
    std::cout << "  joint faces within 2 mm of its ends <= 1.5 cell size: "
              << (near <= 1.5 * settings.cell_size ? "yes" : "NO")
              << "; the longest elsewhere >= 2 cell sizes: "
              << (far >= 2. * settings.cell_size ? "yes" : "NO") << '\n';
    const auto [smallest, largest] = corner_angles(triangulation);
    const double aspect
      = GridTools::compute_maximum_aspect_ratio(MappingQ<2>(1),
                                                triangulation,
                                                QGauss<2>(2));
    std::cout << "  corner angles in [" << std::setprecision(2) << smallest
              << ", " << largest << "] deg, largest aspect ratio " << aspect
              << "; within [30, 150] deg and < 4: "
              << (smallest >= 30. && largest <= 150. && aspect < 4. ? "yes" :
                                                                      "NO")
              << '\n';
  }

  /** The fillet of (c): straight-sided area under refinement. */
  void
  refine_fillet()
  {
    std::cout << "(c) area of the straight-sided mesh (MappingQ1) under "
                 "refinement\n";
    const SectionOutline outline = SectionOutline::parse(
      "0, 0; 0, 50; 60, 50, 2; 60, 70; 100, 70; 100, 0; 0, 0",
      "Geometry/Shaft section");
    SectionMeshSettings settings;
    settings.cell_size     = 2.;
    settings.grading_ratio = 1.3;
    const TaggedSegment joint
      = TaggedSegment::from_drawing(10., 50., 50., 50., BoundaryId::joint);
    for (const bool manifold : {true, false})
      {
        double previous = 0.;
        for (unsigned int level = 0; level < 3; ++level)
          {
            Triangulation<2> triangulation;
            make_section_mesh(triangulation, outline, {{}, {joint}}, settings);
            if (!manifold)
              triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
            triangulation.refine_global(level);
            const double error
              = GridTools::volume(triangulation) - outline.area();
            std::cout << "  " << (manifold ? "with" : "without")
                      << " the manifold, " << level
                      << " refinements: area error " << std::scientific
                      << std::setprecision(2) << error << std::defaultfloat;
            if (level > 0)
              std::cout << ", falls by " << std::setprecision(3)
                        << previous / error;
            std::cout << '\n';
            previous = error;
          }
      }
  }
} // namespace

int
main()
{
  using namespace BoundaryId;
  SectionMeshSettings settings;
  settings.cell_size     = 1.;
  settings.grading_ratio = 1.2;

  run("(a) plain hub",
      "-20, 50; 20, 50; 20, 100; -20, 100; -20, 50",
      TaggedSegment::from_drawing(-20., 50., 20., 50., joint),
      settings,
      {{joint, 40.}, {SectionId::free, 90.}});
  run("(b) gear hub",
      "-25, 50; 25, 50; 25, 80; 6, 80; 6, 150; 15, 150; 15, 180; -15, 180; "
      "-15, 150; -6, 150; -6, 80; -25, 80; -25, 50",
      TaggedSegment::from_drawing(25., 50., -25., 50., joint),
      settings,
      {{joint, 50.}, {SectionId::free, 216.}});
  run("(c) shaft with a shoulder, fillet R 2, joint z 10..50",
      "0, 0; 0, 50; 60, 50, 2; 60, 70; 100, 70; 100, 0; 0, 0",
      TaggedSegment::from_drawing(10., 50., 50., 50., joint),
      settings,
      {{axis, 100.}, {joint, 40.}, {SectionId::free, 126. + pi}});
  run("(d) tapered bore",
      "0, 50; 40, 52; 40, 100; 0, 100; 0, 50",
      TaggedSegment::from_drawing(0., 50., 40., 52., joint),
      settings,
      {{joint, std::sqrt(1601.)}, {SectionId::free, 89.}});
  refine_fillet();

  std::cout << "bad settings and tags:\n";
  const SectionOutline hub
    = SectionOutline::parse("-20, 50; 20, 50; 20, 100; -20, 100; -20, 50",
                            "Geometry/Hub section");
  const auto attempt
    = [&](const SectionBoundary &boundary, const SectionMeshSettings &s) {
        try
          {
            Triangulation<2> triangulation;
            make_section_mesh(triangulation, hub, boundary, s);
            std::cout << "  accepted (WRONG)\n";
          }
        catch (const InputError &e)
          {
            std::cout << "  " << e.what() << '\n';
          }
      };
  SectionMeshSettings s = settings;
  s.cell_size           = 0.;
  attempt({}, s);
  s.cell_size     = 1.;
  s.grading_ratio = 0.5;
  attempt({}, s);
  attempt({{}, {TaggedSegment::from_drawing(0., 60., 20., 50., joint)}},
          settings);
  attempt({{}, {TaggedSegment::from_drawing(0., 50., 0., 50., joint)}},
          settings);
}
