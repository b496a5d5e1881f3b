// --sweep of a stack (a file with Assembly/Bodies), run as a user runs it:
//
// 1. Three rings of equal length swept over the hub's interference: each
//    value's joints against the compound cylinders' closed form (1e-6 at
//    the mesh of stack_lame), each value's summary.json equal to a single
//    run with that value set (1e-12), sweep.csv's pressures equal to the
//    summaries', one subdirectory per value, sweep.png drawn.
// 2. A bad value among good ones: its row has exit 1 and its message, no
//    subdirectory; the others are written; the study exits 1. A value that
//    does not converge (Coupling/Max steps = 2) is written with converged
//    false and exit 2.
// 3. A second study into the same directory replaces the first.
// 4. Refused in one line, exit 1, nothing written: the bodies swept,
//    Output/Directory swept, an entry the stack does not have, a stack
//    and a file of two bodies into one directory.
// 5. --print-parameters FILE.prm lists the stack's own entries.

#include <coaxfit/design/compound_cylinders.h>

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace coaxfit_test;

namespace
{
  const std::string three_rings = R"(subsection Assembly
  set Bodies = Shaft, Sleeve, Hub
end
subsection Geometry
  subsection Shaft
    set Inner diameter = 0
    set Outer diameter = 60
    set Length = 40
  end
  subsection Sleeve
    set Inner diameter = 60
    set Outer diameter = 90
    set Length = 40
  end
  subsection Hub
    set Inner diameter = 90
    set Outer diameter = 160
    set Length = 40
  end
end
subsection Material
  subsection Shaft
    set E = 210000
    set nu = 0.3
  end
  subsection Sleeve
    set E = 110000
    set nu = 0.34
  end
  subsection Hub
    set E = 70000
    set nu = 0.33
  end
end
subsection Fit
  subsection Shaft-Sleeve
    set Diametral interference = 0.04
  end
  subsection Sleeve-Hub
    set Diametral interference = 0.06
  end
end
subsection Mesh
  set Axial cells = 4
  set Radial cells = 6
  set Grading ratio = 1
  set Global refinements = 1
  set Degree = 2
end
subsection Coupling
  set Tolerance = 1e-12
end
subsection Output
  set Write vtu = false
end
)";

  /** The exact pressures of the three rings with the hub's @p U. */
  coaxfit::CompoundCylinders
  exact(const double U)
  {
    return coaxfit::CompoundCylinders({{0., 60., 210000., 0.3},
                                       {60., 90., 110000., 0.34},
                                       {90., 160., 70000., 0.33}},
                                      {0.04, U},
                                      0.,
                                      0.);
  }

  /** The rows of a CSV file, split at commas (no quoted commas here). */
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

  /** The column of sweep.csv named @p name. */
  unsigned int
  column(const std::vector<std::string> &header, const std::string &name)
  {
    for (unsigned int c = 0; c < header.size(); ++c)
      if (header[c] == name)
        return c;
    std::cout << "  no column " << name << '\n';
    return 0;
  }

  /** A refused command: its exit code, lines and whether it wrote. */
  void
  refused(const std::string &what, const std::string &arguments)
  {
    std::filesystem::remove_all("study_sweep");
    const RunResult r = run_coaxfit("study", arguments);
    std::cout << what << ": exit " << r.exit_code << ", " << r.lines
              << " line(s), nothing written "
              << (std::filesystem::exists("study_sweep") ? "NO" : "yes")
              << "\n  " << r.message;
  }
} // namespace



