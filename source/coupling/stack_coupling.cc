#include <deal.II/base/thread_management.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/accelerator.h>
#include <coaxfit/coupling/stack_coupling.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>

namespace coaxfit
{
  Vector<double>
  StackState::pressure(const std::vector<StackJoint> &joints,
                       const unsigned int             k) const
  {
    Vector<double> p(force[k]);
    for (unsigned int i = 0; i < p.size(); ++i)
      p[i] /= joints[k].weights[i];
    return p;
  }



  StackLayout::StackLayout(const std::vector<StackJoint> &joints)
    : n_joints(joints.size())
  {
    for (const StackJoint &joint : joints)
      sizes.push_back(joint.n_points());
  }



  unsigned int
  StackLayout::n_points(const unsigned int b) const
  {
    return (b > 0 ? sizes[b - 1] : 0) + (b < n_joints ? sizes[b] : 0);
  }



  namespace
  {
    /** The concatenation of @p parts. */
    Vector<double>
    concatenated(const std::vector<Vector<double>> &parts)
    {
      std::size_t n = 0;
      for (const auto &p : parts)
        n += p.size();
      Vector<double> all(n);
      std::size_t    at = 0;
      for (const auto &p : parts)
        for (unsigned int i = 0; i < p.size(); ++i)
          all[at++] = p[i];
      return all;
    }

    /** @p all cut into the sizes of @p parts. */
    void
    split(const Vector<double> &all, std::vector<Vector<double>> &parts)
    {
      std::size_t at = 0;
      for (auto &p : parts)
        for (unsigned int i = 0; i < p.size(); ++i)
          p[i] = all[at++];
    }

    /** The accelerator of @p parameters. */
    std::unique_ptr<Accelerator>
    make_accelerator(const StackParameters &parameters)
    {
      switch (parameters.accelerator)
        {
          case StackAccelerator::none:
            return std::make_unique<NoAcceleration>();
          case StackAccelerator::aitken:
            return std::make_unique<AitkenAcceleration>(1.0);
          case StackAccelerator::iqn_ils:
          default:
            return std::make_unique<IQNILSAcceleration>(50, 1e-10);
        }
    }
  } // namespace



  StackCoupling::StackCoupling(const std::vector<InterfaceOperator *> &bodies,
                               const std::vector<StackJoint>          &joints,
                               const StackParameters     &parameters,
                               const std::vector<double> &alpha)
    : bodies(bodies)
    , joints(joints)
    , layout(joints)
    , parameters(parameters)
    , alpha(alpha)
  {
    AssertThrow(bodies.size() == joints.size() + 1
                  && alpha.size() == joints.size(),
                ExcMessage("a stack of N bodies has N - 1 joints"));
    displacement_scale = 0.;
    for (const StackJoint &joint : joints)
      {
        displacement_scale
          = std::max(displacement_scale, joint.largest_interference());
        current.force.emplace_back(joint.n_points());
        current.contact.emplace_back(joint.n_points(), true);
      }
    if (displacement_scale == 0.)
      displacement_scale = 1e-12;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      body_mutex.push_back(std::make_unique<std::mutex>());
  }



  void
  StackCoupling::body_data(const unsigned int                 b,
                           const std::vector<Data>           &data,
                           const std::vector<Vector<double>> &target,
                           std::vector<bool>                 &prescribed,
                           Vector<double>                    &displacement,
                           Vector<double>                    &force) const
  {
    const unsigned int n = layout.n_points(b);
    prescribed.assign(n, false);
    displacement.reinit(n);
    force.reinit(n);
    for (const unsigned int k : {b - 1, b})
      {
        if (k >= joints.size()) // b = 0 has no inner joint (k wraps)
          continue;
        const unsigned int at    = layout.offset(b, k);
        const bool         outer = k + 1 == b; // b is the joint's outer body
        for (unsigned int i = 0; i < joints[k].n_points(); ++i)
          if (data[k] == Data::position && current.contact[k][i])
            {
              prescribed[at + i] = true;
              displacement[at + i]
                = target[k][i] + (outer ? joints[k].interference_at(i) : 0.);
            }
          else if (data[k] == Data::force)
            force[at + i] = current.force[k][i];
      }
  }



