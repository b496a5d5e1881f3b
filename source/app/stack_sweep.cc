#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/stack_fit.h>
#include <coaxfit/app/stack_sweep.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace fs = std::filesystem;



  StackSweep::StackSweep(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides,
    const SweepSpec                                        &sweep,
    const bool                                              verbose,
    std::ostream                                           &out)
    : filename(filename)
    , overrides(overrides)
    , sweep(sweep)
    , verbose(verbose)
    , out(out)
  {}



  namespace
  {
    /** A column of sweep.csv: its name's suffix and its figure. */
    template <typename Figures>
    struct Column
    {
      const char *suffix;
      double (*value)(const Figures &);
    };

    /** Each joint's columns, in order (NaN: none, an empty field). */
    const std::vector<Column<JointFigures>> joint_columns
      = {{"_pressure_mid_plane_MPa",
          [](const JointFigures &f) { return f.p_mid; }},
         {"_pressure_mean_MPa", [](const JointFigures &f) { return f.p_mean; }},
         {"_closed", [](const JointFigures &f) { return f.closed ? 1. : 0.; }},
         {"_safety_slip",
          [](const JointFigures &f) {
            return f.slip_safety > 0. ? f.slip_safety : std::nan("");
          }},
         {"_press_in_force_N",
          [](const JointFigures &f) { return f.press_in_force; }},
         {"_joining_heat_outer_to_C",
          [](const JointFigures &f) { return f.heat_outer_to; }},
         {"_joining_cool_inner_to_C",
          [](const JointFigures &f) { return f.cool_inner_to; }}};

    /** Each body's columns, in order. */
    const std::vector<Column<BodyFigures>> body_columns
      = {{"_von_mises_mid_plane_MPa",
          [](const BodyFigures &f) { return f.von_mises_mid_plane; }},
         {"_safety_yield", [](const BodyFigures &f) {
            return f.yield_safety > 0. ? f.yield_safety : std::nan("");
          }}};

    /** The columns of sweep.csv per joint. */
    const unsigned int per_joint = joint_columns.size();
  } // namespace



  std::vector<std::string>
  StackSweep::columns(const std::vector<std::string> &bodies) const
  {
    std::vector<std::string> names;
    for (unsigned int k = 0; k + 1 < bodies.size(); ++k)
      for (const auto &column : joint_columns)
        names.push_back(bodies[k] + "-" + bodies[k + 1] + column.suffix);
    for (const std::string &b : bodies)
      for (const auto &column : body_columns)
        names.push_back(b + column.suffix);
    return names;
  }



  int
  StackSweep::run()
  {
    if (sweep.entry == "Assembly/Bodies")
      throw InputError("--sweep Assembly/Bodies: the bodies of a stack "
                       "cannot be swept (every value must have the same "
                       "joints); give each stack its own parameter file");
    if (sweep.entry == "Output/Directory")
      throw InputError("--sweep: Output/Directory cannot be swept (each "
                       "value has its subdirectory of the study)");
    // The file must be a stack (else every value fails alike): read with
    // its own entries, or with the first value if that is what it lacks.
    StackParameters base;
    try
      {
        base = read_stack_parameters(filename, overrides);
      }
    catch (const InputError &)
      {
        auto with = overrides;
        with.emplace_back(sweep.entry, sweep.values.front());
        base = read_stack_parameters(filename, with);
      }
    if (!base.declares(sweep.entry))
      throw InputError(
        "--sweep " + sweep.entry
        + ": no such parameter of this stack (coaxfit "
          "--print-parameters FILE.prm lists them as Section/Name; a "
          "stack's entries name its bodies and joints)");

    const std::string study
      = normalized_directory(base.output_directory()) + "_sweep";
    ResultDirectory                directory(study,
                              all_result_file_names(),
                              sweep.study_entries(study));
    const std::vector<std::string> names = columns(base.bodies);
    std::vector<Row>               rows(sweep.values.size());
    for (unsigned int i = 0; i < sweep.values.size(); ++i)
      {
        Row              &row  = rows[i];
        const std::string name = sweep.directory_name(i);
        auto              with = overrides;
        with.emplace_back(sweep.entry, sweep.values[i]);
        // parameters.prm of the case names where it ends up.
        with.emplace_back("Output/Directory", study + "/" + name);
        std::ostringstream log;
        try
          {
            StackParameters p      = read_stack_parameters(filename, with);
            p.case_name            = base.case_name + "_" + name;
            const std::string into = directory.staging_path() + "/" + name;
            fs::create_directory(into);
            StackFit fit(p);
            row.exit_code = fit.run(verbose ? out : log, verbose, into);
            // A diverged process wrote nothing.
            row.written = fs::exists(into + "/summary.json");
            if (!row.written)
              {
                fs::remove_all(into);
                row.error = "diverged: nothing written";
                continue;
              }
            row.verdict = fit.get_verdict().ok() ? "OK" : "FAILED";
            // A selection that found no fits wrote only the selection.
            if (fit.get_selection() && !fit.get_selection()->found())
              {
                row.values.assign(names.size() + 1,
                                  std::numeric_limits<double>::quiet_NaN());
                row.error = "no ISO fits found (Design/Mode = select)";
                continue;
              }
            row.values.push_back(fit.n_steps());
            for (const JointFigures &f : fit.joint_figures())
              for (const auto &column : joint_columns)
                row.values.push_back(column.value(f));
            for (const BodyFigures &f : fit.body_figures())
              for (const auto &column : body_columns)
                row.values.push_back(column.value(f));
            if (row.exit_code == 2)
              row.error = "not converged: written with converged false";
          }
        catch (const InputError &e)
          {
            // Said of the value as the user gave it.
            std::string       message = e.what();
            const std::string set     = "--set " + sweep.entry + "=";
            if (message.compare(0, set.size(), set) == 0)
              message = "--sweep value " + message.substr(set.size());
            row.exit_code = 1;
            row.error     = message;
            fs::remove_all(directory.staging_path() + "/" + name);
          }
      }

    bool any = false;
    for (const Row &row : rows)
      any = any || row.written;
    // The table: each value, its exit code and figures.
    std::size_t width = 12;
    for (const std::string &value : sweep.values)
      width = std::max(width, value.size() + 2);
    std::ostringstream table;
    table << "\ncoaxfit: sweep of " << sweep.entry << " over "
          << sweep.values.size() << " values of " << filename << '\n'
          << "  " << std::left << std::setw(width) << "value" << std::right
          << std::setw(6) << "exit" << std::setw(7) << "steps";
    for (unsigned int k = 0; k < base.n_joints(); ++k)
      table << std::setw(std::max<int>(16, base.joint_name(k).size() + 8))
            << base.joint_name(k) + " p_mean";
    table << "  verdict\n";
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        const Row &row = rows[i];
        table << "  " << std::left << std::setw(width) << sweep.values[i]
              << std::right << std::setw(6) << row.exit_code;
        if (row.written)
          {
            table << std::setw(7) << row.values[0] << std::setprecision(6);
            for (unsigned int k = 0; k < base.n_joints(); ++k)
              table << std::setw(
                std::max<int>(16, base.joint_name(k).size() + 8))
                    << row.values[1 + per_joint * k + 1];
            table << "  " << row.verdict;
          }
        if (!row.error.empty())
          table << "  " << row.error;
        table << '\n';
      }
    out << table.str();
    int code = 0;
    for (const Row &row : rows)
      code = std::max(code, row.exit_code == 2 ? 2 : row.exit_code);
    if (!any)
      {
        out << "coaxfit: no value of the sweep gave a result; nothing "
               "written"
            << (fs::exists(study) ?
                  ", the earlier results in " + study + " are untouched" :
                  std::string())
            << std::endl;
        return std::max(1, code);
      }

    const std::string csv_name = directory.staging_path() + "/sweep.csv";
    std::ofstream     csv      = open_result_file(csv_name);
    csv << csv_field(sweep.entry) << ",exit_code,verdict,steps";
    for (const std::string &n : names)
      csv << ',' << n;
    csv << ",error\n";
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        const Row &row = rows[i];
        csv << csv_field(sweep.values[i]) << ',' << row.exit_code << ','
            << row.verdict;
        for (unsigned int c = 0; c < names.size() + 1; ++c)
          {
            csv << ',';
            if (c < row.values.size() && std::isfinite(row.values[c]))
              csv << row.values[c];
          }
        csv << ',' << csv_field(row.error) << '\n';
      }
    close_result_file(csv, csv_name);
    // The plot's axis is a scale if every value written is a number (a
    // refused one has no figures to draw).
    SweepSpec written = sweep;
    written.values.clear();
    for (unsigned int i = 0; i < rows.size(); ++i)
      if (rows[i].written)
        written.values.push_back(sweep.values[i]);
    const std::string plotted
      = base.write_plots && written.numeric() ?
          plot(directory.staging_path(), base.n_joints()) :
          std::string("sweep.png not drawn (")
            + (base.write_plots ? "values not numbers" :
                                  "Output/Write plots = false")
            + ")";
    directory.commit(out);
    out << "  " << plotted << "\n  results in " << study
        << " (sweep.csv, one subdirectory per value)" << std::endl;
    return code;
  }



  std::string
  StackSweep::plot(const std::string &directory,
                   const unsigned int n_joints) const
  {
    // Columns of sweep.csv: 1 value, 2 exit code, 3 verdict, 4 steps, then
    // per_joint per joint from 5 (p(0), p_mean, closed, slip safety,
    // force, joining temperatures).
    std::ostringstream gp;
    gp << "set key top left noenhanced autotitle columnheader\n"
       << "set ylabel 'mean contact pressure (MPa)'\n"
       << "plot ";
    for (unsigned int k = 0; k < n_joints; ++k)
      gp << (k > 0 ? ", \\\n     " : "")
         << "'sweep.csv' using 1:" << 6 + per_joint * k
         << " with linespoints pt 7";
    gp << '\n';
    return sweep.draw(directory,
                      "960,600",
                      gp.str(),
                      "each joint's mean pressure");
  }
} // namespace coaxfit
