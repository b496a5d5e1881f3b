#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/io/selection_writers.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** A figure of the table: 5 significant digits, "-" if not finite. */
    std::string
    value_cell(const double value)
    {
      std::ostringstream cell;
      if (std::isfinite(value))
        cell << std::setprecision(5) << value;
      else
        cell << '-';
      return cell.str();
    }

    /** "yes (steps)" or "NO (steps)". */
    std::string
    converged_cell(const FitCaseStudy::Row &row)
    {
      return (row.converged ? "yes (" : "NO (") + std::to_string(row.steps)
             + ")";
    }
  } // namespace



  FitCaseStudy::FitCaseStudy(const Parameters &parameters,
                             std::ostream     &out,
                             const bool        verbose)
    : parameters(parameters)
    , out(out)
    , verbose(verbose)
  {}



  std::vector<std::string>
  FitCaseStudy::file_names()
  {
    return {"min", "mean", "max", "fit_cases.csv", "report.md"};
  }



  std::vector<std::string>
  FitCaseStudy::column_names()
  {
    return {"U_mm",
            "U_effective_mm",
            "pressure_mid_plane_MPa",
            "pressure_mean_MPa",
            "pressure_din_MPa",
            "torque_capacity_Nm",
            "torque_capacity_din_Nm",
            "axial_force_capacity_N",
            "axial_force_capacity_din_N",
            "press_in_force_N",
            "press_in_force_din_N",
            "safety_slip",
            "safety_slip_din",
            "safety_yield_hub",
            "safety_yield_hub_din",
            "safety_yield_shaft",
            "safety_yield_shaft_din",
            "safety_yield_hub_assembly",
            "safety_yield_shaft_assembly",
            "safety_fracture_hub",
            "safety_fracture_hub_din"};
  }



  std::vector<double>
  FitCaseStudy::values_of(const Row &row, const std::vector<std::string> &names)
  {
    const std::vector<std::string> all = column_names();
    std::vector<double>            values;
    for (const std::string &name : names)
      {
        const auto at = std::find(all.begin(), all.end(), name);
        values.push_back(at == all.end() ?
                           std::numeric_limits<double>::quiet_NaN() :
                           row.values[at - all.begin()]);
      }
    return values;
  }



  bool
  FitCaseStudy::run()
  {
    check_memory(parameters);
    ResultDirectory directory(parameters.output_directory(),
                              all_result_file_names());
    const bool      all_converged = run_in(directory.staging_path());
    directory.commit(out);
    if (verbose)
      out << "  results in " << parameters.output_directory()
          << " (subdirectories min, mean, max)\n";
    return all_converged;
  }



  bool
  FitCaseStudy::run_in(const std::string &directory)
  {
    bool all_converged = true;
    rows.clear();
    for (const FitCase c : {FitCase::min, FitCase::mean, FitCase::max})
      {
        const Parameters  p   = parameters.for_fit_case(c);
        const std::string sub = directory + "/" + to_string(c);
        std::filesystem::create_directory(sub);
        CoaxialFit            fit(p, out, verbose);
        const bool            converged = fit.run_in(sub);
        const FitDesign      &d         = fit.get_design();
        const PressureSummary pressure  = fit.pressure_summary();
        rows.push_back({c,
                        converged,
                        fit.get_coupling().n_steps(),
                        {p.fit_limits.used(),
                         2. * p.geometry.d,
                         pressure.at_mid_plane,
                         d.mean_pressure,
                         d.pressure_din,
                         d.torque_capacity,
                         d.torque_capacity_din,
                         d.axial_force_capacity,
                         d.axial_force_capacity_din,
                         d.press_in_force,
                         d.press_in_force_din,
                         d.safety_slip,
                         d.safety_slip_din,
                         d.safety_yield_hub,
                         d.safety_yield_hub_din,
                         d.safety_yield_shaft,
                         d.safety_yield_shaft_din,
                         d.safety_yield_hub_assembly,
                         d.safety_yield_shaft_assembly,
                         d.safety_fracture_hub,
                         d.safety_fracture_hub_din},
                        fit.get_verdict().failed});
        all_converged = all_converged && converged;
      }
    output_results(directory);
    return all_converged;
  }



  void
  FitCaseStudy::output_results(const std::string &directory) const
  {
    const std::vector<std::string> columns = column_names();
    const std::string              name    = directory + "/fit_cases.csv";
    std::ofstream                  csv     = open_result_file(name);
    csv << "case,converged,steps";
    for (const std::string &c : columns)
      csv << ',' << c;
    csv << '\n';
    for (const Row &row : rows)
      {
        csv << to_string(row.fit_case) << ',' << (row.converged ? 1 : 0) << ','
            << row.steps;
        for (const double v : row.values)
          {
            csv << ',';
            if (std::isfinite(v))
              csv << v;
          }
        csv << '\n';
      }
    close_result_file(csv, name);

    // The console: one line per figure, one column per case.
    std::ostringstream table;
    // An ISO fit, or a taper's push-on distances.
    const std::string what = parameters.fit_limits.iso_fit.empty() ?
                               parameters.fit_limits.source :
                               "fit " + parameters.fit_limits.iso_fit;
    table << "coaxfit: " << what << " at D_F = " << 2. * parameters.geometry.R1
          << " mm, cases min, mean, max\n"
          << "    " << std::left << std::setw(28) << "" << std::right;
    for (const Row &row : rows)
      table << std::setw(12) << to_string(row.fit_case);
    table << "\n    " << std::left << std::setw(28) << "converged (steps)"
          << std::right;
    for (const Row &row : rows)
      table << std::setw(12) << converged_cell(row);
    table << '\n';
    for (unsigned int i = 0; i < columns.size(); ++i)
      {
        table << "    " << std::left << std::setw(28) << columns[i]
              << std::right;
        for (const Row &row : rows)
          table << std::setw(12) << value_cell(row.values[i]);
        table << '\n';
      }
    table << verdict_line() << '\n'
          << "  fit_cases.csv: the design figures of the three cases\n";
    if (parameters.output.write_report)
      table << "  report.md: the verdict and the table, with links to the "
               "cases' reports\n";
    out << table.str();
    if (!parameters.output.write_report)
      return;

    const std::string report_name = directory + "/report.md";
    std::ofstream     report      = open_result_file(report_name);
    report << "# coaxfit report: " << what
           << " at D_F = " << 2. * parameters.geometry.R1
           << " mm, cases min, mean, max\n\n## Verdict\n\n"
           << verdict_line() << "\n\n"
           << report_section << "## The three cases\n\n| figure |";
    for (const Row &row : rows)
      report << ' ' << to_string(row.fit_case) << " |";
    report << "\n|---|";
    for (unsigned int c = 0; c < rows.size(); ++c)
      report << "---:|";
    report << "\n| converged (steps) |";
    for (const Row &row : rows)
      report << ' ' << converged_cell(row) << " |";
    report << '\n';
    for (unsigned int i = 0; i < columns.size(); ++i)
      {
        report << "| " << columns[i] << " |";
        for (const Row &row : rows)
          report << ' ' << value_cell(row.values[i]) << " |";
        report << '\n';
      }
    report << "\nEach case in full: ";
    for (const Row &row : rows)
      report << '[' << to_string(row.fit_case) << "]("
             << to_string(row.fit_case) << "/report.md)"
             << (&row == &rows.back() ? ".\n" : ", ");
    close_result_file(report, report_name);
  }



  std::string
  FitCaseStudy::verdict_line() const
  {
    std::string failed;
    for (const Row &row : rows)
      for (const std::string &f : row.failed)
        failed
          += (failed.empty() ? "" : "; ") + to_string(row.fit_case) + ": " + f;
    return "Verdict (cases min, mean, max): "
           + (failed.empty() ? std::string("OK") : "FAILED: " + failed);
  }



  std::set<std::string>
  all_result_file_names()
  {
    OutputParameters everything;
    everything.write_vtu    = true;
    everything.write_plots  = true;
    everything.write_report = true;
    std::set<std::string> names;
    for (const auto &writer :
         make_result_writers(everything, Scene::body_keys(Parameters())))
      for (const std::string &name : writer->file_names())
        names.insert(name);
    for (const std::string &name : SummaryWriter().file_names())
      names.insert(name);
    // A Fit/Case = all study may have written the directory before.
    for (const std::string &name : FitCaseStudy::file_names())
      names.insert(name);
    // And a Design/Mode = select run.
    for (const std::string &name : selection_files::file_names())
      names.insert(name);
    // And an elastic-plastic run (PlasticFit) of the same case.
    for (const std::string &name : PlasticFit::file_names())
      names.insert(name);
    return names;
  }
} // namespace coaxfit
