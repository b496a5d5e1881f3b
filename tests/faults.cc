// Faults during a run: the earlier results in the output directory must
// survive byte for byte whatever happens to a new run into it, and no
// staging directory may be left behind. Each fault runs the coaxfit
// executable through bash: a file size limit (a full disk: ulimit -f), an
// address space limit (ulimit -v) that the memory estimate refuses, SIGTERM
// at two moments and SIGINT, an output directory that cannot be written, a
// directory holding a file coaxfit did not write, and two concurrent runs
// into one directory (the last to finish wins with a complete set). A run
// that does not converge writes a complete set marked as such (exit 2).

#include "run_executable.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace
{
  namespace fs = std::filesystem;

  const std::string case_file
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/default.prm";

  /** Every file of @p directory with its content. */
  std::map<std::string, std::string>
  snapshot(const std::string &directory)
  {
    std::map<std::string, std::string> files;
    for (const auto &entry : fs::directory_iterator(directory))
      {
        std::ifstream      in(entry.path());
        std::ostringstream text;
        text << in.rdbuf();
        files[entry.path().filename().string()] = text.str();
      }
    return files;
  }

  /** Staging directories (".NAME.partial-PID") left in the working dir. */
  unsigned int
  n_staging_left()
  {
    unsigned int n = 0;
    for (const auto &entry : fs::directory_iterator("."))
      n += entry.path().filename().string().find(".partial-")
           != std::string::npos;
    return n;
  }

  /**
   * Run `PREFIX coaxfit --quiet ARGUMENTS` through bash, PREFIX being shell
   * commands such as a ulimit; returns exit code and standard error.
   */
  coaxfit_test::RunResult
  run_shell(const std::string &prefix, const std::string &arguments)
  {
    return coaxfit_test::run_command("timeout 120 bash -c '" + prefix + " exec "
                                     + coaxfit_test::coaxfit_executable
                                     + " --quiet " + arguments
                                     + "' 2>&1 >/dev/null");
  }



  /**
   * Shell text that runs the command before it in the background, waits
   * until it has started its work (its staging directory for "results"
   * exists: signal handlers installed, memory and directory checked), then
   * @p seconds more, and sends it SIG@p name; exits with its exit code.
   */
  std::string
  signal_after(const double seconds, const std::string &name)
  {
    return " & p=$!; for i in $(seq 3000); do [ -d .results.partial-$p ] "
           "&& break; sleep 0.02; done; sleep "
           + std::to_string(seconds) + "; kill -" + name
           + " $p; wait $p; exit $?; :";
  }


  /**
   * Run a fault into @p directory, which holds an earlier result, and
   * report exit code, message and whether the earlier result survived.
   */
  void
  fault(const std::string &label,
        const std::string &prefix,
        const std::string &arguments,
        const std::string &directory,
        const std::size_t  words)
  {
    const auto before = snapshot(directory);
    const auto r
      = run_shell(prefix,
                  "--set Output/Directory=" + directory + " " + arguments);
    std::cout << label << ": exit code " << r.exit_code << ", " << r.lines
              << " line(s): " << coaxfit_test::gist(r.message, words) << '\n'
              << "  earlier results (" << before.size() << " files) "
              << (snapshot(directory) == before ? "untouched" : "CHANGED")
              << ", staging directories left: " << n_staging_left() << '\n';
  }

  /** summary.json of @p directory and whether it agrees with its siblings. */
  void
  check_consistent(const std::string &label, const std::string &directory)
  {
    const auto   files   = snapshot(directory);
    const auto   summary = nlohmann::json::parse(files.at("summary.json"));
    const auto   used    = nlohmann::json::parse(files.at("parameters.json"));
    const double U       = summary["fit"]["U_used"];
    const double U_used
      = std::stod(used["Fit"]["Diametral interference"].get<std::string>());
    std::cout << label << ": " << files.size()
              << " files, summary.json agrees with parameters.json: "
              << (U == U_used ? "yes" : "NO") << ", converged "
              << summary["converged"]
              << ", staging directories left: " << n_staging_left() << '\n';
  }
} // namespace



int
main()
{
  const std::string dir = "results";
  fs::remove_all(dir);
  const std::string small = "--set Mesh/Global\\ refinements=0 ";
  auto              r
    = run_shell("", small + "--set Output/Directory=" + dir + " " + case_file);
  std::cout << "earlier run: exit code " << r.exit_code << '\n';
  check_consistent("earlier run", dir);

  fault("disk full (ulimit -f 8)", "ulimit -f 8;", small + case_file, dir, 5);
  fault("memory (ulimit -v 1500000, 4 refinements)",
        "ulimit -v 1500000;",
        "--set Mesh/Global\\ refinements=4 " + case_file,
        dir,
        5);
  // A section from a gmsh file: the estimate counts the file's cells.
  fault("memory (ulimit -v 1500000, a .geo hub at 3 refinements)",
        "ulimit -v 1500000;",
        "--set Mesh/Global\\ refinements=3 " + std::string(COAXFIT_SOURCE_DIR)
          + "/prm/examples/rounded_gear.prm",
        dir,
        16);
  const std::string slow = "--set Mesh/Global\\ refinements=3 " + case_file;
  fault("SIGTERM once the run has started",
        "",
        slow + signal_after(0., "TERM"),
        dir,
        9);
  fault(
    "SIGTERM 1 s after the start", "", slow + signal_after(1., "TERM"), dir, 9);
  fault("SIGINT 0.5 s after the start",
        "",
        slow + signal_after(0.5, "INT"),
        dir,
        9);
  fs::remove_all("foreign");
  fs::create_directories("foreign");
  std::ofstream("foreign/notes.txt") << "mine\n";
  fault("directory with a file coaxfit did not write",
        "",
        small + case_file,
        "foreign",
        5);
  r = run_shell("",
                "--set Output/Directory=/proc/coaxfit_faults " + small
                  + case_file);
  std::cout << "unwritable directory: exit code " << r.exit_code << ", "
            << r.lines << " line(s): " << coaxfit_test::gist(r.message, 5)
            << '\n';

  // Two runs into one directory at once: one complete set, from either.
  r = run_shell("",
                small + "--set Output/Directory=" + dir + " " + case_file
                  + " & " + coaxfit_test::coaxfit_executable + " --quiet "
                  + small + "--set \"Fit/Diametral interference=0.4\" "
                  + "--set Output/Directory=" + dir + " " + case_file
                  + " >/dev/null; a=$?; wait $!; exit $((a + $?)); :");
  std::cout << "two concurrent runs: exit codes sum " << r.exit_code << '\n';
  check_consistent("two concurrent runs", dir);

  // Not converged: a complete set, marked so.
  r = run_shell("",
                small + "--set Coupling/Max\\ steps=2 "
                  + "--set Output/Directory=" + dir + " " + case_file);
  std::cout << "not converged (Max steps = 2): exit code " << r.exit_code
            << '\n';
  check_consistent("not converged", dir);
}
