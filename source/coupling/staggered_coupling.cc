#include <coaxfit/base/concurrency.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/staggered_coupling.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /**
     * The energy-weighted Winkler compliance k = sum |u F| / sum F^2/w of a
     * body that answered the nodal forces @p force with @p u (w: the lumped
     * weights); 0 if there is no load or the sums are not finite.
     */
    double
    winkler_compliance(const Vector<double> &u,
                       const Vector<double> &force,
                       const Vector<double> &weights)
    {
      double work = 0., load = 0.;
      for (unsigned int i = 0; i < force.size(); ++i)
        {
          work += std::abs(u[i] * force[i]);
          load += force[i] * force[i] / weights[i];
        }
      const double k = work / load;
      return (load > 0. && std::isfinite(k)) ? k : 0.;
    }
  } // namespace



  StaggeredCoupling::StaggeredCoupling(BodySolver                &shaft_solver,
                                       BodySolver                &hub_solver,
                                       InterfaceOperator         &shaft,
                                       InterfaceOperator         &hub,
                                       const ContactInterface    &interface,
                                       const CouplingParameters  &parameters,
                                       const UnilateralActiveSet &active_set,
                                       const double active_set_tolerance)
    : InterfaceSolver(active_set)
    , shaft_solver(shaft_solver)
    , hub_solver(hub_solver)
    , shaft(shaft)
    , hub(hub)
    , interface(interface)
    , rule(make_alpha_rule(parameters))
    , accelerator(make_accelerator(parameters))
    , accelerated(parameters.accelerator() != AcceleratorType::none)
    , tolerance(parameters.tolerance)
    , max_steps(parameters.max_steps)
    , active_set_tolerance(
        std::max(active_set_tolerance > 0. ? active_set_tolerance : 0.1,
                 parameters.tolerance))
    , initial_active_set_tolerance(this->active_set_tolerance)
    , automatic_active_set_tolerance(active_set_tolerance == 0.)
    , tolerance_floor(parameters.tolerance)
    , history_on_change(parameters.history_on_change)
  {
    if (parameters.accelerator() == AcceleratorType::ibqn)
      block_model
        = std::make_unique<InterfaceBlockModel>(interface.n_points(),
                                                parameters.iqn_columns,
                                                parameters.iqn_filter);
  }



  void
  StaggeredCoupling::neumann_step()
  {
    force = next_force;
    concurrently([&]() { shaft.solve_neumann(force, u1); },
                 [&]() { hub.solve_neumann(force, u2); });
    // The model takes the solve as it is (the scaled first step may be a
    // zero force).
    if (block_model)
      add_block_model_samples(force, force);
    if (history_rows.empty() && start_loaded && initial_force.size() == 0)
      scale_first_load();
    if (block_model)
      {
        // The flags that made this force are judged by the state below;
        // the model's prediction from it sets those of the next steps.
        const std::vector<bool> made_with = active_set.in_contact();
        last_displacement_mismatch
          = interface.relative_gap_residual(u1, u2, made_with);
        active_set_verified = predict_from_block_model();
        neumann_force       = force;
        neumann_u1          = u1;
        neumann_u2          = u2;
        history_rows.push_back(
          {static_cast<unsigned int>(history_rows.size() + 1),
           true,
           std::numeric_limits<double>::quiet_NaN(),
           last_displacement_mismatch,
           0.,
           static_cast<unsigned int>(
             std::count(made_with.begin(), made_with.end(), false))});
        return;
      }
    update_active_set();
    last_displacement_mismatch
      = interface.relative_gap_residual(u1, u2, active_set.in_contact());

    neumann_force = force;
    neumann_u1    = u1;
    neumann_u2    = u2;

    history_rows.push_back({static_cast<unsigned int>(history_rows.size() + 1),
                            true,
                            rule->representative_alpha(),
                            last_displacement_mismatch,
                            0.,
                            active_set.n_separated()});

    // The alpha of the next Dirichlet step. With an accelerator the rule is
    // asked only until its first estimate, and each new alpha is a new
    // map: the accelerator restarts.
    if (!accelerated || !rule->estimated())
      {
        rule->update({force, u1, u2, last_displacement_mismatch});
        accelerator->restart();
      }
  }



  void
  StaggeredCoupling::update_active_set()
  {
    // The paper updates the flags after every Neumann step; the outer
    // (primal-dual) mode once the iteration has converged for the current
    // set to the active-set tolerance. That residual leaves out the
    // penetration of separated points: the problem with these flags cannot
    // reduce it, only the update can (with flags predicted by a coarser
    // mesh a penetrating point would otherwise wait for ever).
    active_set_verified = false;
    if (active_set.update_mode() == UnilateralActiveSet::Update::every_step
        || (interface.relative_gap_residual(
              u1, u2, active_set.in_contact(), false)
              < active_set_tolerance
            && last_traction_mismatch < active_set_tolerance))
      {
        const std::vector<bool> before = active_set.in_contact();
        const bool changed  = active_set.update(force, interface.gap(u1, u2));
        active_set_verified = !changed;
        if (changed)
          {
            // Back to flags seen before: the updates cycle; take them from
            // better converged states from now on.
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
            // Each outer update starts a new inner iteration; in the
            // paper's every-step mode changes are part of the iteration.
            if (active_set.update_mode()
                == UnilateralActiveSet::Update::when_converged)
              last_change_step = history_rows.size() + 1;
          }
      }
  }



  void
  StaggeredCoupling::add_block_model_samples(const Vector<double> &f_shaft,
                                             const Vector<double> &f_hub)
  {
    block_model->add_sample(InterfaceBlockModel::shaft, f_shaft, u1);
    block_model->add_sample(InterfaceBlockModel::hub, f_hub, u2);
    if (!block_model->has_prior())
      {
        // No coarse model: Winkler compliances measured in this first step.
        const Vector<double> &w = interface.weights();
        block_model->set_winkler_prior(InterfaceBlockModel::shaft,
                                       -winkler_compliance(u1, f_shaft, w),
                                       w);
        block_model->set_winkler_prior(InterfaceBlockModel::hub,
                                       winkler_compliance(u2, f_hub, w),
                                       w);
      }
  }



  bool
  StaggeredCoupling::predict_from_block_model()
  {
    const unsigned int  n = force.size();
    std::vector<double> d(n);
    for (unsigned int i = 0; i < n; ++i)
      d[i] = interface.interference(i);
    std::vector<bool> contact = active_set.in_contact();
    const bool        settled = block_model->predict(
      d, active_set.enabled(), contact, next_force, model_displacement);
    return active_set.set(contact) == false && settled;
  }



  void
  StaggeredCoupling::dirichlet_step()
  {
    const unsigned int n = force.size();
    if (block_model)
      {
        // The model's common interface displacement on the contact points,
        // separated points traction free.
        const std::vector<bool> contact = active_set.in_contact();
        Vector<double> u_shaft(model_displacement), u_hub(n), zero(n), f1, f2;
        for (unsigned int i = 0; i < n; ++i)
          u_hub[i] = u_shaft[i] + interface.interference(i);
        concurrently([&]() { shaft.solve(contact, u_shaft, zero, u1, f1); },
                     [&]() { hub.solve(contact, u_hub, zero, u2, f2); });
        const double mismatch = interface.max_pressure_difference(f1, f2);
        const double magnitude
          = std::max(interface.max_pressure(f1), interface.max_pressure(f2));
        last_traction_mismatch = magnitude > 0. ? mismatch / magnitude : 0.;
        if (!std::isfinite(last_traction_mismatch))
          last_traction_mismatch = std::numeric_limits<double>::quiet_NaN();
        const unsigned int n_separated = active_set.n_separated();
        force                          = f1;
        force.add(0.5, f2);
        force.add(-0.5, f1);
        // Flags changed by this prediction were not those of the state.
        add_block_model_samples(f1, f2);
        if (!predict_from_block_model())
          active_set_verified = false;
        history_rows.push_back(
          {static_cast<unsigned int>(history_rows.size() + 1),
           false,
           std::numeric_limits<double>::quiet_NaN(),
           interface.relative_gap_residual(u1, u2, contact),
           last_traction_mismatch,
           n_separated});
        return;
      }
    const std::vector<bool> &contact = active_set.in_contact();
    Vector<double>           u_shaft(n), u_hub(n), zero(n), f1, f2;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double d = interface.interference(i);
        u_shaft[i]     = u1[i] + (1. - rule->alpha(i)) * (u2[i] - d - u1[i]);
        u_hub[i]       = u_shaft[i] + d;
      }
    // Contact points get the blended displacement, separated points stay
    // traction free in both bodies.
    concurrently([&]() { shaft.solve(contact, u_shaft, zero, u1, f1); },
                 [&]() { hub.solve(contact, u_hub, zero, u2, f2); });
    if (history_rows.size() == 1 && rule->adaptive() && !start_loaded)
      seed_alpha(u_shaft, u_hub, f1, f2);

    for (unsigned int i = 0; i < n; ++i)
      force[i] = f1[i] + rule->alpha(i) * (f2[i] - f1[i]);
    // A tensile blend is a violated contact condition: part of the residual.
    const bool clamping
      = active_set.enabled()
        && active_set.update_mode() == UnilateralActiveSet::Update::every_step;
    const double mismatch = interface.max_pressure_difference(f1, f2);
    const double tension  = clamping ? interface.max_tension(force) : 0.;
    const double magnitude
      = std::max(interface.max_pressure(f1), interface.max_pressure(f2));
    // No force anywhere (every point separated, or no interference): the
    // bodies agree exactly.
    last_traction_mismatch
      = magnitude > 0. ? std::max(mismatch, tension) / magnitude : 0.;
    if (!std::isfinite(last_traction_mismatch))
      last_traction_mismatch = std::numeric_limits<double>::quiet_NaN();

    active_set.clamp(force);
    next_force = force;
    update_prior();
    accelerator->accelerate(neumann_force, next_force);
    active_set.clamp(next_force);

    history_rows.push_back(
      {static_cast<unsigned int>(history_rows.size() + 1),
       false,
       rule->representative_alpha(),
       interface.relative_gap_residual(u1, u2, active_set.in_contact()),
       last_traction_mismatch,
       active_set.n_separated()});
  }



  void
  StaggeredCoupling::use_coarse_model(
    std::unique_ptr<CoarseInterfaceModel> model)
  {
    coarse_model = std::move(model);
  }



  void
  StaggeredCoupling::start_from(const Vector<double>    &force,
                                const std::vector<bool> &contact,
                                const unsigned int       coarse_steps)
  {
    initial_force      = force;
    coarse_start_steps = coarse_steps;
    active_set.assume(contact);
    // Predicted flags are better than an update from a rough state.
    if (automatic_active_set_tolerance)
      initial_active_set_tolerance = std::max(1e-2, tolerance_floor);
  }



  void
  StaggeredCoupling::update_prior()
  {
    // Only with a fixed alpha is the accelerated map fixed; the model
    // learned across a change (Active set change = model) is kept.
    if (!coarse_model || !rule->estimated())
      return;
    const unsigned int  n = force.size();
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
    ++n_coarse_priors;
  }



  void
  StaggeredCoupling::scale_first_load()
  {
    // The first Neumann step applied a uniform unit pressure. The bodies
    // are linear: the uniform pressure s that closes the gap best (least
    // squares with the weights w, s = sum w d_i du / sum w du^2, du =
    // u2 - u1) is the same step scaled by s. With nothing to close
    // (clearance everywhere) the start is the paper's zero force.
    double num = 0., den = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      {
        const double du = u2[i] - u1[i];
        num += interface.weights()[i] * interface.interference(i) * du;
        den += interface.weights()[i] * du * du;
      }
    const double s
      = (den > 0. && num > 0. && std::isfinite(num / den)) ? num / den : 0.;
    force *= s;
    u1 *= s;
    u2 *= s;
    start_loaded = s > 0.;
  }



  void
  StaggeredCoupling::seed_alpha(const Vector<double> &u_shaft,
                                const Vector<double> &u_hub,
                                Vector<double>       &f1,
                                Vector<double>       &f2)
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
    const double k1     = winkler_compliance(u_shaft, f1, interface.weights());
    const double k2     = winkler_compliance(u_hub, f2, interface.weights());
    if (!(k1 > 0.) || !(k2 > 0.))
      return; // no contact point, or nothing prescribed: keep alpha
    const double alpha = std::clamp(k2 / (k1 + k2), 1e-9, 1. - 1e-9);
    const double c1    = (1. - alpha) / (1. - alpha0);
    const double c2    = alpha / alpha0;
    u1 *= c1;
    f1 *= c1;
    u2 *= c2;
    f2 *= c2;
    rule->seed(alpha);
  }



  std::string
  StaggeredCoupling::suggested_alpha_range() const
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



  std::vector<double>
  StaggeredCoupling::latest_mismatches(const bool         neumann,
                                       const unsigned int count) const
  {
    std::vector<double> same_kind;
    for (auto it = history_rows.rbegin();
         it != history_rows.rend() && same_kind.size() < count;
         ++it)
      if (it->neumann == neumann)
        same_kind.push_back(neumann ? it->displacement_mismatch :
                                      it->traction_mismatch);
    return same_kind;
  }



  bool
  StaggeredCoupling::grew(const bool neumann, const unsigned int window) const
  {
    const std::vector<double> same_kind
      = latest_mismatches(neumann, window + 1);
    return same_kind.size() > window
           && std::is_sorted(same_kind.rbegin(),
                             same_kind.rend(),
                             [](double a, double b) { return a <= b; });
  }



  std::string
  StaggeredCoupling::divergence_reason() const
  {
    const CouplingStep &last     = history_rows.back();
    const bool          neumann  = last.neumann;
    const auto          residual = [neumann](const CouplingStep &s) {
      return neumann ? s.displacement_mismatch : s.traction_mismatch;
    };
    const double       current = residual(last);
    std::ostringstream s;
    s << std::setprecision(3);
    if (!std::isfinite(current))
      return "the residual is not a finite number";
    if (current > 1e3)
      return "the relative mismatch exceeds 1e3";
    if (current > 10. * tolerance)
      {
        // The same kind of residual grew in each of the last four steps of
        // that kind.
        // An accelerator's sequence is judged by both residuals: after a
        // restart (a change of the contact zone) its first steps may trade
        // one mismatch for the other while the other still falls.
        const unsigned int window = 4;
        if (grew(neumann, window) && (!accelerated || grew(!neumann, window)))
          {
            s << "the " << (neumann ? "displacement" : "traction")
              << " mismatch grew in each of the last " << window
              << " steps, from "
              << latest_mismatches(neumann, window + 1).back() << " to "
              << current;
            return s.str();
          }
      }
    // A stall: since the last active set change the iteration ran 60 steps
    // and the best mismatch of the last 30 is no better than before them.
    const unsigned int stall_window = 30;
    if (last.step < last_change_step + 2 * stall_window)
      return "";
    double recent = std::numeric_limits<double>::infinity();
    double before = std::numeric_limits<double>::infinity();
    for (const CouplingStep &step : history_rows)
      if (step.step > last_change_step)
        {
          double &level
            = (step.step + stall_window > last.step) ? recent : before;
          level = std::min(level,
                           std::max(step.displacement_mismatch,
                                    step.traction_mismatch));
        }
    if (recent < before)
      return "";
    s << "the iteration stalls: no progress in the last " << stall_window
      << " steps (best mismatch " << before << ")";
    return s.str();
  }



  void
  StaggeredCoupling::check_divergence() const
  {
    const std::string reason = divergence_reason();
    if (reason.empty())
      return;
    const CouplingStep &last = history_rows.back();
    const double        current
      = last.neumann ? last.displacement_mismatch : last.traction_mismatch;

    // Growth or a stall far below the start is the round-off floor of an
    // ill-conditioned interface problem, not a bad alpha.
    double best_displacement = std::numeric_limits<double>::infinity();
    double best_traction     = std::numeric_limits<double>::infinity();
    for (const CouplingStep &s : history_rows)
      if (s.neumann)
        best_displacement
          = std::min(best_displacement, s.displacement_mismatch);
      else
        best_traction = std::min(best_traction, s.traction_mismatch);
    const double       floor = std::max(best_displacement, best_traction);
    std::ostringstream msg;
    if (std::isfinite(current) && current < 1e-4)
      {
        msg << std::setprecision(2) << "the coupling iteration stopped "
            << "improving at step " << last.step << " (" << reason
            << "): the mismatches reached |du|/d = " << best_displacement
            << " and |dp|/p = " << best_traction
            << ", the round-off level of this problem (the forces are "
            << "differences of large nodal reactions; thin walls, with cells "
            << "of large aspect ratio, raise that level); set "
            << "Coupling/Tolerance above " << 2. * floor
            << " or mesh with cells closer to square (Mesh/Axial cells, "
            << "Radial cells and Grading ratio in the proportions of the "
            << "walls).";
        throw SolverError(msg.str());
      }
    msg << "the coupling iteration failed at step " << last.step << " with ";
    if (block_model)
      msg << "Accelerator = ibqn";
    else
      msg << "Coupling/Alpha rule = " << rule->name()
          << " and Accelerator = " << accelerator->name()
          << ", alpha = " << std::setprecision(4)
          << rule->representative_alpha();
    msg << ": " << reason << "; ";
    // Advice that fits what ran: a constant alpha can be changed or
    // accelerated; an accelerated run that fails has the monolithic solver
    // left (the same discrete problem, solved at once).
    if (block_model)
      msg << "the models of the bodies' compliances could not recover; "
          << "try Coupling/Alpha controller = iqn-ils, or solve this scene "
          << "with Solver/Method = monolithic.";
    else if (accelerator->name() == "iqn-ils")
      msg << "the quasi-Newton iteration could not recover; solve this "
          << "scene with Solver/Method = monolithic ("
          << suggested_alpha_range() << ").";
    else
      msg << suggested_alpha_range()
          << " (a Winkler estimate; thin walls can leave no convergent "
          << "constant alpha: then use Coupling/Alpha controller = iqn-ils).";
    throw SolverError(msg.str());
  }



  void
  StaggeredCoupling::print_step(std::ostream &out) const
  {
    const CouplingStep &s = history_rows.back();
    std::ostringstream  line;
    line << std::setw(6) << s.step << "  "
         << (s.neumann ? "Neumann  " : "Dirichlet") << "  " << std::fixed
         << std::setprecision(4);
    if (std::isfinite(s.alpha))
      line << s.alpha;
    else
      line << "     -"; // the interface block model has no alpha
    line << "  " << std::scientific << std::setprecision(3);
    if (s.neumann)
      line << s.displacement_mismatch << "   -";
    else
      line << "-           " << s.traction_mismatch;
    if (active_set.enabled())
      line << "   " << std::setw(4) << s.n_separated;
    out << line.str() << std::endl;
  }



  bool
  StaggeredCoupling::run(std::ostream *progress)
  {
    const unsigned int n = interface.n_points();
    force.reinit(n);
    next_force.reinit(n);
    // The adaptive rules start from a loaded first Neumann step (a uniform
    // pressure, scaled after the step), whose compliances give the
    // Winkler alpha of the first Dirichlet step; the fixed rule from the
    // paper's zero approximation.
    start_loaded = rule->adaptive() || block_model;
    if (start_loaded)
      next_force = interface.weights();
    if (initial_force.size() == n)
      {
        next_force   = initial_force;
        start_loaded = true;
      }
    if (block_model)
      {
        // The maps F -> u are linear (the displacements of loads of
        // operation are part of the interference): no force, no
        // displacement, an exact sample that makes the model independent
        // of the scale of the first one.
        block_model->clear_samples();
        const Vector<double> zero(n);
        block_model->add_sample(InterfaceBlockModel::shaft, zero, zero);
        block_model->add_sample(InterfaceBlockModel::hub, zero, zero);
        if (coarse_model && !block_model->has_prior())
          {
            block_model->set_prior(InterfaceBlockModel::shaft,
                                   coarse_model->compliance_prior(0));
            block_model->set_prior(InterfaceBlockModel::hub,
                                   coarse_model->compliance_prior(1));
            ++n_coarse_priors;
          }
      }
    u1.reinit(n);
    u2.reinit(n);
    history_rows.clear();
    active_set_tolerance       = initial_active_set_tolerance;
    visited_sets               = {active_set.in_contact()};
    has_converged              = false;
    last_displacement_mismatch = std::numeric_limits<double>::infinity();
    last_traction_mismatch     = std::numeric_limits<double>::infinity();

    if (progress)
      *progress << "  step  kind       alpha   |du|/d      |dp|/p"
                << (active_set.enabled() ? "      separated" : "") << '\n';

    while (history_rows.size() < max_steps)
      {
        if (history_rows.size() % 2 == 0)
          neumann_step();
        else
          dirichlet_step();
        if (progress)
          print_step(*progress);
        if (last_displacement_mismatch < tolerance
            && last_traction_mismatch < tolerance && active_set_verified)
          {
            has_converged = true;
            break;
          }
        check_divergence();
      }
    return has_converged;
  }



  std::pair<Vector<double>, Vector<double>>
  StaggeredCoupling::solve_fields()
  {
    // One full solve per body with the final contact force.
    const std::vector<bool> none(force.size(), false);
    const Vector<double>    zero(force.size());
    Vector<double>          shaft_field, hub_field;
    concurrently(
      [&]() { shaft_field = shaft_solver.solve_field(none, zero, force); },
      [&]() { hub_field = hub_solver.solve_field(none, zero, force); });
    return {shaft_field, hub_field};
  }



  SolverStatistics
  StaggeredCoupling::statistics() const
  {
    SolverStatistics s;
    s.method      = "staggered";
    s.alpha_rule  = rule->name();
    s.accelerator = block_model ? "ibqn" : accelerator->name();
    if (coarse_model)
      {
        s.coarse_model_points = coarse_model->n_coarse_points();
        s.coarse_priors       = n_coarse_priors;
        s.coarse_start_steps  = coarse_start_steps;
      }
    s.factorizations = {{"shaft", shaft_solver.n_factorizations()},
                        {"hub", hub_solver.n_factorizations()}};
    if (&shaft != &shaft_solver)
      {
        s.factorizations["shaft_interface"] = shaft.n_factorizations();
        s.factorizations["hub_interface"]   = hub.n_factorizations();
      }
    s.solves
      = {{"shaft", shaft_solver.n_solves()}, {"hub", hub_solver.n_solves()}};
    return s;
  }
} // namespace coaxfit
