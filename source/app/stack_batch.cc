#include <coaxfit/app/process_pool.h>
#include <coaxfit/app/run_guard.h>
#include <coaxfit/app/stack_batch.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_writers.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** How a case ended, in words. */
    std::string
    status_of(const StackCaseOutcome &o)
    {
      switch (o.exit_code)
        {
          case 0:
            return o.joints.empty() ? "no fits" : "converged";
          case 1:
            return "bad input";
          case 2:
            return o.joints.empty() ? "diverged" : "not converged";
          default:
            return "failed";
        }
    }

    /** @p line without a leading "coaxfit: error: ". */
    std::string
    without_prefix(const std::string &line)
    {
      const std::string prefix = "coaxfit: error: ";
      return line.compare(0, prefix.size(), prefix) == 0 ?
               line.substr(prefix.size()) :
               line;
    }
  } // namespace



  std::string
  StackCaseOutcome::serialize() const
  {
    nlohmann::json j;
    j["verdict"]    = verdict;
    j["steps"]      = steps;
    j["fits"]       = fits;
    j["joint_fits"] = joint_fits;
    j["joints"]     = nlohmann::json::array();
    for (const JointFigures &f : joints)
      j["joints"].push_back({{"name", f.name},
                             {"diameter", f.diameter},
                             {"p_mid", f.p_mid},
                             {"p_mean", f.p_mean},
                             {"p_min", f.p_min},
                             {"p_max", f.p_max},
                             {"closed", f.closed},
                             {"slip_safety", f.slip_safety}});
    // Every digit, so that the table equals a single run's figures.
    return j.dump() + '\n';
  }



  void
  StackCaseOutcome::parse(const std::string &text)
  {
    const nlohmann::json j = nlohmann::json::parse(text);
    verdict                = j["verdict"];
    steps                  = j["steps"];
    fits                   = j["fits"];
    joint_fits             = j["joint_fits"].get<std::vector<std::string>>();
    joints.clear();
    // JSON writes a figure that is not a number as null.
    const auto value = [](const nlohmann::json &x) {
      return x.is_number() ? x.get<double>() :
                             std::numeric_limits<double>::quiet_NaN();
    };
    for (const auto &f : j["joints"])
      {
        JointFigures figures;
        figures.name        = f["name"];
        figures.diameter    = value(f["diameter"]);
        figures.p_mid       = value(f["p_mid"]);
        figures.p_mean      = value(f["p_mean"]);
        figures.p_min       = value(f["p_min"]);
        figures.p_max       = value(f["p_max"]);
        figures.closed      = f["closed"];
        figures.slip_safety = value(f["slip_safety"]);
        joints.push_back(figures);
      }
  }



  StackBatch::StackBatch(const unsigned int jobs,
                         const bool         verbose,
                         std::ostream      &out,
                         std::ostream      &err)
    : jobs(jobs)
    , verbose(verbose)
    , out(out)
    , err(err)
  {}



  std::vector<StackCaseOutcome>
  StackBatch::run(const std::vector<StackCase> &cases) const
  {
    std::vector<PoolTask> tasks;
    for (const StackCase &c : cases)
      tasks.push_back(
        {c.label,
         c.parameters ? std::string() : "coaxfit: error: " + c.input_error,
         c.parameters ? c.parameters->output_directory() : std::string()});
    const std::vector<PoolResult> results
      = ProcessPool(jobs, verbose, out, err)
          .run(tasks, [&](const unsigned int i, std::string &row) {
            const StackCase   &c = cases[i];
            StackCaseOutcome   o;
            std::ostringstream discarded; // --quiet: only the table
            std::ostream      &case_out = verbose ? std::cout : discarded;
            const int          code     = exit_code_of(
              [&]() {
                StackFit fit(*c.parameters);
                // What the case computed, also if writing it failed.
                const auto record = [&]() {
                  const auto selection = fit.get_selection();
                  o.joints             = fit.joint_figures();
                  o.steps              = fit.n_steps();
                  for (const JointFit &f : fit.get_parameters().fits)
                    o.joint_fits.push_back(f.source);
                  if (!o.joints.empty() || selection)
                    o.verdict = fit.get_verdict().ok() ? "OK" : "FAILED";
                  if (selection && selection->found())
                    {
                      std::vector<std::string> names;
                      for (const IsoFit &f : selection->chosen)
                        names.push_back(f.name);
                      o.fits = part_text(names);
                    }
                  row = o.serialize();
                };
                int code = 0;
                try
                  {
                    code = fit.run(case_out, verbose);
                  }
                catch (const InputError &)
                  {
                    // Refused, also after the solve (a relief groove the
                    // bodies close): its figures are no result.
                    throw;
                  }
                catch (...)
                  {
                    record();
                    throw;
                  }
                record();
                if (code == 2)
                  std::cerr
                    << "coaxfit: the staggered process of the stack did "
                                    "not converge in Coupling/Max steps = "
                    << c.parameters->max_steps
                    << " steps; raise it or set Solver/Method = "
                                    "monolithic"
                    << std::endl;
                return code;
              },
              std::cerr);
            std::cout.flush();
            return code;
          });
    std::vector<StackCaseOutcome> outcomes(cases.size());
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        StackCaseOutcome &o = outcomes[i];
        if (!results[i].row.empty())
          o.parse(results[i].row);
        o.exit_code = results[i].exit_code;
        o.wall      = results[i].wall;
        o.error     = without_prefix(results[i].error);
      }
    return outcomes;
  }



  void
  StackBatch::print_table(std::ostream                        &out,
                          const std::vector<StackCase>        &cases,
                          const std::vector<StackCaseOutcome> &outcomes)
  {
    std::size_t width = 4;
    for (const StackCase &c : cases)
      width = std::max(width, c.label.size());
    out << "  " << std::left << std::setw(width) << "case" << std::right
        << std::setw(6) << "exit"
        << "  " << std::left << std::setw(14) << "status" << std::right
        << std::setw(6) << "steps"
        << "  verdict  mean pressure of each joint (MPa)\n";
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const StackCaseOutcome &o = outcomes[i];
        out << "  " << std::left << std::setw(width) << cases[i].label
            << std::right << std::setw(6) << o.exit_code << "  " << std::left
            << std::setw(14) << status_of(o) << std::right << std::setw(6)
            << o.steps << "  " << std::left << std::setw(7)
            << (o.verdict.empty() ? "-" : o.verdict) << std::right;
        for (const JointFigures &f : o.joints)
          out << "  " << f.name << ' ' << std::fixed << std::setprecision(4)
              << f.p_mean << std::defaultfloat;
        if (!o.fits.empty())
          out << "  (fits " << o.fits << ")";
        if (o.exit_code != 0 && !o.error.empty())
          out << "  " << o.error;
        out << '\n';
      }
  }



  std::string
  StackBatch::table_csv(const std::vector<StackCase>        &cases,
                        const std::vector<StackCaseOutcome> &outcomes)
  {
    std::ostringstream csv;
    csv << std::setprecision(10)
        << "case,exit_code,status,verdict,steps,wall_s,joint,diameter_mm,"
           "p_mid_MPa,p_mean_MPa,p_min_MPa,p_max_MPa,closed,slip_safety,"
           "fit,error\n";
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const StackCaseOutcome &o    = outcomes[i];
        const std::string       head = csv_field(cases[i].label) + ','
                                 + std::to_string(o.exit_code) + ','
                                 + status_of(o) + ',' + o.verdict + ','
                                 + std::to_string(o.steps) + ',';
        const std::string error = csv_field(o.exit_code == 0 ? "" : o.error);
        if (o.joints.empty())
          csv << head << o.wall << ",,,,,,,,,," << error << '\n';
        for (unsigned int k = 0; k < o.joints.size(); ++k)
          {
            const JointFigures &f = o.joints[k];
            csv << head << o.wall << ',' << f.name << ',' << f.diameter << ','
                << f.p_mid << ',' << f.p_mean << ',' << f.p_min << ','
                << f.p_max << ',' << (f.closed ? "true" : "false") << ',';
            if (f.slip_safety > 0.)
              csv << f.slip_safety;
            csv << ',' << csv_field(o.joint_fits[k]) << ',' << error << '\n';
          }
      }
    return csv.str();
  }



  int
  StackBatch::exit_code(const std::vector<StackCaseOutcome> &outcomes)
  {
    int worst = 0;
    for (const StackCaseOutcome &o : outcomes)
      {
        const int code = o.exit_code >= 0 && o.exit_code <= 3 ? o.exit_code : 3;
        worst          = std::max(worst, code);
      }
    return worst;
  }
} // namespace coaxfit
