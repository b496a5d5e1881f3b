#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/gmsh_session.h>
#include <coaxfit/fe/gmsh_transfer.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_file.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <map>
#include <set>

namespace coaxfit
{
  namespace
  {
    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /** The centre of the circle through three points. */
    bool
    circle_centre(const Point<2> &a,
                  const Point<2> &b,
                  const Point<2> &c,
                  Point<2>       &centre)
    {
      const Tensor<1, 2> ab = b - a, ac = c - a;
      const double       d = 2. * cross(ab, ac);
      if (std::abs(d) <= 1e-12 * (ab * ab + ac * ac))
        return false; // collinear
      const double       ab2 = ab * ab, ac2 = ac * ac;
      const Tensor<1, 2> offset(
        {(ac[1] * ab2 - ab[1] * ac2) / d, (ab[0] * ac2 - ac[0] * ab2) / d});
      centre = a + offset;
      return true;
    }

    /** Point of curve @p tag at parameter @p u. */
    Point<2>
    curve_point(const int tag, const double u)
    {
      std::vector<double> xyz;
      gmsh::model::getValue(1, tag, {u}, xyz);
      return Point<2>(xyz[0], xyz[1]);
    }
  } // namespace



  std::map<std::string, types::boundary_id>
  read_section_file(Triangulation<2>  &triangulation,
                    const std::string &filename,
                    const std::string &entry,
                    const unsigned int global_refinements)
  {
    const std::string context = "parameter " + entry + " = '" + filename + "'";
    std::string       extension = std::filesystem::path(filename).extension();
    std::transform(extension.begin(),
                   extension.end(),
                   extension.begin(),
                   [](const unsigned char c) { return std::tolower(c); });
    if (extension != ".geo" && extension != ".msh")
      throw InputError(
        context + ": a section file must be a gmsh '.geo' or '.msh' file");
    if (!std::filesystem::is_regular_file(filename)
        || !std::ifstream(filename).good())
      throw InputError(context + ": no such file, or it cannot be read");

    std::map<std::string, types::boundary_id> names;
    run_gmsh_session(context, [&]() {
      if (extension == ".geo")
        {
          // coaxfit's choices; the file may set its own.
          gmsh::option::setNumber("Mesh.Algorithm", 6); // frontal-Delaunay
          gmsh::option::setNumber("Mesh.RecombineAll", 1);
          gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
        }
      gmsh::open(filename);
      check_gmsh_error(context);

      // Physical curves: their names, ids and curves.
      std::map<int, CurveTag>    curves;
      std::map<int, std::string> group_of_curve;
      gmsh::vectorpair           groups;
      gmsh::model::getPhysicalGroups(groups, 1);
      types::boundary_id next_id = SectionId::first_named;
      for (const auto &[dim, group] : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(dim, group, name);
          if (name.empty())
            name = std::to_string(group);
          if (names.count(name) == 0)
            names[name] = name == "joint" ? BoundaryId::joint :
                          name == "axis"  ? BoundaryId::axis :
                                            next_id++;
          std::vector<int> entities;
          gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
          for (const int curve : entities)
            {
              const auto other = group_of_curve.find(curve);
              if (other != group_of_curve.end() && other->second != name)
                throw InputError(context + ": curve " + std::to_string(curve)
                                 + " is in two physical curves, '"
                                 + other->second + "' and '" + name
                                 + "'; a face can have one name only");
              group_of_curve[curve]     = name;
              curves[curve].boundary_id = names[name];
            }
        }
      if (names.count("joint") == 0)
        throw InputError(
          context
          + ": no physical curve named 'joint' (the surface that "
            "meets the other body); add one, e.g. "
            "Physical Curve(\"joint\") = {...};");

      // Circle arcs of a .geo: a manifold about their centre.
      std::map<types::manifold_id, Point<2>> arc_centres;
      gmsh::vectorpair                       all_curves;
      gmsh::model::getEntities(all_curves, 1);
      for (const auto &[dim, curve] : all_curves)
        {
          std::string type;
          gmsh::model::getType(dim, curve, type);
          if (type != "Circle")
            continue;
          std::vector<double> low, high;
          gmsh::model::getParametrizationBounds(dim, curve, low, high);
          Point<2> centre;
          if (!circle_centre(curve_point(curve, low[0]),
                             curve_point(curve, 0.5 * (low[0] + high[0])),
                             curve_point(curve, high[0]),
                             centre))
            continue;
          const types::manifold_id id
            = SectionId::first_arc + arc_centres.size();
          arc_centres[id] = centre;
          if (curves.count(curve) == 0) // an arc is never on the axis
            curves[curve].boundary_id = SectionId::free;
          curves[curve].manifold_id = id;
        }

      if (extension == ".geo")
        {
          gmsh::model::mesh::generate(2);
          check_gmsh_error(context);
          std::vector<int>                      types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
          double recombine_all = 0.;
          gmsh::option::getNumber("Mesh.RecombineAll", recombine_all);
          if (recombine_all != 0.
              && std::any_of(types.begin(), types.end(), [](const int t) {
                   return t != 3;
                 }))
            {
              // Blossom left triangles: its full-quad variant splits them.
              gmsh::model::mesh::clear();
              gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
              gmsh::model::mesh::generate(2);
            }
          check_gmsh_error(context);
        }
      transfer_gmsh_mesh(
        triangulation, curves, arc_centres, SectionId::free, context);
    });
    triangulation.refine_global(global_refinements);
    return names;
  }



