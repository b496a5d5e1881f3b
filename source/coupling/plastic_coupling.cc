#include <deal.II/lac/full_matrix.h>

#include <coaxfit/coupling/accelerator.h>
#include <coaxfit/coupling/plastic_coupling.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** A body's Newton solve that failed, in words. */
    std::string
    newton_failure(const PlasticBody &body, const NewtonOutcome &outcome)
    {
      std::ostringstream text;
      if (outcome.singular)
        return "the tangent of the body " + body.discretization().name()
               + " is singular (no stiffness left: a body plastic through "
                 "its wall at its limit load)";
      text << std::setprecision(3) << "the Newton solve of the body "
           << body.discretization().name() << " did not converge ("
           << outcome.iterations << " iterations, ";
      if (std::isfinite(outcome.residual))
        text << "relative residual " << outcome.residual << ")";
      else
        text << "diverged: the residual is not a number)";
      return text.str();
    }
  } // namespace



  PlasticCoupling::PlasticCoupling(PlasticBody    &shaft,
                                   PlasticBody    &hub,
                                   const Settings &settings)
    : shaft(shaft)
    , hub(hub)
    , settings(settings)
  {
    const unsigned int n = hub.discretization().n_interface_points();
    contact_force.reinit(n);
    hub_displacement.reinit(n);
    gaps.reinit(n);
    active_points.assign(n, true);
    committed_force        = contact_force;
    committed_displacement = hub_displacement;
    previous_force         = contact_force;
    previous_displacement  = hub_displacement;
    committed_active       = active_points;
    committed_gaps         = gaps;
  }



  void
  PlasticCoupling::set_separated(const bool apart)
  {
    separated = apart;
    if (apart)
      {
        active_points.assign(active_points.size(), false);
        contact_force = 0;
      }
  }



  void
  PlasticCoupling::extrapolate(const double ratio)
  {
    contact_force = committed_force;
    contact_force.add(ratio, committed_force);
    contact_force.add(-ratio, previous_force);
    hub_displacement = committed_displacement;
    hub_displacement.add(ratio, committed_displacement);
    hub_displacement.add(-ratio, previous_displacement);
  }



  void
  PlasticCoupling::scale_committed(const double factor)
  {
    committed_force *= factor;
    committed_displacement *= factor;
    previous_force        = 0;
    previous_displacement = 0;
    revert();
  }



  void
  PlasticCoupling::revert()
  {
    contact_force    = committed_force;
    hub_displacement = committed_displacement;
    gaps             = committed_gaps;
    active_points    = committed_active;
  }



  void
  PlasticCoupling::commit()
  {
    previous_force         = committed_force;
    previous_displacement  = committed_displacement;
    committed_force        = contact_force;
    committed_displacement = hub_displacement;
    committed_active       = active_points;
    committed_gaps         = gaps;
    peak_force             = std::max(peak_force, contact_force.l2_norm());
  }



  IncrementOutcome
  PlasticCoupling::solve(const Vector<double> &interference,
                         std::ostream         *progress)
  {
    IncrementOutcome total;
    // A set of contact points seen before means the update cycles.
    for (unsigned int round = 0; round < 50; ++round)
      {
        const IncrementOutcome outcome
          = settings.monolithic ? solve_monolithic(interference, progress) :
                                  solve_staggered(interference, progress);
        total.steps += outcome.steps;
        total.body_solves += outcome.body_solves;
        total.max_body_iterations
          = std::max(total.max_body_iterations, outcome.max_body_iterations);
        total.residual          = outcome.residual;
        total.active_set_rounds = round + 1;
        if (!outcome.converged)
          {
            total.failure = outcome.failure;
            return total;
          }
        if (!settings.unilateral || separated || !update_active_set())
          {
            total.converged = true;
            return total;
          }
      }
    total.failure = "the contact points did not settle in 50 rounds of the "
                    "active set";
    return total;
  }



  bool
  PlasticCoupling::update_active_set()
  {
    double scale = 0.;
    for (unsigned int i = 0; i < gaps.size(); ++i)
      scale = std::max(scale, std::abs(hub_displacement[i]));
    bool changed = false;
    for (unsigned int i = 0; i < active_points.size(); ++i)
      if (active_points[i] && contact_force[i] < 0.)
        {
          active_points[i] = false;
          contact_force[i] = 0.;
          changed          = true;
        }
      else if (!active_points[i] && gaps[i] < -1e-12 * scale)
        {
          active_points[i] = true;
          changed          = true;
        }
    return changed;
  }



  IncrementOutcome
  PlasticCoupling::solve_monolithic(const Vector<double> &interference,
                                    std::ostream         *progress)
  {
    const unsigned int        n = active_points.size();
    std::vector<unsigned int> held;
    for (unsigned int i = 0; i < n; ++i)
      if (active_points[i])
        held.push_back(i);
    const Vector<double> zero(n);
    Vector<double>       u_hub(n), u_shaft(n), f_hub(n), f_shaft(n);
    Vector<double>       shaft_data(n);
    IncrementOutcome     outcome;
    // The last iterate both bodies converged at, for backtracking.
    Vector<double> hub_field, shaft_field, last_displacement(n);
    Vector<double> last_change(held.size());
    unsigned int   backtracks = 0;
    for (unsigned int step = 0; step <= settings.max_steps; ++step)
      {
        // Both bodies displacement-driven at the contact points.
        for (unsigned int i = 0; i < n; ++i)
          shaft_data[i] = hub_displacement[i] - interference[i];
        const NewtonOutcome hub_outcome
          = hub.solve(active_points, hub_displacement, zero, u_hub, f_hub);
        const NewtonOutcome shaft_outcome
          = shaft.solve(active_points, shaft_data, zero, u_shaft, f_shaft);
        outcome.body_solves += 2;
        outcome.max_body_iterations = std::max({outcome.max_body_iterations,
                                                hub_outcome.iterations,
                                                shaft_outcome.iterations});
        if (!hub_outcome.converged || !shaft_outcome.converged)
          {
            // A Newton step on the joint that the bodies cannot follow:
            // back to the last iterate they converged at, half the step
            // (a few times before the increment counts as failed).
            if (step > 0 && backtracks < 6)
              {
                ++backtracks;
                hub.set_solution(hub_field);
                shaft.set_solution(shaft_field);
                last_change *= 0.5;
                for (unsigned int a = 0; a < held.size(); ++a)
                  hub_displacement[held[a]]
                    = last_displacement[held[a]] - last_change[a];
                continue;
              }
            outcome.failure
              = newton_failure(hub_outcome.converged ? shaft : hub,
                               hub_outcome.converged ? shaft_outcome :
                                                       hub_outcome);
            return outcome;
          }
        backtracks          = 0;
        hub_field           = hub.solution();
        shaft_field         = shaft.solution();
        last_displacement   = hub_displacement;
        double         norm = 0., scale = 0.;
        Vector<double> residual(held.size());
        for (unsigned int a = 0; a < held.size(); ++a)
          {
            residual[a] = f_hub[held[a]] - f_shaft[held[a]];
            norm += residual[a] * residual[a];
            scale += f_hub[held[a]] * f_hub[held[a]];
          }
        norm             = std::sqrt(norm);
        scale            = force_scale(std::sqrt(scale));
        outcome.residual = scale > 0. ? norm / scale : norm;
        outcome.steps    = step;
        contact_force    = f_hub;
        for (unsigned int i = 0; i < n; ++i)
          gaps[i]
            = active_points[i] ? 0. : u_hub[i] - u_shaft[i] - interference[i];
        hub_displacement = u_hub;
        if (progress != nullptr)
          *progress << "    Newton step " << std::setw(3) << step
                    << "  force residual " << std::scientific
                    << std::setprecision(3) << outcome.residual
                    << std::defaultfloat << "  body iterations "
                    << hub_outcome.iterations << ", "
                    << shaft_outcome.iterations << '\n';
        if (!std::isfinite(norm))
          break;
        if (norm <= settings.tolerance * scale || norm == 0.)
          {
            outcome.converged = true;
            return outcome;
          }
        FullMatrix<double>       jacobian = hub.interface_stiffness();
        const FullMatrix<double> s_shaft  = shaft.interface_stiffness();
        jacobian.add(-1., s_shaft);
        jacobian.gauss_jordan();
        Vector<double> change(held.size());
        jacobian.vmult(change, residual);
        last_change = change;
        for (unsigned int a = 0; a < held.size(); ++a)
          hub_displacement[held[a]] -= change[a];
      }
    std::ostringstream text;
    text << std::setprecision(3)
         << "the monolithic Newton solve did not converge in "
         << settings.max_steps << " steps (Coupling/Max steps; force "
         << "residual " << outcome.residual << ")";
    outcome.failure = text.str();
    return outcome;
  }



  IncrementOutcome
  PlasticCoupling::solve_staggered(const Vector<double> &interference,
                                   std::ostream         *progress)
  {
    const unsigned int      n = active_points.size();
    const std::vector<bool> none(n, false);
    const Vector<double>    zero(n);
    Vector<double>          u_hub(n), u_shaft(n), f_hub(n), f_shaft(n);
    Vector<double>          data(n), x(contact_force), g(n);
    for (unsigned int i = 0; i < n; ++i)
      if (!active_points[i])
        x[i] = 0.;
    // The body that takes the force (Neumann) and the one that takes the
    // displacement (Dirichlet): u_hub = u_shaft + d closes the joint.
    const bool         swap      = settings.neumann_on_hub;
    PlasticBody       &neumann   = swap ? hub : shaft;
    PlasticBody       &dirichlet = swap ? shaft : hub;
    Vector<double>    &u_n       = swap ? u_hub : u_shaft;
    Vector<double>    &u_d       = swap ? u_shaft : u_hub;
    Vector<double>    &f_n       = swap ? f_hub : f_shaft;
    Vector<double>    &f_d       = swap ? f_shaft : f_hub;
    const double       d_sign    = swap ? -1. : 1.;
    IQNILSAcceleration accelerator(settings.iqn_columns, settings.iqn_filter);
    IncrementOutcome   outcome;
    // The last force both bodies converged at, for backtracking.
    Vector<double> neumann_field, dirichlet_field, last_x(x);
    unsigned int   backtracks = 0;
    for (unsigned int step = 0; step <= settings.max_steps; ++step)
      {
        const NewtonOutcome n_outcome = neumann.solve(none, zero, x, u_n, f_n);
        NewtonOutcome       d_outcome;
        if (n_outcome.converged)
          {
            for (unsigned int i = 0; i < n; ++i)
              data[i] = u_n[i] + d_sign * interference[i];
            d_outcome = dirichlet.solve(active_points, data, zero, u_d, f_d);
          }
        outcome.body_solves += 2;
        outcome.max_body_iterations = std::max({outcome.max_body_iterations,
                                                n_outcome.iterations,
                                                d_outcome.iterations});
        if (!n_outcome.converged || !d_outcome.converged)
          {
            // A force the bodies cannot follow: back to the last one they
            // converged at, half way towards the new one (a few times
            // before the increment counts as failed).
            if (step > 0 && backtracks < 6)
              {
                ++backtracks;
                neumann.set_solution(neumann_field);
                dirichlet.set_solution(dirichlet_field);
                x.sadd(0.5, 0.5, last_x);
                continue;
              }
            outcome.failure = n_outcome.converged ?
                                newton_failure(dirichlet, d_outcome) :
                                newton_failure(neumann, n_outcome);
            return outcome;
          }
        backtracks                          = 0;
        neumann_field                       = neumann.solution();
        dirichlet_field                     = dirichlet.solution();
        last_x                              = x;
        const NewtonOutcome  &shaft_outcome = swap ? d_outcome : n_outcome;
        const NewtonOutcome  &hub_outcome   = swap ? n_outcome : d_outcome;
        const Vector<double> &f_dirichlet   = f_d;
        double                norm = 0., scale = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            g[i] = active_points[i] ? f_dirichlet[i] : 0.;
            norm += (g[i] - x[i]) * (g[i] - x[i]);
            scale += g[i] * g[i];
          }
        norm             = std::sqrt(norm);
        scale            = force_scale(std::sqrt(scale));
        outcome.residual = scale > 0. ? norm / scale : norm;
        outcome.steps    = step + 1;
        contact_force    = g;
        hub_displacement = u_hub;
        for (unsigned int i = 0; i < n; ++i)
          gaps[i]
            = active_points[i] ? 0. : u_hub[i] - u_shaft[i] - interference[i];
        if (progress != nullptr)
          *progress << "    step " << std::setw(3) << step + 1
                    << "  force residual " << std::scientific
                    << std::setprecision(3) << outcome.residual
                    << std::defaultfloat << "  body iterations "
                    << shaft_outcome.iterations << ", "
                    << hub_outcome.iterations << '\n';
        if (!std::isfinite(norm))
          break;
        if (norm <= settings.tolerance * scale || norm == 0.)
          {
            outcome.converged = true;
            return outcome;
          }
        Vector<double> next(g);
        accelerator.accelerate(x, next);
        if (step == 0)
          {
            // No history yet: the plain step overshoots when the bodies
            // are about as stiff as each other; half of it does not.
            next = x;
            next.add(0.5, g);
            next.add(-0.5, x);
          }
        for (unsigned int i = 0; i < n; ++i)
          x[i] = active_points[i] ? next[i] : 0.;
      }
    std::ostringstream text;
    text << std::setprecision(3) << "the staggered process did not converge in "
         << settings.max_steps << " steps (Coupling/Max steps; force "
         << "residual " << outcome.residual << ")";
    outcome.failure = text.str();
    return outcome;
  }
} // namespace coaxfit