  void
  StackCoupling::solve_body(const unsigned int                 b,
                            const std::vector<Data>           &data,
                            const std::vector<Vector<double>> &target,
                            Vector<double>                    &u_r,
                            Vector<double>                    &force)
  {
    std::vector<bool> prescribed;
    Vector<double>    displacement, given;
    body_data(b, data, target, prescribed, displacement, given);
    // A body in the middle serves two joints' visits (Jacobi: at once).
    std::lock_guard<std::mutex> lock(*body_mutex[b]);
    bodies[b]->solve(prescribed, displacement, given, u_r, force);
    ++body_solves;
  }



  Vector<double>
  StackCoupling::dirichlet_target(const unsigned int    k,
                                  const Vector<double> &u_inner,
                                  const Vector<double> &u_outer,
                                  Vector<double>       &du) const
  {
    const StackJoint &joint = joints[k];
    du.reinit(joint.n_points());
    Vector<double> target(joint.n_points());
    for (unsigned int i = 0; i < joint.n_points(); ++i)
      {
        du[i]     = u_outer[i] - u_inner[i] - joint.interference_at(i);
        target[i] = u_inner[i] + (1. - alpha[k]) * du[i];
      }
    return target;
  }



  Vector<double>
  StackCoupling::blend(const unsigned int    k,
                       const Vector<double> &p_inner,
                       const Vector<double> &p_outer) const
  {
    Vector<double> next(joints[k].n_points());
    for (unsigned int i = 0; i < next.size(); ++i)
      {
        if (!current.contact[k][i])
          continue;
        next[i] = p_inner[i] + alpha[k] * (p_outer[i] - p_inner[i]);
      }
    return next;
  }



  void
  StackCoupling::measure(const unsigned int    k,
                         const Vector<double> &du,
                         const Vector<double> &p_inner,
                         const Vector<double> &p_outer)
  {
    const StackJoint &joint = joints[k];
    for (unsigned int i = 0; i < joint.n_points(); ++i)
      {
        const double gap
          = current.contact[k][i] ? std::abs(du[i]) : std::max(0., -du[i]);
        step_gap = std::max(step_gap, gap / displacement_scale);
        if (current.contact[k][i])
          step_set_gap = std::max(step_set_gap, gap / displacement_scale);
        pressure_scale
          = std::max(pressure_scale,
                     std::max(std::abs(p_inner[i]), std::abs(p_outer[i]))
                       / joint.weights[i]);
        step_traction
          = std::max(step_traction,
                     std::abs(p_outer[i] - p_inner[i]) / joint.weights[i]);
      }
  }



  StackCoupling::Visit
  StackCoupling::visit_joint(const unsigned int k)
  {
    const unsigned int          in = k, out = k + 1;
    std::vector<Data>           data(joints.size(), Data::force);
    std::vector<Vector<double>> target(joints.size());
    Vector<double>              u_in, f_in, u_out, f_out;
    Visit                       visit;

    // Neumann: both bodies under the current forces of all their joints.
    solve_body(in, data, target, u_in, f_in);
    solve_body(out, data, target, u_out, f_out);
    Vector<double> u_inner(joints[k].n_points()), u_outer(joints[k].n_points());
    for (unsigned int i = 0; i < u_inner.size(); ++i)
      {
        u_inner[i] = u_in[layout.offset(in, k) + i];
        u_outer[i] = u_out[layout.offset(out, k) + i];
      }
    target[k] = dirichlet_target(k, u_inner, u_outer, visit.du);

    // Dirichlet at this joint, the other surfaces still under force.
    data[k] = Data::position;
    solve_body(in, data, target, u_in, f_in);
    solve_body(out, data, target, u_out, f_out);
    visit.p_inner.reinit(u_inner.size());
    visit.p_outer.reinit(u_inner.size());
    for (unsigned int i = 0; i < u_inner.size(); ++i)
      if (current.contact[k][i])
        {
          visit.p_inner[i] = f_in[layout.offset(in, k) + i];
          visit.p_outer[i] = f_out[layout.offset(out, k) + i];
        }
    visit.next = blend(k, visit.p_inner, visit.p_outer);
    return visit;
  }



