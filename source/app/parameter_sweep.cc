#include <deal.II/base/multithread_info.h>

#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/parameter_sweep.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/base/concurrency.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/parameters.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace coaxfit
{
  namespace fs = std::filesystem;

  namespace
  {
    /** @p text as a number, or false. */
    bool
    to_number(const std::string &text, double &value)
    {
      try
        {
          std::size_t used = 0;
          value            = std::stod(text, &used);
          return used == text.size() && std::isfinite(value);
        }
      catch (const std::exception &)
        {
          return false;
        }
    }

    /** @p text for a message: at most 60 characters. */
    std::string
    shown(const std::string &text)
    {
      return text.size() > 60 ? text.substr(0, 57) + "..." : text;
    }

  } // namespace



  SweepSpec
  SweepSpec::parse(const std::string &argument)
  {
    const auto eq = argument.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--sweep " + shown(argument)
                       + ": expected Section/Name=v1,v2,... or "
                         "Section/Name=from:to:count");
    SweepSpec         spec;
    const std::string list = argument.substr(eq + 1);
    spec.entry             = trimmed(argument.substr(0, eq));
    const auto colon       = list.find(':');
    // Values that contain commas (a list of joints) are separated by ';',
    // values that contain ';' too (a section's outline) by '|'.
    const char separator = list.find('|') != std::string::npos ? '|' :
                           list.find(';') != std::string::npos ? ';' :
                                                                 ',';
    if (colon != std::string::npos && list.find(',') == std::string::npos
        && separator == ',')
      {
        const auto        second = list.find(':', colon + 1);
        const std::string n
          = second == std::string::npos ? "" : trimmed(list.substr(second + 1));
        double     from = 0., to = 0., count = 0.;
        const bool ok
          = second != std::string::npos && !n.empty() && n.size() <= 4
            && n.find_first_not_of("0123456789") == std::string::npos
            && to_number(trimmed(list.substr(0, colon)), from)
            && to_number(trimmed(list.substr(colon + 1, second - colon - 1)),
                         to)
            && to_number(n, count);
        if (!ok || count < 2 || count > 1000)
          throw InputError("--sweep " + shown(argument)
                           + ": a range is from:to:count, with numbers from "
                             "and to and a whole count from 2 to 1000");
        for (unsigned int i = 0; i < count; ++i)
          {
            // The end points exactly as given, the others evenly between.
            const double t = i / (count - 1.);
            const double v = i + 1 == count ? to : from * (1. - t) + to * t;
            std::ostringstream s;
            s << std::setprecision(12) << v;
            spec.values.push_back(s.str());
          }
      }
    else
      {
        std::istringstream s(list);
        for (std::string value; std::getline(s, value, separator);)
          spec.values.push_back(trimmed(value));
        if (!list.empty() && list.back() == separator)
          spec.values.emplace_back();
        for (const std::string &value : spec.values)
          if (value.empty())
            throw InputError("--sweep " + shown(argument)
                             + ": an empty value in the list");
        if (spec.values.empty() || spec.values.size() > 1000)
          throw InputError("--sweep " + shown(argument)
                           + ": give from 1 to 1000 values");
      }
    return spec;
  }



  std::string
  SweepSpec::directory_name(const unsigned int index) const
  {
    std::ostringstream name;
    name << std::setw(2) << std::setfill('0') << index + 1 << '_';
    for (const char c : values[index])
      name << ((std::isalnum(static_cast<unsigned char>(c)) || c == '.'
                || c == '+' || c == '-' || c == '=') ?
                 c :
               c == '/' ? '-' :
                          '_');
    return name.str().substr(0, 64);
  }



  std::set<std::string>
  SweepSpec::study_entries(const std::string &study) const
  {
    // The table and plot, and the value subdirectories of this study and
    // of an earlier one (recognized by its sweep.csv).
    std::set<std::string> allowed = {"sweep.csv", "sweep.png", "sweep.gp"};
    for (unsigned int i = 0; i < values.size(); ++i)
      allowed.insert(directory_name(i));
    std::error_code error;
    if (fs::is_regular_file(study + "/sweep.csv", error))
      for (const auto &entry : fs::directory_iterator(study, error))
        {
          const std::string name = entry.path().filename().string();
          if (entry.is_directory() && name.size() > 3
              && std::isdigit(static_cast<unsigned char>(name[0]))
              && name.find('_') != std::string::npos)
            allowed.insert(name);
        }
    return allowed;
  }



  std::string
  SweepSpec::draw(const std::string &directory,
                  const std::string &size,
                  const std::string &plots,
                  const std::string &what) const
  {
    std::ostringstream gp;
    gp << "# coaxfit: gnuplot script of the sweep's plot; run it here with "
          "'gnuplot sweep.gp'\n"
       << "set terminal pngcairo size " << size << " font ',11'\n"
       << "set output 'sweep.png'\n"
       << "set datafile separator ','\n"
       << "set datafile missing ''\n"
       << "set grid\n"
       << "set xlabel '" << entry << "' noenhanced\n"
       << plots;
    std::ofstream script = open_result_file(directory + "/sweep.gp");
    script << gp.str();
    close_result_file(script, directory + "/sweep.gp");
    const std::string problem = run_gnuplot(directory, "sweep.gp");
    if (!problem.empty())
      {
        std::remove((directory + "/sweep.png").c_str());
        return "sweep.png skipped: " + problem;
      }
    check_complete_png(directory + "/sweep.png");
    return "sweep.png: " + what + " against " + entry
           + " (sweep.gp redraws it)";
  }



  bool
  SweepSpec::numeric() const
  {
    double v = 0.;
    for (const std::string &value : values)
      if (!to_number(value, v))
        return false;
    return true;
  }



  ParameterSweep::ParameterSweep(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides,
    const SweepSpec                                        &sweep,
    const unsigned int                                      jobs,
    const bool                                              verbose,
    std::ostream                                           &out,
    std::ostream                                           &err)
    : filename(filename)
    , overrides(overrides)
    , sweep(sweep)
    , jobs(jobs)
    , verbose(verbose)
    , out(out)
    , err(err)
  {}



  int
  ParameterSweep::run()
  {
    // A section is one value with commas in it, which the list of values
    // would cut apart.
    if (sweep.entry == "Geometry/Shaft section"
        || sweep.entry == "Geometry/Hub section")
      throw InputError("--sweep " + sweep.entry
                       + ": a section cannot be swept (its points contain "
                         "commas); give each variant its own parameter file "
                         "and run them together (coaxfit A.prm B.prm ...)");
    // The file itself must be a valid case (otherwise every value fails
    // for the same reason: one message, exit 1).
    // A sweep over Fit/Case replaces the file's case (also Case = all).
    auto base_overrides = overrides;
    if (sweep.entry == "Fit/Case")
      base_overrides.emplace_back(sweep.entry, sweep.values.front());
    Parameters base;
    try
      {
        base = read_parameters(filename, base_overrides);
      }
    catch (const InputError &)
      {
        // The swept entry may be what makes the file a case (a load swept
        // for a selection whose file has none): the file with the first
        // value (its message, if it fails too).
        base_overrides.emplace_back(sweep.entry, sweep.values.front());
        base = read_parameters(filename, base_overrides);
      }
    // Design/Mode = select does not use Fit/Case (its first fit is
    // checked in all three cases).
    if (base.fit.fit_case == FitCase::all
        && base.design.mode != DesignMode::select)
      throw InputError("--sweep runs one fit case per value; Fit/Case = all "
                       "is not allowed with it (give min, mean or max)");
    if (!is_declared_entry(sweep.entry))
      throw InputError("--sweep " + sweep.entry
                       + ": no such parameter (coaxfit --print-parameters "
                         "lists them as Section/Name)");
    if (sweep.entry == "Output/Directory")
      throw InputError("--sweep: Output/Directory cannot be swept (each "
                       "value has its subdirectory of the study)");
    const std::string study
      = normalized_directory(base.output_directory()) + "_sweep";

    std::vector<std::string> names;
    for (unsigned int i = 0; i < sweep.values.size(); ++i)
      names.push_back(sweep.directory_name(i));
    ResultDirectory directory(study,
                              all_result_file_names(),
                              sweep.study_entries(study));

    std::vector<BatchCase> cases(sweep.values.size());
    for (unsigned int i = 0; i < sweep.values.size(); ++i)
      {
        BatchCase &c = cases[i];
        c.label      = sweep.values[i];
        auto with    = overrides;
        with.emplace_back(sweep.entry, sweep.values[i]);
        // parameters.prm of the case names where it ends up.
        with.emplace_back("Output/Directory", study + "/" + names[i]);
        try
          {
            auto p
              = std::make_shared<Parameters>(read_parameters(filename, with));
            p->case_name = base.case_name + "_" + names[i];
            if (p->output.sweep_files == SweepFiles::figures)
              {
                p->output.write_vtu    = false;
                p->output.write_plots  = false;
                p->output.write_report = false;
              }
            c.parameters = p;
            c.directory  = directory.staging_path() + "/" + names[i];
            fs::create_directory(c.directory);
          }
        catch (const InputError &e)
          {
            // Said of the value as the user gave it.
            std::string       message = e.what();
            const std::string set     = "--set " + sweep.entry + "=";
            if (message.compare(0, set.size(), set) == 0)
              message = "--sweep value " + message.substr(set.size());
            c.input_error = message;
          }
      }

    // Meshes, matrices and factorizations made once, here, when only the
    // interference, the loads or the settings change: every value's
    // process starts from this set-up case (fork copies it).
    std::unique_ptr<CoaxialFit> prepared;
    // (Not with AMG: MPI, which Trilinos needs, must not be started
    // before the fork.)
    if (CoaxialFit::reusable_across(sweep.entry) && !use_amg(base))
      for (BatchCase &c : cases)
        if (c.parameters)
          {
            if (!prepared)
              {
                check_memory(*c.parameters);
                // No thread pool in this process: the cases are forked.
                dealii::MultithreadInfo::set_thread_limit(1);
                prepared = std::make_unique<CoaxialFit>(*c.parameters,
                                                        std::cout,
                                                        verbose);
                // On a thread that ends before any fork: the OpenMP
                // thread pool of CHOLMOD's factorization belongs to it and
                // ends with it (a pool does not survive fork).
                each_on_own_thread({[&]() {
                  prepared->setup_system();
                  prepared->prepare_corner_trend();
                }});
              }
            c.prepared = prepared.get();
          }

    const std::vector<CaseOutcome> outcomes
      = CaseBatch(jobs, verbose, out, err).run(cases);

    // A case that wrote no valid result leaves no directory behind.
    bool any = false;
    for (unsigned int i = 0; i < cases.size(); ++i)
      if (!cases[i].directory.empty())
        {
          if (outcomes[i].figures.values.empty())
            fs::remove_all(cases[i].directory);
          else
            any = true;
        }
    if (!any)
      {
        CaseBatch::print_table(out, cases, outcomes);
        err << "coaxfit: error: no value of the sweep gave a result; "
               "nothing written, the earlier results in "
            << study << " are untouched" << std::endl;
        return std::max(1, CaseBatch::exit_code(outcomes));
      }

    std::ofstream csv
      = open_result_file(directory.staging_path() + "/sweep.csv");
    csv << CaseBatch::table_csv(cases, outcomes, sweep.entry, sweep.values);
    close_result_file(csv, directory.staging_path() + "/sweep.csv");
    const std::string plotted = plot(directory.staging_path());
    out << "\ncoaxfit: sweep of " << sweep.entry << " over "
        << sweep.values.size() << " values of " << filename << '\n';
    CaseBatch::print_table(out, cases, outcomes);
    directory.commit(out);
    out << "  " << plotted << "\n  results in " << study
        << " (sweep.csv, one subdirectory per value)" << std::endl;
    return CaseBatch::exit_code(outcomes);
  }



  std::string
  ParameterSweep::plot(const std::string &directory) const
  {
    // Columns of sweep.csv: 1 value, 2 case, 3 exit code, 4 status,
    // 5 steps, 6 p(0), 7 p_mean, 8 p_DIN, 9 torque, 10 torque DIN.
    const std::string  x    = sweep.numeric() ? "1" : "0";
    const std::string  tics = sweep.numeric() ? "" : ":xtic(1)";
    std::ostringstream gp;
    gp << "set key top left\n"
       << "set multiplot layout 2,1\n"
       << "set ylabel 'contact pressure (MPa)'\n"
       << "plot 'sweep.csv' skip 1 using " << x << ":7" << tics
       << " with linespoints pt 7 title 'mean, FE', \\\n"
       << "     '' skip 1 using " << x << ":8" << tics
       << " with linespoints pt 4 dt 2 title 'DIN 7190', \\\n"
       << "     '' skip 1 using " << x << ":6" << tics
       << " with linespoints pt 5 title 'mid-plane p(0), FE'\n"
       << "set ylabel 'torque capacity (N m)'\n"
       << "plot 'sweep.csv' skip 1 using " << x << ":9" << tics
       << " with linespoints pt 7 title 'FE', \\\n"
       << "     '' skip 1 using " << x << ":10" << tics
       << " with linespoints pt 4 dt 2 title 'DIN 7190'\n"
       << "unset multiplot\n";
    return sweep.draw(directory,
                      "960,900",
                      gp.str(),
                      "pressures and torque capacity");
  }
} // namespace coaxfit
