// What a user of an assembly of several bodies opens, checked as they see
// it: prm/examples/bushing_in_housing.prm (a shaft with clearance in a
// bushing pressed into a housing: one joint open, one closed) run as a
// user runs it, then
// - its files: report.md (verdict, the joint table), the gnuplot plots,
//   interface_<joint>.vtp and solution.pvd;
// - with ParaView's own reader (tests/stack_paraview_check.py): a block per
//   body and per joint with units; at each joint the two sides meet where
//   in contact (the interface file's sides and the bodies warped by
//   displacement_mm) and stand apart by the gap where open, the diametral
//   gap as summary.json gives it, the pressure as the CSV gives it;
// - tools/paraview/view.py draws the section, the 3D part, the chart of
//   both joints and the close-up of the open joint;
// - prm/examples/two_seats.prm (two seats beside a relief groove): view.py
//   draws each seat apart in the chart and leaves the peaks at the groove's
//   corners out of the pressure away from the edges (106.5 MPa, as the
//   CSV gives it 2.5 mm from every seat end).
// Without pvpython or xvfb-run the test fails (it does not skip).

#include "run_executable.h"
#include "run_summary.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  const std::string source_dir = COAXFIT_SOURCE_DIR;

  /** Whether @p file is a PNG of a drawing (its signature and size). */
  void
  describe_png(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    char          signature[4] = {};
    in.read(signature, 4);
    const bool png = in && static_cast<unsigned char>(signature[0]) == 0x89
                     && signature[1] == 'P' && signature[2] == 'N'
                     && signature[3] == 'G';
    const auto bytes
      = std::filesystem::exists(file) ? std::filesystem::file_size(file) : 0;
    std::cout << "  " << std::filesystem::path(file).filename().string()
              << ": PNG " << (png ? "yes" : "NO")
              << ", more than 10 kB: " << (bytes > 10000 ? "yes" : "NO")
              << '\n';
  }

  /**
   * Run tools/paraview/view.py on the result directory @p dir, writing
   * into @p png_dir, and show its lines on the joints (its whole log's end
   * if it fails) and the @p pictures. view.py starts its own virtual
   * display when there is none.
   */
  void
  show_views(const std::string              &dir,
             const std::string              &png_dir,
             const std::vector<std::string> &pictures)
  {
    std::filesystem::remove_all(png_dir);
    const coaxfit_test::RunResult view = coaxfit_test::run_command(
      "timeout 300 pvpython " + source_dir + "/tools/paraview/view.py " + dir
      + " --png-dir " + png_dir + " > view.log 2>&1");
    std::cout << "view.py " << dir << ": exit code " << view.exit_code << '\n';
    std::cout << coaxfit_test::run_command(
                   view.exit_code == 0 ?
                     "grep -E '^  contact_|separated zone' view.log" :
                     "tail -5 view.log")
                   .message;
    for (const std::string &name : pictures)
      describe_png(png_dir + "/" + name);
  }
} // namespace


int
main()
{
  for (const std::string tool : {"pvpython", "xvfb-run", "gnuplot"})
    if (coaxfit_test::run_command("command -v " + tool + " >/dev/null")
          .exit_code
        != 0)
      {
        std::cout << tool
                  << " not found: install Debian's paraview, xvfb, xauth and "
                     "gnuplot-nox (.ci/packages)\n";
        return 1;
      }
  const std::string dir = "bushing";
  std::filesystem::remove_all(dir);
  const coaxfit_test::RunResult run
    = coaxfit_test::run_coaxfit(dir,
                                "--set 'Output/Print timing=false' "
                                  + source_dir
                                  + "/prm/examples/bushing_in_housing.prm");
  std::cout << "bushing_in_housing.prm: exit code " << run.exit_code << '\n';
  if (run.exit_code != 0)
    return 1;
  const nlohmann::json summary = coaxfit_test::read_summary(dir);
  std::cout << "  summary verdict ok " << summary["verdict"]["ok"]
            << ", failed " << summary["verdict"]["failed"].size() << '\n';

  // report.md: the verdict and a row per joint.
  {
    std::ifstream in(dir + "/report.md");
    std::string   line;
    while (std::getline(in, line))
      if (line.rfind("Verdict", 0) == 0 || line.rfind("| Shaft-Bushing", 0) == 0
          || line.rfind("| Bushing-Housing", 0) == 0)
        std::cout << "  report.md: " << line << '\n';
  }
  for (const std::string file : {"plots.gp",
                                 "interface_Shaft-Bushing.vtp",
                                 "interface_Bushing-Housing.vtp",
                                 "solution.pvd"})
    std::cout << "  " << file << ": "
              << (std::filesystem::exists(dir + "/" + file) ? "written" :
                                                              "MISSING")
              << '\n';
  for (const std::string name : {"contact_pressure.png", "convergence.png"})
    describe_png(dir + "/" + name);

  const coaxfit_test::RunResult check = coaxfit_test::run_command(
    "timeout 300 pvpython " + source_dir + "/tests/stack_paraview_check.py "
    + dir + " 2>&1");
  std::cout << check.message << "stack_paraview_check.py: exit code "
            << check.exit_code << '\n';

  show_views(
    dir,
    "views",
    {"section.png", "part_3d.png", "contact_chart.png", "separation_zoom.png"});

  // Two seats beside a relief groove: the chart draws each seat apart (no
  // line across the groove), and the pressure away from the edges leaves
  // out the peaks at the groove's corners as at the joint's ends (the
  // seats' means are 100.1 and 90.8 MPa, the peaks 450 MPa).
  const std::string seats = "two_seats";
  std::filesystem::remove_all(seats);
  const coaxfit_test::RunResult seats_run
    = coaxfit_test::run_coaxfit(seats,
                                "--set 'Output/Print timing=false' "
                                  + source_dir + "/prm/examples/two_seats.prm");
  std::cout << "two_seats.prm: exit code " << seats_run.exit_code << '\n';
  if (seats_run.exit_code != 0)
    return 1;
  show_views(seats,
             "seats_views",
             {"section.png", "part_3d.png", "contact_chart.png"});
}