  bool
  StackCoupling::run(std::ostream *progress)
  {
    std::unique_ptr<Accelerator> accelerator = make_accelerator(parameters);
    if (progress)
      *progress << "  step   displacement   traction   contact points\n";
    // The residual at which the contact points are updated: loose at
    // first, tightened a hundredfold whenever the points come back to a set
    // they had (a point at the edge of contact with next to no force and
    // no gap flips on an unsettled iterate), down to the tolerance.
    double                      settle = std::max(parameters.tolerance, 1e-4);
    std::set<std::vector<bool>> sets_seen;
    const auto                  all_points = [this]() {
      std::vector<bool> all;
      for (const auto &c : current.contact)
        all.insert(all.end(), c.begin(), c.end());
      return all;
    };
    sets_seen.insert(all_points());
    for (steps = 1; steps <= parameters.max_steps; ++steps)
      {
        step_gap = step_set_gap = step_traction = 0.;
        bool                        changed     = false;
        const Vector<double>        x           = concatenated(current.force);
        std::vector<Vector<double>> du(joints.size());
        std::vector<Vector<double>> next(joints.size());
        if (parameters.ordering == StackOrdering::jacobi)
          {
            // Every joint's visit at once from the same forces (a task
            // each; join() rethrows a task's exception).
            std::vector<Visit>       visits(joints.size());
            Threads::TaskGroup<void> tasks;
            for (unsigned int k = 0; k < joints.size(); ++k)
              tasks += Threads::new_task(
                [this, k, &visits]() { visits[k] = visit_joint(k); });
            tasks.join_all();
            for (unsigned int k = 0; k < joints.size(); ++k)
              {
                measure(k, visits[k].du, visits[k].p_inner, visits[k].p_outer);
                du[k]   = visits[k].du;
                next[k] = visits[k].next;
              }
          }
        else
          // Joint by joint, inside out: each visit sees the newest forces.
          for (unsigned int k = 0; k < joints.size(); ++k)
            {
              const Visit visit = visit_joint(k);
              measure(k, visit.du, visit.p_inner, visit.p_outer);
              du[k]            = visit.du;
              current.force[k] = visit.next;
              next[k]          = visit.next;
            }
        const double traction = pressure_scale > 0. ?
                                  step_traction / pressure_scale :
                                  step_traction;
        residuals.emplace_back(step_gap, traction);
        if (!std::isfinite(step_gap) || !std::isfinite(traction))
          throw SolverError("the staggered process of the stack gave a "
                            "non-finite residual in step "
                            + std::to_string(steps)
                            + "; try Solver/Method = monolithic");
        // The contact points are updated once the process has settled for
        // the current ones (a primal-dual active set over the staggered
        // solves): a point whose force pulls separates, a separated point
        // that penetrates closes; the history then restarts.
        const double set_residual = std::max(step_set_gap, traction);
        if (parameters.unilateral && set_residual < settle)
          {
            for (unsigned int k = 0; k < joints.size(); ++k)
              for (unsigned int i = 0; i < next[k].size(); ++i)
                {
                  if (current.contact[k][i] && next[k][i] < 0.)
                    {
                      current.contact[k][i] = false;
                      changed               = true;
                    }
                  else if (!current.contact[k][i]
                           && du[k][i] < -1e-12 * displacement_scale)
                    {
                      current.contact[k][i] = true;
                      changed               = true;
                    }
                }
            if (changed && !sets_seen.insert(all_points()).second)
              settle = std::max(parameters.tolerance, 1e-2 * settle);
          }
        unsigned int n_contact = 0, n_points = 0;
        for (const auto &c : current.contact)
          {
            n_contact += std::count(c.begin(), c.end(), true);
            n_points += c.size();
          }
        if (progress)
          *progress << std::setw(6) << steps << std::setw(15) << std::scientific
                    << std::setprecision(3) << step_gap << std::setw(11)
                    << traction << std::defaultfloat << std::setw(10)
                    << n_contact << "/" << n_points
                    << (changed ? "  (contact changed)" : "") << '\n';
        if (!changed && set_residual < parameters.tolerance
            && step_gap < parameters.tolerance)
          {
            current.force = next;
            return true;
          }
        // The fixed point over the forces of all joints.
        Vector<double> g = concatenated(next);
        if (changed)
          accelerator->restart();
        else
          accelerator->accelerate(x, g);
        split(g, next);
        for (unsigned int k = 0; k < joints.size(); ++k)
          for (unsigned int i = 0; i < next[k].size(); ++i)
            if (!current.contact[k][i])
              next[k][i] = 0.;
        current.force = next;
      }
    steps = parameters.max_steps;
    return false;
  }



