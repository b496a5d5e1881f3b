#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/monolithic_solver.h>
#include <coaxfit/coupling/tied_pattern.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace coaxfit
{
  MonolithicSolver::MonolithicSolver(const Scene               &scene,
                                     const ContactInterface    &interface,
                                     const UnilateralActiveSet &active_set,
                                     const unsigned int         max_steps)
    : InterfaceSolver(active_set)
    , shaft(*scene.inner(scene.joint()).discretization)
    , hub(*scene.outer(scene.joint()).discretization)
    , interface(interface)
    , max_steps(max_steps)
  {
    if (scene.has_transfer())
      {
        this->scene       = &scene;
        transfer_matrix   = scene.joint_transfer().matrix();
        hub_is_point_side = scene.point_body() == scene.joint().outer;
        // M = D^{-1} R is full, but its entries decay geometrically away
        // from each point's faces (D is banded): those below 1e-14 of a
        // row's largest are dropped, so that the ties stay local and the
        // factorization sparse (all of them made every tied row couple to
        // every joint DoF of the other body: 29 s instead of 2.3 s on a
        // rounded bore edge's 337 points).
        for (unsigned int i = 0; i < transfer_matrix.m(); ++i)
          {
            double largest = 0.;
            for (unsigned int j = 0; j < transfer_matrix.n(); ++j)
              largest = std::max(largest, std::abs(transfer_matrix(i, j)));
            for (unsigned int j = 0; j < transfer_matrix.n(); ++j)
              if (std::abs(transfer_matrix(i, j)) < 1e-14 * largest)
                transfer_matrix(i, j) = 0.;
          }
      }
  }



  void
  MonolithicSolver::setup_pattern()
  {
    // The condensed matrix of any active set has its entries among those
    // of the two stiffness matrices side by side with each row and each
    // column either kept or (tied point) moved to the shaft's DoF: the
    // union of the patterns of all active sets.
    const SparseMatrix<double> &K1
      = shaft.stiffness_in_interface_frame(shaft_rotated);
    const SparseMatrix<double> &K2
      = hub.stiffness_in_interface_frame(hub_rotated);
    const unsigned int              n1 = K1.m(), n = K1.m() + K2.m();
    const AffineConstraints<double> all_tied = tie_constraints(
      std::vector<bool>(shaft.get_interface_dofs().size(), true));
    DynamicSparsityPattern dsp(n, n);
    add_tied_pattern(dsp, K1, 0, all_tied);
    add_tied_pattern(dsp, K2, n1, all_tied);
    pattern.copy_from(dsp);
    cholesky.analyze(SparseMatrix<double>(pattern));
  }



  AffineConstraints<double>
  MonolithicSolver::tie_constraints(const std::vector<bool> &tied) const
  {
    const unsigned int        n1    = shaft.n_dofs();
    const auto               &dofs1 = shaft.get_interface_dofs();
    const auto               &dofs2 = hub.get_interface_dofs();
    AffineConstraints<double> constraints;
    if (scene == nullptr)
      for (unsigned int i = 0; i < dofs1.size(); ++i)
        {
          if (!tied[i])
            continue;
          constraints.add_line(n1 + dofs2[i]);
          constraints.add_entry(n1 + dofs2[i], dofs1[i], 1.);
          constraints.set_inhomogeneity(n1 + dofs2[i],
                                        interface.interference(i));
        }
    else
      // u_hub = M u_shaft + d at the hub's points, or u_shaft = M u_hub - d
      // at the shaft's.
      for (unsigned int i = 0; i < transfer_matrix.m(); ++i)
        {
          if (!tied[i])
            continue;
          const auto line = hub_is_point_side ? n1 + dofs2[i] : dofs1[i];
          constraints.add_line(line);
          for (unsigned int j = 0; j < transfer_matrix.n(); ++j)
            if (transfer_matrix(i, j) != 0.)
              constraints.add_entry(line,
                                    hub_is_point_side ? dofs1[j] :
                                                        n1 + dofs2[j],
                                    transfer_matrix(i, j));
          constraints.set_inhomogeneity(line,
                                        hub_is_point_side ?
                                          interface.interference(i) :
                                          -interface.interference(i));
        }
    constraints.close();
    return constraints;
  }



  void
  MonolithicSolver::solve_tied()
  {
    const SparseMatrix<double> &K1
      = shaft.stiffness_in_interface_frame(shaft_rotated);
    const SparseMatrix<double> &K2
      = hub.stiffness_in_interface_frame(hub_rotated);
    const unsigned int n1 = K1.m(), n = K1.m() + K2.m();
    const auto        &dofs1 = shaft.get_interface_dofs();

    if (pattern.empty())
      setup_pattern();

    // u2 = u1 + d_i at every tied point, as an inhomogeneous constraint on
    // the hub's DoF there.
    const AffineConstraints<double> constraints
      = tie_constraints(active_set.in_contact());
    SparseMatrix<double> matrix(pattern);
    Vector<double>       rhs(n);
    for (unsigned int row = 0; row < K1.m(); ++row)
      for (auto e = K1.begin(row); e != K1.end(row); ++e)
        matrix.set(row, e->column(), e->value());
    for (unsigned int row = 0; row < K2.m(); ++row)
      for (auto e = K2.begin(row); e != K2.end(row); ++e)
        matrix.set(n1 + row, n1 + e->column(), e->value());
    constraints.condense(matrix, rhs);

    cholesky.solve(*cholesky.factorize(matrix), rhs);
    ++factorizations;
    constraints.distribute(rhs);

    Vector<double> x1(K1.m()), x2(K2.m());
    for (unsigned int i = 0; i < K1.m(); ++i)
      x1[i] = rhs[i];
    for (unsigned int i = 0; i < K2.m(); ++i)
      x2[i] = rhs[n1 + i];
    shaft.from_interface_frame(x1);
    hub.from_interface_frame(x2);
    shaft_field = x1;
    hub_field   = x2;

    // Contact force from the shaft's reaction (row of K1 u1); the hub's
    // reaction must be the same force (checked as the traction mismatch).
    if (scene == nullptr)
      {
        const std::vector<bool> all(dofs1.size(), true);
        const Vector<double>    no_force(dofs1.size());
        Vector<double>          hub_force;
        shaft.interface_values(all, no_force, x1, state.u1, state.force);
        hub.interface_values(all, no_force, x2, state.u2, hub_force);
        const double magnitude = std::max(interface.max_pressure(state.force),
                                          interface.max_pressure(hub_force));
        state.traction_mismatch
          = magnitude > 0. ?
              interface.max_pressure_difference(state.force, hub_force)
                / magnitude :
              0.;
        return;
      }
    // Non-matching: the point side's reaction is the contact force; the
    // other side's own reaction must be M^T of it (checked, in pressures
    // on that side's points).
    const BodyDiscretization &P  = hub_is_point_side ? hub : shaft;
    const BodyDiscretization &A  = hub_is_point_side ? shaft : hub;
    const Vector<double>     &xP = hub_is_point_side ? x2 : x1;
    const Vector<double>     &xA = hub_is_point_side ? x1 : x2;
    Vector<double>            uP, uA_own, forceA;
    P.interface_values(std::vector<bool>(P.n_interface_points(), true),
                       Vector<double>(P.n_interface_points()),
                       xP,
                       uP,
                       state.force);
    A.interface_values(std::vector<bool>(A.n_interface_points(), true),
                       Vector<double>(A.n_interface_points()),
                       xA,
                       uA_own,
                       forceA);
    const unsigned int   a        = scene->mortar_body();
    const Vector<double> uA       = scene->joint_values(a, uA_own);
    const Vector<double> expected = scene->body_forces(a, state.force);
    state.u1                      = hub_is_point_side ? uA : uP;
    state.u2                      = hub_is_point_side ? uP : uA;
    double largest = 0., difference = 0.;
    for (unsigned int j = 0; j < expected.size(); ++j)
      {
        const double w = A.interface_weights()[j];
        if (w <= 0.)
          continue;
        largest = std::max(largest, std::abs(expected[j]) / w);
        difference
          = std::max(difference, std::abs(forceA[j] - expected[j]) / w);
      }
    state.traction_mismatch = largest > 0. ? difference / largest : 0.;
  }



  bool
  MonolithicSolver::run(std::ostream *progress)
  {
    history_rows.clear();
    has_converged = false;
    if (progress)
      *progress << "  monolithic solve  |du|/d      |dp|/p      separated\n";
    for (unsigned int step = 1; step <= max_steps; ++step)
      {
        solve_tied();
        state.displacement_mismatch
          = interface.relative_gap_residual(state.u1,
                                            state.u2,
                                            active_set.in_contact());
        // Released points carry no force: the reaction there is zero.
        for (unsigned int i = 0; i < state.force.size(); ++i)
          if (!active_set.in_contact()[i])
            state.force[i] = 0.;
        const bool changed
          = active_set.update(state.force, interface.gap(state.u1, state.u2));
        history_rows.push_back({step,
                                true,
                                0.,
                                state.displacement_mismatch,
                                state.traction_mismatch,
                                active_set.n_separated()});
        if (progress)
          *progress << std::setw(6) << step << "            " << std::scientific
                    << std::setprecision(3) << state.displacement_mismatch
                    << "   " << state.traction_mismatch << "   " << std::setw(4)
                    << active_set.n_separated() << std::endl;
        if (!changed)
          {
            has_converged = true;
            break;
          }
      }
    return has_converged;
  }



  std::pair<Vector<double>, Vector<double>>
  MonolithicSolver::solve_fields()
  {
    return {shaft_field, hub_field};
  }



  SolverStatistics
  MonolithicSolver::statistics() const
  {
    SolverStatistics s;
    s.method         = "monolithic";
    s.factorizations = {{"coupled", factorizations}};
    return s;
  }
} // namespace coaxfit
