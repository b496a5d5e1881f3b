#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/stack_monolithic_solver.h>
#include <coaxfit/coupling/tied_pattern.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  StackMonolithicSolver::StackMonolithicSolver(
    const std::vector<const BodyDiscretization *> &bodies,
    const std::vector<StackJoint>                 &joints,
    const bool                                     unilateral)
    : bodies(bodies)
    , joints(joints)
    , unilateral(unilateral)
    , offset(bodies.size() + 1, 0)
    , rotated(bodies.size())
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (bodies[b]->curved_joint())
          throw InputError("the monolithic solver of a stack takes "
                           "cylindrical joints only (body "
                           + bodies[b]->name() + ")");
        offset[b + 1] = offset[b] + bodies[b]->n_dofs();
      }
  }



  unsigned int
  StackMonolithicSolver::joint_dof(const unsigned int b,
                                   const unsigned int k,
                                   const unsigned int i) const
  {
    // Body k + 1's bore points come first; body k's outer points follow
    // its own bore points.
    const unsigned int at = b == k ? bodies[b]->n_inner_interface_points() : 0;
    return offset[b] + bodies[b]->get_interface_dofs()[at + i];
  }



  AffineConstraints<double>
  StackMonolithicSolver::tie_constraints(
    const std::vector<std::vector<bool>> &tied) const
  {
    AffineConstraints<double> constraints;
    for (unsigned int k = 0; k < joints.size(); ++k)
      for (unsigned int i = 0; i < joints[k].n_points(); ++i)
        if (tied[k][i])
          {
            const unsigned int line = joint_dof(k + 1, k, i);
            constraints.add_line(line);
            constraints.add_entry(line, joint_dof(k, k, i), 1.);
            constraints.set_inhomogeneity(line, joints[k].interference_at(i));
          }
    constraints.close();
    return constraints;
  }



  void
  StackMonolithicSolver::setup_pattern()
  {
    // The condensed matrix of any active set has its entries among those
    // of the bodies' stiffness matrices side by side, each row and column
    // kept or (a tied point) moved to the inner body's DoF: the union of
    // the patterns of all active sets.
    std::vector<std::vector<bool>> all;
    for (const StackJoint &joint : joints)
      all.emplace_back(joint.n_points(), true);
    const AffineConstraints<double> all_tied = tie_constraints(all);
    DynamicSparsityPattern          dsp(offset.back(), offset.back());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      add_tied_pattern(dsp,
                       bodies[b]->stiffness_in_interface_frame(rotated[b]),
                       offset[b],
                       all_tied);
    pattern.copy_from(dsp);
    cholesky.analyze(SparseMatrix<double>(pattern));
  }



  void
  StackMonolithicSolver::solve_tied(const std::vector<std::vector<bool>> &tied,
                                    std::vector<Vector<double>>          &force,
                                    std::vector<Vector<double>>          &gap)
  {
    if (pattern.empty())
      setup_pattern();
    const AffineConstraints<double> constraints = tie_constraints(tied);
    SparseMatrix<double>            matrix(pattern);
    Vector<double>                  x(offset.back());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const SparseMatrix<double> &K
          = bodies[b]->stiffness_in_interface_frame(rotated[b]);
        for (unsigned int row = 0; row < K.m(); ++row)
          for (auto e = K.begin(row); e != K.end(row); ++e)
            matrix.set(offset[b] + row, offset[b] + e->column(), e->value());
      }
    constraints.condense(matrix, x);
    cholesky.solve(*cholesky.factorize(matrix), x);
    ++factorizations;
    constraints.distribute(x);

    // Each body's u_r and reaction at its points.
    std::vector<Vector<double>> u(bodies.size()), reaction(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        Vector<double> x_b(bodies[b]->n_dofs());
        for (unsigned int i = 0; i < x_b.size(); ++i)
          x_b[i] = x[offset[b] + i];
        const unsigned int n = bodies[b]->n_interface_points();
        bodies[b]->interface_values(std::vector<bool>(n, true),
                                    Vector<double>(n),
                                    x_b,
                                    u[b],
                                    reaction[b]);
      }
    force.assign(joints.size(), Vector<double>());
    gap.assign(joints.size(), Vector<double>());
    double largest = 0., difference = 0.;
    for (unsigned int k = 0; k < joints.size(); ++k)
      {
        const unsigned int n  = joints[k].n_points();
        const unsigned int at = bodies[k]->n_inner_interface_points();
        force[k].reinit(n);
        gap[k].reinit(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            force[k][i] = reaction[k][at + i];
            gap[k][i]
              = u[k + 1][i] - u[k][at + i] - joints[k].interference_at(i);
            const double w = joints[k].weights[i];
            if (w <= 0.)
              continue;
            largest = std::max(largest, std::abs(force[k][i]) / w);
            difference
              = std::max(difference,
                         std::abs(force[k][i] - reaction[k + 1][i]) / w);
          }
      }
    mismatch = largest > 0. ? difference / largest : 0.;
  }



  StackState
  StackMonolithicSolver::solve(unsigned int &active_set_steps)
  {
    std::vector<std::vector<bool>> tied;
    unsigned int                   n     = 0;
    double                         scale = 0.;
    for (const StackJoint &joint : joints)
      {
        tied.emplace_back(joint.n_points(), true);
        n += joint.n_points();
        scale = std::max(scale, joint.largest_interference());
      }
    if (scale <= 0.)
      scale = 1.;
    std::vector<Vector<double>> force, gap;
    for (active_set_steps = 1;; ++active_set_steps)
      {
        solve_tied(tied, force, gap);
        for (unsigned int k = 0; k < joints.size(); ++k)
          for (unsigned int i = 0; i < joints[k].n_points(); ++i)
            if (!tied[k][i])
              force[k][i] = 0.; // a released point carries no force
        if (!unilateral)
          break;
        bool changed = false;
        for (unsigned int k = 0; k < joints.size(); ++k)
          for (unsigned int i = 0; i < joints[k].n_points(); ++i)
            {
              const bool in
                = tied[k][i] ? force[k][i] >= 0. : gap[k][i] < -1e-12 * scale;
              changed    = changed || in != tied[k][i];
              tied[k][i] = in;
            }
        if (!changed)
          break;
        if (active_set_steps >= 4 * n + 10)
          throw SolverError("the active set of the stack's monolithic "
                            "solve on the full operators did not settle");
      }
    StackState state;
    state.force   = force;
    state.contact = tied;
    return state;
  }
} // namespace coaxfit