  StackState
  solve_stack_contact(const std::vector<FullMatrix<double>> &compliances,
                      const std::vector<StackJoint>         &joints,
                      const bool                             unilateral,
                      unsigned int                          &active_set_steps)
  {
    const StackLayout         layout(joints);
    const unsigned int        N = joints.size();
    std::vector<unsigned int> start(N + 1, 0);
    for (unsigned int k = 0; k < N; ++k)
      start[k + 1] = start[k] + joints[k].n_points();
    const unsigned int n = start[N];

    // g_k = C_{k+1}(bore, .) F - C_k(outer, .) F - d_k: the rows of joint k
    // take body k + 1's bore rows (+) and body k's outer rows (-), each
    // over the joints that body touches.
    FullMatrix<double> A(n, n);
    Vector<double>     d(n);
    for (unsigned int k = 0; k < N; ++k)
      for (const auto &[b, sign] :
           {std::pair<unsigned int, double>{k + 1, 1.}, {k, -1.}})
        for (const unsigned int j : {b - 1, b})
          {
            if (j >= N)
              continue;
            const FullMatrix<double> &C = compliances[b];
            for (unsigned int i = 0; i < joints[k].n_points(); ++i)
              for (unsigned int l = 0; l < joints[j].n_points(); ++l)
                A(start[k] + i, start[j] + l)
                  += sign * C(layout.offset(b, k) + i, layout.offset(b, j) + l);
          }
    for (unsigned int k = 0; k < N; ++k)
      for (unsigned int i = 0; i < joints[k].n_points(); ++i)
        d[start[k] + i] = joints[k].interference_at(i);

    std::vector<bool> contact(n, true);
    Vector<double>    F(n);
    const double      scale = [&]() {
      double s = 0.;
      for (const StackJoint &j : joints)
        s = std::max(s, j.largest_interference());
      return s > 0. ? s : 1.;
    }();
    for (active_set_steps = 1; active_set_steps <= 4 * n + 10;
         ++active_set_steps)
      {
        std::vector<unsigned int> P;
        for (unsigned int i = 0; i < n; ++i)
          if (contact[i])
            P.push_back(i);
        F = 0.;
        if (!P.empty())
          {
            LAPACKFullMatrix<double> A_PP(P.size(), P.size());
            Vector<double>           rhs(P.size());
            for (unsigned int a = 0; a < P.size(); ++a)
              {
                rhs[a] = d[P[a]];
                for (unsigned int b = 0; b < P.size(); ++b)
                  A_PP(a, b) = A(P[a], P[b]);
              }
            A_PP.compute_lu_factorization();
            A_PP.solve(rhs);
            for (unsigned int a = 0; a < P.size(); ++a)
              F[P[a]] = rhs[a];
          }
        if (!unilateral)
          break;
        // Gaps of the separated points, then the new set.
        Vector<double> g(n);
        A.vmult(g, F);
        g -= d;
        bool changed = false;
        for (unsigned int i = 0; i < n; ++i)
          {
            const bool in = contact[i] ? F[i] >= 0. : g[i] < -1e-12 * scale;
            changed       = changed || in != contact[i];
            contact[i]    = in;
          }
        if (!changed)
          break;
        if (active_set_steps == 4 * n + 10)
          throw SolverError("the active set of the stack's contact problem "
                            "did not settle");
      }

    StackState state;
    for (unsigned int k = 0; k < N; ++k)
      {
        state.force.emplace_back(joints[k].n_points());
        state.contact.emplace_back(joints[k].n_points());
        for (unsigned int i = 0; i < joints[k].n_points(); ++i)
          {
            state.force[k][i]   = F[start[k] + i];
            state.contact[k][i] = contact[start[k] + i];
          }
      }
    return state;
  }
} // namespace coaxfit