  bool
  is_section_file_name(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t");
    const auto last  = text.find_last_not_of(" \t");
    if (first == std::string::npos || text.find(';') != std::string::npos)
      return false;
    std::string word = text.substr(first, last - first + 1);
    if (word.size() < 5)
      return false;
    std::transform(word.begin(),
                   word.end(),
                   word.begin(),
                   [](const unsigned char c) { return std::tolower(c); });
    const std::string extension = word.substr(word.size() - 4);
    return extension == ".geo" || extension == ".msh";
  }



  SectionOutline
  outline_of_mesh(const Triangulation<2> &triangulation,
                  const std::string      &entry,
                  const std::string      &filename)
  {
    const std::string context = "parameter " + entry + " = '" + filename + "'";
    // The boundary faces as vertex pairs, each vertex's two neighbours.
    std::map<unsigned int, std::vector<unsigned int>> neighbours;
    std::size_t                                       n_faces = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            neighbours[face->vertex_index(0)].push_back(face->vertex_index(1));
            neighbours[face->vertex_index(1)].push_back(face->vertex_index(0));
            ++n_faces;
          }
    const std::vector<Point<2>> &vertices = triangulation.get_vertices();
    for (const auto &[v, list] : neighbours)
      if (list.size() != 2)
        throw InputError(context + ": the section's boundary meets itself at "
                         + "(r = " + number(vertices[v][0], 6)
                         + ", z = " + number(vertices[v][1], 6)
                         + "); a section must be one region bounded by one "
                           "closed curve");
    // Walk the loop from its first vertex.
    std::vector<Point<2>> loop;
    const unsigned int    start    = neighbours.begin()->first;
    unsigned int          previous = start, current = neighbours[start][0];
    loop.push_back(vertices[start]);
    while (current != start && loop.size() <= n_faces)
      {
        loop.push_back(vertices[current]);
        const std::vector<unsigned int> &next = neighbours[current];
        const unsigned int following = next[0] == previous ? next[1] : next[0];
        previous                     = current;
        current                      = following;
      }
    if (loop.size() != n_faces)
      throw InputError(context + ": the section's boundary is "
                       + "not one closed curve (a hole, or pieces that do "
                         "not touch); a section must be one region without "
                         "holes");
    // Neighbours on one straight line merged (relative to the edges).
    std::vector<Point<2>> corners;
    const std::size_t     n = loop.size();
    for (std::size_t i = 0; i < n; ++i)
      {
        const Point<2> &a = loop[(i + n - 1) % n], &b = loop[i],
                       &c    = loop[(i + 1) % n];
        const Tensor<1, 2> u = b - a, w = c - b;
        if (std::abs(cross(u, w)) > 1e-10 * u.norm() * w.norm() || u * w < 0.)
          corners.push_back(b);
      }
    std::vector<OutlineCorner> points;
    for (const Point<2> &p : corners)
      points.push_back(OutlineCorner{p[1], 2. * p[0], 0.});
    points.push_back(points.front()); // closed explicitly
    return SectionOutline(points, entry);
  }
} // namespace coaxfit
