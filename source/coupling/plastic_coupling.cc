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
      text << std::setprecision(3) << "the Newton solve of the body "
           << body.discretization().name() << " did not converge ("
           << outcome.iterations << " iterations, relative residual "
           << outcome.residual << ")";
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
        if (!settings.unilateral || !update_active_set())
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
            outcome.failure
              = newton_failure(hub_outcome.converged ? shaft : hub,
                               hub_outcome.converged ? shaft_outcome :
                                                       hub_outcome);
            return outcome;
          }
        double         norm = 0., scale = 0.;
        Vector<double> residual(held.size());
        for (unsigned int a = 0; a < held.size(); ++a)
          {
            residual[a] = f_hub[held[a]] - f_shaft[held[a]];
            norm += residual[a] * residual[a];
            scale += f_hub[held[a]] * f_hub[held[a]];
          }
        norm             = std::sqrt(norm);
        scale            = std::sqrt(scale);
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
    Vector<double>          hub_data(n), x(contact_force), g(n);
    for (unsigned int i = 0; i < n; ++i)
      if (!active_points[i])
        x[i] = 0.;
    IQNILSAcceleration accelerator(settings.iqn_columns, settings.iqn_filter);
    IncrementOutcome   outcome;
    for (unsigned int step = 0; step <= settings.max_steps; ++step)
      {
        // Neumann step of the shaft, Dirichlet step of the hub.
        const NewtonOutcome shaft_outcome
          = shaft.solve(none, zero, x, u_shaft, f_shaft);
        if (!shaft_outcome.converged)
          {
            outcome.failure = newton_failure(shaft, shaft_outcome);
            return outcome;
          }
        for (unsigned int i = 0; i < n; ++i)
          hub_data[i] = u_shaft[i] + interference[i];
        const NewtonOutcome hub_outcome
          = hub.solve(active_points, hub_data, zero, u_hub, f_hub);
        outcome.body_solves += 2;
        outcome.max_body_iterations = std::max({outcome.max_body_iterations,
                                                hub_outcome.iterations,
                                                shaft_outcome.iterations});
        if (!hub_outcome.converged)
          {
            outcome.failure = newton_failure(hub, hub_outcome);
            return outcome;
          }
        double norm = 0., scale = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            g[i] = active_points[i] ? f_hub[i] : 0.;
            norm += (g[i] - x[i]) * (g[i] - x[i]);
            scale += g[i] * g[i];
          }
        norm             = std::sqrt(norm);
        scale            = std::sqrt(scale);
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
