// Several cases in one command: `coaxfit A.prm B.prm BAD.prm` and
// `coaxfit --sweep`. Each case runs in a process of its own, forked from
// one that read the parameters (and, in a sweep over the interference or
// the loads, set up the meshes and factorizations once).
//
// Checked against physics: the equal-length pair is Lame's case, p = 187.5
// MPa at U = 0.5 mm, linear in the interference (93.75 MPa at 0.25 mm); a
// hub heated by 50 K (alpha 1.2e-5 1/K, shaft at 20 C) loses
// D alpha dT = 0.12 mm of interference: 142.5 MPa. A bad file fails alone
// (exit 1 for the batch, the others written); the table has every case.
// A sweep value's result must equal, to round-off, the same case run on
// its own (the reused factorizations change nothing).

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  std::string
  lame_file(const std::string &interference, const std::string &extra = "")
  {
    return "subsection Geometry\n"
           "  set Joint diameter = 200\n"
           "  set Shaft bore diameter = 0\n"
           "  set Hub outer diameter = 400\n"
           "  set Shaft length = 200\n"
           "  set Hub length = 200\n"
           "end\n"
           "subsection Fit\n"
           "  set Diametral interference = "
           + interference
           + "\nend\n"
             "subsection Material\n"
             "  subsection Shaft\n"
             "    set E = 2e5\n"
             "    set nu = 0.33\n"
             "    set Thermal expansion = 1.2e-5\n"
             "  end\n"
             "  subsection Hub\n"
             "    set E = 2e5\n"
             "    set nu = 0.33\n"
             "    set Thermal expansion = 1.2e-5\n"
             "  end\n"
             "end\n"
             "subsection Output\n"
             "  set Print timing = false\n"
             "end\n"
           + extra;
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  /** The rows of a CSV file (header first), split at commas. */
  std::vector<std::vector<std::string>>
  read_csv(const std::string &name)
  {
    std::vector<std::vector<std::string>> rows;
    std::ifstream                         in(name);
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> row;
        std::istringstream       s(line);
        for (std::string field; std::getline(s, field, ',');)
          row.push_back(field);
        rows.push_back(row);
      }
    return rows;
  }

  /** The column @p name of @p rows' header. */
  unsigned int
  column(const std::vector<std::vector<std::string>> &rows,
         const std::string                           &name)
  {
    for (unsigned int i = 0; i < rows[0].size(); ++i)
      if (rows[0][i] == name)
        return i;
    throw std::runtime_error("no column " + name);
  }

  nlohmann::json
  summary(const std::string &directory)
  {
    std::ifstream in(directory + "/summary.json");
    return nlohmann::json::parse(in);
  }

  /** Relative difference, printed as "below 1e-N" for numdiff. */
  std::string
  agreement(const double a, const double b)
  {
    const double e = std::abs(a - b) / std::abs(b);
    for (const double bound : {1e-12, 1e-8, 1e-4, 1e-3, 1e-2})
      if (e < bound)
        {
          std::ostringstream s;
          s << "below " << bound;
          return s.str();
        }
    return "NOT within 1e-2 (" + std::to_string(e) + ")";
  }
} // namespace



