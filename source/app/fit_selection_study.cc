#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/fit_selection_study.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/design/verdict.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/io/selection_writers.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace coaxfit
{
  FitSelectionStudy::FitSelectionStudy(const Parameters &parameters,
                                       std::ostream     &out,
                                       const bool        verbose)
    : parameters(parameters)
    , out(out)
    , verbose(verbose)
  {}



  Parameters
  FitSelectionStudy::checking(const Parameters  &parameters,
                              const std::string &fit)
  {
    Parameters p   = parameters;
    p.design.mode  = DesignMode::check;
    p.fit.iso_fit  = fit;
    p.fit.fit_case = FitCase::all;
    p.fit_limits   = fit_limits_of(p.fit, p.drawing.joint_diameter);
    p.geometry.d   = 0.5 * p.fit_limits.effective();
    // Its parameters.prm (and those of its cases) check this fit.
    p.used_prm = replace_prm_line(p.used_prm, "Mode", "check");
    p.used_prm = replace_prm_line(p.used_prm, "ISO fit", fit);
    p.used_prm = replace_prm_line(p.used_prm, "Case", "all");
    p.used_prm = replace_prm_line(p.used_prm, "Diametral interference", "");
    return p;
  }



  Parameters
  FitSelectionStudy::checking_push_on(const Parameters &parameters,
                                      const double      U_min,
                                      const double      U_max)
  {
    Parameters p        = parameters;
    p.design.mode       = DesignMode::check;
    p.fit.iso_fit       = "";
    p.fit.fit_case      = FitCase::all;
    const double C      = p.sections->taper();
    p.fit_limits.U_min  = U_min;
    p.fit_limits.U_max  = U_max;
    p.fit_limits.source = "push-on distances " + figure_text(U_min / C, 5)
                          + " to " + figure_text(U_max / C, 5) + " mm";
    p.fit_limits.fit_case  = FitCase::mean;
    p.geometry.d           = 0.5 * p.fit_limits.effective();
    p.fit.push_on_distance = p.fit_limits.used() / C;
    // Each case's parameters.prm (Parameters::for_fit_case) gives its
    // push-on distance and Case = mean.
    p.used_prm = replace_prm_line(p.used_prm, "Mode", "check");
    return p;
  }



  bool
  FitSelectionStudy::run()
  {
    check_memory(parameters);
    ResultDirectory directory(parameters.output_directory(),
                              all_result_file_names());
    const bool      converged = run_in(directory.staging_path());
    directory.commit(out);
    if (verbose)
      out << "  results in " << parameters.output_directory()
          << (mean_values.empty() ?
                "" :
                (parameters.sections && parameters.sections->conical() ?
                   " (the push-on distances' cases in min, mean, max)" :
                   " (the first fit's cases in min, mean, max)"))
          << '\n';
    return converged;
  }



  bool
  FitSelectionStudy::run_in(const std::string &staging)
  {
    if (verbose)
      out << "coaxfit: case " << parameters.case_name
          << ": fit selection (Design/Mode = select)\n";

    // One case set up once; every state of the selection reuses its
    // meshes and factorizations.
    // The elastic states: the bodies as elastic (a selection that lets
    // the hub yield follows its load paths with PlasticFit).
    const auto as_elastic = [](Parameters p) {
      p.shaft.plastic = false;
      p.hub.plastic   = false;
      return p;
    };
    std::ostringstream quiet;
    CoaxialFit         fit(FitSelection::at_interference(at_assembly(
                                                   as_elastic(parameters)),
                                                 parameters.fit_limits.used()),
                   quiet,
                   false);
    fit.setup_system();
    const FitSelection selection(
      parameters,
      [&](const Parameters &p) {
        fit.reuse_for(as_elastic(p));
        fit.solve(nullptr);
        return fit.solved_state();
      },
      &FitSelectionStudy::follow_load_path);

    std::ostringstream section;
    selection.print_markdown(section);
    std::ostringstream console;
    selection.print(console);
    out << console.str();

    bool        converged = true;
    std::string first_fit;
    Verdict     verdict = Verdict::no_fit(selection.conflict());
    if (selection.found() && selection.allowed_utilisation > 0.)
      {
        // The hub may yield: the first fit's ends on their load paths.
        first_fit = selection.fits.front().name;
        converged = check_plastic(
          selection, first_fit, staging, section.str(), verdict);
      }
    else if (selection.found())
      {
        // The first fit, or a taper's band of push-on distances, checked
        // as with Fit/Case = all.
        Parameters checked;
        if (selection.taper_fit())
          {
            checked = checking_push_on(parameters,
                                       selection.least.U,
                                       selection.largest.U);
            if (verbose)
              out << "coaxfit: the push-on distances from "
                  << figure_text(selection.push_on(selection.least.U), 5)
                  << " to "
                  << figure_text(selection.push_on(selection.largest.U), 5)
                  << " mm, checked at both ends and the middle\n";
          }
        else
          {
            first_fit = selection.fits.front().name;
            checked   = checking(parameters, first_fit);
            if (verbose)
              out << "coaxfit: the first fit, " << first_fit
                  << ", checked as with Fit/Case = all\n";
          }
        FitCaseStudy study(checked, out, verbose);
        study.set_report_section(section.str());
        converged = study.run_in(staging);
        verdict.failed.clear();
        for (const FitCaseStudy::Row &row : study.get_rows())
          {
            for (const std::string &f : row.failed)
              verdict.failed.push_back(to_string(row.fit_case) + ": " + f);
            if (row.fit_case == FitCase::mean)
              {
                mean_steps = row.steps;
                mean_values
                  = FitCaseStudy::values_of(row, CaseFigures::column_names());
              }
          }
      }
    else
      {
        // No fit: the verdict and the selection are the report.
        write_report(staging, "", verdict, section.str());
        out << verdict.line() << '\n';
      }

    const std::vector<std::string> lines{
      selection_files::write_csv(selection, staging),
      selection_files::write_summary(
        parameters.case_name, selection, verdict, first_fit, staging)};
    {
      const std::string name = staging + "/parameters.prm";
      std::ofstream     prm  = open_result_file(name);
      prm << parameters.used_prm;
      close_result_file(prm, name);
    }
    if (verbose)
      for (const std::string &line : lines)
        out << "  " << line << '\n';
    return converged;
  }



  void
  FitSelectionStudy::write_report(const std::string &directory,
                                  const std::string &title,
                                  const Verdict     &verdict,
                                  const std::string &body) const
  {
    if (!parameters.output.write_report)
      return;
    const std::string name   = directory + "/report.md";
    std::ofstream     report = open_result_file(name);
    report << "# coaxfit report: fit selection at D_F = "
           << parameters.drawing.joint_diameter << " mm" << title
           << "\n\n## Verdict\n\n"
           << verdict.line() << "\n\n"
           << body;
    close_result_file(report, name);
  }
} // namespace coaxfit
