#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/gmsh_transfer.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <gmsh.h>
#include <sstream>
#include <utility>

namespace coaxfit
{
  namespace
  {
    std::string
    where(const Point<2> &p)
    {
      return "(r = " + number(p[0], 6) + ", z = " + number(p[1], 6) + ")";
    }

    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    using Edge = std::pair<std::size_t, std::size_t>; // gmsh node tags

    Edge
    sorted(const std::size_t a, const std::size_t b)
    {
      return a < b ? Edge(a, b) : Edge(b, a);
    }
  } // namespace



  void
  transfer_gmsh_mesh(Triangulation<2>              &triangulation,
                     const std::map<int, CurveTag> &curves,
                     const std::map<types::manifold_id, Point<2>> &arc_centres,
                     const types::boundary_id                      untagged_id,
                     const std::string                            &context)
  {
    // Every node of the model, by gmsh tag.
    std::vector<std::size_t> node_tags;
    std::vector<double>      coordinates, parametric;
    gmsh::model::mesh::getNodes(node_tags,
                                coordinates,
                                parametric,
                                -1,
                                -1,
                                /*includeBoundary=*/true,
                                /*returnParametricCoord=*/false);
    std::map<std::size_t, Point<2>> nodes;
    double                          size = 0.;
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      {
        const Point<2> p(coordinates[3 * i], coordinates[3 * i + 1]);
        nodes[node_tags[i]] = p;
        size                = std::max({size, std::abs(p[0]), std::abs(p[1])});
      }
    const double tol = 1e-9 * size;
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      {
        const Point<2> &p = nodes[node_tags[i]];
        if (p[0] < -tol)
          throw InputError(context + ": a node at r = x = " + number(p[0], 6)
                           + " < 0; the section must lie in x = r >= 0");
        if (std::abs(coordinates[3 * i + 2]) > tol)
          throw InputError(context + ": a node at z-coordinate "
                           + number(coordinates[3 * i + 2], 6)
                           + "; the section must lie in the plane z = 0 (x = "
                             "r, y = axial position)");
      }

    // The 2D elements: first-order quadrilaterals only.
    std::vector<int>                      types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, -1);
    std::size_t              n_quads = 0, n_other = 0;
    std::vector<std::size_t> quads;
    std::string              other_name;
    for (unsigned int k = 0; k < types.size(); ++k)
      if (types[k] == 3)
        {
          n_quads += element_tags[k].size();
          quads = element_nodes[k];
        }
      else
        {
          n_other += element_tags[k].size();
          std::string         name;
          int                 dim, order, n_nodes, n_primary;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(
            types[k], name, dim, order, n_nodes, local, n_primary);
          other_name = name;
        }
    if (n_quads == 0 && n_other == 0)
      throw InputError(context
                       + ": no 2D mesh (no surface elements); a section needs "
                         "quadrilaterals (gmsh saves only the elements of "
                         "physical groups when there are any: add a Physical "
                         "Surface or set Mesh.SaveAll = 1)");
    if (n_other > 0)
      throw InputError(context + ": not all quadrilaterals: "
                       + std::to_string(n_other) + " elements of type '"
                       + other_name + "' beside " + std::to_string(n_quads)
                       + " first-order quadrilaterals; coaxfit needs a mesh of "
                         "first-order quadrilaterals only (recombined)");

    // deal.II's vertices: the nodes the quadrilaterals use.
    std::map<std::size_t, unsigned int> index;
    std::vector<Point<2>>               vertices;
    for (const std::size_t tag : quads)
      if (index.emplace(tag, vertices.size()).second)
        {
          if (nodes.count(tag) == 0)
            throw InputError(context + ": an element refers to node "
                             + std::to_string(tag) + ", which does not exist");
          vertices.push_back(nodes[tag]);
        }

    std::vector<CellData<2>> cells(n_quads);
    for (std::size_t c = 0; c < n_quads; ++c)
      {
        std::size_t q[4];
        for (unsigned int v = 0; v < 4; ++v)
          q[v] = quads[4 * c + v];
        const auto corner
          = [&](const unsigned int v) { return nodes[q[v % 4]]; };
        double signed_area = 0.;
        for (unsigned int v = 0; v < 4; ++v)
          signed_area += 0.5 * cross(corner(v), corner(v + 1));
        if (signed_area < 0.)
          std::swap(q[1], q[3]); // counter-clockwise
        double smallest = std::abs(signed_area);
        for (unsigned int v = 0; v < 4; ++v)
          smallest = std::min(smallest,
                              cross(corner(v + 1) - corner(v),
                                    corner(v + 2) - corner(v + 1)));
        if (!(smallest > 1e-12 * std::abs(signed_area)))
          throw InputError(context
                           + ": a degenerate or non-convex "
                             "quadrilateral near "
                           + where(corner(0)) + "; the mesh cannot be used");
        // gmsh goes round the cell, deal.II numbers it lexicographically.
        cells[c].vertices
          = {index[q[0]], index[q[1]], index[q[3]], index[q[2]]};
      }
    GridTools::consistently_order_cells(cells);
    try
      {
        triangulation.create_triangulation(vertices, cells, SubCellData());
      }
    catch (const std::exception &exc)
      {
        throw InputError(
          context + ": deal.II cannot use the mesh: " + one_line_message(exc));
      }

    // Boundary and manifold ids from the gmsh curves the faces lie on.
    std::map<Edge, CurveTag> boundary_lines;
    for (const auto &[tag, curve] : curves)
      {
        std::vector<int>                      line_types;
        std::vector<std::vector<std::size_t>> line_tags, line_nodes;
        gmsh::model::mesh::getElements(
          line_types, line_tags, line_nodes, 1, tag);
        for (unsigned int k = 0; k < line_types.size(); ++k)
          if (line_types[k] == 1)
            for (std::size_t l = 0; l + 1 < line_nodes[k].size(); l += 2)
              boundary_lines[sorted(line_nodes[k][l], line_nodes[k][l + 1])]
                = curve;
      }
    std::vector<std::size_t> tag_of(vertices.size());
    for (const auto &[tag, i] : index)
      tag_of[i] = tag;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const auto line
              = boundary_lines.find(sorted(tag_of[face->vertex_index(0)],
                                           tag_of[face->vertex_index(1)]));
            if (line != boundary_lines.end())
              {
                face->set_boundary_id(line->second.boundary_id);
                face->set_manifold_id(line->second.manifold_id);
              }
            else if (std::abs(face->vertex(0)[0]) <= tol
                     && std::abs(face->vertex(1)[0]) <= tol)
              face->set_boundary_id(BoundaryId::axis);
            else
              face->set_boundary_id(untagged_id);
          }
    for (const auto &[id, centre] : arc_centres)
      triangulation.set_manifold(id, PolarManifold<2>(centre));
  }
} // namespace coaxfit
