#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/convergence_monitor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace coaxfit
{
  ConvergenceMonitor::ConvergenceMonitor(const double tolerance,
                                         const bool   judge_both)
    : tolerance(tolerance)
    , judge_both(judge_both)
  {}



  void
  ConvergenceMonitor::start()
  {
    last_change_step = 0;
  }



  void
  ConvergenceMonitor::new_inner_iteration(const unsigned int step)
  {
    last_change_step = step;
  }



  std::vector<double>
  ConvergenceMonitor::latest_mismatches(
    const std::vector<CouplingStep> &history,
    const bool                       neumann,
    const unsigned int               count)
  {
    std::vector<double> same_kind;
    for (auto it = history.rbegin();
         it != history.rend() && same_kind.size() < count;
         ++it)
      if (it->neumann == neumann)
        same_kind.push_back(neumann ? it->displacement_mismatch :
                                      it->traction_mismatch);
    return same_kind;
  }



  bool
  ConvergenceMonitor::grew(const std::vector<CouplingStep> &history,
                           const bool                       neumann,
                           const unsigned int               window)
  {
    const std::vector<double> same_kind
      = latest_mismatches(history, neumann, window + 1);
    return same_kind.size() > window
           && std::is_sorted(same_kind.rbegin(),
                             same_kind.rend(),
                             [](double a, double b) { return a <= b; });
  }



  std::string
  ConvergenceMonitor::divergence_reason(
    const std::vector<CouplingStep> &history) const
  {
    const CouplingStep &last     = history.back();
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
        if (grew(history, neumann, window)
            && (!judge_both || grew(history, !neumann, window)))
          {
            s << "the " << (neumann ? "displacement" : "traction")
              << " mismatch grew in each of the last " << window
              << " steps, from "
              << latest_mismatches(history, neumann, window + 1).back()
              << " to " << current;
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
    for (const CouplingStep &step : history)
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
  ConvergenceMonitor::fail(const std::vector<CouplingStep> &history,
                           const std::string               &reason,
                           const std::string               &method,
                           const std::string               &advice) const
  {
    const CouplingStep &last = history.back();
    const double        current
      = last.neumann ? last.displacement_mismatch : last.traction_mismatch;

    // Growth or a stall far below the start is the round-off floor of an
    // ill-conditioned interface problem, not a bad alpha.
    double best_displacement = std::numeric_limits<double>::infinity();
    double best_traction     = std::numeric_limits<double>::infinity();
    for (const CouplingStep &s : history)
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
    msg << "the coupling iteration failed at step " << last.step << " with "
        << method << ": " << reason << "; " << advice;
    throw SolverError(msg.str());
  }



  void
  ConvergenceMonitor::print_header(std::ostream &out, const bool separated)
  {
    out << "  step  kind       alpha   |du|/d      |dp|/p"
        << (separated ? "      separated" : "") << '\n';
  }



  void
  ConvergenceMonitor::print_step(std::ostream       &out,
                                 const CouplingStep &s,
                                 const bool          separated)
  {
    std::ostringstream line;
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
    if (separated)
      line << "   " << std::setw(4) << s.n_separated;
    out << line.str() << std::endl;
  }
} // namespace coaxfit
