// Driver of the .prm tests (TEST_TARGET of tests/CMakeLists.txt): runs the
// coaxfit executable on the parameter file, as a user would, and writes the
// file "output" that deal.II's test scripts compare with numdiff:
//
// - the exit code and the console output (report, errors), without the
//   residuals of every coupling step (their number stays, in "converged
//   in N steps", and so do the final residuals);
// - summary.json, parsed (it must be valid JSON) and printed without its
//   "timing" object (wall times differ from run to run) and without the
//   alpha of every step (coupling.alpha_history);
// - contact_pressure.csv;
// - whether a second run from the parameters.prm the first run wrote
//   reproduces summary.json and contact_pressure.csv to the last digit.
//
// The parameter file must set Output/Directory (relative: in the test's
// directory) and Output/Print timing = false.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace
{
  /** Run @p command, return its exit code, append its output to @p text. */
  int
  run(const std::string &command, std::string &text)
  {
    FILE *pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
      throw std::runtime_error("cannot run " + command);
    char buffer[4096];
    while (fgets(buffer, sizeof(buffer), pipe))
      text += buffer;
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  std::string
  read(const std::string &filename)
  {
    std::ifstream      in(filename);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /** summary.json without the wall times and the alpha of every step. */
  nlohmann::ordered_json
  summary(const std::string &directory)
  {
    nlohmann::ordered_json j
      = nlohmann::ordered_json::parse(read(directory + "/summary.json"));
    j.erase("timing");
    if (j.contains("coupling"))
      j["coupling"].erase("alpha_history");
    return j;
  }

  /** @p console without the table of the coupling steps. */
  std::string
  without_step_table(const std::string &console)
  {
    static const std::regex step_row(
      R"(^\s*(step\s+kind\b.*|\d+\s+(Neumann|Dirichlet)\b.*)$)");
    std::istringstream in(console);
    std::string        kept, line;
    while (std::getline(in, line))
      if (!std::regex_match(line, step_row))
        kept += line + '\n';
    return kept;
  }

  /** The Output/Directory the parameter file sets. */
  std::string
  output_directory(const std::string &prm)
  {
    std::istringstream in(read(prm));
    std::string        line;
    while (std::getline(in, line))
      {
        const auto key = line.find("set Directory");
        const auto eq  = line.find('=');
        if (key != std::string::npos && eq != std::string::npos)
          {
            std::string value = line.substr(eq + 1);
            value.erase(0, value.find_first_not_of(" \t"));
            value.erase(value.find_last_not_of(" \t") + 1);
            return value;
          }
      }
    throw std::runtime_error(prm + " does not set Output/Directory");
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::cerr << "usage: prm_test_driver FILE.prm" << std::endl;
      return 1;
    }
  const std::string prm       = argv[1];
  const std::string directory = output_directory(prm);
  const std::string coaxfit   = COAXFIT_EXECUTABLE;
  std::filesystem::remove_all(directory);

  std::string   console;
  const int     code = run(coaxfit + " " + prm, console);
  std::ofstream out("output");
  out << "exit code " << code << "\n" << without_step_table(console);
  if (!std::filesystem::exists(directory + "/summary.json"))
    return 0;

  const nlohmann::ordered_json first = summary(directory);
  out << "summary.json (without timing):\n" << first.dump(2) << "\n";
  out << "contact_pressure.csv:\n" << read(directory + "/contact_pressure.csv");

  std::string       ignored;
  const std::string again = directory + "_rerun";
  std::filesystem::remove_all(again);
  run(coaxfit + " --quiet --set Output/Directory=" + again + " " + directory
        + "/parameters.prm",
      ignored);
  nlohmann::ordered_json second = summary(again);
  second["case"]                = first["case"];
  out << "rerun from parameters.prm reproduces summary.json and "
         "contact_pressure.csv: "
      << (second == first
              && read(again + "/contact_pressure.csv")
                   == read(directory + "/contact_pressure.csv") ?
            "yes" :
            "NO")
      << std::endl;
  return 0;
}
