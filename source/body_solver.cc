#include <coaxfit/body_solver.h>

namespace coaxfit
{
  BodySolver::BodySolver(const BodyDiscretization &body)
    : body(body)
  {}



  const SparseCholesky::Factor &
  BodySolver::factorization(const std::vector<bool> &prescribed)
  {
    return factorizations.get(prescribed, [&]() {
      // K with the rows and columns of the prescribed points eliminated
      // symmetrically; the diagonal entries stay.
      const auto          &dofs = body.get_interface_dofs();
      SparseMatrix<double> matrix(body.get_sparsity_pattern());
      matrix.copy_from(body.get_stiffness_matrix());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        if (prescribed[i])
          for (auto entry = matrix.begin(dofs[i]); entry != matrix.end(dofs[i]);
               ++entry)
            if (entry->column() != dofs[i])
              {
                matrix.set(entry->column(), dofs[i], 0.);
                entry->value() = 0.;
              }
      if (!analyzed)
        {
          // The interface points last: the compliance is then the inverse
          // of the trailing block of the factor (interface_compliance()).
          cholesky.analyze(matrix, dofs);
          analyzed = true;
        }
      return cholesky.factorize(matrix);
    });
  }



  void
  BodySolver::factorize(const std::vector<bool> &prescribed)
  {
    factorization(prescribed);
  }



  Vector<double>
  BodySolver::solve_field(const std::vector<bool> &prescribed,
                          const Vector<double>    &displacement,
                          const Vector<double>    &force)
  {
    const auto                 &dofs   = body.get_interface_dofs();
    const SparseMatrix<double> &K      = body.get_stiffness_matrix();
    const double                normal = body.geometry().contact_normal();
    AssertDimension(prescribed.size(), dofs.size());

    // Contact forces act against the outward normal; prescribed points
    // are lifted and eliminated symmetrically.
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
        rhs[dofs[i]] = -normal * force[i];
    if (any_prescribed)
      {
        Vector<double> K_lift(body.n_dofs());
        K.vmult(K_lift, lift);
        rhs -= K_lift;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (prescribed[i])
            rhs[dofs[i]] = K.diag_element(dofs[i]) * displacement[i];
      }

    cholesky.solve(factorization(prescribed), rhs);
    ++solve_count;
    body.get_constraints().distribute(rhs);
    return rhs;
  }



  Vector<double>
  BodySolver::solve_load_field(const Vector<double> &load)
  {
    AssertDimension(load.size(), body.n_dofs());
    Vector<double> field(load);
    cholesky.solve(factorization(
                     std::vector<bool>(body.n_interface_points(), false)),
                   field);
    ++solve_count;
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
    const std::vector<bool> none(body.n_interface_points(), false);
    cholesky.trailing_inverse(factorization(none), compliance);
    // A unit contact force at point j is the load -normal e_j.
    compliance *= -body.geometry().contact_normal();
  }
} // namespace coaxfit
