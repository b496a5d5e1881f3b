#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/stack_case_study.h>
#include <coaxfit/app/stack_fit.h>
#include <coaxfit/app/stack_study.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace coaxfit
{
  namespace fs = std::filesystem;

  namespace
  {
    /** One case: its name and the case of each varied joint. */
    struct Case
    {
      std::string              name;
      std::vector<std::string> joint_case;
    };

    /** What became of a case. */
    using Row = StackStudyRun;

    /** The cases: min, mean and max, then the mixed corners. */
    std::vector<Case>
    cases_of(const unsigned int J)
    {
      std::vector<Case> cases;
      for (const std::string c : {"min", "mean", "max"})
        cases.push_back({c, std::vector<std::string>(J, c)});
      for (unsigned int m = 1; J > 1 && m + 1 < (1u << J); ++m)
        {
          Case c;
          for (unsigned int j = 0; j < J; ++j)
            {
              c.joint_case.push_back(((m >> (J - 1 - j)) & 1u) ? "max" : "min");
              c.name += (j > 0 ? "-" : "") + c.joint_case.back();
            }
          cases.push_back(c);
        }
      return cases;
    }

    /** A figure for the tables: 6 digits, or "-" for NaN. */
    std::string
    figure(const double x)
    {
      if (!std::isfinite(x))
        return "-";
      std::ostringstream s;
      s << std::setprecision(6) << x;
      return s.str();
    }

    /** A finished study: its stack, cases, their runs, its ISO fits. */
    struct Study
    {
      const StackParameters   &base;
      const std::vector<Case> &cases;
      const std::vector<Row>  &rows;
      const std::string        fits; ///< "Shaft-Sleeve H7/s6, ..."
      const bool selected; ///< the fits chosen by Design/Mode = select
    };

    /**
     * The varied joints' ISO fits @p iso_fits (one per joint), as the
     * headings name them.
     */
    std::string
    fits_text(const StackParameters           &base,
              const std::vector<unsigned int> &varied,
              const std::vector<std::string>  &iso_fits)
    {
      std::string fits;
      for (const unsigned int k : varied)
        fits += (fits.empty() ? "" : ", ") + base.joint_name(k) + " "
                + (k < iso_fits.size() && !iso_fits[k].empty() ?
                     iso_fits[k] :
                     std::string("(not chosen)"));
      return fits;
    }

    /**
     * A selection's answer (no fits) moved from the case of the means,
     * `mean/`, into the study's directory @p dir: named as the study
     * @p base (summary.json's case, report.md's heading), its
     * parameters.prm the study's (run again, it gives the same answer).
     */
    void
    take_selection_answer(const std::string &dir, const StackParameters &base)
    {
      for (const auto &entry : fs::directory_iterator(dir + "/mean"))
        fs::rename(entry.path(), dir + "/" + entry.path().filename().string());
      fs::remove(dir + "/mean");
      const std::string mean = base.case_name + "_mean";
      {
        std::ifstream  in(dir + "/summary.json");
        nlohmann::json j = nlohmann::json::parse(in);
        j["case"]        = base.case_name;
        std::ofstream o  = open_result_file(dir + "/summary.json");
        o << j.dump(2) << '\n';
        close_result_file(o, dir + "/summary.json");
      }
      if (fs::exists(dir + "/report.md"))
        {
          std::ifstream      in(dir + "/report.md");
          std::ostringstream text;
          text << in.rdbuf();
          std::string       report  = text.str();
          const std::string heading = "# coaxfit: " + mean + "\n";
          if (report.rfind(heading, 0) == 0)
            report.replace(0,
                           heading.size(),
                           "# coaxfit: " + base.case_name + "\n");
          std::ofstream o = open_result_file(dir + "/report.md");
          o << report;
          close_result_file(o, dir + "/report.md");
        }
      std::ofstream o = open_result_file(dir + "/parameters.prm");
      o << base.used_prm;
      close_result_file(o, dir + "/parameters.prm");
    }

    /**
     * The verdict over every case: each failed criterion (its text before
     * the figures, which the table and each case's report give) with the
     * cases that fail it; a case without a verdict fails the study.
     */
    std::string
    verdict_line(const Study &study)
    {
      std::vector<std::string>                        criteria;
      std::map<std::string, std::vector<std::string>> failing;
      std::vector<std::string>                        unjudged;
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        {
          const Row &row = study.rows[i];
          if (!row.written || row.exit_code != 0)
            unjudged.push_back(study.cases[i].name);
          for (const std::string &failed : row.failed)
            {
              const std::string criterion = failed.substr(0, failed.find(": "));
              if (failing.count(criterion) == 0)
                criteria.push_back(criterion);
              failing[criterion].push_back(study.cases[i].name);
            }
        }
      std::string case_list;
      for (const Case &c : study.cases)
        case_list += (case_list.empty() ? "" : ", ") + c.name;
      std::string verdict = "Verdict (cases " + case_list + "): ";
      if (criteria.empty() && unjudged.empty())
        return verdict + "OK";
      std::string reasons;
      for (const std::string &criterion : criteria)
        {
          std::string in;
          for (const std::string &name : failing[criterion])
            in += (in.empty() ? "" : ", ") + name;
          reasons += (reasons.empty() ? "" : "; ") + criterion + " in "
                     + (failing[criterion].size() == study.cases.size() ?
                          std::string("every case") :
                          in);
        }
      for (const std::string &name : unjudged)
        reasons += (reasons.empty() ? "" : "; ") + std::string("case ") + name
                   + " without a converged result";
      return verdict + "FAILED: " + reasons;
    }

    /** The table's rows: a figure each, a cell per case. */
    using Table = std::vector<std::pair<std::string, std::vector<std::string>>>;

    /** The figures of every case: exit code, steps, U, columns, verdict. */
    Table
    figure_table(const Study &study)
    {
      Table      table;
      const auto add = [&](const std::string &label, const auto &cell) {
        std::vector<std::string> cells;
        for (const Row &row : study.rows)
          cells.push_back(cell(row));
        table.emplace_back(label, cells);
      };
      add("exit code",
          [](const Row &r) { return std::to_string(r.exit_code); });
      add("steps", [](const Row &r) {
        return r.written ? std::to_string(r.steps) : std::string("-");
      });
      for (unsigned int k = 0; k < study.base.n_joints(); ++k)
        add(study.base.joint_name(k) + "_U_mm", [k](const Row &r) {
          return k < r.U.size() ? figure(r.U[k]) : std::string("-");
        });
      const std::vector<std::string> names
        = stack_column_names(study.base.bodies);
      for (unsigned int c = 0; c < names.size(); ++c)
        add(names[c], [c](const Row &r) {
          return c < r.values.size() ? figure(r.values[c]) : std::string("-");
        });
      add("verdict", [](const Row &r) {
        return r.verdict.empty() ? std::string("-") : r.verdict;
      });
      return table;
    }

    /** The console's table, each case's error and the verdict. */
    void
    print_table(std::ostream      &out,
                const Study       &study,
                const Table       &table,
                const std::string &verdict,
                const std::string &filename)
    {
      std::size_t width = 6;
      for (const auto &[label, cells] : table)
        width = std::max(width, label.size());
      std::size_t column = 10;
      for (const Case &c : study.cases)
        column = std::max(column, c.name.size() + 2);
      std::ostringstream console;
      console << "\ncoaxfit: Fit/Case = all of " << filename << ": "
              << study.cases.size() << " cases of the ISO fits " << study.fits
              << " (the joints' cases in this order)\n"
              << "  " << std::left << std::setw(width) << "figure"
              << std::right;
      for (const Case &c : study.cases)
        console << std::setw(column) << c.name;
      console << '\n';
      for (const auto &[label, cells] : table)
        {
          console << "  " << std::left << std::setw(width) << label
                  << std::right;
          for (const std::string &cell : cells)
            console << std::setw(column) << cell;
          console << '\n';
        }
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        if (!study.rows[i].error.empty())
          console << "  case " << study.cases[i].name << ": "
                  << study.rows[i].error << '\n';
      console << verdict << '\n';
      out << console.str();
    }

    /** fit_cases.csv: a row per case. */
    void
    write_fit_cases(const std::string &name, const Study &study)
    {
      const std::vector<std::string> names
        = stack_column_names(study.base.bodies);
      std::ofstream csv = open_result_file(name);
      csv << std::setprecision(10) << "case,exit_code,verdict,steps";
      for (unsigned int k = 0; k < study.base.n_joints(); ++k)
        csv << ',' << study.base.joint_name(k) << "_U_mm";
      for (const std::string &n : names)
        csv << ',' << n;
      csv << ",error\n";
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        {
          const Row &row = study.rows[i];
          csv << study.cases[i].name << ',' << row.exit_code << ','
              << row.verdict << ',';
          if (row.written)
            csv << row.steps;
          for (unsigned int k = 0; k < study.base.n_joints(); ++k)
            {
              csv << ',';
              if (k < row.U.size())
                csv << row.U[k];
            }
          write_study_values(csv, row, names.size());
          csv << ',' << csv_field(row.error) << '\n';
        }
      close_result_file(csv, name);
    }

    /** report.md: the verdict, the table, the cases' reports. */
    void
    write_report(const std::string &name,
                 const Study       &study,
                 const Table       &table,
                 const std::string &verdict)
    {
      std::ofstream md = open_result_file(name);
      md << "# coaxfit report: " << study.base.case_name
         << ", Fit/Case = all: the ISO fits " << study.fits << ", "
         << study.cases.size() << " cases\n\n## Verdict\n\n"
         << verdict << "\n\n## The cases\n\n"
         << "Each case has the joints " << study.fits
         << " at their smallest (min) or largest (max) interference, or all "
            "at their means; a mixed corner's name gives their cases in this "
            "order. The joints interact, so a body's stress may be largest "
            "in a mixed corner.";
      if (study.selected)
        md << " The selection (Design/Mode = select) chose the fits in the "
              "case of the means: its choice is in fit_selection.csv (here "
              "and in mean/) and in [mean/report.md](mean/report.md)'s "
              "\"Fit selection\"; the other cases run those fits.";
      md << "\n\n| figure |";
      for (const Case &c : study.cases)
        md << ' ' << c.name << " |";
      md << "\n|---|";
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        md << "---:|";
      md << '\n';
      for (const auto &[label, cells] : table)
        {
          md << "| " << label << " |";
          for (const std::string &cell : cells)
            md << ' ' << cell << " |";
          md << '\n';
        }
      md << "\nEach case's report:";
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        if (study.rows[i].written)
          md << " [" << study.cases[i].name << "](" << study.cases[i].name
             << "/report.md)";
      md << '\n';
      for (unsigned int i = 0; i < study.cases.size(); ++i)
        if (!study.rows[i].error.empty())
          md << "\nCase " << study.cases[i].name << ": " << study.rows[i].error
             << '\n';
      close_result_file(md, name);
    }
  } // namespace



  StackCaseStudy::StackCaseStudy(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides,
    const bool                                              verbose,
    std::ostream                                           &out)
    : filename(filename)
    , overrides(overrides)
    , verbose(verbose)
    , out(out)
  {}



  int
  StackCaseStudy::run()
  {
    const StackParameters base = read_stack_parameters(filename, overrides);
    // With Design/Mode = select the selected joints' fits are chosen first
    // (in the case of the means) and then varied as well.
    const bool                selecting = base.select_mode();
    std::vector<unsigned int> varied;
    for (unsigned int k = 0; k < base.n_joints(); ++k)
      if ((!base.fits[k].iso_fit.empty() || (selecting && base.selected[k]))
          && base.joint_cases[k].empty())
        varied.push_back(k);
    if (varied.empty())
      throw InputError(
        "parameter Fit/Case = all: every joint with an ISO fit gives its own "
        "Fit/<joint>/Case, so no band is left to run through; allowed: min, "
        "mean or max, or a joint with an ISO fit and no Case of its own");
    std::vector<Case> cases = cases_of(varied.size());

    // The directory: replaced as a whole; directly in it the study's
    // files, the cases, an earlier single run's files (an earlier study's
    // corners: ResultDirectory knows them).
    const std::string target  = normalized_directory(base.output_directory());
    std::set<std::string> top = all_result_file_names();
    for (const Case &c : cases)
      top.insert(c.name);
    for (unsigned int k = 0; k < base.n_joints(); ++k)
      {
        top.insert("contact_pressure_" + base.joint_name(k) + ".csv");
        top.insert("interface_" + base.joint_name(k) + ".vtp");
      }
    for (const std::string &b : base.bodies)
      top.insert(Body::key_of(b) + ".vtu");
    ResultDirectory directory(target, all_result_file_names(), top);

    std::vector<Row>         rows(cases.size());
    std::vector<std::string> iso_fits;
    for (const JointFit &f : base.fits)
      iso_fits.push_back(f.iso_fit);
    bool       chosen = false; // the selection's fits used
    const auto run    = [&](const unsigned int i) {
      const Case &c    = cases[i];
      auto        with = overrides;
      with.emplace_back("Fit/Case", "mean");
      for (unsigned int j = 0; j < varied.size(); ++j)
        with.emplace_back("Fit/" + base.joint_name(varied[j]) + "/Case",
                          c.joint_case[j]);
      // parameters.prm of the case names where it ends up.
      with.emplace_back("Output/Directory", target + "/" + c.name);
      rows[i] = run_stack_study_case(
        [&]() {
          StackParameters p = read_stack_parameters(filename, with);
          p.case_name       = base.case_name + "_" + c.name;
          // The fits the selection chose, at this case (its parameters.prm
          // selects them again: the same choice).
          if (chosen)
            {
              for (unsigned int k = 0; k < p.n_joints(); ++k)
                if (p.selected[k])
                  p.use_iso_fit(k, iso_fit(iso_fits[k], p.joint_diameter(k)));
              p.design_mode = "check";
            }
          return p;
        },
        directory.staging_path() + "/" + c.name,
        verbose,
        out);
    };
    if (selecting)
      {
        // The selection, in the case of the means (cases[1]); the other
        // cases check its fits. Without fits the study is that case.
        run(1);
        const Row &mean = rows[1];
        if (mean.no_fits)
          {
            // No fits: the study is the selection's answer, written as a
            // select run writes it (no case to run).
            take_selection_answer(directory.staging_path(), base);
            out << "\ncoaxfit: Fit/Case = all of " << filename
                << ": no case run, the selection found no fits\n"
                << "  Verdict: FAILED: " << mean.failed.front() << '\n';
            directory.commit(out);
            out << "  results in " << target << std::endl;
            return 0;
          }
        // The fits it chose (also where their run did not converge);
        // none known if the case was refused: then only that case.
        chosen = mean.iso_fits.size() == base.n_joints();
        for (unsigned int k = 0; chosen && k < base.n_joints(); ++k)
          chosen = !base.selected[k] || !mean.iso_fits[k].empty();
        if (chosen)
          iso_fits = mean.iso_fits;
        else
          {
            cases = {cases[1]};
            rows  = {rows[1]};
          }
      }
    for (unsigned int i = 0; i < cases.size(); ++i)
      if (!(selecting && cases[i].name == "mean"))
        run(i);

    const Study study{
      base, cases, rows, fits_text(base, varied, iso_fits), chosen};
    const std::string verdict = verdict_line(study);
    const auto        table   = figure_table(study);
    print_table(out, study, table, verdict, filename);
    // Each case without a converged result: one line on the error stream,
    // as its own run would give (its column in the table says the same).
    for (unsigned int i = 0; i < cases.size(); ++i)
      say_unconverged(rows[i], "case " + cases[i].name + " of Fit/Case = all");

    bool      nothing = true;
    const int code
      = stack_study_exit_code(std::vector<StackStudyRun>(rows.begin(),
                                                         rows.end()),
                              "case of the study",
                              target,
                              out,
                              nothing);
    if (nothing)
      return code;
    write_fit_cases(directory.staging_path() + "/fit_cases.csv", study);
    // A selection's table beside the study's, where a select run has it.
    const std::string selection
      = directory.staging_path() + "/mean/fit_selection.csv";
    if (selecting && fs::exists(selection))
      fs::copy_file(selection, directory.staging_path() + "/fit_selection.csv");
    write_report(directory.staging_path() + "/report.md",
                 study,
                 table,
                 verdict);
    directory.commit(out);
    out << "  results in " << target
        << " (fit_cases.csv, report.md, one subdirectory per case)"
        << std::endl;
    return code;
  }
} // namespace coaxfit
