#include <deal.II/base/thread_management.h>

#include <coaxfit/input_error.h>
#include <coaxfit/staggered_coupling.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** Run two jobs concurrently and wait for both. */
    template <typename F1, typename F2>
    void
    concurrently(const F1 &job1, const F2 &job2)
    {
      Threads::Task<void> task = Threads::new_task(job1);
      job2();
      task.join();
    }
  } // namespace



  StaggeredCoupling::StaggeredCoupling(InterfaceOperator         &shaft,
                                       InterfaceOperator         &hub,
                                       const ContactInterface    &interface,
                                       AlphaController           &controller,
                                       const double               tolerance,
                                       const unsigned int         max_steps,
                                       const UnilateralActiveSet &active_set,
                                       const double active_set_tolerance)
    : InterfaceSolver(active_set)
    , shaft(shaft)
    , hub(hub)
    , interface(interface)
    , controller(controller)
    , tolerance(tolerance)
    , max_steps(max_steps)
    , active_set_tolerance(std::max(active_set_tolerance, tolerance))
  {}



  double
  StaggeredCoupling::relative_gap_residual() const
  {
    // At contact points the gap must vanish; separated points carry no
    // force and may open (gap >= 0) but must not penetrate.
    const double             d        = interface.interference();
    const std::vector<bool> &contact  = active_set.in_contact();
    double                   mismatch = 0.;
    for (unsigned int i = 0; i < u1.size(); ++i)
      {
        const double gap = u2[i] - u1[i] - d;
        mismatch = std::max(mismatch, contact[i] ? std::abs(gap) : -gap);
      }
    const double r = mismatch / d;
    return std::isfinite(r) ? r : std::numeric_limits<double>::quiet_NaN();
  }



  void
  StaggeredCoupling::neumann_step()
  {
    force = next_force;
    concurrently([&]() { shaft.solve_neumann(force, u1); },
                 [&]() { hub.solve_neumann(force, u2); });

    // The paper updates the flags after every Neumann step; the outer
    // (primal-dual) mode once the iteration has converged for the current
    // set to the active-set tolerance.
    active_set_changed  = false;
    active_set_verified = false;
    if (active_set.update_mode() == UnilateralActiveSet::Update::every_step
        || (relative_gap_residual() < active_set_tolerance
            && last_traction_mismatch < active_set_tolerance))
      {
        std::vector<double> gap(force.size());
        for (unsigned int i = 0; i < force.size(); ++i)
          gap[i] = u2[i] - u1[i] - interface.interference();
        active_set_changed  = active_set.update(force, gap);
        active_set_verified = !active_set_changed;
        if (active_set_changed)
          {
            controller.restart();
            // Each outer update starts a new inner iteration; in the
            // paper's every-step mode changes are part of the iteration.
            if (active_set.update_mode()
                == UnilateralActiveSet::Update::when_converged)
              last_change_step = history_rows.size() + 1;
          }
      }
    last_displacement_mismatch = relative_gap_residual();

    neumann_force = force;
    neumann_u1    = u1;
    neumann_u2    = u2;
    history_rows.push_back({static_cast<unsigned int>(history_rows.size() + 1),
                            true,
                            controller.representative_alpha(),
                            last_displacement_mismatch,
                            0.,
                            active_set.n_separated()});
  }



  void
  StaggeredCoupling::dirichlet_step()
  {
    const unsigned int       n       = force.size();
    const double             d       = interface.interference();
    const std::vector<bool> &contact = active_set.in_contact();
    std::vector<double>      u_shaft(n), u_hub(n), zero(n, 0.), f1, f2;
    for (unsigned int i = 0; i < n; ++i)
      {
        u_shaft[i] = u1[i] + (1. - controller.alpha(i)) * (u2[i] - d - u1[i]);
        u_hub[i]   = u_shaft[i] + d;
      }
    // Contact points get the blended displacement, separated points stay
    // traction free in both bodies.
    concurrently([&]() { shaft.solve(contact, u_shaft, zero, u1, f1); },
                 [&]() { hub.solve(contact, u_hub, zero, u2, f2); });

    const std::vector<double> &w        = interface.weights();
    double                     mismatch = 0., tension = 0., magnitude = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        force[i] = f1[i] + controller.alpha(i) * (f2[i] - f1[i]);
        mismatch = std::max(mismatch, std::abs(f2[i] - f1[i]) / w[i]);
        if (active_set.enabled()
            && active_set.update_mode()
                 == UnilateralActiveSet::Update::every_step)
          tension = std::max(tension, -force[i] / w[i]);
        magnitude = std::max(
          {magnitude, std::abs(f1[i]) / w[i], std::abs(f2[i]) / w[i]});
      }
    // A tensile blend is a violated contact condition: part of the residual.
    last_traction_mismatch = std::max(mismatch, tension) / magnitude;
    if (!std::isfinite(last_traction_mismatch))
      last_traction_mismatch = std::numeric_limits<double>::quiet_NaN();

    active_set.clamp(force);
    next_force = force;
    controller.accelerate(neumann_force, next_force);
    active_set.clamp(next_force);

    history_rows.push_back({static_cast<unsigned int>(history_rows.size() + 1),
                            false,
                            controller.representative_alpha(),
                            relative_gap_residual(),
                            last_traction_mismatch,
                            active_set.n_separated()});
  }



  std::string
  StaggeredCoupling::suggested_alpha_range() const
  {
    // Energy-weighted Winkler compliances k_i = u_i / p of the last Neumann
    // step with a non-zero load; for a Winkler pair the process contracts
    // for |alpha rho - (1 - alpha)/rho| < 1, rho = sqrt(k1/k2), and is
    // exact for alpha = k2 / (k1 + k2), formula (4.20).
    double work1 = 0., work2 = 0., load = 0.;
    for (unsigned int i = 0; i < neumann_force.size(); ++i)
      {
        work1 -= neumann_u1[i] * neumann_force[i];
        work2 += neumann_u2[i] * neumann_force[i];
        load += neumann_force[i] * neumann_force[i] / interface.weights()[i];
      }
    std::ostringstream msg;
    if (!(load > 0.) || !(work1 > 0.) || !(work2 > 0.)
        || !std::isfinite(work1 + work2))
      {
        msg << "try a value of Coupling/Alpha closer to the paper's table";
        return msg.str();
      }
    const double k1  = work1 / load;
    const double k2  = work2 / load;
    const double rho = std::sqrt(k1 / k2);
    const double lo  = std::max(0., (1. / rho - 1.) / (rho + 1. / rho));
    const double hi  = std::min(1., (1. / rho + 1.) / (rho + 1. / rho));
    msg << std::setprecision(3) << "the compliances of the bodies suggest "
        << "Coupling/Alpha in (" << lo << ", " << hi << "), best near "
        << k2 / (k1 + k2);
    return msg.str();
  }



  void
  StaggeredCoupling::check_divergence() const
  {
    const CouplingStep &last     = history_rows.back();
    const bool          neumann  = last.neumann;
    const auto          residual = [neumann](const CouplingStep &s) {
      return neumann ? s.displacement_mismatch : s.traction_mismatch;
    };
    const double current = residual(last);
    std::string  reason;
    if (!std::isfinite(current))
      reason = "the residual is not a finite number";
    else if (current > 1e3)
      reason = "the relative mismatch exceeds 1e3";
    else if (current > 10. * tolerance)
      {
        // The same kind of residual grew in each of the last four steps of
        // that kind.
        const unsigned int  window = 4;
        std::vector<double> same_kind;
        for (auto it = history_rows.rbegin();
             it != history_rows.rend() && same_kind.size() <= window;
             ++it)
          if (it->neumann == neumann)
            same_kind.push_back(residual(*it));
        if (same_kind.size() > window
            && std::is_sorted(same_kind.rbegin(),
                              same_kind.rend(),
                              [](double a, double b) { return a <= b; }))
          {
            std::ostringstream s;
            s << std::setprecision(3) << "the "
              << (neumann ? "displacement" : "traction")
              << " mismatch grew in each of the last " << window
              << " steps, from " << same_kind.back() << " to " << current;
            reason = s.str();
          }
      }
    // A stall: since the last active set change the iteration ran 60 steps
    // and the best mismatch of the last 30 is no better than before them.
    const unsigned int stall_window = 30;
    if (reason.empty() && last.step >= last_change_step + 2 * stall_window)
      {
        const auto level = [](const CouplingStep &s) {
          return std::max(s.displacement_mismatch, s.traction_mismatch);
        };
        double recent = std::numeric_limits<double>::infinity();
        double before = std::numeric_limits<double>::infinity();
        for (const CouplingStep &s : history_rows)
          if (s.step > last_change_step)
            (s.step + stall_window > last.step ? recent : before)
              = std::min(s.step + stall_window > last.step ? recent : before,
                         level(s));
        if (recent >= before)
          {
            std::ostringstream s;
            s << std::setprecision(3) << "the iteration stalls: no progress "
              << "in the last " << stall_window << " steps (best mismatch "
              << before << ")";
            reason = s.str();
          }
      }
    if (reason.empty())
      return;

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
    const double floor = std::max(best_displacement, best_traction);
    if (std::isfinite(current) && current < 1e-4)
      {
        std::ostringstream msg;
        msg << std::setprecision(2) << "the coupling iteration stopped "
            << "improving at step " << last.step << " (" << reason
            << "): the mismatches reached |du|/d = " << best_displacement
            << " and |dp|/p = " << best_traction
            << ", the round-off level of this problem (thin walls give "
            << "cells of large aspect ratio and an ill-conditioned "
            << "interface problem); set Coupling/Tolerance above " << 2. * floor
            << " or use fewer Mesh/Radial cells.";
        throw SolverError(msg.str());
      }

    std::ostringstream msg;
    msg << "the coupling iteration failed at step " << last.step
        << " with Coupling/Alpha controller = " << controller.name()
        << ", alpha = " << std::setprecision(4)
        << controller.representative_alpha() << ": " << reason << "; "
        << suggested_alpha_range()
        << " (a Winkler estimate; thin walls can leave no convergent "
        << "constant alpha: then use Coupling/Alpha controller = iqn-ils).";
    throw SolverError(msg.str());
  }



  bool
  StaggeredCoupling::run(std::ostream *progress)
  {
    const unsigned int n = interface.n_points();
    force.assign(n, 0.); // the paper's zero approximation
    next_force = force;
    u1.assign(n, 0.);
    u2.assign(n, 0.);
    history_rows.clear();
    has_converged              = false;
    last_displacement_mismatch = std::numeric_limits<double>::infinity();
    last_traction_mismatch     = std::numeric_limits<double>::infinity();

    if (progress)
      *progress << "  step  kind       alpha   |du|/d      |dp|/p"
                << (active_set.enabled() ? "      separated" : "") << '\n';

    while (history_rows.size() < max_steps)
      {
        if (history_rows.size() % 2 == 0)
          {
            neumann_step();
            controller.update({history_rows.back().step,
                               force,
                               u1,
                               u2,
                               interface.weights(),
                               last_displacement_mismatch});
          }
        else
          dirichlet_step();

        const CouplingStep &s = history_rows.back();
        if (progress)
          {
            std::ostringstream line;
            line << std::setw(6) << s.step << "  "
                 << (s.neumann ? "Neumann  " : "Dirichlet") << "  "
                 << std::fixed << std::setprecision(4) << s.alpha << "  "
                 << std::scientific << std::setprecision(3);
            if (s.neumann)
              line << s.displacement_mismatch << "   -";
            else
              line << "-           " << s.traction_mismatch;
            if (active_set.enabled())
              line << "   " << std::setw(4) << s.n_separated;
            *progress << line.str() << std::endl;
          }
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



} // namespace coaxfit
