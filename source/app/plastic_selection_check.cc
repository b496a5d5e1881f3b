#include <coaxfit/app/fit_selection_study.h>
#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/io/result_writers.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** The figures a selection takes from the load path @p fit followed. */
    FitSelection::PlasticState
    state_of(const PlasticFit &fit, const Parameters &parameters)
    {
      FitSelection::PlasticState state;
      const auto                &stages = fit.stage_results();
      state.completed        = !stages.empty() && stages.back().completed;
      state.failure          = fit.failure_text();
      state.elastic_fraction = fit.elastic_limit();
      state.plastic_diameter = parameters.drawing.joint_diameter;
      double least           = std::numeric_limits<double>::infinity();
      for (const PlasticFit::StageResult &stage : stages)
        {
          // The zone never shrinks along the path: its largest is the last.
          const PlasticFit::BodyFigures &hub = stage.figures[1];
          if (hub.yields && hub.utilisation > state.utilisation)
            {
              state.utilisation       = hub.utilisation;
              state.plastic_diameter  = hub.plastic_diameter_mid;
              state.utilisation_stage = to_string(stage.kind);
            }
          if (stage.normal_force < least)
            {
              least             = stage.normal_force;
              state.least_stage = to_string(stage.kind);
            }
        }
      state.least_normal_force = std::isfinite(least) ? least : 0.;
      if (!stages.empty())
        state.joined_pressure = stages.front().p_mean;
      return state;
    }
  } // namespace



  FitSelection::PlasticState
  FitSelectionStudy::follow_load_path(const Parameters &parameters)
  {
    std::ostringstream quiet;
    PlasticFit         fit(parameters, quiet, false);
    fit.compute();
    return state_of(fit, parameters);
  }



  bool
  FitSelectionStudy::check_plastic(const FitSelection &selection,
                                   const std::string  &fit,
                                   const std::string  &directory,
                                   const std::string  &section,
                                   Verdict            &verdict)
  {
    const Parameters checked = checking(parameters, fit);
    if (verbose)
      out << "coaxfit: the first fit, " << fit
          << ", checked on the elastic-plastic load paths of its least and "
             "largest interference (Fit/Case = min and max)\n";
    bool               completed = true;
    std::ostringstream table;
    table << "## The first fit on its load paths\n\n"
          << fit
          << " at its least interference (slip) and its largest (the hub's "
             "plastic utilisation, allowed "
          << figure_text(selection.allowed_utilisation, 4)
          << "); each case's files in its directory.\n\n| case | U (mm) | "
             "hub utilisation | D_p (mm) | slip | least | joined mean p "
             "(MPa) |\n|---|---:|---:|---:|---:|---|---:|\n";
    verdict.failed.clear();
    for (const FitCase c : {FitCase::min, FitCase::max})
      {
        Parameters p            = checked.for_fit_case(c);
        p.fit.fit_case          = c;
        p.load_path.stages_text = FitSelection::load_path_stages(p);
        const auto        name  = to_string(c);
        const std::string sub   = directory + "/" + name;
        std::filesystem::create_directory(sub);
        PlasticFit run(p, out, verbose);
        const int  code = run.run_in(sub);
        // The figures from the case's own load path; a case that stays
        // elastic runs the elastic code, whose path is then followed here.
        const FitSelection::PlasticState state = run.stage_results().empty() ?
                                                   follow_load_path(p) :
                                                   state_of(run, p);
        const double slip = selection.slip_safety_of(state.least_normal_force);
        const double U    = 2. * p.geometry.d + p.fit_limits.smoothing_loss;
        completed         = completed && code == 0 && state.completed;
        table << "| " << name << " | " << figure_text(U, 5) << " | "
              << figure_text(state.utilisation, 4) << " | "
              << figure_text(state.plastic_diameter, 5) << " | "
              << figure_text(slip, 4) << " | "
              << FitSelection::stage_words(state.least_stage) << " | "
              << figure_text(state.joined_pressure, 5) << " |\n";
        if (!state.completed)
          verdict.failed.push_back(name
                                   + ": the load path was not "
                                     "completed: "
                                   + state.failure);
        if (c == FitCase::min && slip < parameters.design.slip_safety)
          verdict.failed.push_back(
            name + ": safety against slip " + figure_text(slip, 4) + " < "
            + figure_text(parameters.design.slip_safety, 4) + " "
            + FitSelection::stage_words(state.least_stage));
        // The selection aims at most at the allowed utilisation; a fit
        // inside its band stays below it up to the load path's error.
        if (c == FitCase::max
            && state.utilisation > (1. + 1e-3) * selection.allowed_utilisation)
          verdict.failed.push_back(
            name + ": plastic utilisation of the hub "
            + figure_text(state.utilisation, 4) + " > "
            + figure_text(selection.allowed_utilisation, 4));
      }
    write_report(directory,
                 ", the hub may yield",
                 verdict,
                 section + table.str() + '\n');
    out << verdict.line() << '\n';
    return completed;
  }
} // namespace coaxfit