int
main()
{
  std::ofstream("three_rings.prm") << three_rings;

  // Part 1: the hub's interference swept.
  const std::vector<double> U = {0.03, 0.06, 0.09};
  std::filesystem::remove_all("study_sweep");
  RunResult r = run_coaxfit(
    "study",
    "--quiet --sweep 'Fit/Sleeve-Hub/Diametral interference=0.03:0.09:3' "
    "three_rings.prm");
  const auto csv = read_csv("study_sweep/sweep.csv");
  std::cout << "sweep of Fit/Sleeve-Hub/Diametral interference: exit "
            << r.exit_code << ", " << csv.size() - 1 << " rows, sweep.png "
            << (std::filesystem::exists("study_sweep/sweep.png") ? "drawn" :
                                                                   "MISSING")
            << '\n';
  // Every row has a field for each column (the error field empty).
  bool same = true;
  for (const auto &row : csv)
    same
      = same && row.size() + 1 >= csv[0].size() && row.size() <= csv[0].size();
  std::cout << "  " << csv[0].size()
            << " columns, every row as many: " << (same ? "yes" : "NO") << '\n';
  const unsigned int mean_0 = column(csv[0], "Shaft-Sleeve_pressure_mean_MPa");
  const unsigned int mean_1 = column(csv[0], "Sleeve-Hub_pressure_mean_MPa");
  const std::vector<std::string> directories
    = {"01_0.03", "02_0.06", "03_0.09"};
  for (unsigned int i = 0; i < U.size(); ++i)
    {
      const nlohmann::json s = read_summary("study_sweep/" + directories[i]);
      const coaxfit::CompoundCylinders e = exact(U[i]);
      // The same value run alone.
      std::filesystem::remove_all("alone");
      run_coaxfit("alone",
                  "--quiet --set 'Fit/Sleeve-Hub/Diametral interference="
                    + csv[i + 1][0] + "' three_rings.prm");
      const nlohmann::json a = read_summary("alone");
      std::cout << "  U " << csv[i + 1][0] << " mm: exit " << csv[i + 1][1]
                << ", verdict " << csv[i + 1][2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          const nlohmann::json &j = s["joints"][k];
          std::cout << "; " << j["name"].get<std::string>() << ' '
                    << std::setprecision(6) << e.pressure(k)
                    << " MPa exact: mean "
                    << agreement(j["pressure"]["mean"], e.pressure(k), 1e-6)
                    << ", alone "
                    << agreement(j["pressure"]["mean"],
                                 a["joints"][k]["pressure"]["mean"],
                                 1e-12)
                    << ", csv "
                    << agreement(std::stod(
                                   csv[i + 1][k == 0 ? mean_0 : mean_1]),
                                 j["pressure"]["mean"],
                                 1e-12);
        }
      std::cout << '\n';
    }

  // Part 2: a bad value and one that does not converge.
  std::filesystem::remove_all("study_sweep");
  r = run_coaxfit("study",
                  "--quiet --sweep 'Fit/Sleeve-Hub/Diametral interference="
                  "0.06,abc' three_rings.prm");
  std::cout << "a bad value: exit " << r.exit_code << "; subdirectories "
            << std::filesystem::exists("study_sweep/01_0.06") << ' '
            << std::filesystem::exists("study_sweep/02_abc") << "; " << r.lines
            << " line on the error stream: " << gist(r.message, 6) << '\n';
  const auto bad = read_csv("study_sweep/sweep.csv");
  for (unsigned int i = 1; i < bad.size(); ++i)
    std::cout << "  " << bad[i][0] << ", exit " << bad[i][1] << ", "
              << (bad[i].back().empty() ? "no error" : bad[i].back()) << '\n';
  r                = run_coaxfit("study",
                  "--quiet --sweep 'Coupling/Max steps=2,100' three_rings.prm");
  const auto steps = read_csv("study_sweep/sweep.csv");
  std::cout << "Coupling/Max steps swept into the same directory: exit "
            << r.exit_code << " (the first study replaced: 01_0.06 "
            << (std::filesystem::exists("study_sweep/01_0.06") ? "LEFT" :
                                                                 "gone")
            << "); " << r.lines
            << " line on the error stream: " << gist(r.message, 8) << '\n';
  for (unsigned int i = 1; i < steps.size(); ++i)
    {
      const nlohmann::json s = read_summary(
        "study_sweep/" + std::string(i == 1 ? "01_2" : "02_100"));
      std::cout << "  " << steps[i][0] << ", exit " << steps[i][1]
                << ", verdict " << steps[i][2] << ", converged "
                << s["converged"] << ", "
                << (steps[i].back().empty() ? "no error" : steps[i].back())
                << '\n';
    }

  // Part 4: refused.
  refused("the bodies swept",
          "--sweep 'Assembly/Bodies=Shaft, Hub' three_rings.prm");
  refused("the directory swept",
          "--sweep Output/Directory=a,b three_rings.prm");
  refused("no such entry",
          "--sweep 'Fit/Shaft-Hub/Diametral interference=0.1,0.2' "
          "three_rings.prm");
  std::filesystem::copy_file(std::string(COAXFIT_SOURCE_DIR)
                               + "/prm/default.prm",
                             "two_bodies.prm",
                             std::filesystem::copy_options::overwrite_existing);
  refused("a stack and a file of two bodies into one directory",
          "--set Output/Directory=both three_rings.prm two_bodies.prm");

  // Part 5: the stack's entries listed.
  const std::string list = std::string(coaxfit_executable)
                           + " --print-parameters three_rings.prm 2>&1 | ";
  std::cout << "--print-parameters three_rings.prm: 'set Order' "
            << run_command(list + "grep -c 'set Order '").message
            << "  'set Press-in friction coefficient' (Fit and each joint) "
            << run_command(list + "grep -c 'set Press-in friction'").message
            << "  'subsection Shaft-Sleeve' "
            << run_command(list + "grep -c 'subsection Shaft-Sleeve'").message;
}
