#include <coaxfit/base/concurrency.h>
#include <coaxfit/coupling/staggered_coupling.h>

#include <cmath>

namespace coaxfit
{
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
    , update(make_coupling_update(parameters,
                                  interface,
                                  this->active_set,
                                  active_set_tolerance))
    , monitor(parameters.tolerance,
              parameters.accelerator() != AcceleratorType::none)
    , tolerance(parameters.tolerance)
    , max_steps(parameters.max_steps)
  {}



  void
  StaggeredCoupling::neumann_step()
  {
    const unsigned int steps_taken = history_rows.size();
    state.force                    = next_force;
    concurrently([&]() { shaft.solve_neumann(state.force, state.u1); },
                 [&]() { hub.solve_neumann(state.force, state.u2); });
    update->sample_neumann(state);
    if (steps_taken == 0 && start_loaded && initial_force.size() == 0)
      scale_first_load();
    const NeumannOutcome outcome = update->after_neumann(state,
                                                         steps_taken,
                                                         next_force,
                                                         active_set_verified);
    if (outcome.new_inner_iteration)
      monitor.new_inner_iteration(steps_taken + 1);
    history_rows.push_back({steps_taken + 1,
                            true,
                            outcome.alpha,
                            state.displacement_mismatch,
                            0.,
                            outcome.n_separated});
  }



  void
  StaggeredCoupling::dirichlet_step()
  {
    const unsigned int      n           = interface.n_points();
    const unsigned int      steps_taken = history_rows.size();
    const std::vector<bool> contact     = active_set.in_contact();
    Vector<double>          u_shaft(n), u_hub(n), zero(n), f1, f2;
    update->dirichlet_data(state, u_shaft, u_hub);
    // Contact points get the prescribed displacement, separated points
    // stay traction free in both bodies.
    concurrently([&]() { shaft.solve(contact, u_shaft, zero, state.u1, f1); },
                 [&]() { hub.solve(contact, u_hub, zero, state.u2, f2); });
    const unsigned int n_separated = active_set.n_separated();
    const double       alpha
      = update->after_dirichlet(state,
                                steps_taken == 1 && !start_loaded,
                                u_shaft,
                                u_hub,
                                f1,
                                f2,
                                next_force,
                                active_set_verified);
    history_rows.push_back(
      {steps_taken + 1,
       false,
       alpha,
       interface.relative_gap_residual(state.u1, state.u2, contact),
       state.traction_mismatch,
       n_separated});
  }



  void
  StaggeredCoupling::use_coarse_model(
    std::unique_ptr<CoarseInterfaceModel> model)
  {
    coarse_model = std::move(model);
    update->use_coarse_model(coarse_model.get());
  }



  void
  StaggeredCoupling::start_from(const Vector<double>    &force,
                                const std::vector<bool> &contact,
                                const unsigned int       coarse_steps)
  {
    initial_force      = force;
    coarse_start_steps = coarse_steps;
    active_set.assume(contact);
  }



  void
  StaggeredCoupling::scale_first_load()
  {
    // The first Neumann step applied a uniform unit pressure. The bodies
    // are linear: the uniform pressure s that closes the gap best (least
    // squares with the weights w, s = sum w d_i du / sum w du^2, du =
    // u2 - u1) is the same step scaled by s. With nothing to close
    // (clearance everywhere) the start is the paper's zero force.
    double                num = 0., den = 0.;
    const Vector<double> &gap = interface.drawing_gap();
    for (unsigned int i = 0; i < state.force.size(); ++i)
      {
        if (gap.size() > 0 && gap[i] > 0.)
          continue; // open by its shape (a rounded edge)
        const double du = state.u2[i] - state.u1[i];
        num += interface.weights()[i] * interface.interference(i) * du;
        den += interface.weights()[i] * du * du;
      }
    const double s
      = (den > 0. && num > 0. && std::isfinite(num / den)) ? num / den : 0.;
    state.force *= s;
    state.u1 *= s;
    state.u2 *= s;
    start_loaded = s > 0.;
  }



  bool
  StaggeredCoupling::run(std::ostream *progress)
  {
    const unsigned int n = interface.n_points();
    state.force.reinit(n);
    next_force.reinit(n);
    start_loaded = update->loaded_start();
    if (start_loaded)
      {
        // A uniform unit pressure on the joint (not on a rounded edge
        // beyond it, open by its shape).
        next_force                = interface.weights();
        const Vector<double> &gap = interface.drawing_gap();
        for (unsigned int i = 0; i < gap.size(); ++i)
          if (gap[i] > 0.)
            next_force[i] = 0.;
      }
    if (initial_force.size() == n)
      {
        next_force   = initial_force;
        start_loaded = true;
      }
    update->start(initial_force.size() == n);
    monitor.start();
    state.u1.reinit(n);
    state.u2.reinit(n);
    history_rows.clear();
    has_converged               = false;
    active_set_verified         = false;
    state.displacement_mismatch = std::numeric_limits<double>::infinity();
    state.traction_mismatch     = std::numeric_limits<double>::infinity();

    if (progress)
      ConvergenceMonitor::print_header(*progress, active_set.enabled());
    while (history_rows.size() < max_steps)
      {
        if (history_rows.size() % 2 == 0)
          neumann_step();
        else
          dirichlet_step();
        if (progress)
          ConvergenceMonitor::print_step(*progress,
                                         history_rows.back(),
                                         active_set.enabled());
        if (state.displacement_mismatch < tolerance
            && state.traction_mismatch < tolerance && active_set_verified)
          {
            has_converged = true;
            break;
          }
        const std::string reason = monitor.divergence_reason(history_rows);
        if (!reason.empty())
          monitor.fail(history_rows,
                       reason,
                       update->description(),
                       update->failure_advice());
      }
    return has_converged;
  }



  std::pair<Vector<double>, Vector<double>>
  StaggeredCoupling::solve_fields()
  {
    // One full solve per body with the final contact force (on its own
    // joint points: the transposed transfer for a mortar side).
    const auto field = [&](BodySolver &solver, const unsigned int side) {
      const Vector<double> force
        = force_to_body ? force_to_body(side, state.force) : state.force;
      const std::vector<bool> none(force.size(), false);
      return solver.solve_field(none, Vector<double>(force.size()), force);
    };
    Vector<double> shaft_field, hub_field;
    concurrently([&]() { shaft_field = field(shaft_solver, 0); },
                 [&]() { hub_field = field(hub_solver, 1); });
    return {shaft_field, hub_field};
  }



  SolverStatistics
  StaggeredCoupling::statistics() const
  {
    SolverStatistics s;
    s.method      = "staggered";
    s.alpha_rule  = update->alpha_rule_name();
    s.accelerator = update->accelerator_name();
    if (coarse_model)
      {
        s.coarse_model_points = coarse_model->n_coarse_points();
        s.coarse_priors       = update->n_coarse_priors();
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
