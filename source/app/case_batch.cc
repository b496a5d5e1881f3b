#include <deal.II/base/multithread_info.h>

#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/fit_selection_study.h>
#include <coaxfit/app/process_pool.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/app/run_guard.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sched.h>
#include <sstream>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

namespace coaxfit
{
  std::vector<std::string>
  CaseFigures::column_names()
  {
    return {"pressure_mid_plane_MPa",
            "pressure_mean_MPa",
            "pressure_din_MPa",
            "torque_capacity_Nm",
            "torque_capacity_din_Nm",
            "safety_slip",
            "safety_yield_hub",
            "safety_yield_shaft",
            "safety_yield_hub_assembly",
            "safety_yield_shaft_assembly"};
  }



  std::string
  CaseFigures::serialize() const
  {
    std::ostringstream s;
    s << std::setprecision(17) << (converged ? 1 : 0) << ' ' << steps << ' '
      << (no_fit ? 1 : 0);
    for (const double v : values)
      s << ' ' << (std::isfinite(v) ? v : std::nan(""));
    return s.str();
  }



  CaseFigures
  CaseFigures::parse(const std::string &text)
  {
    std::istringstream s(text);
    CaseFigures        f;
    int                converged = 0, no_fit = 0;
    s >> converged >> f.steps >> no_fit;
    f.converged = converged == 1;
    f.no_fit    = no_fit == 1;
    std::string word;
    while (s >> word)
      f.values.push_back(word == "nan" || word == "-nan" ? std::nan("") :
                                                           std::stod(word));
    if (!s.eof() || f.values.size() != column_names().size())
      throw std::runtime_error("unreadable figures from a case: '" + text
                               + "'");
    return f;
  }



  CaseFigures
  run_case(const Parameters  &parameters,
           std::ostream      &out,
           const bool         verbose,
           const std::string &directory,
           CoaxialFit        *prepared)
  {
    CaseFigures figures;
    // A selection of a fit whose hub may yield is one of a single file
    // (main refuses it in a study up front).
    if ((parameters.shaft.plastic || parameters.hub.plastic)
        && parameters.design.mode != DesignMode::select)
      throw InputError(
        "parameter Material/"
        + std::string(parameters.hub.plastic ? "Hub" : "Shaft")
        + "/Plasticity = von Mises: an elastic-plastic fit runs on its own "
          "in this version (one parameter file, no --sweep, not one case of "
          "several files); allowed in a study is Plasticity = none");
    if (parameters.design.mode == DesignMode::select)
      {
        // A case of a sweep: into the sweep's directory; a prepared case
        // is not used (the selection sets up its own).
        if (!directory.empty())
          check_memory(parameters);
        FitSelectionStudy study(parameters, out, verbose);
        figures.converged
          = directory.empty() ? study.run() : study.run_in(directory);
        figures.steps  = study.mean_case_steps();
        figures.values = study.mean_case_values();
        figures.no_fit = figures.values.empty();
        if (figures.values.empty())
          figures.values.assign(CaseFigures::column_names().size(),
                                std::nan(""));
        return figures;
      }
    if (parameters.fit.fit_case == FitCase::all)
      {
        if (!directory.empty())
          throw InputError("Fit/Case = all cannot be a case of a study; "
                           "give Fit/Case = min, mean or max");
        FitCaseStudy study(parameters, out, verbose);
        figures.converged = study.run();
        for (const FitCaseStudy::Row &row : study.get_rows())
          if (row.fit_case == FitCase::mean)
            {
              figures.steps = row.steps;
              figures.values
                = FitCaseStudy::values_of(row, CaseFigures::column_names());
            }
        return figures;
      }
    std::unique_ptr<CoaxialFit> own;
    if (prepared)
      prepared->reuse_for(parameters);
    else
      {
        if (!directory.empty())
          check_memory(parameters);
        own = std::make_unique<CoaxialFit>(parameters, out, verbose);
      }
    CoaxialFit &fit    = prepared ? *prepared : *own;
    figures.converged  = directory.empty() ? fit.run() : fit.run_in(directory);
    const FitDesign &d = fit.get_design();
    figures.steps      = fit.get_coupling().n_steps();
    figures.values     = {fit.pressure_summary().at_mid_plane,
                          d.mean_pressure,
                          d.pressure_din,
                          d.torque_capacity,
                          d.torque_capacity_din,
                          d.safety_slip,
                          d.safety_yield_hub,
                          d.safety_yield_shaft,
                          d.safety_yield_hub_assembly,
                          d.safety_yield_shaft_assembly};
    return figures;
  }



