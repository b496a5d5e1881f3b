// Bad input: each invalid parameter file or command line must stop coaxfit
// before any work with a one-line message naming the parameter (or file)
// and the allowed range, exit code 1, and no output directory. A diverging
// constant alpha (0.2 for variant 5, whose convergent range is about
// 0.38-0.98) must stop with exit code 2, a one-line message naming alpha,
// and no output either (so no NaN can be written). Hostile input that
// once crashed, hung or was misclassified (subnormal numbers, walls too
// thin for double precision, grading overflow, include cycles, deep JSON,
// a full standard output) gets the same treatment (exit 3 for the last).

#include "run_executable.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  const std::string valid = "subsection Geometry\n"
                            "  set R0 = 0\n"
                            "  set R1 = 100\n"
                            "  set R2 = 200\n"
                            "  set L1 = 200\n"
                            "  set L2 = 100\n"
                            "  set d = 0.25\n"
                            "end\n"
                            "subsection Material\n"
                            "  subsection Shaft\n"
                            "    set E = 2e5\n"
                            "    set nu = 0.33\n"
                            "  end\n"
                            "  subsection Hub\n"
                            "    set E = 2e5\n"
                            "    set nu = 0.33\n"
                            "  end\n"
                            "end\n";

  /** Run coaxfit with @p arguments; print its stderr line and exit code. */
  void
  run(const std::string &label, const std::string &arguments)
  {
    const std::string directory = "out_" + label;
    std::filesystem::remove_all(directory);
    const coaxfit_test::RunResult r
      = coaxfit_test::run_coaxfit(directory, arguments);
    std::cout << label << ": exit code " << r.exit_code << ", " << r.lines
              << " line(s), output directory written: "
              << (std::filesystem::exists(directory) ? "YES" : "no") << '\n'
              << "  " << r.message;
  }

  /** Write the valid file with one line added in section Geometry. */
  std::string
  file_with(const std::string &label, const std::string &extra)
  {
    const std::string name = label + ".prm";
    std::ofstream(name) << valid << extra;
    return name;
  }

  std::string
  geometry(const std::string &label, const std::string &entry)
  {
    return file_with(label, "subsection Geometry\n  set " + entry + "\nend\n");
  }
} // namespace

int
main()
{
  run("R0_not_below_R1", geometry("R0_not_below_R1", "R0 = 100"));
  run("R1_not_below_R2", geometry("R1_not_below_R2", "R2 = 90"));
  run("d_zero", geometry("d_zero", "d = 0"));
  run("L1_negative", geometry("L1_negative", "L1 = -5"));
  run("d_nan", geometry("d_nan", "d = nan"));
  run("malformed_number", geometry("malformed_number", "R2 = 2e5x"));
  run("nu_half",
      file_with("nu_half",
                "subsection Material\n subsection Hub\n  set nu = 0.5\n "
                "end\nend\n"));
  run("E_negative",
      file_with("E_negative",
                "subsection Material\n subsection Shaft\n  set E = -1\n "
                "end\nend\n"));
  run("alpha_one",
      file_with("alpha_one", "subsection Coupling\n  set Alpha = 1\nend\n"));
  run("unknown_entry", geometry("unknown_entry", "R3 = 5"));
  run("unknown_section",
      file_with("unknown_section",
                "subsection Geometrie\n  set R1 = 5\nend\n"));
  run("unknown_controller",
      file_with("unknown_controller",
                "subsection Coupling\n  set Alpha controller = magic\nend\n"));
  run("beta_out_of_range",
      file_with("beta_out_of_range",
                "subsection Coupling\n  set Alpha controller = pointwise\n"
                "  set Beta = 2\nend\n"));
  run("iqn_filter_negative",
      file_with("iqn_filter_negative",
                "subsection Coupling\n  set IQN-ILS filter = -1\nend\n"));
  run("set_out_of_range",
      "--set Mesh/Degree=7 " + file_with("set_out_of_range", ""));
  run("unknown_option", "--fast " + file_with("unknown_option", ""));
  run("missing_file", "no_such_file.prm");
  // The scene has no silent defaults: every missing entry is named.
  std::ofstream("scene_incomplete.prm")
    << "subsection Geometry\n  set R1 = 20\n  set R2 = 40\nend\n";
  run("scene_incomplete", "scene_incomplete.prm");
  std::filesystem::create_directories("a_directory.prm");
  run("unreadable_file", "a_directory.prm");
  run("d_infinite", geometry("d_infinite", "d = inf"));
  run("diverging_alpha",
      "--set \"Coupling/Alpha controller=fixed\" --set Coupling/Alpha=0.2 "
        + std::string(COAXFIT_SOURCE_DIR) + "/prm/variant_05.prm");
  std::ofstream("a_file") << "x";
  run("directory_not_creatable",
      "--set Output/Directory=a_file/sub "
        + file_with("directory_not_creatable", ""));

  // Hostile input that once crashed, hung or ended with exit 2 or 3.
  run("d_subnormal", geometry("d_subnormal", "d = 1e-320"));
  run("shaft_wall_too_thin", geometry("shaft_wall_too_thin", "R0 = 99.9999"));
  run("hub_wall_too_thin", geometry("hub_wall_too_thin", "R2 = 100.00000001"));
  run("E_huge",
      file_with("E_huge",
                "subsection Material\n subsection Hub\n  set E = 1e300\n "
                "end\nend\n"));
  run("grading_overflow",
      "--set \"Mesh/Axial cells=2200\" --set \"Mesh/Radial cells=1\" "
        + file_with("grading_overflow", ""));
  run("too_many_cells_beyond_contact",
      "--set \"Mesh/Grading ratio=1\" --set Geometry/L1=1e6 "
        + file_with("too_many_cells_beyond_contact", ""));
  run("directory_name_too_long",
      "--set Output/Directory=" + std::string(300, 'x') + " "
        + file_with("directory_name_too_long", ""));
  std::ofstream("includes_itself.prm") << "include includes_itself.prm\n";
  run("include_cycle", "includes_itself.prm");
  std::ofstream("deep.json")
    << std::string(100000, '[') << std::string(100000, ']');
  run("json_nested_too_deep", "deep.json");
  {
    // Standard output on a full device: exit 3 and one line.
    const coaxfit_test::RunResult r
      = coaxfit_test::run_command(std::string(coaxfit_test::coaxfit_executable)
                                  + " --print-parameters 2>&1 >/dev/full");
    std::cout << "print_parameters_to_full_device: exit code " << r.exit_code
              << "\n  " << r.message;
  }
}
