// Several stack files in one command (`coaxfit A.prm B.prm ...`): each file
// runs as it would on its own, into its own Output/Directory, and a case
// that fails ends alone. The test runs three_rings.prm, gear_rim.prm, a
// file with an unknown body's subsection (bad input) and three_rings.prm
// stopped after two coupling steps (not converged) together, and checks
// 1. the batch's exit code (the worst: 2), the table's rows (one per joint
//    of each case, one for a case without figures) and each row's status,
//    two cases at a time (--jobs 2) and one at a time (the same rows);
// 2. each converged case's mean pressures and steps against the same file
//    run on its own (identical: the same process runs it the same way);
// 3. the directories: written for every case but the bad one;
// 4. --table FILE.csv, and refusals before any case runs (exit 1, one
//    line, nothing written): two cases with one output directory, a stack
//    and a file of two bodies with one;
// 5. stacks mixed with a file of two bodies: two tables, cases.csv and
//    cases_stacks.csv, the case of two bodies equal to its own run.

#include "run_executable.h"
#include "run_summary.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace coaxfit_test;

namespace
{
  const std::string examples
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/";

  /** The rows of a CSV file (the header first), split at commas. */
  std::vector<std::vector<std::string>>
  read_csv(const std::string &file)
  {
    std::vector<std::vector<std::string>> rows;
    std::ifstream                         in(file);
    std::string                           line;
    while (std::getline(in, line))
      {
        std::vector<std::string> fields;
        std::istringstream       s(line);
        std::string              field;
        while (std::getline(s, field, ','))
          fields.push_back(field);
        rows.push_back(fields);
      }
    return rows;
  }

  /** A copy of @p example in @p dir with @p extra appended. */
  std::string
  variant(const std::string &dir,
          const std::string &name,
          const std::string &example,
          const std::string &extra)
  {
    std::ifstream     in(examples + example);
    const std::string text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    const std::string file = dir + "/" + name + ".prm";
    std::ofstream(file) << text << extra;
    return file;
  }
} // namespace

