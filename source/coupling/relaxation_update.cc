#include <coaxfit/coupling/relaxation_update.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace coaxfit
{
  RelaxationUpdate::RelaxationUpdate(const CouplingParameters &parameters,
                                     const ContactInterface   &interface,
                                     UnilateralActiveSet      &active_set,
                                     const double active_set_tolerance)
    : CouplingUpdate(interface, active_set)
    , rule(make_alpha_rule(parameters))
    , accelerator(make_accelerator(parameters))
    , accelerated(parameters.accelerator() != AcceleratorType::none)
    , history_on_change(parameters.history_on_change)
    , active_set_tolerance(
        std::max(active_set_tolerance > 0. ? active_set_tolerance : 0.1,
                 parameters.tolerance))
    , initial_active_set_tolerance(this->active_set_tolerance)
    , automatic_active_set_tolerance(active_set_tolerance == 0.)
    , tolerance_floor(parameters.tolerance)
  {}



  std::string
  RelaxationUpdate::alpha_rule_name() const
  {
    return rule->name();
  }



  std::string
  RelaxationUpdate::accelerator_name() const
  {
    return accelerator->name();
  }



  std::string
  RelaxationUpdate::description() const
  {
    std::ostringstream s;
    s << "Coupling/Alpha rule = " << rule->name()
      << " and Accelerator = " << accelerator->name()
      << ", alpha = " << std::setprecision(4) << rule->representative_alpha();
    return s.str();
  }



  std::string
  RelaxationUpdate::failure_advice() const
  {
    // Advice that fits what ran: a constant alpha can be changed or
    // accelerated; an accelerated run that fails has the monolithic solver
    // left (the same discrete problem, solved at once).
    if (accelerator->name() == "iqn-ils")
      return "the quasi-Newton iteration could not recover; solve this "
             "scene with Solver/Method = monolithic ("
             + suggested_alpha_range() + ").";
    return suggested_alpha_range()
           + " (a Winkler estimate; thin walls can leave no convergent "
             "constant alpha: then use Coupling/Alpha controller = iqn-ils).";
  }



  bool
  RelaxationUpdate::loaded_start() const
  {
    // The adaptive rules start from a loaded first Neumann step, whose
    // compliances give the Winkler alpha of the first Dirichlet step; the
    // fixed rule from the paper's zero approximation.
    return rule->adaptive();
  }



  void
  RelaxationUpdate::start(const bool predicted)
  {
    // Predicted flags are better than an update from a rough state.
    active_set_tolerance = (predicted && automatic_active_set_tolerance) ?
                             std::max(1e-2, tolerance_floor) :
                             initial_active_set_tolerance;
    visited_sets         = {active_set.in_contact()};
  }



  NeumannOutcome
  RelaxationUpdate::after_neumann(InterfaceState &state,
                                  unsigned int,
                                  Vector<double> &,
                                  bool &verified)
  {
    NeumannOutcome outcome;
    outcome.new_inner_iteration = update_active_set(state, verified);
    state.displacement_mismatch
      = interface.relative_gap_residual(state.u1,
                                        state.u2,
                                        active_set.in_contact());
    neumann_force       = state.force;
    neumann_u1          = state.u1;
    neumann_u2          = state.u2;
    outcome.alpha       = rule->representative_alpha();
    outcome.n_separated = active_set.n_separated();

    // The alpha of the next Dirichlet step. With an accelerator the rule is
    // asked only until its first estimate, and each new alpha is a new
    // map: the accelerator restarts.
    if (!accelerated || !rule->estimated())
      {
        rule->update(
          {state.force, state.u1, state.u2, state.displacement_mismatch});
        accelerator->restart();
      }
    return outcome;
  }



  bool
  RelaxationUpdate::update_active_set(const InterfaceState &state,
                                      bool                 &verified)
  {
    // The paper updates the flags after every Neumann step; the outer
    // (primal-dual) mode once the iteration has converged for the current
    // set to the active-set tolerance. That residual leaves out the
    // penetration of separated points: the problem with these flags cannot
    // reduce it, only the update can (with flags predicted by a coarser
    // mesh a penetrating point would otherwise wait for ever).
    verified = false;
    if (!(active_set.update_mode() == UnilateralActiveSet::Update::every_step
          || (interface.relative_gap_residual(
                state.u1, state.u2, active_set.in_contact(), false)
                < active_set_tolerance
              && state.traction_mismatch < active_set_tolerance)))
      return false;
    const std::vector<bool> before = active_set.in_contact();
    const bool              changed
      = active_set.update(state.force, interface.gap(state.u1, state.u2));
    verified = !changed;
    if (!changed)
      return false;
    // Back to flags seen before: the updates cycle; take them from better
    // converged states from now on.
    if (!visited_sets.insert(active_set.in_contact()).second)
      active_set_tolerance
        = std::max(tolerance_floor, 1e-2 * active_set_tolerance);
    if (history_on_change == HistoryOnChange::restart)
      accelerator->restart();
    else if (history_on_change != HistoryOnChange::keep)
      {
        std::vector<bool> flipped(before.size());
        for (unsigned int i = 0; i < before.size(); ++i)
          flipped[i] = before[i] != active_set.in_contact()[i];
        if (history_on_change == HistoryOnChange::filter)
          accelerator->forget_points(flipped);
        else
          accelerator->keep_model(flipped);
      }
    // Each outer update starts a new inner iteration; in the paper's
    // every-step mode changes are part of the iteration.
    return active_set.update_mode()
           == UnilateralActiveSet::Update::when_converged;
  }



  void
  RelaxationUpdate::dirichlet_data(const InterfaceState &state,
                                   Vector<double>       &u_inner,
                                   Vector<double>       &u_outer)
  {
    for (unsigned int i = 0; i < u_inner.size(); ++i)
      {
        const double d = interface.interference(i);
        u_inner[i]     = state.u1[i]
                     + (1. - rule->alpha(i)) * (state.u2[i] - d - state.u1[i]);
        u_outer[i] = u_inner[i] + d;
      }
  }



  double
  RelaxationUpdate::after_dirichlet(InterfaceState       &state,
                                    const bool            after_zero_start,
                                    const Vector<double> &u_inner,
                                    const Vector<double> &u_outer,
                                    Vector<double>       &f_inner,
                                    Vector<double>       &f_outer,
                                    Vector<double>       &next_force,
                                    bool &)
  {
    if (after_zero_start && rule->adaptive())
      seed_alpha(state, u_inner, u_outer, f_inner, f_outer);

    Vector<double> &force = state.force;
    for (unsigned int i = 0; i < force.size(); ++i)
      force[i] = f_inner[i] + rule->alpha(i) * (f_outer[i] - f_inner[i]);
    // A tensile blend is a violated contact condition: part of the residual.
    const bool clamping
      = active_set.enabled()
        && active_set.update_mode() == UnilateralActiveSet::Update::every_step;
    const double mismatch = interface.max_pressure_difference(f_inner, f_outer);
    const double tension  = clamping ? interface.max_tension(force) : 0.;
    state.traction_mismatch = relative_to_pressure(std::max(mismatch, tension),
                                                   f_inner,
                                                   f_outer,
                                                   interface);

    active_set.clamp(force);
    next_force = force;
    update_prior();
    accelerator->accelerate(neumann_force, next_force);
    active_set.clamp(next_force);
    return rule->representative_alpha();
  }



  void
  RelaxationUpdate::update_prior()
  {
    // Only with a fixed alpha is the accelerated map fixed; the model
    // learned across a change (Active set change = model) is kept.
    if (!coarse_model || !rule->estimated())
      return;
    const unsigned int  n = interface.n_points();
    std::vector<double> alpha(n);
    for (unsigned int i = 0; i < n; ++i)
      alpha[i] = rule->alpha(i);
    const std::vector<bool> &contact = active_set.in_contact();
    if (alpha == prior_alpha && contact == prior_contact)
      return;
    if (!prior_alpha.empty() && history_on_change == HistoryOnChange::model)
      return;
    accelerator->set_prior(
      coarse_model->inverse_jacobian_prior(alpha, contact));
    prior_alpha   = alpha;
    prior_contact = contact;
    ++n_priors;
  }



  void
  RelaxationUpdate::seed_alpha(InterfaceState       &state,
                               const Vector<double> &u_inner,
                               const Vector<double> &u_outer,
                               Vector<double>       &f_inner,
                               Vector<double>       &f_outer)
  {
    // The first Dirichlet step follows the zero Neumann step (u1 = u2 = 0),
    // so it prescribes -(1 - alpha) d_i to the shaft and alpha d_i to the
    // hub: the bodies' answers measure their compliances before any alpha
    // is known, k = sum |u F| / sum F^2/w (the energy-weighted Winkler
    // compliance), and the Winkler alpha k2 / (k1 + k2), formula (4.20), is
    // exact for a Winkler pair. The bodies are linear and the prescribed
    // displacements proportional to d_i, so the step with that alpha is the
    // step taken, rescaled: no further solve. Without it a hub or shaft much
    // softer than the other gets a first force off by the ratio of the
    // stiffnesses (1e3 for E ratios of 1e4) and the iteration fails.
    const double alpha0 = rule->representative_alpha();
    const double k1 = winkler_compliance(u_inner, f_inner, interface.weights());
    const double k2 = winkler_compliance(u_outer, f_outer, interface.weights());
    if (!(k1 > 0.) || !(k2 > 0.))
      return; // no contact point, or nothing prescribed: keep alpha
    const double alpha = std::clamp(k2 / (k1 + k2), 1e-9, 1. - 1e-9);
    const double c1    = (1. - alpha) / (1. - alpha0);
    const double c2    = alpha / alpha0;
    state.u1 *= c1;
    f_inner *= c1;
    state.u2 *= c2;
    f_outer *= c2;
    rule->seed(alpha);
  }



  std::string
  RelaxationUpdate::suggested_alpha_range() const
  {
    // Energy-weighted Winkler compliances k_i = u_i / p of the last Neumann
    // step with a non-zero load; for a Winkler pair the process contracts
    // for |alpha rho - (1 - alpha)/rho| < 1, rho = sqrt(k1/k2), and is
    // exact for alpha = k2 / (k1 + k2), formula (4.20).
    const double k1
      = winkler_compliance(neumann_u1, neumann_force, interface.weights());
    const double k2
      = winkler_compliance(neumann_u2, neumann_force, interface.weights());
    std::ostringstream msg;
    if (!(k1 > 0.) || !(k2 > 0.))
      {
        msg << "try a value of Coupling/Alpha closer to the paper's table";
        return msg.str();
      }
    const double rho = std::sqrt(k1 / k2);
    const double lo  = std::max(0., (1. / rho - 1.) / (rho + 1. / rho));
    const double hi  = std::min(1., (1. / rho + 1.) / (rho + 1. / rho));
    msg << std::setprecision(3) << "the compliances of the bodies suggest "
        << "Coupling/Alpha in (" << lo << ", " << hi << "), best near "
        << k2 / (k1 + k2);
    return msg.str();
  }
} // namespace coaxfit