  unsigned int
  available_cores()
  {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof(set), &set) == 0)
      return std::max(1, CPU_COUNT(&set));
    return std::max(1u, dealii::MultithreadInfo::n_cores());
  }



  void
  write_file_atomically(const std::string &filename, const std::string &text)
  {
    const std::string temporary
      = filename + ".partial-" + std::to_string(::getpid());
    const int fd = ::open(temporary.c_str(),
                          O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC,
                          0644);
    if (fd < 0)
      throw ResourceError("cannot write '" + filename
                          + "': " + std::strerror(errno));
    std::size_t written = 0;
    while (written < text.size())
      {
        const ssize_t n
          = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          break;
        written += n;
      }
    const bool ok = written == text.size() && ::fsync(fd) == 0;
    ::close(fd);
    if (!ok || std::rename(temporary.c_str(), filename.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw ResourceError("writing '" + filename
                            + "' failed: disk full, quota or file size limit "
                              "reached (the earlier file is untouched)");
      }
  }



  CaseBatch::CaseBatch(const unsigned int jobs,
                       const bool         verbose,
                       std::ostream      &out,
                       std::ostream      &err)
    : jobs(std::max(1u, jobs))
    , verbose(verbose)
    , out(out)
    , err(err)
  {}



  std::vector<CaseOutcome>
  CaseBatch::run(const std::vector<BatchCase> &cases)
  {
    std::vector<PoolTask> tasks;
    for (const BatchCase &c : cases)
      tasks.push_back(
        {c.label,
         c.parameters ? std::string() : "coaxfit: error: " + c.input_error,
         c.parameters && c.directory.empty() ?
           c.parameters->output_directory() :
           std::string()});
    const std::vector<PoolResult> results
      = ProcessPool(jobs, verbose, out, err)
          .run(tasks, [&](const unsigned int i, std::string &row) {
            const BatchCase &c = cases[i];
            return exit_code_of(
              [&]() {
                const CaseFigures figures = run_case(
                  *c.parameters, std::cout, verbose, c.directory, c.prepared);
                std::cout.flush();
                row = figures.serialize();
                if (!figures.converged)
                  std::cerr << not_converged_message(*c.parameters)
                            << std::endl;
                return figures.converged ? 0 : 2;
              },
              std::cerr);
          });
    std::vector<CaseOutcome> outcomes(cases.size());
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        outcomes[i].exit_code = results[i].exit_code;
        outcomes[i].wall      = results[i].wall;
        outcomes[i].error     = results[i].error;
        if (!results[i].row.empty())
          outcomes[i].figures = CaseFigures::parse(results[i].row);
      }
    return outcomes;
  }



  int
  CaseBatch::exit_code(const std::vector<CaseOutcome> &outcomes)
  {
    int worst = 0;
    for (const int code : {1, 2, 3})
      for (const CaseOutcome &o : outcomes)
        if (o.exit_code == code)
          worst = code;
    for (const CaseOutcome &o : outcomes)
      if (o.exit_code != 0 && o.exit_code != 1 && o.exit_code != 2)
        worst = 3;
    return worst;
  }



  namespace
  {
    std::string
    status_of(const CaseOutcome &o)
    {
      switch (o.exit_code)
        {
          case 0:
            return o.figures.no_fit ? "no fit" : "converged";
          case 1:
            return "bad input";
          case 2:
            return o.figures.values.empty() ? "diverged" : "not converged";
          default:
            return "failed";
        }
    }

  } // namespace



  std::string
  CaseBatch::table_csv(const std::vector<BatchCase>   &cases,
                       const std::vector<CaseOutcome> &outcomes,
                       const std::string              &key_name,
                       const std::vector<std::string> &keys)
  {
    std::ostringstream csv;
    csv << std::setprecision(15);
    if (!key_name.empty())
      csv << csv_field(key_name) << ',';
    csv << "case,exit_code,status,steps";
    for (const std::string &name : CaseFigures::column_names())
      csv << ',' << name;
    csv << ",wall_s,directory,error\n";
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const CaseOutcome &o = outcomes[i];
        if (!key_name.empty())
          csv << csv_field(keys[i]) << ',';
        csv << csv_field(cases[i].label) << ',' << o.exit_code << ','
            << status_of(o) << ',';
        if (!o.figures.values.empty())
          csv << o.figures.steps;
        for (unsigned int k = 0; k < CaseFigures::column_names().size(); ++k)
          {
            csv << ',';
            if (k < o.figures.values.size()
                && std::isfinite(o.figures.values[k]))
              csv << o.figures.values[k];
          }
        csv << ',' << std::setprecision(4) << o.wall << std::setprecision(15)
            << ','
            << csv_field(!cases[i].parameters || o.figures.values.empty() ?
                           "" :
                         cases[i].directory.empty() ?
                           cases[i].parameters->output_directory() :
                           cases[i].parameters->output.directory)
            << ',' << csv_field(o.exit_code == 0 ? "" : o.error) << '\n';
      }
    return csv.str();
  }



  void
  CaseBatch::print_table(std::ostream                   &out,
                         const std::vector<BatchCase>   &cases,
                         const std::vector<CaseOutcome> &outcomes)
  {
    std::size_t width = 4;
    for (const BatchCase &c : cases)
      width = std::max(width, c.label.size());
    width = std::min<std::size_t>(width, 40);
    out << std::left << std::setw(width + 2) << "case" << std::right
        << std::setw(5) << "exit" << std::setw(15) << "status" << std::setw(6)
        << "steps" << std::setw(11) << "p(0) MPa" << std::setw(11) << "p_m MPa"
        << std::setw(11) << "p_DIN MPa" << std::setw(12) << "T N m"
        << std::setw(8) << "S_slip" << std::setw(8) << "wall s" << '\n';
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const CaseOutcome &o = outcomes[i];
        const std::string  label
          = cases[i].label.size() > width ?
              "..." + cases[i].label.substr(cases[i].label.size() - width + 3) :
              cases[i].label;
        out << std::left << std::setw(width + 2) << label << std::right
            << std::setw(5) << o.exit_code << std::setw(15) << status_of(o);
        if (o.figures.values.empty())
          out << std::setw(6) << "-" << std::setw(11) << "-" << std::setw(11)
              << "-" << std::setw(11) << "-" << std::setw(12) << "-"
              << std::setw(8) << "-";
        else
          {
            const std::vector<double> &v = o.figures.values;
            // p(0), mean, DIN, torque, slip safety: "-" where undefined.
            const std::vector<std::pair<unsigned int, int>> shown{
              {0, 11}, {1, 11}, {2, 11}, {3, 12}, {5, 8}};
            out << std::setw(6) << o.figures.steps;
            for (const auto &[k, width] : shown)
              if (std::isfinite(v[k]))
                out << std::fixed << std::setprecision(k == 3 ? 1 : 2)
                    << std::setw(width) << v[k];
              else
                out << std::setw(width) << "-";
          }
        out << std::fixed << std::setprecision(2) << std::setw(8) << o.wall
            << '\n';
        out.unsetf(std::ios::floatfield);
      }
  }
} // namespace coaxfit
