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
                            "  set Joint diameter = 200\n"
                            "  set Shaft bore diameter = 0\n"
                            "  set Hub outer diameter = 400\n"
                            "  set Shaft length = 400\n"
                            "  set Hub length = 200\n"
                            "end\n"
                            "subsection Fit\n"
                            "  set Diametral interference = 0.5\n"
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

  std::string
  fit(const std::string &label, const std::string &entries)
  {
    return file_with(label, "subsection Fit\n" + entries + "end\n");
  }
} // namespace

int
main()
{
  run("bore_not_below_joint",
      geometry("bore_not_below_joint", "Shaft bore diameter = 200"));
  run("hub_not_above_joint",
      geometry("hub_not_above_joint", "Hub outer diameter = 180"));
  run("clearance_too_large",
      fit("clearance_too_large", "  set Diametral interference = -25\n"));
  run("shaft_length_negative",
      geometry("shaft_length_negative", "Shaft length = -5"));
  run("U_nan", fit("U_nan", "  set Diametral interference = nan\n"));
  run("malformed_number",
      geometry("malformed_number", "Hub outer diameter = 2e5x"));
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
                "subsection Geometrie\n  set Joint diameter = 5\nend\n"));
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
    << "subsection Geometry\n  set Joint diameter = 20\n  set Hub outer "
       "diameter = 40\nend\n";
  run("scene_incomplete", "scene_incomplete.prm");
  std::filesystem::create_directories("a_directory.prm");
  run("unreadable_file", "a_directory.prm");
  run("U_infinite", fit("U_infinite", "  set Diametral interference = inf\n"));
  run("diverging_alpha",
      "--set \"Coupling/Alpha controller=fixed\" --set Coupling/Alpha=0.2 "
        + std::string(COAXFIT_SOURCE_DIR) + "/prm/variant_05.prm");
  std::ofstream("a_file") << "x";
  run("directory_not_creatable",
      "--set Output/Directory=a_file/sub "
        + file_with("directory_not_creatable", ""));

  // Hostile input that once crashed, hung or ended with exit 2 or 3.
  run("U_subnormal",
      fit("U_subnormal", "  set Diametral interference = 1e-320\n"));
  run("shaft_wall_too_thin",
      geometry("shaft_wall_too_thin", "Shaft bore diameter = 199.9998"));
  run("hub_wall_too_thin",
      geometry("hub_wall_too_thin", "Hub outer diameter = 200.00000002"));
  run("E_huge",
      file_with("E_huge",
                "subsection Material\n subsection Hub\n  set E = 1e300\n "
                "end\nend\n"));
  run("grading_overflow",
      "--set \"Mesh/Axial cells=2200\" --set \"Mesh/Radial cells=1\" "
        + file_with("grading_overflow", ""));
  run("too_many_cells_beyond_contact",
      "--set \"Mesh/Grading ratio=1\" --set \"Geometry/Shaft length=1e5\" "
      "--set \"Geometry/Hub length=1\" "
        + file_with("too_many_cells_beyond_contact", ""));
  run("directory_name_too_long",
      "--set Output/Directory=" + std::string(300, 'x') + " "
        + file_with("directory_name_too_long", ""));
  // The fit and the materials in the engineer's terms.
  // A clearance fit, and a shaft basis hole with a shaft that is not h
  // (H7/k6 and S7/h6 are covered since the fit selection).
  run("iso_fit_clearance", fit("iso_fit_clearance", "  set ISO fit = H7/g6\n"));
  run("iso_fit_shaft_basis",
      fit("iso_fit_shaft_basis", "  set ISO fit = S7/g6\n"));
  run("iso_fit_grade", fit("iso_fit_grade", "  set ISO fit = H7/s12\n"));
  run("iso_fit_t_below_24",
      "--set \"Geometry/Joint diameter=20\" --set \"Geometry/Hub outer "
      "diameter=40\" "
        + fit("iso_fit_t_below_24", "  set ISO fit = H7/t6\n"));
  run("iso_fit_diameter",
      "--set \"Geometry/Joint diameter=600\" --set \"Geometry/Hub outer "
      "diameter=1200\" "
        + fit("iso_fit_diameter", "  set ISO fit = H7/s6\n"));
  run("shaft_temperature_text",
      "--set \"Operation/Shaft temperature=hot\" "
        + file_with("shaft_temperature_text", ""));
  run("hub_temperature_below_absolute_zero",
      "--set \"Operation/Hub temperature=-300\" "
        + file_with("hub_temperature_below_absolute_zero", ""));
  run("bore_pressure_solid_shaft",
      "--set \"Operation/Shaft bore pressure=10\" "
        + file_with("bore_pressure_solid_shaft", ""));
  run("speed_without_density",
      "--set Operation/Speed=3000 " + file_with("speed_without_density", ""));
  run("temperature_without_expansion",
      "--set \"Operation/Hub temperature=120\" "
        + file_with("temperature_without_expansion", ""));
  run("joining_clearance_too_large",
      "--set \"Operation/Joining clearance=50\" "
        + file_with("joining_clearance_too_large", ""));
  run("slip_safety_below_one",
      file_with("slip_safety_below_one",
                "subsection Design\n  set Slip safety = 0.9\nend\n"));
  // The fit selection: K_A below 1 or negative, nothing to carry.
  run("application_factor_below_one",
      file_with("application_factor_below_one",
                "subsection Design\n  set Application factor = 0.8\nend\n"));
  run("application_factor_negative",
      file_with("application_factor_negative",
                "subsection Design\n  set Application factor = -1.25\nend\n"));
  run("select_without_load",
      file_with("select_without_load",
                "subsection Design\n  set Mode = select\nend\n"));
  run("case_without_iso_fit",
      fit("case_without_iso_fit", "  set Case = max\n"));
  run("material_unknown",
      file_with("material_unknown",
                "subsection Material\n subsection Hub\n  set Name = S235\n "
                "end\nend\n"));
  // The friction coefficient: auto for a pairing DIN 7190-1 does not
  // tabulate, a number out of range, a malformed one; a material entry out
  // of its pattern is named with its subsection.
  run("friction_pairing_without_steel",
      file_with("friction_pairing_without_steel",
                "subsection Material\n subsection Shaft\n  set Name = EN AW-"
                "7075 T6\n end\n subsection Hub\n  set Name = EN-GJL-250\n "
                "end\nend\n"));
  run("friction_zero",
      file_with("friction_zero",
                "subsection Design\n  set Friction coefficient = 0\nend\n"));
  run("friction_malformed",
      file_with("friction_malformed",
                "subsection Design\n  set Friction coefficient = 0.1x\nend\n"));
  run(
    "friction_auto_misspelt",
    file_with("friction_auto_misspelt",
              "subsection Design\n  set Friction coefficient = autox\nend\n"));
  run(
    "friction_hexadecimal",
    file_with("friction_hexadecimal",
              "subsection Design\n  set Friction coefficient = 0x0.2\nend\n"));
  run("entry_misspelt",
      file_with("entry_misspelt",
                "subsection Material\n subsection Hub\n  set Yeld strength = "
                "300\n end\nend\n"));
  run("joining_unknown",
      file_with("joining_unknown",
                "subsection Design\n  set Joining = glue\nend\n"));
  run("material_E_malformed",
      file_with("material_E_malformed",
                "subsection Material\n subsection Hub\n  set E = 2e5 MPa\n "
                "end\nend\n"));
  std::ofstream("includes_itself.prm") << "include includes_itself.prm\n";
  run("include_cycle", "includes_itself.prm");
  std::ofstream("deep.json")
    << std::string(100000, '[') << std::string(100000, ']');
  run("json_nested_too_deep", "deep.json");
  {
    // The template of --print-parameters is not a scene: a copy refuses to
    // run until its required entries are given, and names them.
    const coaxfit_test::RunResult t
      = coaxfit_test::run_command(std::string(coaxfit_test::coaxfit_executable)
                                  + " --print-parameters > template.prm");
    std::cout << "print_parameters_template: exit code " << t.exit_code << '\n';
    run("template_unfilled", "template.prm");
  }
  {
    // Standard output on a full device: exit 3 and one line.
    const coaxfit_test::RunResult r
      = coaxfit_test::run_command(std::string(coaxfit_test::coaxfit_executable)
                                  + " --print-parameters 2>&1 >/dev/full");
    std::cout << "print_parameters_to_full_device: exit code " << r.exit_code
              << "\n  " << r.message;
  }
}