int
main()
{
  using coaxfit_test::coaxfit_executable;
  using coaxfit_test::run_command;
  // Not output/: deal.II's test scripts write the file "output" here.
  fs::remove_all("results");
  auto directory = [](const std::string &name) {
    return "subsection Output\n  set Directory = results/" + name + "\nend\n";
  };
  write("lame_a.prm", lame_file("0.5", directory("lame_a")));
  write("lame_b.prm", lame_file("0.25", directory("lame_b")));
  write("bad.prm",
        lame_file("0.5",
                  directory("bad")
                    + "subsection Mesh\n  set Radial cells = 0\nend\n"));

  // Several files, two at a time; one of them bad.
  {
    const coaxfit_test::RunResult r
      = run_command("timeout 120 " + std::string(coaxfit_executable)
                    + " --quiet --jobs 2 lame_a.prm lame_b.prm bad.prm "
                      "2>&1 >/dev/null");
    std::cout << "three files: exit code " << r.exit_code << " (1: a bad file)"
              << ", error lines " << r.lines << '\n'
              << "  " << r.message;
    const auto rows = read_csv("results/cases.csv");
    std::cout << "  results/cases.csv: " << rows.size() - 1 << " rows\n";
    const double lame[] = {187.5, 93.75};
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const auto &row = rows[i];
        std::cout << "  " << row[column(rows, "case")] << ": exit "
                  << row[column(rows, "exit_code")] << ", "
                  << row[column(rows, "status")];
        if (i < 3)
          std::cout
            << ", mean pressure against Lame "
            << agreement(std::stod(row[column(rows, "pressure_mean_MPa")]),
                         lame[i - 1])
            << ", directory "
            << (fs::exists(row[column(rows, "directory")] + "/shaft.vtu") ?
                  "complete" :
                  "INCOMPLETE");
        std::cout << '\n';
      }
    std::cout << "  results/bad written: "
              << (fs::exists("results/bad") ? "YES" : "no") << '\n';
  }

  // A sweep over the interference of lame_a.prm.
  {
    const coaxfit_test::RunResult r = run_command(
      "timeout 120 " + std::string(coaxfit_executable)
      + " --quiet --sweep 'Fit/Diametral interference=0.25:0.75:3'"
        " lame_a.prm 2>&1 >/dev/null");
    std::cout << "sweep of the interference: exit code " << r.exit_code
              << ", error lines " << r.lines << '\n';
    const std::string study = "results/lame_a_sweep";
    const auto        rows  = read_csv(study + "/sweep.csv");
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const double u
          = std::stod(rows[i][column(rows, "Fit/Diametral interference")]);
        const std::string dir = rows[i][column(rows, "directory")];
        std::cout << "  U = " << u << " mm: " << rows[i][column(rows, "status")]
                  << ", mean pressure against Lame 187.5 U/0.5: "
                  << agreement(std::stod(
                                 rows[i][column(rows, "pressure_mean_MPa")]),
                               187.5 * u / 0.5)
                  << ", summary.json "
                  << (fs::exists(dir + "/summary.json") ? "yes" : "NO")
                  << ", shaft.vtu (figures only) "
                  << (fs::exists(dir + "/shaft.vtu") ? "YES" : "no") << '\n';
      }
    std::cout << "  sweep.png "
              << (fs::exists(study + "/sweep.png") ? "yes" : "NO")
              << ", sweep.gp "
              << (fs::exists(study + "/sweep.gp") ? "yes" : "NO") << '\n';
    // The reused setup changes nothing: U = 0.5 equals lame_a.prm alone.
    const nlohmann::json alone = summary("results/lame_a");
    const nlohmann::json swept = summary(study + "/02_0.5");
    std::cout << "  U = 0.5 against the same case alone: p(0) "
              << agreement(swept["pressure"]["at_mid_plane"].get<double>(),
                           alone["pressure"]["at_mid_plane"].get<double>())
              << ", mean "
              << agreement(swept["pressure"]["mean"].get<double>(),
                           alone["pressure"]["mean"].get<double>())
              << ", steps " << swept["iterations"] << " and "
              << alone["iterations"] << '\n';
  }

  // A sweep over a load of operation (the loads change, the matrices not).
  {
    const coaxfit_test::RunResult r
      = run_command("timeout 120 " + std::string(coaxfit_executable)
                    + " --quiet --sweep 'Operation/Hub temperature=20,70'"
                      " lame_a.prm 2>&1 >/dev/null");
    const coaxfit_test::RunResult alone = run_command(
      "timeout 120 " + std::string(coaxfit_executable)
      + " --quiet --set 'Operation/Hub temperature=70' --set "
        "Output/Directory=results/hot lame_a.prm 2>&1 >/dev/null");
    std::cout << "sweep of the hub temperature: exit code " << r.exit_code
              << ", the hot case alone: exit code " << alone.exit_code << '\n';
    const nlohmann::json hot = summary("results/lame_a_sweep/02_70");
    std::cout
      << "  70 C: operating mean pressure against Lame with U - "
         "D alpha dT (142.5 MPa): "
      << agreement(hot["pressure"]["mean"].get<double>(), 142.5)
      << "; against the case alone: "
      << agreement(hot["pressure"]["mean"].get<double>(),
                   summary("results/hot")["pressure"]["mean"].get<double>())
      << '\n';
    const nlohmann::json cold = summary("results/lame_a_sweep/01_20");
    std::cout << "  20 C: mean pressure against Lame (187.5 MPa): "
              << agreement(cold["pressure"]["mean"].get<double>(), 187.5)
              << '\n';
  }

  // A sweep of the load of a selection whose file has none: the file is a
  // case with the first value; 1e7 N m no interference up to 0.1 D_F
  // carries (status no fit, exit code 0).
  {
    const coaxfit_test::RunResult r = run_command(
      "timeout 120 " + std::string(coaxfit_executable)
      + " --quiet --jobs 1 --set Design/Mode=select --set "
        "Output/Directory=results/select --sweep 'Design/Required "
        "torque=100,200,1e7' lame_a.prm 2>&1 >/dev/null");
    const auto rows = read_csv("results/select_sweep/sweep.csv");
    std::cout << "sweep of the torque of a selection (the file without a "
                 "load): exit code "
              << r.exit_code << ", " << rows.size() - 1 << " rows:";
    const unsigned int value  = column(rows, "Design/Required torque"),
                       status = column(rows, "status");
    for (unsigned int i = 1; i < rows.size(); ++i)
      std::cout << ' ' << rows[i][value] << ' ' << rows[i][status];
    std::cout << '\n';
  }

  // Guards, before any case runs: directories inside each other, a table
  // that would land in a case's directory (replaced as a whole), overwrite
  // an input file or replace a directory.
  {
    write("nested.prm", lame_file("0.5", directory("lame_a/inner")));
    const coaxfit_test::RunResult nested
      = run_command("timeout 120 " + std::string(coaxfit_executable)
                    + " --quiet lame_a.prm nested.prm 2>&1 >/dev/null");
    std::cout << "a case inside another's directory: exit code "
              << nested.exit_code << '\n'
              << "  " << nested.message << "  results/lame_a/inner written: "
              << (fs::exists("results/lame_a/inner") ? "YES" : "no") << '\n';
    for (const std::string table :
         {"results/lame_a/summary.json", "lame_b.prm", "results"})
      {
        const coaxfit_test::RunResult r = run_command(
          "timeout 120 " + std::string(coaxfit_executable) + " --quiet --table "
          + table + " lame_a.prm lame_b.prm 2>&1 >/dev/null");
        std::cout << "--table " << table << ": exit code " << r.exit_code
                  << "\n  " << r.message;
      }
    std::ifstream input("lame_b.prm");
    std::string   first;
    std::getline(input, first);
    std::cout << "  lame_b.prm untouched: "
              << (first == "subsection Geometry" ? "yes" : "NO")
              << "; results/lame_a/summary.json still a summary: "
              << (summary("results/lame_a").contains("pressure") ? "yes" : "NO")
              << '\n';
  }
}
