#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/stack_fit.h>
#include <coaxfit/app/stack_study.h>
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
    /** The columns of sweep.csv per joint. */
    const unsigned int per_joint = stack_joint_columns().size();
  } // namespace



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
    if (base.fit_case == "all" && sweep.entry != "Fit/Case")
      throw InputError(
        "parameter Fit/Case = all: the study of the ISO fits' corners is a "
        "run of its own, not the case of a --sweep; allowed in a sweep: "
        "min, mean or max");
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
    const std::vector<std::string> names = stack_column_names(base.bodies);
    std::vector<StackStudyRun>     rows(sweep.values.size());
    for (unsigned int i = 0; i < sweep.values.size(); ++i)
      {
        const std::string name = sweep.directory_name(i);
        auto              with = overrides;
        with.emplace_back(sweep.entry, sweep.values[i]);
        // parameters.prm of the case names where it ends up.
        with.emplace_back("Output/Directory", study + "/" + name);
        rows[i] = run_stack_study_case(
          [&]() {
            StackParameters p = read_stack_parameters(filename, with);
            p.case_name       = base.case_name + "_" + name;
            return p;
          },
          directory.staging_path() + "/" + name,
          verbose,
          out);
        // Said of the value as the user gave it.
        const std::string set = "--set " + sweep.entry + "=";
        if (rows[i].error.compare(0, set.size(), set) == 0)
          rows[i].error = "--sweep value " + rows[i].error.substr(set.size());
      }

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
        const StackStudyRun &row = rows[i];
        table << "  " << std::left << std::setw(width) << sweep.values[i]
              << std::right << std::setw(6) << row.exit_code;
        if (row.written && !row.no_fits)
          {
            table << std::setw(7) << row.steps << std::setprecision(6);
            for (unsigned int k = 0; k < base.n_joints(); ++k)
              table << std::setw(
                std::max<int>(16, base.joint_name(k).size() + 8))
                    << row.values[per_joint * k + 1];
            table << "  " << row.verdict;
          }
        else if (row.written)
          table << std::setw(7) << "-"
                << "  " << row.verdict;
        if (!row.error.empty())
          table << "  " << row.error;
        table << '\n';
      }
    out << table.str();
    // Each value without a converged result: one line on the error stream,
    // as its own run would give (its row in the table says the same).
    for (unsigned int i = 0; i < rows.size(); ++i)
      say_unconverged(rows[i], "--sweep value " + sweep.values[i]);
    bool      nothing = true;
    const int code
      = stack_study_exit_code(rows, "value of the sweep", study, out, nothing);
    if (nothing)
      return code;

    const std::string csv_name = directory.staging_path() + "/sweep.csv";
    std::ofstream     csv      = open_result_file(csv_name);
    csv << csv_field(sweep.entry) << ",exit_code,verdict,steps";
    for (const std::string &n : names)
      csv << ',' << n;
    csv << ",error\n";
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        const StackStudyRun &row = rows[i];
        csv << csv_field(sweep.values[i]) << ',' << row.exit_code << ','
            << row.verdict << ',';
        if (row.written && !row.no_fits)
          csv << row.steps;
        write_study_values(csv, row, names.size());
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
