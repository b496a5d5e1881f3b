// Fit/Case = all of a stack: the joints' ISO fits over their bands. Three
// rings of equal length (the three_rings example's: a steel shaft D 60, a
// bronze sleeve D 60-90, an aluminium hub D 90-160, 60 mm long), the
// joints H7/s6 at D 60 and H7/r6 at D 90 (ISO 286-2: H7 0/+30 and s6
// +53/+72 um in 50-65 mm, so U 0.023 to 0.072 mm; H7 0/+35 and r6
// +51/+73 um in 80-100 mm, so U 0.016 to 0.073 mm), frictionless, no
// loads: each ring is in a plane-stress Lame state, so every case's
// pressures are the compound cylinders' of its interferences.
//
// 1. The five cases (min, mean, max and the mixed corners min-max,
//    max-min): each joint's interference as ISO 286 gives it (1e-12),
//    each joint's pressure at the mid-plane and mean against the compound
//    cylinders (1e-5), fit_cases.csv's figures equal to each case's
//    summary.json (1e-9).
// 2. The verdict over all cases (Design/Required torque 1300 N m, slip
//    safety 1.5): T = nu p pi D^2 l / 2 is 40.715 p N m at D 60 and
//    91.609 p N m at D 90, so the shaft's joint needs p >= 47.89 MPa and
//    the hub's p >= 21.29 MPa. The verdict lists each failed criterion
//    with exactly the cases whose slip safety in fit_cases.csv is below
//    1.5: the shaft's joint in min and min-max (42.13 MPa: the hub's fit
//    at its largest squeezes it, not enough), the hub's in min and max-min
//    (20.53 MPa); the case of the means passes both.
// 3. A case's parameters.prm repeats it (1e-12); a second study replaces
//    the first, and a single run the study; cases that do not converge
//    are written with exit 2 and a line each on the error stream; a
//    standard output closed during the study gives exit 3 with nothing
//    put in place; a joint with its own Fit/<joint>/Case keeps it while
//    the other varies (three cases).
// 4. Bad input: exit 1, one line naming the entry, nothing written.
// 5. Design/Mode = select with Fit/Case = all: the selection chooses in
//    the case of the means (the same fits as a select run at Case =
//    mean), the other cases run them: each case's U as ISO 286 gives it
//    for the chosen fits, its pressures the compound cylinders' (1e-5),
//    every slip safety at least the 1.5 the selection's FE check at the
//    corners promised; a case's parameters.prm selects again and repeats
//    it; a torque no fit carries gives the selection's answer and no case
//    (named as the study, its parameters.prm the study's); a selected
//    joint with its own Case keeps its chosen fit at that case throughout.

#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/parameters/iso286.h>

#include "run_executable.h"
#include "run_summary.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace coaxfit_test;

namespace
{
  /** The three rings with ISO fits; @p extra appended. */
  std::string
  rings_prm(const std::string &extra = "")
  {
    return "subsection Assembly\n  set Bodies = Shaft, Sleeve, Hub\nend\n"
           "subsection Geometry\n"
           "  subsection Shaft\n    set Inner diameter = 0\n"
           "    set Outer diameter = 60\n    set Length = 60\n  end\n"
           "  subsection Sleeve\n    set Inner diameter = 60\n"
           "    set Outer diameter = 90\n    set Length = 60\n  end\n"
           "  subsection Hub\n    set Inner diameter = 90\n"
           "    set Outer diameter = 160\n    set Length = 60\n  end\n"
           "end\n"
           "subsection Material\n"
           "  subsection Shaft\n    set E = 210000\n    set nu = 0.3\n"
           "    set Yield strength = 650\n  end\n"
           "  subsection Sleeve\n    set E = 110000\n    set nu = 0.34\n"
           "    set Yield strength = 250\n  end\n"
           "  subsection Hub\n    set E = 70000\n    set nu = 0.33\n"
           "    set Yield strength = 200\n  end\n"
           "end\n"
           "subsection Fit\n  set Case = all\n"
           "  set Friction coefficient = 0.12\n"
           "  subsection Shaft-Sleeve\n    set ISO fit = H7/s6\n  end\n"
           "  subsection Sleeve-Hub\n    set ISO fit = H7/r6\n  end\n"
           "end\n"
           "subsection Design\n  set Required torque = 1300\n"
           "  set Slip safety = 1.5\nend\n"
           "subsection Mesh\n  set Global refinements = 1\nend\n"
           "subsection Coupling\n  set Tolerance = 1e-10\nend\n"
           + extra;
  }

