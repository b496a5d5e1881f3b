// Sections read from gmsh files (x = r, y = z, mm), the names of their
// physical curves turned into boundary ids: a .geo of a hub D 50-100,
// z 0..40, its bore edge at z = 40 rounded with R 2 (meshed into
// quadrilaterals here; area 1000 - (4 - pi), the arc kept under refinement
// by its manifold), and a hand-written .msh of two quadrilaterals (one
// written clockwise) with a named load face. Then files that are refused,
// each with its one-line error.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_file.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>

namespace
{
  using namespace coaxfit;

  constexpr double pi = numbers::PI;

  const char *rounded_bore = R"(// hub D 50-100, z 0..40, bore edge rounded
Point(1) = {25, 0, 0, 1};
Point(2) = {50, 0, 0, 4};
Point(3) = {50, 40, 0, 4};
Point(4) = {27, 40, 0, 0.5};
Point(5) = {27, 38, 0, 1};
Point(6) = {25, 38, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Circle(4) = {4, 5, 6};
Line(5) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Curve("joint") = {5};
Physical Curve("outer") = {2};
Physical Curve("end face") = {1, 3};
Physical Surface("hub") = {1};
)";

  std::string
  msh(const std::string &names, const std::string &elements)
  {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" + names
           + "$EndPhysicalNames\n$Nodes\n6\n1 25 0 0\n2 50 0 0\n3 50 20 0\n"
             "4 25 20 0\n5 25 40 0\n6 50 40 0\n$EndNodes\n$Elements\n"
           + elements + "$EndElements\n";
  }

  const std::string names = "3\n1 1 \"joint\"\n1 2 \"load face\"\n2 3 "
                            "\"hub\"\n";
  // The second quadrilateral goes round clockwise.
  const std::string two_quads = "5\n1 1 2 1 1 1 4\n2 1 2 1 1 4 5\n"
                                "3 1 2 2 2 5 6\n4 3 2 3 1 1 2 3 4\n"
                                "5 3 2 3 1 4 5 6 3\n";

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  std::map<types::boundary_id, double>
  lengths(const Triangulation<2> &triangulation)
  {
    const MappingQ<2>   mapping(3);
    const FE_Nothing<2> fe;
    FEFaceValues<2>     values(mapping, fe, QGauss<1>(4), update_JxW_values);
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

  void
  show(const std::string                          &file,
       const std::map<types::boundary_id, double> &exact)
  {
    Triangulation<2> triangulation;
    const auto       ids
      = read_section_file(triangulation, file, "Geometry/Hub section");
    std::cout << file << ": " << triangulation.n_active_cells()
              << " quadrilaterals; names:";
    for (const auto &[name, id] : ids)
      std::cout << " '" << name << "' " << int(id);
    std::cout << '\n';
    for (const auto &[id, length] : lengths(triangulation))
      {
        const double e = exact.count(id) ? exact.at(id) : -1.;
        std::cout << "  id " << std::setw(2) << int(id) << " length "
                  << std::setprecision(9) << std::setw(12) << length
                  << "  exact " << std::setw(12) << e << "  rel. error < 1e-6: "
                  << (std::abs(length - e) < 1e-6 * e ? "yes" : "NO") << '\n';
      }
  }
} // namespace

int
main()
{
  write("rounded_bore.geo", rounded_bore);
  // joint 2, 'outer' 10, 'end face' 11 (named ids in the order of the
  // groups), the arc free (6): its length pi R = 2 pi / 2.
  show("rounded_bore.geo", {{2, 38.}, {10, 40.}, {11, 48.}, {6, pi}});
  std::cout << "  area of the straight-sided mesh under refinement:\n";
  const double exact    = 1000. - (4. - pi);
  double       previous = 0.;
  for (unsigned int level = 0; level < 3; ++level)
    {
      Triangulation<2> triangulation;
      read_section_file(triangulation,
                        "rounded_bore.geo",
                        "Geometry/Hub section",
                        level);
      const double error = GridTools::volume(triangulation) - exact;
      std::cout << "    " << level << " refinements: error " << std::scientific
                << std::setprecision(2) << error << std::defaultfloat;
      if (level > 0)
        std::cout << ", falls by " << std::setprecision(3) << previous / error;
      std::cout << '\n';
      previous = error;
    }

  write("two_quads.msh", msh(names, two_quads));
  show("two_quads.msh", {{2, 40.}, {10, 25.}, {6, 65.}});

  std::cout << "refused:\n";
  write("section.txt", "");
  write("triangles.msh",
        msh(names,
            "4\n1 1 2 1 1 1 4\n2 2 2 3 1 1 2 3\n3 2 2 3 1 1 3 4\n"
            "4 3 2 3 1 4 3 6 5\n"));
  write("no_joint.msh",
        msh("1\n1 2 \"load face\"\n",
            "3\n1 1 2 2 2 5 6\n2 3 2 3 1 1 2 3 4\n"
            "3 3 2 3 1 4 3 6 5\n"));
  write("broken.geo", "Point(1) = {0, 0, 0;\n");
  write("open_loop.geo",
        "Point(1) = {25, 0, 0}; Point(2) = {50, 0, 0}; Point(3) = {50, 40, 0};"
        "\nLine(1) = {1, 2}; Line(2) = {2, 3};\nCurve Loop(1) = {1, 2};\n"
        "Plane Surface(1) = {1};\nPhysical Curve(\"joint\") = {1};\n");
  write("triangles.geo",
        std::string(rounded_bore) + "Mesh.RecombineAll = 0;\n");
  for (const char *file : {"missing.msh",
                           "section.txt",
                           "triangles.msh",
                           "no_joint.msh",
                           "broken.geo",
                           "open_loop.geo",
                           "triangles.geo"})
    {
      try
        {
          Triangulation<2> triangulation;
          read_section_file(triangulation, file, "Geometry/Hub section");
          std::cout << "  " << file << ": accepted (WRONG)\n";
        }
      catch (const InputError &e)
        {
          std::cout << "  " << e.what() << '\n';
        }
    }
}
