#include <algorithm>
#include <cmath>
#include <coaxfit/input_error.h>
#include <coaxfit/staggered_coupling.h>
#include <deal.II/base/thread_management.h>
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



  StaggeredCoupling::StaggeredCoupling(Body                   &shaft,
                                       Body                   &hub,
                                       const ContactInterface &interface,
                                       AlphaController        &controller,
                                       const double            tolerance,
                                       const unsigned int      max_steps)
    : shaft(shaft)
    , hub(hub)
    , interface(interface)
    , controller(controller)
    , tolerance(tolerance)
    , max_steps(max_steps)
    , last_displacement_mismatch(std::numeric_limits<double>::infinity())
    , last_traction_mismatch(std::numeric_limits<double>::infinity())
  {}



  void
  StaggeredCoupling::neumann_step()
  {
    force = next_force;
    concurrently([&]() { shaft.solve_neumann(force, u1); },
                 [&]() { hub.solve_neumann(force, u2); });

    const double d        = interface.interference();
    double       mismatch = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      mismatch = std::max(mismatch, std::abs(u2[i] - u1[i] - d));
    last_displacement_mismatch = mismatch / d;
    if (!std::isfinite(last_displacement_mismatch))
      last_displacement_mismatch = std::numeric_limits<double>::quiet_NaN();

    neumann_force = force;
    neumann_u1    = u1;
    neumann_u2    = u2;
    history_rows.push_back({static_cast<unsigned int>(history_rows.size() + 1),
                            true,
                            controller.representative_alpha(),
                            last_displacement_mismatch,
                            0.});
  }



  void
  StaggeredCoupling::dirichlet_step()
  {
    const unsigned int  n = force.size();
    const double        d = interface.interference();
    std::vector<double> u_shaft(n), u_hub(n), f1, f2;
    for (unsigned int i = 0; i < n; ++i)
      {
        u_shaft[i] = u1[i] + (1. - controller.alpha(i)) * (u2[i] - d - u1[i]);
        u_hub[i]   = u_shaft[i] + d;
      }
    concurrently([&]() { shaft.solve_dirichlet(u_shaft, f1); },
                 [&]() { hub.solve_dirichlet(u_hub, f2); });

    const std::vector<double> &w         = interface.weights();
    double                     mismatch  = 0.;
    double                     magnitude = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        mismatch  = std::max(mismatch, std::abs(f2[i] - f1[i]) / w[i]);
        magnitude = std::max(
          {magnitude, std::abs(f1[i]) / w[i], std::abs(f2[i]) / w[i]});
      }
    last_traction_mismatch = mismatch / magnitude;
    if (!std::isfinite(last_traction_mismatch))
      last_traction_mismatch = std::numeric_limits<double>::quiet_NaN();

    u1 = u_shaft;
    u2 = u_hub;
    for (unsigned int i = 0; i < n; ++i)
      force[i] = f1[i] + controller.alpha(i) * (f2[i] - f1[i]);
    next_force = force;
    controller.accelerate(neumann_force, next_force);

    history_rows.push_back({static_cast<unsigned int>(history_rows.size() + 1),
                            false,
                            controller.representative_alpha(),
                            0.,
                            last_traction_mismatch});
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
    if (reason.empty())
      return;

    std::ostringstream msg;
    msg << "the coupling iteration diverged at step " << last.step
        << " with Coupling/Alpha controller = " << controller.name()
        << ", alpha = " << std::setprecision(4)
        << controller.representative_alpha() << ": " << reason << "; "
        << suggested_alpha_range() << '.';
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
      *progress << "  step  kind       alpha   |du|/d      |dp|/p\n";

    while (history_rows.size() < max_steps)
      {
        if (history_rows.size() % 2 == 0)
          {
            neumann_step();
            controller.update(
              {history_rows.back().step, force, u1, u2, interface.weights()});
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
            *progress << line.str() << std::endl;
          }
        if (last_displacement_mismatch < tolerance
            && last_traction_mismatch < tolerance)
          {
            has_converged = true;
            break;
          }
        check_divergence();
      }
    return has_converged;
  }



  unsigned int
  StaggeredCoupling::steps_to_displacement_mismatch(
    const double criterion) const
  {
    for (const CouplingStep &s : history_rows)
      if (s.neumann && s.displacement_mismatch < criterion)
        return s.step;
    return 0;
  }
} // namespace coaxfit