  /** fit_cases.csv of @p dir: case -> column -> text. */
  std::map<std::string, std::map<std::string, std::string>>
  read_table(const std::string &dir)
  {
    std::ifstream in(dir + "/fit_cases.csv");
    std::string   line;
    std::map<std::string, std::map<std::string, std::string>> table;
    std::getline(in, line);
    const std::vector<std::string> header = csv_fields(line);
    while (std::getline(in, line))
      {
        const std::vector<std::string> fields = csv_fields(line);
        for (unsigned int c = 0; c < fields.size() && c < header.size(); ++c)
          table[fields[0]][header[c]] = fields[c];
      }
    return table;
  }

  /** The line of @p dir/report.md that begins with "Verdict". */
  std::string
  verdict_of(const std::string &dir)
  {
    std::ifstream in(dir + "/report.md");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("Verdict", 0) == 0)
        return line;
    return "NO VERDICT";
  }

  /** The entries directly in @p dir, sorted. */
  std::string
  entries(const std::string &dir)
  {
    std::vector<std::string> names;
    for (const auto &e : std::filesystem::directory_iterator(dir))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string s;
    for (const std::string &n : names)
      s += (s.empty() ? "" : " ") + n;
    return s;
  }
  /**
   * Run the min-max case of the study in @p dir again from its
   * parameters.prm into @p again; print its exit code and whether both
   * joints' mean pressures are the case's (1e-12).
   */
  void
  repeat(const std::string &dir, const std::string &again)
  {
    std::filesystem::remove_all(again);
    const RunResult r
      = run_coaxfit(again, quiet + dir + "/min-max/parameters.prm");
    const nlohmann::json a = read_summary(again),
                         b = read_summary(dir + "/min-max");
    std::cout << "min-max/parameters.prm: exit " << r.exit_code
              << ", the mean pressures "
              << agreement(a["joints"][0]["pressure"]["mean"],
                           b["joints"][0]["pressure"]["mean"],
                           1e-12)
              << ", "
              << agreement(a["joints"][1]["pressure"]["mean"],
                           b["joints"][1]["pressure"]["mean"],
                           1e-12)
              << '\n';
  }
} // namespace


