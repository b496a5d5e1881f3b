#include <coaxfit/app/stack_study.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace coaxfit
{
  namespace fs = std::filesystem;



  StackStudyRun
  run_stack_study_case(const std::function<StackParameters()> &read,
                       const std::string                      &into,
                       const bool                              verbose,
                       std::ostream                           &out)
  {
    StackStudyRun      run;
    std::ostringstream log; // not verbose: only the study's table
    try
      {
        const StackParameters parameters = read();
        const auto            fits_of    = [&](const StackParameters &p) {
          run.U.clear();
          run.iso_fits.clear();
          for (const JointFit &f : p.fits)
            {
              run.U.push_back(f.nominal_interference);
              run.iso_fits.push_back(f.iso_fit);
            }
        };
        fits_of(parameters);
        fs::create_directory(into);
        StackFit fit(parameters);
        run.exit_code = fit.run(verbose ? out : log, verbose, into);
        // A selection's choice.
        fits_of(fit.get_parameters());
        // A diverged process wrote nothing.
        run.written = fs::exists(into + "/summary.json");
        if (!run.written)
          {
            fs::remove_all(into);
            run.error = "diverged: nothing written";
            return run;
          }
        run.verdict = fit.get_verdict().ok() ? "OK" : "FAILED";
        run.failed  = fit.get_verdict().failed;
        run.steps   = fit.n_steps();
        // A selection that found no fits wrote only the selection.
        if (fit.get_selection() && !fit.get_selection()->found())
          {
            run.no_fits = true;
            run.error   = "no ISO fits found (Design/Mode = select)";
            return run;
          }
        run.values = stack_column_values(fit);
        if (run.exit_code == 2)
          run.error = "not converged: written with converged false";
      }
    catch (const InputError &e)
      {
        run.exit_code = 1;
        run.error     = e.what();
        fs::remove_all(into);
      }
    return run;
  }



  void
  write_study_values(std::ostream        &csv,
                     const StackStudyRun &run,
                     const std::size_t    n)
  {
    for (std::size_t c = 0; c < n; ++c)
      {
        csv << ',';
        if (c < run.values.size() && std::isfinite(run.values[c]))
          csv << run.values[c];
      }
  }



  void
  say_unconverged(const StackStudyRun &run, const std::string &label)
  {
    if (run.exit_code == 0)
      return;
    std::cerr << "coaxfit: " << (run.exit_code == 2 ? "" : "error: ")
              << (run.error.compare(0, label.size(), label) == 0 ? "" :
                                                                   label + ": ")
              << run.error << std::endl;
  }



  int
  stack_study_exit_code(const std::vector<StackStudyRun> &runs,
                        const std::string                &what,
                        const std::string                &target,
                        std::ostream                     &out,
                        bool                             &nothing)
  {
    int code = 0;
    nothing  = true;
    for (const StackStudyRun &run : runs)
      {
        code    = std::max(code, run.exit_code == 2 ? 2 : run.exit_code);
        nothing = nothing && !run.written;
      }
    if (!nothing)
      return code;
    out << "coaxfit: no " << what << " gave a result; nothing written"
        << (fs::exists(target) ?
              ", the earlier results in " + target + " are untouched" :
              std::string())
        << std::endl;
    return std::max(1, code);
  }
} // namespace coaxfit
