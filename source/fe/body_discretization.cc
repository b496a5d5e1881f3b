#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/fe/displacement_postprocessor.h>
#include <coaxfit/fe/stress_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  BodyDiscretization::BodyDiscretization(
    const std::string  &name,
    const BodyGeometry &geometry,
    const Material     &material,
    const unsigned int  degree,
    const bool          reduced_volumetric_integration,
    const BodyLoad     &load)
    : body_name(name)
    , body_geometry(geometry)
    , body_material(material)
    , reduced_volumetric_integration(reduced_volumetric_integration)
    , body_load(load)
    , fe(FE_Q<2>(degree), 2)
    , dof_handler(triangulation)
  {}



  void
  BodyDiscretization::setup_system()
  {
    if (mesh_builder)
      mesh_builder(triangulation);
    else
      make_body_mesh(triangulation, body_geometry);
    dof_handler.distribute_dofs(fe);
    collect_interface_points();

    constraints.clear();
    const FEValuesExtractors::Scalar u_r(0), u_z(1);
    // A section's mesh carries the axis id where it touches r = 0.
    if (body_geometry.r_inner == 0. || mesh_builder)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               BoundaryId::axis,
                                               Functions::ZeroFunction<2>(2),
                                               constraints,
                                               fe.component_mask(u_r));
    VectorTools::interpolate_boundary_values(dof_handler,
                                             BoundaryId::symmetry,
                                             Functions::ZeroFunction<2>(2),
                                             constraints,
                                             fe.component_mask(u_z));
    // A held end face (a taper fit's supports): u_z = 0 on it, but at its
    // corner on the joint, whose displacement the joint's normal frame
    // describes (a contact node is free along the joint).
    bool has_held_face = false;
    {
      const std::set<types::global_dof_index> on_joint(
        interface_axial_dofs.begin(), interface_axial_dofs.end());
      const IndexSet held
        = DoFTools::extract_boundary_dofs(dof_handler,
                                          fe.component_mask(u_z),
                                          {BoundaryId::held});
      for (const auto dof : held)
        if (on_joint.count(dof) == 0 && !constraints.is_constrained(dof))
          constraints.add_line(dof);
      has_held_face = held.n_elements() > 0;
    }
    // Without a symmetry plane or a held face (a whole section on a
    // cylinder) nothing fixes the axial rigid motion: u_z = 0 at the joint
    // node nearest the joint's middle (or set_axial_pin_z()). A frictionless
    // cylindrical joint passes no axial force, so this reaction is zero and the
    // stresses do not depend on the choice.
    axial_pin = numbers::invalid_dof_index;
    if (mesh_builder && !interface_z_coordinates.empty() && !has_held_face)
      {
        bool has_plane = false;
        for (const auto &face : triangulation.active_face_iterators())
          has_plane = has_plane
                      || (face->at_boundary()
                          && face->boundary_id() == BoundaryId::symmetry);
        if (!has_plane)
          {
            const double middle = axial_pin_z ?
                                    *axial_pin_z :
                                    0.5
                                      * (interface_z_coordinates.front()
                                         + interface_z_coordinates.back());
            unsigned int best   = 0;
            for (unsigned int i = 1; i < interface_z_coordinates.size(); ++i)
              if (std::abs(interface_z_coordinates[i] - middle)
                  < std::abs(interface_z_coordinates[best] - middle))
                best = i;
            axial_pin = interface_axial_dofs[best];
            constraints.add_line(axial_pin);
          }
      }
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
  }



  void
  BodyDiscretization::collect_interface_points()
  {
    std::map<types::global_dof_index, Point<2>> support_points;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         dof_handler,
                                         support_points);
    // The DoFs of one component on S, ordered by z (u_r and u_z share
    // their support points, so both lists name the same points); a ring
    // in a stack has the points of its bore's joint first.
    const auto on_contact
      = [&](const unsigned int component, const types::boundary_id id) {
          const IndexSet dofs = DoFTools::extract_boundary_dofs(
            dof_handler,
            fe.component_mask(FEValuesExtractors::Scalar(component)),
            {id});
          std::vector<std::pair<double, types::global_dof_index>> by_z;
          for (const auto dof : dofs)
            by_z.emplace_back(support_points[dof][1], dof);
          std::sort(by_z.begin(), by_z.end());
          return by_z;
        };
    auto radial          = on_contact(0, BoundaryId::inner_joint);
    auto axial           = on_contact(1, BoundaryId::inner_joint);
    n_inner_joint_points = radial.size();
    {
      const auto outer_radial = on_contact(0, BoundaryId::joint);
      const auto outer_axial  = on_contact(1, BoundaryId::joint);
      radial.insert(radial.end(), outer_radial.begin(), outer_radial.end());
      axial.insert(axial.end(), outer_axial.begin(), outer_axial.end());
    }
    AssertThrow(radial.size() == axial.size(),
                ExcMessage("u_r and u_z differ in points on S"));
    interface_dofs.clear();
    interface_axial_dofs.clear();
    interface_z_coordinates.clear();
    points.clear();
    for (unsigned int i = 0; i < radial.size(); ++i)
      {
        interface_z_coordinates.push_back(radial[i].first);
        points.push_back(support_points[radial[i].second]);
        interface_dofs.push_back(radial[i].second);
        interface_axial_dofs.push_back(axial[i].second);
      }
    weights.reinit(interface_dofs.size());
  }



  void
  BodyDiscretization::assemble_system()
  {
    const QGauss<2> quadrature(fe.degree + 1);
    const QGauss<2> reduced_quadrature(fe.degree);
    const auto      flags = update_values | update_gradients
                       | update_quadrature_points | update_JxW_values;
    FEValues<2>        fe_values(fe, quadrature, flags);
    FEValues<2>        reduced_values(fe, reduced_quadrature, flags);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    std::vector<Axisymmetric::Vector4>   B(dofs_per_cell);
    // Selective reduced integration: the full rule sees a material without
    // lambda (same mu), the reduced rule adds lambda tr(e_i) tr(e_j).
    const Material full_rule_material = reduced_volumetric_integration ?
                                          body_material.without_lambda() :
                                          body_material;

    // The strain of every shape function at quadrature point q.
    const auto shape_strains
      = [&](const FEValues<2> &values, const unsigned int q) {
          const double r = values.quadrature_point(q)[0];
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              const unsigned int comp = fe.system_to_component_index(i).first;
              const double       N    = values.shape_value(i, q);
              const Tensor<1, 2> grad = values.shape_grad(i, q);
              const Tensor<1, 2> zero;
              B[i] = (comp == 0) ? Axisymmetric::strain(N, grad, zero, r) :
                                   Axisymmetric::strain(0., zero, grad, r);
            }
          return r * values.JxW(q);
        };

    stiffness_matrix = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_matrix = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double weight = shape_strains(fe_values, q);
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              {
                const Axisymmetric::Vector4 sigma_j
                  = Axisymmetric::stress(full_rule_material, B[j]);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  cell_matrix(i, j)
                    += (B[i][0] * sigma_j[0] + B[i][1] * sigma_j[1]
                        + B[i][2] * sigma_j[2] + B[i][3] * sigma_j[3])
                       * weight;
              }
          }
        if (reduced_volumetric_integration)
          {
            reduced_values.reinit(cell);
            const double lambda = body_material.lambda();
            for (const unsigned int q :
                 reduced_values.quadrature_point_indices())
              {
                const double weight = shape_strains(reduced_values, q);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) += lambda * Axisymmetric::trace(B[i])
                                         * Axisymmetric::trace(B[j]) * weight;
              }
          }
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_matrix,
                                               local_dof_indices,
                                               stiffness_matrix);
      }
    assemble_interface_weights();
  }



  Vector<double>
  BodyDiscretization::assemble_load_vector(const BodyLoad &load) const
  {
    const QGauss<2> quadrature(fe.degree + 1);
    const QGauss<2> reduced_quadrature(fe.degree);
    const QGauss<1> face_quadrature(fe.degree + 1);
    const auto      flags = update_values | update_gradients
                       | update_quadrature_points | update_JxW_values;
    FEValues<2>        fe_values(fe, quadrature, flags);
    FEValues<2>        reduced_values(fe, reduced_quadrature, flags);
    FEFaceValues<2>    face_values(fe,
                                face_quadrature,
                                update_values | update_quadrature_points
                                  | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>     cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    const bool     reduced = reduced_volumetric_integration;
    const Material full_rule_material
      = reduced ? body_material.without_lambda() : body_material;
    const double e_th = load.thermal_strain;
    // The eigenstress C e_th (1, 1, 1, 0); with reduced integration its
    // lambda part 3 lambda e_th goes with the reduced rule.
    const Axisymmetric::Vector4 thermal_stress
      = Axisymmetric::stress(full_rule_material, {{e_th, e_th, e_th, 0.}});
    // rho omega^2 in N/mm^4: kg/m^3 -> 1e-9 kg/mm^3, kg mm/s^2 = 1e-3 N.
    const double centrifugal
      = 1e-12 * body_material.density * load.omega_squared;
    // The pressure on a free face, selected by its boundary id: the bore
    // carries inner_pressure, the outer surface outer_pressure (the
    // traction -p n along the outward normal n); nothing else is loaded.
    const auto face_pressure = [&](const auto &face) {
      if (!face->at_boundary())
        return 0.;
      if (face->boundary_id() == BoundaryId::bore)
        return load.inner_pressure;
      if (face->boundary_id() == BoundaryId::outer)
        return load.outer_pressure;
      const auto named = load.face_pressures.find(face->boundary_id());
      return named == load.face_pressures.end() ? 0. : named->second;
    };

    Vector<double> rhs(n_dofs());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_rhs = 0;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double r      = fe_values.quadrature_point(q)[0];
            const double weight = r * fe_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const unsigned int comp = fe.system_to_component_index(i).first;
                const double       N    = fe_values.shape_value(i, q);
                const Tensor<1, 2> grad = fe_values.shape_grad(i, q);
                const Tensor<1, 2> zero;
                const Axisymmetric::Vector4 B
                  = (comp == 0) ? Axisymmetric::strain(N, grad, zero, r) :
                                  Axisymmetric::strain(0., zero, grad, r);
                double value = 0.;
                for (unsigned int c = 0; c < 4; ++c)
                  value += B[c] * thermal_stress[c];
                if (comp == 0)
                  value += N * centrifugal * r;
                cell_rhs[i] += value * weight;
              }
          }
        if (reduced && e_th != 0.)
          {
            reduced_values.reinit(cell);
            const double volumetric = 3. * body_material.lambda() * e_th;
            for (const unsigned int q :
                 reduced_values.quadrature_point_indices())
              {
                const double r = reduced_values.quadrature_point(q)[0];
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const unsigned int comp
                      = fe.system_to_component_index(i).first;
                    const Tensor<1, 2>          zero;
                    const Axisymmetric::Vector4 B
                      = (comp == 0) ?
                          Axisymmetric::strain(reduced_values.shape_value(i, q),
                                               reduced_values.shape_grad(i, q),
                                               zero,
                                               r) :
                          Axisymmetric::strain(0.,
                                               zero,
                                               reduced_values.shape_grad(i, q),
                                               r);
                    cell_rhs[i] += volumetric * Axisymmetric::trace(B) * r
                                   * reduced_values.JxW(q);
                  }
              }
          }
        for (const auto &face : cell->face_iterators())
          {
            const double pressure = face_pressure(face);
            if (pressure == 0.)
              continue;
            face_values.reinit(cell, face);
            const Tensor<1, 2> n
              = outward_normal(cell, cell->face_iterator_to_index(face));
            for (const unsigned int q : face_values.quadrature_point_indices())
              {
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const unsigned int c
                      = fe.system_to_component_index(i).first;
                    if (n[c] != 0.)
                      cell_rhs[i] += -pressure * n[c]
                                     * face_values.shape_value(i, q)
                                     * face_values.quadrature_point(q)[0]
                                     * face_values.JxW(q);
                  }
              }
          }
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_rhs,
                                               local_dof_indices,
                                               rhs);
      }
    return rhs;
  }



  void
  BodyDiscretization::assemble_interface_weights()
  {
    const QGauss<1>                      face_quadrature(fe.degree + 1);
    FEFaceValues<2>                      fe_face_values(fe,
                                   face_quadrature,
                                   update_values | update_quadrature_points
                                     | update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    std::map<types::global_dof_index, unsigned int> interface_index;
    for (unsigned int i = 0; i < interface_dofs.size(); ++i)
      interface_index[interface_dofs[i]] = i;

    weights = 0;
    // The outward normal at each point: that of its faces (straight faces:
    // constant along the face); where two faces of different direction
    // meet, their mean.
    normals.assign(interface_dofs.size(), Tensor<1, 2>());
    std::vector<unsigned int> n_faces(interface_dofs.size(), 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary()
            && (face->boundary_id() == BoundaryId::joint
                || face->boundary_id() == BoundaryId::inner_joint))
          {
            cell->get_dof_indices(local_dof_indices);
            fe_face_values.reinit(cell, face);
            const Tensor<1, 2> face_normal
              = outward_normal(cell, cell->face_iterator_to_index(face));
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const auto point = interface_index.find(local_dof_indices[i]);
                if (point == interface_index.end())
                  continue;
                Tensor<1, 2> &n = normals[point->second];
                if (n_faces[point->second]++ == 0)
                  n = face_normal;
                else if ((n - face_normal).norm() > 1e-12)
                  {
                    n += face_normal;
                    n /= n.norm();
                  }
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  weights[point->second]
                    += fe_face_values.shape_value(i, q)
                       * fe_face_values.quadrature_point(q)[0]
                       * fe_face_values.JxW(q);
              }
          }
    // The interface value of a point is the displacement along the
    // joint's normal pointing out of the shaft (u_r on a cylinder). A joint
    // not on a cylinder (a cone) is solved in that frame (BodySolver).
    // A curved chain (a joint that goes on over a fillet) keeps the radial
    // frame: gap and force are radial there, which the contact on a
    // fillet's flat beginning needs (its slope is small where it touches;
    // its steep part never closes).
    frame.resize(normals.size());
    load_factor.resize(normals.size());
    rotated     = false;
    curved      = false;
    double side = 0.;
    // (A ring in a stack: each of its two joints on its own.)
    for (unsigned int i = 0; i < normals.size(); ++i)
      {
        const unsigned int first
          = i < n_inner_joint_points ? 0 : n_inner_joint_points;
        side += normals[i][0];
        curved = curved || (normals[i] - normals[first]).norm() > 1e-9;
      }
    for (unsigned int i = 0; i < normals.size(); ++i)
      {
        if (curved)
          {
            frame[i]       = Tensor<1, 2>({1., 0.});
            load_factor[i] = side > 0. ? 1. : -1.;
            continue;
          }
        if (!(normals[i][0] > 0.05 || normals[i][0] < -0.05))
          throw std::logic_error("the joint of a body runs along its radius "
                                 "(a face): not modelled");
        frame[i] = normals[i][0] > 0. ? normals[i] : -normals[i];
        rotated  = rotated || std::abs(frame[i][1]) > 1e-12;
      }
    // The interface DoF's share of a contact force: n_r = +-1 on a
    // cylinder, +-1 along the frame's normal on a cone.
    if (!curved)
      for (unsigned int i = 0; i < normals.size(); ++i)
        load_factor[i]
          = rotated ? (normals[i][0] > 0. ? 1. : -1.) : normals[i][0];
    if (rotated)
      for (const auto dof : interface_dofs)
        if (constraints.is_constrained(dof))
          throw std::logic_error("a constrained joint node on a cone");
  }



  void
  BodyDiscretization::to_interface_frame(Vector<double> &v) const
  {
    if (!rotated)
      return;
    for (unsigned int i = 0; i < frame.size(); ++i)
      {
        const double a = v[interface_dofs[i]], b = v[interface_axial_dofs[i]];
        v[interface_dofs[i]]       = frame[i][0] * a + frame[i][1] * b;
        v[interface_axial_dofs[i]] = -frame[i][1] * a + frame[i][0] * b;
      }
  }



  void
  BodyDiscretization::from_interface_frame(Vector<double> &v) const
  {
    if (!rotated)
      return;
    for (unsigned int i = 0; i < frame.size(); ++i)
      {
        const double n = v[interface_dofs[i]], t = v[interface_axial_dofs[i]];
        v[interface_dofs[i]]       = frame[i][0] * n - frame[i][1] * t;
        v[interface_axial_dofs[i]] = frame[i][1] * n + frame[i][0] * t;
      }
  }



  const SparseMatrix<double> &
  BodyDiscretization::stiffness_in_interface_frame(
    SparseMatrix<double> &storage) const
  {
    if (!rotated)
      return stiffness_matrix;
    if (storage.empty())
      {
        storage.reinit(sparsity_pattern);
        storage.copy_from(stiffness_matrix);
        to_interface_frame(storage);
      }
    return storage;
  }



  void
  BodyDiscretization::to_interface_frame(SparseMatrix<double> &K) const
  {
    if (!rotated)
      return;
    // K' = R^T K R with R the rotation of each joint node's (u_r, u_z)
    // into (u_n, u_t): rows first (R^T K), then columns. Both DoFs of a
    // node couple with the same DoFs (FESystem), so every entry exists.
    const SparsityPattern &pattern = K.get_sparsity_pattern();
    const auto             check   = [&](const types::global_dof_index i,
                           const types::global_dof_index j) {
      if (!pattern.exists(i, j))
        throw std::logic_error("the joint frame needs the entry ("
                               + std::to_string(i) + ", " + std::to_string(j)
                               + ") of the sparsity pattern");
    };
    for (unsigned int i = 0; i < frame.size(); ++i)
      {
        const auto   a = interface_dofs[i], b = interface_axial_dofs[i];
        const double c = frame[i][0], s = frame[i][1];
        for (auto entry = K.begin(a); entry != K.end(a); ++entry)
          {
            const auto j = entry->column();
            check(b, j);
            const double ka = entry->value(), kb = K(b, j);
            entry->value() = c * ka + s * kb;
            K.set(b, j, -s * ka + c * kb);
          }
      }
    for (unsigned int i = 0; i < frame.size(); ++i)
      {
        const auto   a = interface_dofs[i], b = interface_axial_dofs[i];
        const double c = frame[i][0], s = frame[i][1];
        for (auto entry = K.begin(a); entry != K.end(a); ++entry)
          {
            // The pattern is symmetric: the rows k with an entry in column
            // a are the columns of row a.
            const auto k = entry->column();
            check(k, a);
            check(k, b);
            const double ka = K(k, a), kb = K(k, b);
            K.set(k, a, c * ka + s * kb);
            K.set(k, b, -s * ka + c * kb);
          }
      }
  }



  void
  BodyDiscretization::interface_values(const std::vector<bool> &prescribed,
                                       const Vector<double>    &force,
                                       const Vector<double>    &solution,
                                       Vector<double>          &u_r,
                                       Vector<double>          &force_out) const
  {
    const auto &dofs = interface_dofs;

    // Reactions: the rows of K u - f (f = 0 at a prescribed point).
    Vector<double> residual(n_dofs());
    stiffness_matrix.residual(residual, solution, Vector<double>(n_dofs()));
    u_r.reinit(dofs.size());
    force_out.reinit(dofs.size());
    const Vector<double> u_n = interface_radial_values(solution);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        u_r[i] = u_n[i];
        force_out[i]
          = !prescribed[i] ? force[i] :
            rotated        ? normals[i][0] * residual[dofs[i]]
                        + normals[i][1] * residual[interface_axial_dofs[i]] :
                      load_factor[i] * residual[dofs[i]];
      }
  }



  void
  BodyDiscretization::volumetric_field(const Vector<double> &solution,
                                       DoFHandler<2>        &dof_handler_out,
                                       Vector<double>       &field) const
  {
    const FESystem<2> fe_out(FE_Q<2>(fe.degree),
                             2,
                             FE_DGQArbitraryNodes<2>(QGauss<1>(fe.degree)),
                             1);
    dof_handler_out.distribute_dofs(fe_out);
    field.reinit(dof_handler_out.n_dofs());
    const QGauss<2> reduced(fe.degree);
    FEValues<2>     values(
      fe, reduced, update_values | update_gradients | update_quadrature_points);
    std::vector<Vector<double>>            u(reduced.size(), Vector<double>(2));
    std::vector<std::vector<Tensor<1, 2>>> grad(reduced.size(),
                                                std::vector<Tensor<1, 2>>(2));
    std::vector<types::global_dof_index>   dofs(fe.n_dofs_per_cell()),
      dofs_out(fe_out.n_dofs_per_cell());
    // The reduced point at each node of the volumetric element.
    std::vector<unsigned int> point_of_node;
    for (const Point<2> &node :
         fe_out.base_element(1).get_unit_support_points())
      {
        unsigned int q = 0;
        for (unsigned int k = 1; k < reduced.size(); ++k)
          if (reduced.point(k).distance(node) < reduced.point(q).distance(node))
            q = k;
        point_of_node.push_back(q);
      }
    auto cell_out = dof_handler_out.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values.get_function_values(solution, u);
        values.get_function_gradients(solution, grad);
        cell->get_dof_indices(dofs);
        cell_out->get_dof_indices(dofs_out);
        for (unsigned int i = 0; i < fe_out.n_dofs_per_cell(); ++i)
          {
            const auto base = fe_out.system_to_base_index(i);
            if (base.first.first == 0) // displacement component
              field[dofs_out[i]]
                = solution[dofs[fe.component_to_system_index(base.first.second,
                                                             base.second)]];
            else
              {
                const unsigned int          q = point_of_node[base.second];
                const Axisymmetric::Vector4 e
                  = Axisymmetric::strain(u[q][0],
                                         grad[q][0],
                                         grad[q][1],
                                         values.quadrature_point(q)[0]);
                field[dofs_out[i]]
                  = body_material.lambda()
                    * Axisymmetric::trace(
                      Axisymmetric::mechanical(e, body_load.thermal_strain));
              }
          }
        ++cell_out;
      }
  }



  void
  BodyDiscretization::output_results(const Vector<double> &solution,
                                     std::ostream         &out,
                                     const unsigned int    body_id,
                                     const double          oversize,
                                     const double          offset) const
  {
    for (const double value : solution)
      if (!std::isfinite(value))
        throw std::runtime_error("the displacement to be written is not "
                                 "finite");
    DoFHandler<2>  dof_handler_out(triangulation);
    Vector<double> field;
    if (reduced_volumetric_integration)
      volumetric_field(solution, dof_handler_out, field);

    const AssembledDisplacement assembled("displacement_mm", oversize, offset);
    const StressPostprocessor   stresses(body_material,
                                       reduced_volumetric_integration,
                                       body_load.thermal_strain);
    DataOut<2>                  data_out;
    std::vector<std::string>    names(2, "elastic_displacement_mm");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(2,
                     DataComponentInterpretation::component_is_part_of_vector);
    if (reduced_volumetric_integration)
      {
        names.emplace_back("volumetric_stress_MPa");
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    const DoFHandler<2> &handler
      = reduced_volumetric_integration ? dof_handler_out : dof_handler;
    const Vector<double> &data
      = reduced_volumetric_integration ? field : solution;
    data_out.attach_dof_handler(handler);
    // The assembled displacement first: ParaView's Warp By Vector takes the
    // first vector array.
    data_out.add_data_vector(data, assembled);
    data_out.add_data_vector(data,
                             names,
                             DataOut<2>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(data, stresses);
    Vector<float> body(triangulation.n_active_cells());
    body = static_cast<float>(body_id);
    data_out.add_data_vector(body, "body_id", DataOut<2>::type_cell_data);
    data_out.build_patches(fe.degree);

    DataOutBase::VtkFlags flags;
    flags.print_date_and_time = false;
    flags.compression_level   = DataOutBase::VtkFlags::best_speed;
    // The unit is the last part of every name written (body_id has none).
    std::vector<std::string> written = stresses.get_names();
    written.insert(written.end(), names.begin(), names.end());
    written.push_back(assembled.get_names()[0]);
    for (const std::string &name : written)
      flags.physical_units[name] = name.substr(name.rfind('_') + 1);
    data_out.set_flags(flags);
    data_out.write_vtu(out);
  }
} // namespace coaxfit
