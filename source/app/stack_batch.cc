#include <coaxfit/app/run_guard.h>
#include <coaxfit/app/stack_batch.h>
#include <coaxfit/io/result_writers.h>

#include <chrono>
#include <iomanip>
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

    /** The last non-empty line of @p text. */
    std::string
    last_line(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line, last;
      while (std::getline(in, line))
        if (!line.empty())
          last = line;
      const std::string prefix = "coaxfit: error: ";
      return last.compare(0, prefix.size(), prefix) == 0 ?
               last.substr(prefix.size()) :
               last;
    }
  } // namespace



  StackBatch::StackBatch(const bool    verbose,
                         std::ostream &out,
                         std::ostream &err)
    : verbose(verbose)
    , out(out)
    , err(err)
  {}



  std::vector<StackCaseOutcome>
  StackBatch::run(const std::vector<StackCase> &cases) const
  {
    std::vector<StackCaseOutcome> outcomes(cases.size());
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const StackCase  &c = cases[i];
        StackCaseOutcome &o = outcomes[i];
        if (i > 0 && verbose)
          out << '\n';
        if (!c.parameters)
          {
            o.exit_code = 1;
            o.error     = c.input_error;
            out.flush();
            err << "coaxfit: error: " << c.input_error << std::endl;
            continue;
          }
        const auto         start = std::chrono::steady_clock::now();
        std::ostringstream errors;
        // --quiet: only the table.
        std::ostringstream discarded;
        std::ostream      &case_out = verbose ? out : discarded;
        o.exit_code                 = exit_code_of(
          [&]() {
            StackFit fit(*c.parameters);
            // What the case computed, also if writing it failed.
            const auto record = [&]() {
              const auto selection = fit.get_selection();
              o.joints             = fit.joint_figures();
              o.bodies             = fit.body_figures();
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
            };
            int code = 0;
            try
              {
                code = fit.run(case_out, verbose);
              }
            catch (...)
              {
                record();
                throw;
              }
            record();
            if (code == 2)
              errors << "coaxfit: the staggered process of the stack did "
                                        "not converge in Coupling/Max steps = "
                     << c.parameters->max_steps
                     << " steps; raise it or set Solver/Method = monolithic\n";
            return code;
          },
          errors);
        o.wall = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                               - start)
                   .count();
        out.flush();
        err << errors.str() << std::flush;
        o.error = last_line(errors.str());
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
