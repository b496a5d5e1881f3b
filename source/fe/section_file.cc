#include <deal.II/grid/manifold_lib.h>

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
                    const unsigned int global_refinements,
                    const bool         joint_required)
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
    if (std::filesystem::is_directory(filename))
      throw InputError(context + ": is a directory, not a gmsh file");
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
      if (joint_required && names.count("joint") == 0)
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



  std::string
  resolved_section_file(const std::string &text,
                        const std::string &parameter_file,
                        const std::string &entry)
  {
    // A parameter file's comments begin at '#': the written parameters.prm
    // could not repeat such a path.
    if (text.find('#') != std::string::npos)
      throw InputError("parameter " + entry + " = '" + trimmed(text)
                       + "': a section file's name may not contain '#' (it "
                         "begins a comment in a parameter file); rename it");
    const std::filesystem::path given = trimmed(text);
    return std::filesystem::absolute(
             given.is_absolute() ?
               given :
               std::filesystem::path(parameter_file).parent_path() / given)
      .lexically_normal()
      .string();
  }



  bool
  is_section_file_name(const std::string &text)
  {
    std::string word = trimmed(text);
    if (word.empty() || text.find(';') != std::string::npos)
      return false;
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
    // The boundary faces as vertex pairs, each vertex's two neighbours,
    // and the manifold of each face.
    std::map<unsigned int, std::vector<unsigned int>> neighbours;
    std::map<std::pair<unsigned int, unsigned int>, types::manifold_id>
                face_manifold;
    std::size_t n_faces = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const unsigned int a = face->vertex_index(0),
                               b = face->vertex_index(1);
            neighbours[a].push_back(b);
            neighbours[b].push_back(a);
            face_manifold[{std::min(a, b), std::max(a, b)}]
              = face->manifold_id();
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
    std::vector<unsigned int> loop;
    const unsigned int        start    = neighbours.begin()->first;
    unsigned int              previous = start, current = neighbours[start][0];
    loop.push_back(start);
    while (current != start && loop.size() <= n_faces)
      {
        loop.push_back(current);
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
    const std::size_t n        = loop.size();
    const auto        manifold = [&](const std::size_t i) {
      const unsigned int a = loop[i % n], b = loop[(i + 1) % n];
      return face_manifold.at({std::min(a, b), std::max(a, b)});
    };
    // Start at a straight face that follows a face on another manifold (or
    // anywhere if the boundary has no arc), so that no arc wraps round.
    std::size_t first = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (manifold(i) == numbers::flat_manifold_id
          && manifold(i + n - 1) != numbers::flat_manifold_id)
        {
          first = i;
          break;
        }
    std::rotate(loop.begin(), loop.begin() + first, loop.end());

    // Pieces: straight faces, and arcs (consecutive faces on one manifold).
    struct Piece
    {
      std::vector<Point<2>> points; ///< from start to end
      types::manifold_id    manifold;
    };
    std::vector<Piece> pieces;
    for (std::size_t i = 0; i < n; ++i)
      {
        const types::manifold_id m = manifold(i);
        if (m != numbers::flat_manifold_id && !pieces.empty()
            && pieces.back().manifold == m)
          pieces.back().points.push_back(vertices[loop[(i + 1) % n]]);
        else
          pieces.push_back(
            {{vertices[loop[i]], vertices[loop[(i + 1) % n]]}, m});
      }
    // An arc tangent to the straight pieces on both sides is a fillet: its
    // corner is where their lines meet. Any other arc stays as its chords.
    const std::size_t     k = pieces.size();
    std::vector<double>   fillet(k, 0.);
    std::vector<Point<2>> corner(k);
    for (std::size_t j = 0; j < k; ++j)
      {
        const Piece &arc = pieces[j], &before = pieces[(j + k - 1) % k],
                    &after = pieces[(j + 1) % k];
        if (arc.manifold == numbers::flat_manifold_id
            || before.manifold != numbers::flat_manifold_id
            || after.manifold != numbers::flat_manifold_id)
          continue;
        const auto *polar = dynamic_cast<const PolarManifold<2> *>(
          &triangulation.get_manifold(arc.manifold));
        if (polar == nullptr)
          continue;
        const Point<2>    &p = arc.points.front(), &q = arc.points.back();
        const double       R = p.distance(polar->center);
        const Tensor<1, 2> t_in
          = (before.points.back() - before.points.front())
            / before.points.front().distance(before.points.back());
        const Tensor<1, 2> t_out
          = (after.points.back() - after.points.front())
            / after.points.front().distance(after.points.back());
        const double turn = cross(t_in, t_out);
        if (std::abs((p - polar->center) * t_in) > 1e-6 * R
            || std::abs((q - polar->center) * t_out) > 1e-6 * R
            || std::abs(turn) < 1e-6)
          continue;
        // p + s t_in = q - u t_out.
        const double s = cross(q - p, t_out) / turn;
        corner[j]      = p + s * t_in;
        fillet[j]      = R;
      }
    std::vector<OutlineCorner> points;
    for (std::size_t j = 0; j < k; ++j)
      {
        if (fillet[j] > 0.)
          {
            points.push_back({corner[j][1], 2. * corner[j][0], fillet[j]});
            continue;
          }
        // A straight piece after a fillet starts at its tangent point,
        // which the fillet's corner replaces.
        const std::size_t from = fillet[(j + k - 1) % k] > 0. ? 1 : 0;
        for (std::size_t i = from; i + 1 < pieces[j].points.size(); ++i)
          points.push_back(
            {pieces[j].points[i][1], 2. * pieces[j].points[i][0], 0.});
      }
    // Sharp corners on one straight line with their neighbours merged.
    std::vector<OutlineCorner> merged;
    const std::size_t          m = points.size();
    for (std::size_t i = 0; i < m; ++i)
      {
        const OutlineCorner &a = points[(i + m - 1) % m], &b = points[i],
                            &c = points[(i + 1) % m];
        const Tensor<1, 2> u({b.diameter - a.diameter, b.z - a.z}),
          w({c.diameter - b.diameter, c.z - b.z});
        if (b.fillet_radius > 0.
            || std::abs(cross(u, w)) > 1e-10 * u.norm() * w.norm()
            || u * w < 0.)
          merged.push_back(b);
      }
    merged.push_back(merged.front()); // closed explicitly
    return SectionOutline(merged, entry);
  }

} // namespace coaxfit
