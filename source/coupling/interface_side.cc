#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <coaxfit/coupling/interface_side.h>
#include <coaxfit/fe/mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  namespace
  {
    /** A face of the boundary part as the mesh gives it, not yet oriented. */
    struct RawFace
    {
      /**
       * Its nodes in FE_Q's face numbering: vertex 0, vertex 1, then the
       * interior support points from vertex 0 to vertex 1.
       */
      std::vector<std::array<types::global_dof_index, 2>> dofs;
      std::vector<Point<2>>                               points;
      Tensor<1, 2>                                        normal;
    };



    /** The faces of @p boundary_id on @p dof_handler, in any order. */
    std::vector<RawFace>
    collect_faces(const DoFHandler<2>     &dof_handler,
                  const types::boundary_id boundary_id)
    {
      const FiniteElement<2> &fe          = dof_handler.get_fe();
      const unsigned int      p           = fe.degree;
      const auto             &unit_points = fe.get_unit_face_support_points();
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      std::vector<RawFace>                 faces;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary()
              && cell->face(f)->boundary_id() == boundary_id)
            {
              const auto face = cell->face(f);
              face->get_dof_indices(face_dofs);
              RawFace raw;
              raw.dofs.resize(p + 1);
              raw.points.resize(p + 1);
              raw.normal = outward_normal(cell, f);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const auto [component, node]
                    = fe.face_system_to_component_index(i);
                  raw.dofs[node][component] = face_dofs[i];
                  raw.points[node]
                    = face->vertex(0)
                      + unit_points[i][0] * (face->vertex(1) - face->vertex(0));
                }
              faces.push_back(raw);
            }
      return faces;
    }



    /** Check that @p fe is FE_Q(p)^2 and return p. */
    unsigned int
    trace_degree(const FiniteElement<2> &fe)
    {
      const auto *system = dynamic_cast<const FESystem<2> *>(&fe);
      if (system == nullptr || fe.n_components() != 2
          || system->n_base_elements() != 1
          || dynamic_cast<const FE_Q<2> *>(&system->base_element(0)) == nullptr)
        throw std::logic_error("InterfaceSide: the element is not "
                               "FESystem(FE_Q(p)^2) but "
                               + fe.get_name());
      return fe.degree;
    }
  } // namespace



  InterfaceSide::InterfaceSide(const DoFHandler<2>     &dof_handler,
                               const types::boundary_id boundary_id)
    : p(trace_degree(dof_handler.get_fe()))
    , weighted_area(0.)
  {
    const std::string where = "InterfaceSide: the faces of boundary id "
                              + std::to_string(boundary_id);
    const std::vector<RawFace> faces = collect_faces(dof_handler, boundary_id);
    if (faces.empty())
      throw std::logic_error(where + " do not exist");

    // The face parameters of the nodes: FE_Q's support points on [0, 1].
    for (const Point<1> &t :
         dof_handler.get_fe().base_element(0).get_unit_face_support_points())
      node_parameters.push_back(t[0]);
    std::sort(node_parameters.begin(), node_parameters.end());

    // The chain's ends are the vertex nodes (keyed by their r DoF) in one
    // face; every other vertex node is in two.
    std::map<types::global_dof_index, std::vector<unsigned int>> at_vertex;
    double                                                       size = 0.;
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int v = 0; v < 2; ++v)
        {
          at_vertex[faces[f].dofs[v][0]].push_back(f);
          size = std::max(size, faces[f].points[v].norm());
          size
            = std::max(size, faces[f].points[0].distance(faces[f].points[1]));
        }
    std::vector<std::pair<unsigned int, unsigned int>> ends; // (face, vertex)
    for (const auto &[dof, adjacent] : at_vertex)
      {
        if (adjacent.size() > 2)
          throw std::logic_error(where + " branch: a vertex joins "
                                 + std::to_string(adjacent.size()) + " faces");
        if (adjacent.size() == 1)
          ends.emplace_back(adjacent[0],
                            faces[adjacent[0]].dofs[0][0] == dof ? 0 : 1);
      }
    if (ends.size() != 2)
      throw std::logic_error(where + " do not form one open chain ("
                             + std::to_string(ends.size()) + " ends)");

    // Start at the end of smaller z, of smaller r if both have the same z.
    const Point<2> a         = faces[ends[0].first].points[ends[0].second];
    const Point<2> b         = faces[ends[1].first].points[ends[1].second];
    const double   tolerance = 1e-10 * size;
    const bool     b_first
      = std::abs(a[1] - b[1]) > tolerance ? b[1] < a[1] : b[0] < a[0];
    const auto [first_face, first_vertex] = b_first ? ends[1] : ends[0];

    // Walk along the chain, appending each face's nodes in curve order.
    std::vector<bool> visited(faces.size(), false);
    unsigned int      face = first_face, vertex = first_vertex;
    node_points.push_back(faces[face].points[vertex]);
    node_dofs.push_back(faces[face].dofs[vertex]);
    while (true)
      {
        visited[face]          = true;
        const RawFace     &raw = faces[face];
        const unsigned int e   = 1 - vertex; // the vertex it leaves by
        Face               chain_face;
        chain_face.nodes.push_back(node_points.size() - 1);
        // The interior nodes (2, ..., p in FE_Q's numbering) from the entry
        // vertex on.
        std::vector<unsigned int> interior;
        for (unsigned int k = 2; k <= p; ++k)
          interior.push_back(k);
        std::sort(interior.begin(),
                  interior.end(),
                  [&](const unsigned int i, const unsigned int j) {
                    return raw.points[i].distance(raw.points[vertex])
                           < raw.points[j].distance(raw.points[vertex]);
                  });
        for (const unsigned int node : interior)
          {
            chain_face.nodes.push_back(node_points.size());
            node_points.push_back(raw.points[node]);
            node_dofs.push_back(raw.dofs[node]);
          }
        chain_face.nodes.push_back(node_points.size());
        node_points.push_back(raw.points[e]);
        node_dofs.push_back(raw.dofs[e]);
        chain_face.start  = raw.points[vertex];
        chain_face.end    = raw.points[e];
        chain_face.normal = raw.normal;
        chain_face.length = chain_face.start.distance(chain_face.end);
        chain.push_back(chain_face);

        const auto &next = at_vertex[raw.dofs[e][0]];
        if (next.size() == 1)
          break;
        face   = next[0] == face ? next[1] : next[0];
        vertex = faces[face].dofs[0][0] == raw.dofs[e][0] ? 0 : 1;
      }
    if (chain.size() != faces.size())
      throw std::logic_error(where + " do not form one open chain ("
                             + std::to_string(faces.size() - chain.size())
                             + " faces apart from it)");

    // Normals, arc lengths and lumped weights, face by face.
    const unsigned int n = node_points.size();
    node_normals.assign(n, Tensor<1, 2>());
    node_arc_length.assign(n, 0.);
    lumped_weights.reinit(n);
    const QGauss<1> quadrature(p + 1); // N_i r: degree p + 1
    for (unsigned int f = 0; f < chain.size(); ++f)
      {
        const Face  &cf = chain[f];
        const double s0 = node_arc_length[cf.nodes.front()];
        for (unsigned int j = 0; j <= p; ++j)
          {
            const unsigned int i = cf.nodes[j];
            if (j > 0)
              node_arc_length[i] = s0 + node_parameters[j] * cf.length;
            if (j == 0 && f > 0)
              {
                // Shared with the previous face: the mean direction.
                if ((node_normals[i] - cf.normal).norm() > 1e-12)
                  {
                    node_normals[i] += cf.normal;
                    node_normals[i] /= node_normals[i].norm();
                  }
              }
            else
              node_normals[i] = cf.normal;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double t = quadrature.point(q)[0];
                lumped_weights[i] += shape_value(j, t) * cf.point(t)[0]
                                     * cf.length * quadrature.weight(q);
              }
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      weighted_area += lumped_weights[i];
  }



  double
  InterfaceSide::shape_value(const unsigned int j, const double t) const
  {
    AssertIndexRange(j, p + 1);
    double value = 1.;
    for (unsigned int m = 0; m <= p; ++m)
      if (m != j)
        value *= (t - node_parameters[m])
                 / (node_parameters[j] - node_parameters[m]);
    return value;
  }



  Vector<double>
  InterfaceSide::normal_component(const Vector<double> &solution) const
  {
    Vector<double> u_n(n_nodes());
    for (unsigned int i = 0; i < n_nodes(); ++i)
      u_n[i] = solution[node_dofs[i][0]] * node_normals[i][0]
               + solution[node_dofs[i][1]] * node_normals[i][1];
    return u_n;
  }
} // namespace coaxfit
