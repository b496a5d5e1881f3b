#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/solvers/body_solver.h>

#include <iomanip>
#include <sstream>

namespace coaxfit
{
  BodySolver::BodySolver(const BodyDiscretization &body, const bool amg)
    : body(body)
    , amg(amg)
  {}



  SparseMatrix<double>
  BodySolver::eliminated_matrix(const std::vector<bool> &prescribed)
  {
    // K with the rows and columns of the prescribed points eliminated
    // symmetrically; the diagonal entries stay.
    const auto          &dofs = body.get_interface_dofs();
    SparseMatrix<double> matrix(body.get_sparsity_pattern());
    matrix.copy_from(stiffness());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (prescribed[i])
        for (auto entry = matrix.begin(dofs[i]); entry != matrix.end(dofs[i]);
             ++entry)
          if (entry->column() != dofs[i])
            {
              matrix.set(entry->column(), dofs[i], 0.);
              entry->value() = 0.;
            }
    return matrix;
  }



  const SparseCholesky::Factor &
  BodySolver::factorization(const std::vector<bool> &prescribed)
  {
    return factorizations.get(prescribed, [&]() {
      const SparseMatrix<double> matrix = eliminated_matrix(prescribed);
      if (!analyzed)
        {
          // The interface points last: the compliance is then the inverse
          // of the trailing block of the factor (interface_compliance()).
          cholesky.analyze(matrix, body.get_interface_dofs());
          analyzed = true;
        }
      return cholesky.factorize(matrix);
    });
  }



  const BodySolver::AmgSystem &
  BodySolver::amg_system(const std::vector<bool> &prescribed)
  {
    return amg_systems.get(prescribed, [&]() {
      auto system = std::make_unique<AmgSystem>();
      system->matrix.reinit(eliminated_matrix(prescribed));
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = body.get_dof_handler().get_fe().degree > 1;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      DoFTools::extract_constant_modes(body.get_dof_handler(),
                                       ComponentMask(2, true),
                                       data.constant_modes);
      system->preconditioner.initialize(system->matrix, data);
      return system;
    });
  }



  void
  BodySolver::solve_system(const std::vector<bool> &prescribed,
                           Vector<double>          &rhs)
  {
    if (!amg)
      {
        cholesky.solve(factorization(prescribed), rhs);
        return;
      }
    const AmgSystem &system = amg_system(prescribed);
    const double     norm   = rhs.l2_norm();
    if (norm == 0.)
      return; // the answer to no load is no displacement
    // Relative residual 1e-12: the coupling's mismatches (1e-8 by
    // default) are then not limited by the body solves. Where the AMG
    // preconditioner serves the mesh, CG takes 150-460 iterations (the
    // graded meshes of benchmarks/README.md); 2000 bounds a failure to
    // seconds instead of minutes.
    constexpr unsigned int   max_iterations = 2000;
    SolverControl            control(max_iterations, 1e-12 * norm);
    SolverCG<Vector<double>> cg(control);
    Vector<double>           solution(rhs.size());
    try
      {
        cg.solve(system.matrix, solution, rhs, system.preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << std::setprecision(2)
                << "Solver/Linear solver = amg: conjugate gradients with "
                   "the AMG preconditioner did not reach the relative "
                   "residual 1e-12 on the body "
                << body.name() << " in " << e.last_step
                << " iterations (reached " << e.last_residual / norm
                << "); this mesh (thin walls, cells of large aspect ratio) "
                   "is beyond what the AMG path serves: use Solver/Linear "
                   "solver = direct, or Axial/Radial cells closer to the "
                   "proportions of the walls";
        throw SolverError(message.str());
      }
    cg_iterations += control.last_step();
    rhs.swap(solution);
  }



  void
  BodySolver::factorize(const std::vector<bool> &prescribed)
  {
    if (amg)
      amg_system(prescribed);
    else
      factorization(prescribed);
  }



  Vector<double>
  BodySolver::solve_field(const std::vector<bool> &prescribed,
                          const Vector<double>    &displacement,
                          const Vector<double>    &force)
  {
    const auto                 &dofs = body.get_interface_dofs();
    const SparseMatrix<double> &K    = stiffness();
    AssertDimension(prescribed.size(), dofs.size());

    // Contact forces act against the outward normal (their share on the
    // interface DoF: BodyDiscretization::interface_load_factor()); prescribed
    // points are lifted and eliminated symmetrically.
    Vector<double> rhs(body.n_dofs());
    Vector<double> lift(body.n_dofs());
    bool           any_prescribed = false;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (prescribed[i])
        {
          lift[dofs[i]]  = displacement[i];
          any_prescribed = true;
        }
      else
        rhs[dofs[i]] = -body.interface_load_factor()[i] * force[i];
    if (any_prescribed)
      {
        Vector<double> K_lift(body.n_dofs());
        K.vmult(K_lift, lift);
        rhs -= K_lift;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (prescribed[i])
            rhs[dofs[i]] = K.diag_element(dofs[i]) * displacement[i];
      }

    solve_system(prescribed, rhs);
    ++solve_count;
    body.from_interface_frame(rhs);
    body.get_constraints().distribute(rhs);
    return rhs;
  }



  Vector<double>
  BodySolver::solve_load_field(const Vector<double> &load)
  {
    AssertDimension(load.size(), body.n_dofs());
    Vector<double> field(load);
    body.to_interface_frame(field);
    solve_system(std::vector<bool>(body.n_interface_points(), false), field);
    ++solve_count;
    body.from_interface_frame(field);
    body.get_constraints().distribute(field);
    return field;
  }



  void
  BodySolver::solve(const std::vector<bool> &prescribed,
                    const Vector<double>    &displacement,
                    const Vector<double>    &force,
                    Vector<double>          &u_r,
                    Vector<double>          &force_out)
  {
    body.interface_values(prescribed,
                          force,
                          solve_field(prescribed, displacement, force),
                          u_r,
                          force_out);
  }



  void
  BodySolver::interface_compliance(FullMatrix<double> &compliance)
  {
    AssertThrow(!amg,
                ExcMessage("the interface compliance needs the direct "
                           "solver (Solver/Linear solver = direct)"));
    const std::vector<bool> none(body.n_interface_points(), false);
    cholesky.trailing_inverse(factorization(none), compliance);
    // A unit contact force at point j is the load -n_j e_j (n_j = +-e_r),
    // in the joint's frame -+1 along its DoF.
    for (unsigned int i = 0; i < compliance.m(); ++i)
      for (unsigned int j = 0; j < compliance.n(); ++j)
        compliance(i, j) *= -body.interface_load_factor()[j];
  }



  const SparseMatrix<double> &
  BodySolver::stiffness()
  {
    return body.stiffness_in_interface_frame(rotated_stiffness);
  }
} // namespace coaxfit