int
main()
{
  const std::vector<coaxfit::CompoundCylinders::Ring> rings
    = {{0., 60., 210000., 0.3},
       {60., 90., 110000., 0.34},
       {90., 160., 70000., 0.33}};
  const std::map<std::string, std::vector<double>> iso
    = {{"min", {0.023, 0.016}},
       {"mean", {0.0475, 0.0445}},
       {"max", {0.072, 0.073}},
       {"min-max", {0.023, 0.073}},
       {"max-min", {0.072, 0.016}}};
  const std::vector<std::string> joints = {"Shaft-Sleeve", "Sleeve-Hub"};

  std::cout << "1. The cases against the compound cylinders\n";
  std::ofstream("rings.prm") << rings_prm();
  std::filesystem::remove_all("all");
  RunResult r = run_coaxfit("all", quiet + "rings.prm");
  std::cout << "exit " << r.exit_code << "; all/: " << entries("all") << '\n';
  auto table = read_table("all");
  for (const std::string c : {"min", "mean", "max", "min-max", "max-min"})
    {
      const nlohmann::json             s = read_summary("all/" + c);
      const coaxfit::CompoundCylinders exact(rings, iso.at(c), 0., 0.);
      std::cout << c << ": exit " << table[c]["exit_code"] << ", verdict "
                << table[c]["verdict"] << '\n';
      for (unsigned int k = 0; k < 2; ++k)
        {
          const nlohmann::json &j = s["joints"][k];
          const double          p = exact.pressure(k);
          std::cout << "  " << joints[k] << ": U "
                    << agreement(std::stod(table[c][joints[k] + "_U_mm"]),
                                 iso.at(c)[k],
                                 1e-12)
                    << " with ISO 286, p exact " << std::setprecision(6) << p
                    << " MPa: mid-plane "
                    << agreement(j["pressure"]["at_mid_plane"], p, 1e-5)
                    << ", mean " << agreement(j["pressure"]["mean"], p, 1e-5)
                    << "; fit_cases.csv = summary.json: "
                    << agreement(std::stod(
                                   table[c][joints[k] + "_pressure_mean_MPa"]),
                                 j["pressure"]["mean"],
                                 1e-9)
                    << '\n';
        }
      std::cout << "  Sleeve's von Mises at its mid-plane "
                << std::setprecision(5)
                << std::stod(table[c]["Sleeve_von_mises_mid_plane_MPa"])
                << " MPa\n";
    }

  std::cout << "\n2. The verdict over all cases\n" << verdict_of("all") << '\n';
  for (const std::string &joint : joints)
    {
      std::cout << "  " << joint << ": slip safety below 1.5 in";
      for (const std::string c : {"min", "mean", "max", "min-max", "max-min"})
        if (std::stod(table[c][joint + "_safety_slip"]) < 1.5)
          std::cout << ' ' << c;
      std::cout << '\n';
    }

  std::cout << "\n3. Repeated, replaced, a joint's own Case\n";
  {
    repeat("all", "again");
    r = run_coaxfit("all", quiet + "rings.prm");
    std::cout << "a second study into all/: exit " << r.exit_code << "; "
              << entries("all") << '\n';
    r = run_coaxfit("all", quiet + "--set Fit/Case=mean rings.prm");
    std::cout << "a single run (Fit/Case = mean) into the study's directory: "
                 "exit "
              << r.exit_code << "; " << entries("all") << '\n';
    // Cases that do not converge in two steps: written, exit 2, a line on
    // the error stream each.
    std::filesystem::remove_all("steps");
    r = run_coaxfit("steps", quiet + "--set 'Coupling/Max steps=2' rings.prm");
    std::cout << "Coupling/Max steps = 2: exit " << r.exit_code << ", "
              << r.lines
              << " lines on the error stream, the first: " << gist(r.message, 9)
              << "; steps/: " << entries("steps") << '\n';
    // Standard output closed during the study: exit 3, nothing put in place.
    std::filesystem::remove_all("piped");
    r = run_command("bash -c '" + std::string(coaxfit_executable) + quiet
                    + "--set Output/Directory=piped rings.prm 2>/dev/null | "
                      "head -c 1 >/dev/null; echo ${PIPESTATUS[0]}'");
    std::cout << "its standard output closed after one byte: exit "
              << r.message.substr(0, r.message.find('\n'))
              << ", results put in place "
              << (std::filesystem::exists("piped") ? "YES" : "no")
              << ", a staging directory left "
              << (coaxfit_test::run_command("ls -a | grep -q partial").exit_code
                      == 0 ?
                    "YES" :
                    "no")
              << '\n';
    std::filesystem::remove_all("own");
    r = run_coaxfit("own", quiet + "--set Fit/Sleeve-Hub/Case=max rings.prm");
    table = read_table("own");
    std::cout << "Sleeve-Hub at its own Case max: exit " << r.exit_code
              << "; own/: " << entries("own") << "\n  Sleeve-Hub U:";
    for (const std::string c : {"min", "mean", "max"})
      std::cout << ' ' << c << ' ' << table[c]["Sleeve-Hub_U_mm"];
    std::cout << "\n  Shaft-Sleeve U:";
    for (const std::string c : {"min", "mean", "max"})
      std::cout << ' ' << c << ' ' << table[c]["Shaft-Sleeve_U_mm"];
    std::cout << '\n';
  }

  std::cout << "\n5. Design/Mode = select with Fit/Case = all\n";
  {
    // The selection in the case of the means; the other cases run its
    // fits. The same fits as a select run at Case = mean; each case's
    // interferences as ISO 286 gives them for those fits, its pressures
    // the compound cylinders'; the selection's FE check at the corners
    // promised every case its slip safety of 1.5.
    std::filesystem::remove_all("chosen");
    std::filesystem::remove_all("chosen_mean");
    r = run_coaxfit("chosen", quiet + "--set Design/Mode=select rings.prm");
    const RunResult plain = run_coaxfit(
      "chosen_mean",
      quiet + "--set Design/Mode=select --set Fit/Case=mean rings.prm");
    const nlohmann::json         mean = read_summary("chosen_mean");
    std::vector<coaxfit::IsoFit> fits;
    for (unsigned int k = 0; k < 2; ++k)
      fits.push_back(coaxfit::iso_fit(
        mean["selection"]["joints"][k]["fit"].get<std::string>(),
        rings[k].outer_diameter));
    std::cout << "exit " << r.exit_code << " (the select run at Case = mean "
              << plain.exit_code << "); chosen/: " << entries("chosen")
              << "\n  the select run's fits: " << fits[0].name << ", "
              << fits[1].name << '\n';
    table             = read_table("chosen");
    double least_slip = 1e9;
    for (const std::string c : {"min", "mean", "max", "min-max", "max-min"})
      {
        const nlohmann::json s = read_summary("chosen/" + c);
        std::vector<double>  U(2);
        for (unsigned int k = 0; k < 2; ++k)
          {
            const std::string joint_case
              = c == "mean" ? "mean" :
                              c.substr(k == 0 ? 0 : c.find('-') + 1, 3);
            U[k] = 1e-3
                   * (joint_case == "min" ? fits[k].min_interference() :
                      joint_case == "max" ? fits[k].max_interference() :
                                            0.5
                                              * (fits[k].min_interference()
                                                 + fits[k].max_interference()));
          }
        const coaxfit::CompoundCylinders exact(rings, U, 0., 0.);
        std::cout << c << ": exit " << table[c]["exit_code"] << ", verdict "
                  << table[c]["verdict"];
        for (unsigned int k = 0; k < 2; ++k)
          {
            const nlohmann::json &j = s["joints"][k];
            std::cout << "; " << joints[k] << " "
                      << j["fit"].get<std::string>().substr(0, 14) << " U "
                      << agreement(std::stod(table[c][joints[k] + "_U_mm"]),
                                   U[k],
                                   1e-12)
                      << ", p " << std::setprecision(6) << exact.pressure(k)
                      << " MPa "
                      << agreement(j["pressure"]["mean"],
                                   exact.pressure(k),
                                   1e-5);
            least_slip
              = std::min(least_slip,
                         std::stod(table[c][joints[k] + "_safety_slip"]));
          }
        std::cout << '\n';
      }
    std::cout << "  least slip safety over the cases " << std::setprecision(5)
              << least_slip
              << " (>= 1.5: " << (least_slip >= 1.5 ? "yes" : "NO") << ")\n"
              << verdict_of("chosen") << '\n';
    const auto text = [](const std::string &file) {
      std::ifstream      in(file);
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    };
    std::cout << "  fit_selection.csv = mean/fit_selection.csv = the select "
                 "run's: "
              << (text("chosen/fit_selection.csv")
                        == text("chosen/mean/fit_selection.csv")
                      && text("chosen/fit_selection.csv")
                           == text("chosen_mean/fit_selection.csv") ?
                    "yes" :
                    "NO")
              << '\n';
    // A case's parameters.prm selects again and runs that case.
    repeat("chosen", "chosen_again");
    // No fit carries the torque: the selection's answer, no case run.
    std::filesystem::remove_all("none");
    r = run_coaxfit("none",
                    "--set Design/Mode=select --set 'Design/Required "
                    "torque=1e6' rings.prm");
    std::cout << "Required torque 1e6 N m: exit " << r.exit_code
              << "; none/: " << entries("none") << "\n  "
              << read_summary("none")["verdict"]["failed"][0]
                   .get<std::string>()
                   .substr(0, 60)
              << "\n  named " << read_summary("none")["case"];
    // Its parameters.prm is the study's: run again, the same answer.
    r = run_coaxfit("none", quiet + "none/parameters.prm");
    std::cout << "; its parameters.prm run again: exit " << r.exit_code << ", "
              << entries("none") << '\n';
    // A selected joint with its own Case keeps the chosen fit at that case
    // in every case, the other joint varies.
    std::filesystem::remove_all("own_case");
    r     = run_coaxfit("own_case",
                    quiet
                      + "--set Design/Mode=select --set "
                            "Fit/Shaft-Sleeve/Case=max rings.prm");
    table = read_table("own_case");
    std::cout << "Shaft-Sleeve selected with its own Case max: exit "
              << r.exit_code << "; U of " << fits[0].name << " at max "
              << 1e-3 * fits[0].max_interference() << " mm:";
    for (const std::string c : {"min", "mean", "max"})
      std::cout << ' ' << c << ' ' << table[c]["Shaft-Sleeve_U_mm"];
    std::cout << "; Sleeve-Hub:";
    for (const std::string c : {"min", "mean", "max"})
      std::cout << ' ' << c << ' ' << table[c]["Sleeve-Hub_U_mm"];
    std::cout << '\n';
  }

  std::cout << "\n4. Bad input\n";
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"a joint's Case without an ISO fit",
        "--set 'Fit/Shaft-Sleeve/ISO fit=' --set 'Fit/Shaft-Sleeve/Diametral "
        "interference=0.04' --set Fit/Shaft-Sleeve/Case=min rings.prm"},
       {"a joint's Case misspelt",
        "--set Fit/Shaft-Sleeve/Case=lowest rings.prm"},
       {"every ISO joint with its own Case",
        "--set Fit/Shaft-Sleeve/Case=min --set Fit/Sleeve-Hub/Case=max "
        "rings.prm"},
       {"in a --sweep", "--sweep 'Design/Slip safety=1.5,2' rings.prm"}};
  for (const auto &[what, arguments] : bad)
    {
      std::filesystem::remove_all("bad");
      std::filesystem::remove_all("bad_sweep");
      r = run_coaxfit("bad", quiet + arguments);
      std::cout << what << ": exit " << r.exit_code << ", " << r.lines
                << " line(s), nothing written "
                << (std::filesystem::exists("bad")
                        || std::filesystem::exists("bad_sweep") ?
                      "NO" :
                      "yes")
                << "\n  " << gist(r.message, 40) << '\n';
    }
  // One file of a batch: its row says why.
  {
    std::ofstream("plain.prm")
      << rings_prm("subsection Fit\n  set Case = mean\nend\n"
                   "subsection Output\n  set Directory = batch_plain\nend\n");
    std::ofstream("study.prm")
      << rings_prm("subsection Output\n  set Directory = batch_study\nend\n");
    std::filesystem::remove_all("batch_plain");
    std::filesystem::remove_all("batch_study");
    r = run_command("timeout 60 " + std::string(coaxfit_executable) + quiet
                    + "--table batch.csv plain.prm study.prm 2>&1");
    std::cout << "a batch of a plain file and a study: exit " << r.exit_code
              << ", study written "
              << (std::filesystem::exists("batch_study") ? "YES" : "no")
              << '\n';
    // Its row: the case, exit code and status, and the error (the last
    // field, quoted), not the wall time.
    std::ifstream in("batch.csv");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("study.prm", 0) == 0)
        {
          const std::vector<std::string> fields = csv_fields(line);
          std::cout << "  " << fields[0] << ": exit " << fields[1] << ", "
                    << fields[2] << ": "
                    << gist(line.substr(line.find('"')), 25) << '\n';
        }
  }
  return 0;
}