int
main()
{
  namespace fs           = std::filesystem;
  const std::string base = fs::current_path().string();
  const std::string in   = base + "/in";
  fs::remove_all(in);
  fs::create_directories(in);
  const std::string out = base + "/out";
  fs::remove_all(out);

  // Each case into out/<name>.
  const auto into = [&](const std::string &name) {
    return "subsection Output\n  set Directory = " + out + "/" + name
           + "\n  set Write vtu = false\n  set Write plots = false\n"
             "  set Print timing = false\nend\n";
  };
  const std::string rings
    = variant(in, "rings", "three_rings.prm", into("rings"));
  const std::string gear = variant(in, "gear", "gear_rim.prm", into("gear"));
  const std::string bad  = variant(in,
                                  "bad",
                                  "three_rings.prm",
                                  "subsection Material\n  subsection Collar\n"
                                   "    set E = 1\n  end\nend\n"
                                    + into("bad"));
  const std::string stopped
    = variant(in,
              "stopped",
              "three_rings.prm",
              "subsection Coupling\n  set Max steps = 2\nend\n"
                + into("stopped"));

  // 1. The batch.
  const RunResult r = run_command(
    std::string("timeout 120 ") + coaxfit_executable + " --quiet --jobs 2 "
    + rings + " " + gear + " " + bad + " " + stopped + " 2>&1 >/dev/null");
  std::cout << "1. four stack files: exit code " << r.exit_code << ", "
            << r.lines << " lines on standard error\n";
  const auto  rows = read_csv(out + "/cases.csv");
  std::string header;
  for (const std::string &f :
       rows.empty() ? std::vector<std::string>() : rows[0])
    header += f + ' ';
  std::cout << "  out/cases.csv: " << (rows.empty() ? 0 : rows.size() - 1)
            << " rows; header " << header << '\n';
  std::map<std::string, std::vector<std::string>> by_joint;
  for (std::size_t i = 1; i < rows.size(); ++i)
    {
      const std::string name = fs::path(rows[i][0]).stem().string();
      std::cout << "  " << name << ": exit " << rows[i][1] << ", " << rows[i][2]
                << ", verdict " << (rows[i][3].empty() ? "-" : rows[i][3])
                << ", joint " << (rows[i][6].empty() ? "-" : rows[i][6])
                << '\n';
      if (!rows[i][6].empty())
        by_joint[name + " " + rows[i][6]] = rows[i];
    }

  // 1b. The cases one at a time (--jobs 1): the same rows (wall times
  // aside) and exit code.
  {
    const std::string table = base + "/one_job.csv";
    const RunResult   one
      = run_command(std::string("timeout 120 ") + coaxfit_executable
                    + " --quiet --jobs 1 --table " + table + " " + rings + " "
                    + gear + " " + bad + " " + stopped + " 2>&1 >/dev/null");
    auto one_rows = read_csv(table), two_rows = rows;
    for (auto *t : {&one_rows, &two_rows})
      for (auto &row : *t)
        if (row.size() > 5)
          row[5].clear(); // wall_s
    std::cout << "1b. --jobs 1: exit code " << one.exit_code << ", rows "
              << (one_rows == two_rows ? "the same" : "DIFFERENT") << '\n';
  }

  // 2. Each converged case against the file run on its own.
  for (const auto &[name, file] :
       std::vector<std::pair<std::string, std::string>>{{"rings", rings},
                                                        {"gear", gear}})
    {
      const std::string alone = base + "/alone_" + name;
      fs::remove_all(alone);
      const RunResult      single = run_coaxfit(alone, "--quiet " + file);
      const nlohmann::json j      = read_summary(alone);
      std::cout << "2. " << name << " alone: exit " << single.exit_code;
      for (const auto &joint : j["joints"])
        {
          const auto &row
            = by_joint[name + " " + joint["name"].get<std::string>()];
          const double mean = joint["pressure"]["mean"].get<double>();
          std::cout << "; " << joint["name"].get<std::string>() << " mean "
                    << std::setprecision(7) << mean << " MPa, the batch's "
                    << agreement(std::stod(row[9]), mean, 1e-9);
        }
      std::cout << "; steps " << j["coupling"]["steps"] << '\n';
    }

  // 3. The directories.
  std::cout << "3. written:";
  for (const std::string name : {"rings", "gear", "bad", "stopped"})
    std::cout << ' ' << name << ' '
              << (fs::exists(out + "/" + name + "/summary.json") ? "yes" :
                                                                   "no");
  std::cout << '\n';

  // 4. --table, and refusals.
  {
    const std::string table = base + "/table/mine.csv";
    fs::remove_all(base + "/table");
    const RunResult t = run_command(
      std::string("timeout 120 ") + coaxfit_executable + " --quiet --table "
      + table + " " + rings + " " + gear + " 2>&1 >/dev/null");
    std::cout << "4. --table: exit code " << t.exit_code << ", "
              << read_csv(table).size() - 1 << " rows\n";
  }
  const auto refused = [&](const std::string &what, const std::string &files) {
    fs::remove_all(out);
    const RunResult x
      = run_command(std::string("timeout 60 ") + coaxfit_executable
                    + " --quiet " + files + " 2>&1 >/dev/null");
    std::string message = x.message;
    for (const auto &[path, name] :
         {std::make_pair(base, std::string("DIR")),
          std::make_pair(std::string(COAXFIT_SOURCE_DIR), std::string("SRC"))})
      for (std::size_t at; (at = message.find(path)) != std::string::npos;)
        message.replace(at, path.size(), name);
    std::cout << "  " << what << ": exit code " << x.exit_code << ", "
              << x.lines << " line: " << gist(message, 16)
              << "; written: " << (fs::exists(out) ? "yes" : "nothing") << '\n';
  };
  const std::string twin = variant(in, "twin", "gear_rim.prm", into("rings"));
  refused("two cases, one directory", rings + " " + twin);
  const std::string steel_twin
    = variant(in, "steel_twin", "steel_hub_H7s6.prm", into("rings"));
  refused("a stack and a file of two bodies, one directory",
          rings + " " + steel_twin);

  // 5. Stacks mixed with files of two bodies: each kind runs as a batch of
  // its own, the two-body table in cases.csv, the stacks' beside it.
  {
    fs::remove_all(out);
    const std::string steel
      = variant(in, "steel", "steel_hub_H7s6.prm", into("steel"));
    const RunResult m = run_command(
      std::string("timeout 120 ") + coaxfit_executable + " --quiet " + rings
      + " " + steel + " " + gear + " 2>&1 >/dev/null");
    const auto two_body = read_csv(out + "/cases.csv"),
               stacks   = read_csv(out + "/cases_stacks.csv");
    std::cout << "5. a stack, a file of two bodies, a stack: exit code "
              << m.exit_code << "; cases.csv "
              << (two_body.empty() ? 0 : two_body.size() - 1)
              << " row(s), cases_stacks.csv "
              << (stacks.empty() ? 0 : stacks.size() - 1) << " rows; written:";
    for (const std::string name : {"rings", "steel", "gear"})
      std::cout << ' ' << name << ' '
                << (fs::exists(out + "/" + name + "/report.md") ? "yes" : "no");
    // The case of two bodies against the file run on its own.
    const std::string alone = base + "/alone_steel";
    fs::remove_all(alone);
    run_coaxfit(alone, "--quiet " + steel);
    // Fit/Case = all: the mean case gives the batch's figures.
    const nlohmann::json j = read_summary(alone + "/mean");
    std::cout << "\n  steel_hub_H7s6 alone (its mean case): mean "
              << std::setprecision(7) << j["pressure"]["mean"].get<double>()
              << " MPa, the batch's "
              << agreement(two_body.size() > 1 ? std::stod(two_body[1][5]) : 0.,
                           j["pressure"]["mean"].get<double>(),
                           1e-9)
              << '\n';
  }
  return 0;
}
