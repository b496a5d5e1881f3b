#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

#include <coaxfit/fe/displacement_postprocessor.h>
#include <coaxfit/solvers/plastic_body.h>

#include <cmath>

namespace coaxfit
{
  PlasticBody::PlasticBody(const BodyDiscretization &body,
                           const LoadPathParameters &load_path)
    : body(body)
    , load_path(load_path)
    , material(body.material())
    , may_yield(body.material().plastic)
  {}



  void
  PlasticBody::setup_system()
  {
    const DoFHandler<2>   &dof_handler = body.get_dof_handler();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    pattern.copy_from(dsp);
    tangent.reinit(pattern);
    eliminated.reinit(pattern);
    internal_force.reinit(dof_handler.n_dofs());
    current.reinit(dof_handler.n_dofs());
    committed_field.reinit(dof_handler.n_dofs());
    previous_committed_field.reinit(dof_handler.n_dofs());

    const QGauss<2> quadrature(dof_handler.get_fe().degree + 1);
    FEValues<2>     fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_quadrature_points);
    q_per_cell = quadrature.size();
    points.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          points.push_back(fe_values.quadrature_point(q));
      }
    committed.assign(points.size(), PlasticState());
    trial = committed;

    // The loads of operation: the thermal strain enters the return, the
    // rest are forces.
    BodyLoad forces       = body.load();
    thermal_strain        = forces.thermal_strain;
    forces.thermal_strain = 0.;
    operation_force       = body.assemble_load_vector(forces);
  }



  void
  PlasticBody::set_load_factor(const double factor)
  {
    if (factor != load_factor)
      tangent_factor_valid = false;
    load_factor = factor;
  }



  std::vector<bool>
  PlasticBody::fixed_dofs(const std::vector<bool> &prescribed) const
  {
    std::vector<bool> fixed(body.n_dofs(), false);
    for (unsigned int dof = 0; dof < body.n_dofs(); ++dof)
      fixed[dof] = body.get_constraints().is_constrained(dof);
    const auto &dofs = body.get_interface_dofs();
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (prescribed[i])
        fixed[dofs[i]] = true;
    return fixed;
  }



  bool
  PlasticBody::assemble_system()
  {
    const DoFHandler<2>                 &dof_handler = body.get_dof_handler();
    const FiniteElement<2>              &fe          = dof_handler.get_fe();
    const QGauss<2>                      quadrature(fe.degree + 1);
    FEValues<2>                          fe_values(fe,
                          quadrature,
                          update_values | update_gradients
                            | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_force(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<Axisymmetric::Vector4>   B(n);
    std::vector<Vector<double>>          values(q_per_cell, Vector<double>(2));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      q_per_cell, std::vector<Tensor<1, 2>>(2));
    const Tensor<1, 2> zero;

    tangent                  = 0;
    internal_force           = 0;
    bool         any_plastic = false;
    unsigned int point       = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(current, values);
        fe_values.get_function_gradients(current, gradients);
        cell_matrix = 0;
        cell_force  = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double r      = fe_values.quadrature_point(q)[0];
            const double weight = r * fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int component
                  = fe.system_to_component_index(i).first;
                const double        N    = fe_values.shape_value(i, q);
                const Tensor<1, 2> &grad = fe_values.shape_grad(i, q);
                B[i] = component == 0 ? Axisymmetric::strain(N, grad, zero, r) :
                                        Axisymmetric::strain(0., zero, grad, r);
              }
            Axisymmetric::Vector4 strain = Axisymmetric::strain(values[q][0],
                                                                gradients[q][0],
                                                                gradients[q][1],
                                                                r);
            for (unsigned int a = 0; a < 3; ++a)
              strain[a] -= load_factor * thermal_strain;
            // A body without plasticity answers elastically whatever its
            // stress (its state never changes).
            const PlasticMaterial::Response used
              = (may_yield && !elastic_only) ?
                  material.respond(strain, committed[point + q]) :
                  material.respond_elastic(strain);
            trial[point + q] = used.state;
            any_plastic      = any_plastic || used.plastic;
            for (unsigned int j = 0; j < n; ++j)
              {
                Axisymmetric::Vector4 DB{{0., 0., 0., 0.}};
                for (unsigned int a = 0; a < 4; ++a)
                  for (unsigned int b = 0; b < 4; ++b)
                    DB[a] += used.tangent[a][b] * B[j][b];
                for (unsigned int i = 0; i < n; ++i)
                  cell_matrix(i, j) += (B[i][0] * DB[0] + B[i][1] * DB[1]
                                        + B[i][2] * DB[2] + B[i][3] * DB[3])
                                       * weight;
              }
            for (unsigned int i = 0; i < n; ++i)
              cell_force(i)
                += (B[i][0] * used.stress[0] + B[i][1] * used.stress[1]
                    + B[i][2] * used.stress[2] + B[i][3] * used.stress[3])
                   * weight;
          }
        point += q_per_cell;
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < n; ++i)
          {
            internal_force(indices[i]) += cell_force(i);
            for (unsigned int j = 0; j < n; ++j)
              tangent.add(indices[i], indices[j], cell_matrix(i, j));
          }
      }
    return any_plastic;
  }



  void
  PlasticBody::eliminate(const std::vector<bool> &fixed)
  {
    eliminated.copy_from(tangent);
    for (unsigned int dof = 0; dof < fixed.size(); ++dof)
      if (fixed[dof])
        {
          const double diagonal = tangent.diag_element(dof);
          for (auto entry = eliminated.begin(dof); entry != eliminated.end(dof);
               ++entry)
            {
              entry->value() = 0.;
              eliminated.set(entry->column(), dof, 0.);
            }
          eliminated.set(dof, dof, diagonal > 0. ? diagonal : 1.);
        }
  }



  SparseDirectUMFPACK &
  PlasticBody::factorization(const std::vector<bool> &prescribed,
                             const bool               plastic)
  {
    // While nothing yields the tangent is the elastic stiffness: one
    // factorization per set of prescribed points, kept.
    if (!plastic)
      {
        auto &elastic = elastic_factors[prescribed];
        if (!elastic)
          {
            eliminate(fixed_dofs(prescribed));
            elastic = std::make_unique<SparseDirectUMFPACK>();
            elastic->initialize(eliminated);
            ++factorization_count;
          }
        return *elastic;
      }
    if (!tangent_factor_valid)
      {
        eliminate(fixed_dofs(prescribed));
        tangent_factor.initialize(eliminated);
        ++factorization_count;
        tangent_factor_valid = true;
      }
    return tangent_factor;
  }



  NewtonOutcome
  PlasticBody::solve(const std::vector<bool> &prescribed,
                     const Vector<double>    &displacement,
                     const Vector<double>    &force,
                     Vector<double>          &u_r,
                     Vector<double>          &force_out)
  {
    const auto             &dofs   = body.get_interface_dofs();
    const auto             &factor = body.interface_load_factor();
    const std::vector<bool> fixed  = fixed_dofs(prescribed);
    last_prescribed                = prescribed;
    tangent_factor_valid           = false;

    // The change of the prescribed displacements enters the first Newton
    // step through the tangent (a lifting), not as a jump of the joint's
    // nodes alone: a jump strains the joint's cells far beyond yield in
    // the first iterate (a new stage of the load path starts without an
    // extrapolation that would bring the field near).
    Vector<double> external(body.n_dofs()), lift(body.n_dofs());
    if (load_factor != 0.)
      external.add(load_factor, operation_force);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (!prescribed[i])
        external(dofs[i]) -= factor[i] * force[i];
      else
        lift(dofs[i]) = displacement[i] - current(dofs[i]);
    bool lifting = lift.linfty_norm() > 0.;

    NewtonOutcome  outcome;
    Vector<double> residual(body.n_dofs());
    double         last_step_norm = 0.;
    const auto    &z              = body.interface_z();
    const double   force_floor
      = z.empty() ? 0. :
                    1e-14 * body.material().E * body.interface_points()[0][0]
                      * std::max(1e-6 * z.back(), z.back() - z.front());
    for (unsigned int iteration = 0;; ++iteration)
      {
        const bool plastic = assemble_system();
        residual           = external;
        residual -= internal_force;
        if (lifting)
          {
            // The out-of-balance forces linearized about the prescribed
            // change: r - K du_p.
            Vector<double> lifted(body.n_dofs());
            tangent.vmult(lifted, lift);
            residual -= lifted;
          }
        double scale = external.l2_norm();
        {
          // The forces the body carries: its reactions at the fixed DoFs.
          double reactions = 0.;
          for (unsigned int dof = 0; dof < fixed.size(); ++dof)
            if (fixed[dof])
              {
                reactions += residual(dof) * residual(dof);
                residual(dof) = 0.;
              }
          scale += std::sqrt(reactions);
        }
        // A floor under the scale: the force of a strain of 1e-14 over the
        // body's joint (a body without load has no force to compare with).
        scale              = std::max(scale, force_floor);
        const double norm  = residual.l2_norm();
        outcome.iterations = iteration;
        outcome.residual   = scale > 0. ? norm / scale : norm;
        outcome.plastic    = plastic;
        last_plastic       = plastic;
        if (!std::isfinite(norm))
          return outcome;
        if (!lifting
            && (norm <= load_path.newton_tolerance * scale || norm == 0.))
          break;
        // Round-off: the last correction changed the field by less than
        // 1e-12 of itself (an ill-conditioned body, nu near 0.5 or a thin
        // wall, whose residual cannot go below the tolerance).
        if (!lifting && iteration > 0
            && last_step_norm <= 1e-12 * current.l2_norm())
          break;
        if (iteration >= load_path.max_newton_iterations)
          return outcome;

        Vector<double> step(residual);
        try
          {
            factorization(prescribed, plastic).solve(step);
          }
        catch (const SparseDirectUMFPACK::ExcUMFPACKError &)
          {
            // A tangent without stiffness in some direction (a perfectly
            // plastic body yielding through its wall at its limit load): a
            // failed solve, which the caller cuts, never an internal error.
            outcome.singular = true;
            return outcome;
          }
        if (lifting)
          {
            // The prescribed values reached exactly.
            step += lift;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (prescribed[i])
                step(dofs[i]) = displacement[i] - current(dofs[i]);
            lifting = false;
          }
        last_step_norm = step.l2_norm();
        ++newton_iterations;
        current += step;
        tangent_factor_valid = false;
      }

    outcome.converged = true;
    u_r.reinit(dofs.size());
    force_out.reinit(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        u_r[i] = current(dofs[i]);
        // The reaction (f_int - f) at a prescribed point is the load the
        // contact applies there: -c_i F_i.
        force_out[i]
          = prescribed[i] ?
              -factor[i] * (internal_force(dofs[i]) - external(dofs[i])) :
              force[i];
      }
    return outcome;
  }



  FullMatrix<double>
  PlasticBody::interface_stiffness()
  {
    // S = d F / d u on the prescribed points: the response of the body
    // with all fixed DoFs held to a unit displacement u_r of one prescribed
    // point, its reactions there (F_i = -c_i times the tangent's rows).
    const auto             &dofs   = body.get_interface_dofs();
    const auto             &factor = body.interface_load_factor();
    const std::vector<bool> fixed  = fixed_dofs(last_prescribed);
    SparseDirectUMFPACK &solver = factorization(last_prescribed, last_plastic);
    std::vector<unsigned int> held;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (last_prescribed[i])
        held.push_back(i);
    FullMatrix<double> stiffness(held.size(), held.size());
    Vector<double>     unit(body.n_dofs()), rhs(body.n_dofs()),
      response(body.n_dofs());
    for (unsigned int b = 0; b < held.size(); ++b)
      {
        unit                = 0;
        unit(dofs[held[b]]) = 1.;
        tangent.vmult(rhs, unit);
        rhs *= -1.;
        for (unsigned int dof = 0; dof < fixed.size(); ++dof)
          if (fixed[dof])
            rhs(dof) = 0.;
        solver.solve(rhs);
        rhs += unit;
        tangent.vmult(response, rhs);
        for (unsigned int a = 0; a < held.size(); ++a)
          stiffness(a, b) = -factor[held[a]] * response(dofs[held[a]]);
      }
    return stiffness;
  }



  void
  PlasticBody::commit()
  {
    committed                = trial;
    committed_factor         = load_factor;
    previous_committed_field = committed_field;
    committed_field          = current;
  }



  void
  PlasticBody::extrapolate(const double ratio)
  {
    current = committed_field;
    current.add(ratio, committed_field);
    current.add(-ratio, previous_committed_field);
  }



  void
  PlasticBody::scale_committed(const double factor)
  {
    committed_field *= factor;
    current                  = committed_field;
    previous_committed_field = 0;
  }



  double
  PlasticBody::max_yield_ratio() const
  {
    if (!may_yield)
      return 0.;
    const std::vector<Axisymmetric::Vector4> stresses = committed_stresses();
    double                                   ratio    = 0.;
    for (unsigned int i = 0; i < stresses.size(); ++i)
      ratio = std::max(ratio,
                       Axisymmetric::von_mises(stresses[i])
                         / material.yield_stress(
                           committed[i].equivalent_plastic_strain));
    return ratio;
  }



  void
  PlasticBody::revert()
  {
    trial   = committed;
    current = committed_field;
  }



  std::vector<Axisymmetric::Vector4>
  PlasticBody::committed_stresses() const
  {
    const DoFHandler<2>        &dof_handler = body.get_dof_handler();
    const QGauss<2>             quadrature(dof_handler.get_fe().degree + 1);
    FEValues<2>                 fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_values | update_gradients
                            | update_quadrature_points);
    std::vector<Vector<double>> values(q_per_cell, Vector<double>(2));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      q_per_cell, std::vector<Tensor<1, 2>>(2));
    std::vector<Axisymmetric::Vector4> stresses;
    stresses.reserve(points.size());
    unsigned int point = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(committed_field, values);
        fe_values.get_function_gradients(committed_field, gradients);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Axisymmetric::Vector4 strain
              = Axisymmetric::strain(values[q][0],
                                     gradients[q][0],
                                     gradients[q][1],
                                     fe_values.quadrature_point(q)[0]);
            // The committed state is the converged one of this field: the
            // elastic strain is strain - plastic strain.
            Axisymmetric::Vector4 elastic = strain;
            for (unsigned int a = 0; a < 3; ++a)
              elastic[a] -= committed[point + q].plastic_strain[a]
                            + committed_factor * thermal_strain;
            elastic[3] -= 2. * committed[point + q].plastic_strain[3];
            stresses.push_back(Axisymmetric::stress(body.material(), elastic));
          }
        point += q_per_cell;
      }
    return stresses;
  }



  void
  PlasticBody::output_results(std::ostream      &out,
                              const unsigned int body_id,
                              const double       oversize) const
  {
    const DoFHandler<2> &dof_handler                  = body.get_dof_handler();
    const std::vector<Axisymmetric::Vector4> stresses = committed_stresses();
    const unsigned int                       n_cells  = body.n_cells();
    std::vector<Vector<double>> cell_data(8, Vector<double>(n_cells));
    unsigned int                point = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        for (unsigned int q = 0; q < q_per_cell; ++q, ++point)
          {
            const Axisymmetric::Vector4 &s = stresses[point];
            for (unsigned int a = 0; a < 4; ++a)
              cell_data[a](c) += s[a] / q_per_cell;
            cell_data[4](c) += Axisymmetric::von_mises(s) / q_per_cell;
            cell_data[5](c)
              += committed[point].equivalent_plastic_strain / q_per_cell;
            cell_data[6](c)
              += (committed[point].equivalent_plastic_strain > 0. ? 1. : 0.)
                 / q_per_cell;
          }
        cell_data[7](c) = body_id;
      }

    AssembledDisplacement displacement("displacement_mm", oversize);
    DataOut<2>            data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(committed_field, displacement);
    const char *names[8] = {"sigma_rr_MPa",
                            "sigma_zz_MPa",
                            "sigma_tt_MPa",
                            "sigma_rz_MPa",
                            "von_Mises_MPa",
                            "equivalent_plastic_strain",
                            "plastic_fraction",
                            "body_id"};
    for (unsigned int k = 0; k < 8; ++k)
      data_out.add_data_vector(cell_data[k],
                               names[k],
                               DataOut<2>::type_cell_data);
    data_out.build_patches(dof_handler.get_fe().degree);
    data_out.write_vtu(out);
  }
} // namespace coaxfit
