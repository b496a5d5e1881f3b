// The example prm/examples/three_rings.prm run as a user runs it: each
// joint's pressure at the mid-plane and mean against the compound-cylinder
// closed form (equal lengths, frictionless: exact in the FE limit; 1e-6 at
// the example's mesh) and alone against the two-ring closed form; the
// staggered process in Jacobi ordering and the monolithic solver against
// the Gauss-Seidel run (1e-8); the target (no more than twice the
// steps of the two-body sub-problems); the files of the run; the run
// repeated from its parameters.prm; a sleeve with clearance in the hub
// (contact lost, exit 0); the verdict's criteria (yield, slip, fracture of a
// brittle body) against hand figures from the closed form; bad input (exit
// 1, one line naming the entry).

#include <coaxfit/design/compound_cylinders.h>

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

using namespace coaxfit_test;

namespace
{
  const std::string example
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/three_rings.prm";

  /** The example's rings, for the closed form. */
  const std::vector<coaxfit::CompoundCylinders::Ring> rings
    = {{0., 60., 210000., 0.3},
       {60., 90., 110000., 0.34},
       {90., 160., 70000., 0.33}};

  /** Run the example in @p dir with @p arguments; its summary. */
  nlohmann::json
  run_example(const std::string &dir, const std::string &arguments)
  {
    std::filesystem::remove_all(dir);
    const RunResult r = run_coaxfit(dir,
                                    "--set 'Output/Print timing=false' "
                                      + arguments + " " + example);
    std::cout << "  exit code " << r.exit_code
              << (r.message.empty() ? "" : ", message: " + r.message);
    if (r.exit_code != 0)
      return nlohmann::json();
    std::cout << '\n';
    return read_summary(dir);
  }

  /** The example's parameter file as text. */
  std::string
  example_text()
  {
    std::ifstream in(example);
    return std::string((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
  }

  /** Every @p from in @p text replaced by @p to. */
  void
  replace_all(std::string &text, const std::string &from, const std::string &to)
  {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at             = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }

  /** The largest relative difference of the joints' pressures. */
  double
  difference(const nlohmann::json &a, const nlohmann::json &b)
  {
    double d = 0.;
    for (unsigned int k = 0; k < a["joints"].size(); ++k)
      for (const char *key : {"at_mid_plane", "mean", "min", "max"})
        {
          const double x = a["joints"][k]["pressure"][key];
          const double y = b["joints"][k]["pressure"][key];
          d = std::max(d, std::abs(x - y) / std::max(std::abs(y), 1e-300));
        }
    return d;
  }
} // namespace

int
main()
{
  std::cout << "three_rings.prm, staggered (gauss-seidel):\n";
  const nlohmann::json             gs = run_example("gs", "");
  const coaxfit::CompoundCylinders exact(rings, {0.04, 0.06});
  unsigned int                     alone_steps = 0;
  for (unsigned int k = 0; k < 2; ++k)
    {
      const nlohmann::json &j = gs["joints"][k];
      const double          alone_exact
        = coaxfit::CompoundCylinders({rings[k], rings[k + 1]},
                                     {k == 0 ? 0.04 : 0.06})
            .pressure(0);
      std::cout << "  " << j["name"].get<std::string>() << " (D "
                << j["diameter"].get<double>() << "): exact "
                << exact.pressure(k) << " MPa; p(0) "
                << agreement(j["pressure"]["at_mid_plane"],
                             exact.pressure(k),
                             1e-6)
                << ", mean "
                << agreement(j["pressure"]["mean"], exact.pressure(k), 1e-6)
                << "; alone: exact " << alone_exact << " MPa, mean "
                << agreement(j["alone"]["pressure"]["mean"], alone_exact, 1e-6)
                << ", closed " << j["contact"]["closed"] << '\n';
      alone_steps = std::max(alone_steps,
                             j["alone"]["staggered_steps"].get<unsigned int>());
    }
  const unsigned int steps = gs["coupling"]["steps"];
  std::cout << "  steps " << steps << ", the joints alone at most "
            << alone_steps << ": "
            << (steps <= 2 * alone_steps ? "within" : "MORE THAN")
            << " twice\n";
  const std::string dir = "gs";
  for (const std::string file : {"summary.json",
                                 "parameters.prm",
                                 "convergence.csv",
                                 "solution.pvd",
                                 "shaft.vtu",
                                 "sleeve.vtu",
                                 "hub.vtu",
                                 "contact_pressure_Shaft-Sleeve.csv",
                                 "contact_pressure_Sleeve-Hub.csv",
                                 "interface_Shaft-Sleeve.vtp",
                                 "interface_Sleeve-Hub.vtp",
                                 "report.md",
                                 "plots.gp",
                                 "contact_pressure.png",
                                 "convergence.png"})
    std::cout << "  " << file << ": "
              << (std::filesystem::exists(dir + "/" + file) ? "written" :
                                                              "MISSING")
              << '\n';

  std::cout << "the run repeated from its parameters.prm:\n";
  {
    std::filesystem::remove_all("again");
    const RunResult r = run_coaxfit("again", "gs/parameters.prm");
    nlohmann::json  a = read_summary("again"), b = gs;
    a.erase("timing");
    b.erase("timing");
    a.erase("case");
    b.erase("case");
    std::cout << "  exit code " << r.exit_code << ", summary.json "
              << (a == b ? "identical" : "DIFFERS") << '\n';
  }

  std::cout << "jacobi ordering:\n";
  const nlohmann::json jacobi
    = run_example("jacobi", "--set Coupling/Ordering=jacobi");
  std::cout << "  = gauss-seidel "
            << (difference(jacobi, gs) < 1e-8 ? "to 1e-8" : "NOT to 1e-8")
            << '\n';
  std::cout << "monolithic:\n";
  const nlohmann::json mono
    = run_example("mono", "--set Solver/Method=monolithic");
  std::cout << "  = gauss-seidel "
            << (difference(mono, gs) < 1e-8 ? "to 1e-8" : "NOT to 1e-8")
            << '\n';

  std::cout << "the sleeve 0.04 mm loose in the hub:\n";
  const nlohmann::json loose
    = run_example("loose",
                  "--set 'Fit/Sleeve-Hub/Diametral interference=-0.04'");
  {
    const nlohmann::json &in = loose["joints"][0], &out = loose["joints"][1];
    const double          alone_exact
      = coaxfit::CompoundCylinders({rings[0], rings[1]}, {0.04}).pressure(0);
    std::cout << "  Sleeve-Hub closed " << out["contact"]["closed"]
              << ", separated points " << out["contact"]["separated_points"]
              << ", max pressure " << out["pressure"]["max"]
              << "; Shaft-Sleeve mean "
              << agreement(in["pressure"]["mean"], alone_exact, 1e-6)
              << " (the two-ring answer " << alone_exact << ")\n";
  }

  std::cout << "the same sleeve loose, bonded radially "
               "(Contact/Unilateral = false):\n";
  {
    const nlohmann::json bonded
      = run_example("bonded",
                    "--set 'Fit/Sleeve-Hub/Diametral interference=-0.04' "
                    "--set Contact/Unilateral=false");
    const coaxfit::CompoundCylinders two_sided(
      rings, {0.04, -0.04}, 0., 0., false);
    for (unsigned int k = 0; k < 2; ++k)
      {
        const nlohmann::json &j = bonded["joints"][k];
        std::cout << "  " << j["name"].get<std::string>()
                  << ": the two-sided closed form " << two_sided.pressure(k)
                  << " MPa; FE mean "
                  << agreement(j["pressure"]["mean"],
                               two_sided.pressure(k),
                               1e-6)
                  << ", the run's plane-stress column "
                  << agreement(j["plane_stress_estimate"]["pressure"],
                               two_sided.pressure(k),
                               1e-12)
                  << '\n';
      }
  }

  std::cout << "ISO fits (Fit/ISO fit = H7/s6 for every joint, the "
               "Shaft-Sleeve joint its own H7/u6):\n";
  {
    std::string text = example_text();
    // The example's fits replaced by ISO fits.
    const std::size_t a = text.find("subsection Fit");
    const std::size_t b = text.find("subsection Mesh");
    text.replace(a,
                 b - a,
                 "subsection Fit\n  set ISO fit = H7/s6\n  subsection "
                 "Shaft-Sleeve\n    set ISO fit = H7/u6\n  end\nend\n\n");
    std::ofstream("iso.prm") << text;
    for (const std::string fit_case : {"min", "mean", "max"})
      {
        std::filesystem::remove_all("iso");
        const RunResult r
          = run_coaxfit("iso", "--set Fit/Case=" + fit_case + " iso.prm");
        const nlohmann::json s = read_summary("iso");
        std::cout << "  Case " << fit_case << ": exit " << r.exit_code;
        for (const auto &j : s["joints"])
          std::cout << "; " << j["name"].get<std::string>() << " U "
                    << j["diametral_interference"].get<double>() << " mm ("
                    << j["fit"].get<std::string>() << ")";
        std::cout << '\n';
      }
  }

  std::cout << "roughness (Fit/Shaft-Sleeve/Inner 4 um, Outer 6 um; "
               "Fit/Outer roughness Rz 3 um for the other joint):\n";
  {
    const nlohmann::json rough
      = run_example("rough",
                    "--set 'Fit/Shaft-Sleeve/Inner roughness Rz=4' --set "
                    "'Fit/Shaft-Sleeve/Outer roughness Rz=6' --set "
                    "'Fit/Outer roughness Rz=3'");
    // DIN 7190-1: U_w = U - 0.8 (Rz_i + Rz_o).
    const double                     U0 = 0.04 - 0.8e-3 * (4. + 6.);
    const double                     U1 = 0.06 - 0.8e-3 * (0. + 3.);
    const coaxfit::CompoundCylinders smoothed(rings, {U0, U1});
    for (unsigned int k = 0; k < 2; ++k)
      {
        const nlohmann::json &j = rough["joints"][k];
        std::cout
          << "  " << j["name"].get<std::string>() << ": U "
          << j["diametral_interference"].get<double>() << " mm, smoothing loss "
          << j["smoothing_loss"].get<double>() << " mm, U_w "
          << agreement(j["effective_interference"], k == 0 ? U0 : U1, 1e-12)
          << " with U - 0.8 (Rz_i + Rz_o); closed form with U_w "
          << smoothed.pressure(k) << " MPa: mean "
          << agreement(j["pressure"]["mean"], smoothed.pressure(k), 1e-6)
          << '\n';
      }
  }

  std::cout << "the verdict (each criterion against its hand figure):\n";
  {
    const auto verdict = [](const nlohmann::json &j) {
      std::cout << "  verdict ok " << j["verdict"]["ok"];
      for (const auto &f : j["verdict"]["failed"])
        std::cout << "; " << f.get<std::string>();
      std::cout << '\n';
    };
    std::cout << "  the example (no strength, no torque: nothing judged):\n";
    verdict(gs);
    // The sleeve's von Mises stress at its bore, from the closed form's
    // radial and hoop stresses there.
    const double p0 = exact.pressure(0), p1 = exact.pressure(1);
    const double a2 = 30. * 30., b2 = 45. * 45.;
    const double hoop_sleeve = (p0 * (a2 + b2) - 2. * p1 * b2) / (b2 - a2);
    const double vm_sleeve
      = std::sqrt(p0 * p0 + hoop_sleeve * hoop_sleeve + p0 * hoop_sleeve);
    std::cout << "  Material/Sleeve/Yield strength = 100 MPa, Design/Yield "
                 "safety = 1.5; by hand 100 / "
              << vm_sleeve << " = " << 100. / vm_sleeve << ":\n";
    const nlohmann::json yield
      = run_example("yield",
                    "--set 'Material/Sleeve/Yield strength=100' --set "
                    "'Design/Yield safety=1.5'");
    // The FE's surface stress carries its discretization error (2.4e-4).
    std::cout << "  the run's yield safety of the Sleeve "
              << agreement(yield["bodies"][1]["yield_safety"],
                           100. / vm_sleeve,
                           1e-3)
              << " (1e-3)\n";
    verdict(yield);
    // Torque capacity nu p pi D^2 l / 2 of each joint, l = 60 mm.
    const double T0 = 0.1 * p0 * M_PI * 60. * 60. * 60. / 2. / 1000.;
    const double T1 = 0.1 * p1 * M_PI * 90. * 90. * 60. / 2. / 1000.;
    std::cout << "  Fit/Friction coefficient = 0.1, Design/Required torque "
                 "= 1500 N m, Design/Slip safety = 1.2; by hand "
              << T0 / 1500. << " and " << T1 / 1500. << ":\n";
    const nlohmann::json slip
      = run_example("slip",
                    "--set 'Fit/Friction coefficient=0.1' --set "
                    "'Design/Required torque=1500' --set 'Design/Slip "
                    "safety=1.2'");
    std::cout
      << "  the run's safeties against slip "
      << agreement(slip["joints"][0]["design"]["slip_safety"], T0 / 1500., 1e-6)
      << " and "
      << agreement(slip["joints"][1]["design"]["slip_safety"], T1 / 1500., 1e-6)
      << " (1e-6)\n";
    verdict(slip);
    // With an axial force and K_A: DIN 7190's resultant, the friction
    // force nu p pi D l over K_A sqrt((2 M / D)^2 + F^2).
    const auto resultant = [](const double D) {
      return 1.25 * std::hypot(2e3 * 1500. / D, 30000.);
    };
    const double S0 = 2e3 * T0 / 60. / resultant(60.),
                 S1 = 2e3 * T1 / 90. / resultant(90.);
    std::cout << "  and Design/Required axial force = 30000 N, Application "
                 "factor = 1.25; by hand "
              << S0 << " and " << S1 << ":\n";
    const nlohmann::json axial
      = run_example("axial",
                    "--set 'Fit/Friction coefficient=0.1' --set "
                    "'Design/Required torque=1500' --set 'Design/Slip "
                    "safety=1.2' --set 'Design/Required axial force=30000' "
                    "--set 'Design/Application factor=1.25'");
    std::cout
      << "  the run's safeties against slip "
      << agreement(axial["joints"][0]["design"]["slip_safety"], S0, 1e-6)
      << " and "
      << agreement(axial["joints"][1]["design"]["slip_safety"], S1, 1e-6)
      << " (1e-6), axial force capacity of Shaft-Sleeve "
      << agreement(axial["joints"][0]["design"]["axial_force_capacity"],
                   2e3 * T0 / 60.,
                   1e-6)
      << " (1e-6)\n";
    verdict(axial);
    // Friction coefficient = auto: DIN 7190-1's value of each joint's
    // pairing and Design/Joining; the torque capacity nu p_mean pi D^2 l
    // / 2 with it.
    for (const std::string &options :
         {std::string("--set 'Material/Sleeve/Name=CuSn8' --set "
                      "'Fit/Sleeve-Hub/Friction coefficient=0.1'"),
          std::string("--set 'Design/Joining=shrink degreased' --set "
                      "'Material/Sleeve/Name=C45' --set "
                      "'Material/Hub/Name=S355'")})
      {
        std::cout << "  Fit/Friction coefficient = auto, " << options << ":\n";
        const nlohmann::json a
          = run_example("auto",
                        "--set 'Fit/Friction coefficient=auto' " + options);
        for (const auto &j : a["joints"])
          {
            const double D = j["diameter"], p = j["pressure"]["mean"],
                         mu = j["design"]["friction_coefficient"];
            std::cout << "    " << j["name"].get<std::string>() << ": " << mu
                      << " ("
                      << j["design"]["friction_source"].get<std::string>()
                      << "), torque capacity "
                      << agreement(j["design"]["torque_capacity"],
                                   mu * p * M_PI * D * D * 60. / 2. / 1000.,
                                   1e-9)
                      << '\n';
          }
      }
    // A running fit (bushing_in_housing.prm: the shaft with clearance in
    // the bushing) passes no load: its slip is not judged, the bushing's
    // seat in the housing is.
    {
      std::cout << "  bushing_in_housing.prm, Required torque 300 N m, axial "
                   "force 5000 N, Friction coefficient 0.12:\n";
      std::filesystem::remove_all("bushing");
      const RunResult r = run_coaxfit(
        "bushing",
        "--set 'Design/Required torque=300' --set 'Design/Required axial "
        "force=5000' --set 'Fit/Friction coefficient=0.12' "
          + std::string(COAXFIT_SOURCE_DIR)
          + "/prm/examples/bushing_in_housing.prm");
      const nlohmann::json b = read_summary("bushing");
      std::cout << "    exit code " << r.exit_code;
      for (const auto &j : b["joints"])
        {
          std::cout << "; " << j["name"].get<std::string>() << ": ";
          if (!j["design"].contains("slip_safety"))
            std::cout << "slip not judged";
          else
            std::cout
              << "safety against slip "
              << agreement(j["design"]["slip_safety"],
                           j["design"]["axial_force_capacity"].get<double>()
                             / std::hypot(2e3 * 300.
                                            / j["diameter"].get<double>(),
                                          5000.),
                           1e-9);
        }
      std::cout << '\n';
      verdict(b);
    }
    // The hub's hoop stress at its bore, p1 (b^2 + a^2) / (b^2 - a^2).
    const double hoop_hub
      = p1 * (80. * 80. + 45. * 45.) / (80. * 80. - 45. * 45.);
    std::cout << "  Material/Hub/Kind = brittle, Tensile strength = 100 MPa "
                 "(Design/Fracture safety 2); by hand 100 / "
              << hoop_hub << " = " << 100. / hoop_hub << ":\n";
    const nlohmann::json brittle
      = run_example("brittle",
                    "--set 'Material/Hub/Kind=brittle' --set "
                    "'Material/Hub/Tensile strength=100'");
    std::cout << "  the run's safety against fracture of the Hub "
              << agreement(brittle["bodies"][2]["fracture_safety"],
                           100. / hoop_hub,
                           1e-3)
              << " (1e-3)\n";
    verdict(brittle);
    std::cout << "  the sleeve 0.04 mm loose in the hub (a clearance may "
                 "stand open):\n";
    verdict(loose);
    std::cout << "  Rz 50 um on both surfaces of the 0.04 mm joint (U_w "
                 "-0.04 mm: a press fit the roughness turns loose):\n";
    verdict(run_example("eaten",
                        "--set 'Fit/Shaft-Sleeve/Inner roughness Rz=50' "
                        "--set 'Fit/Shaft-Sleeve/Outer roughness Rz=50'"));
    std::cout << "  Fit/Friction coefficient 0.1, Required torque 1742.5 N "
                 "m (a safety just below 1 is printed with the digits that "
                 "tell it from 1):\n";
    verdict(run_example("limit",
                        "--set 'Fit/Friction coefficient=0.1' --set "
                        "'Design/Required torque=1742.5'"));
  }

  std::cout << "Output/Write plots = false, Write report = false, Write "
               "vtu = false:\n";
  {
    std::filesystem::remove_all("lean");
    const RunResult r = run_coaxfit(
      "lean",
      "--set 'Output/Write plots=false' --set 'Output/Write report=false' "
      "--set 'Output/Write vtu=false' "
        + example);
    std::cout << "  exit code " << r.exit_code << ", files:";
    std::set<std::string> files;
    for (const auto &entry : std::filesystem::directory_iterator("lean"))
      files.insert(entry.path().filename().string());
    for (const std::string &file : files)
      std::cout << ' ' << file;
    std::cout << '\n';
  }

  std::cout << "Coupling/Max steps = 2 (not converged: exit 2, the last "
               "state written):\n";
  {
    std::filesystem::remove_all("unconverged");
    const RunResult r
      = run_coaxfit("unconverged", "--set 'Coupling/Max steps=2' " + example);
    const nlohmann::json j = read_summary("unconverged");
    std::cout << "  exit code " << r.exit_code << ", converged "
              << j["converged"] << ", verdict failed " << j["verdict"]["failed"]
              << '\n';
  }

  std::cout << "the hub renamed Housing, run into the directory of the "
               "Shaft, Sleeve, Hub run, then a run of two bodies into it:\n";
  {
    std::string text = example_text();
    replace_all(text, "Hub", "Housing");
    std::ofstream("housing.prm") << text;
    const RunResult a = run_coaxfit("gs", "housing.prm");
    std::cout << "  exit code " << a.exit_code << ", hub.vtu replaced by "
              << "housing.vtu "
              << (!std::filesystem::exists("gs/hub.vtu")
                      && std::filesystem::exists("gs/housing.vtu") ?
                    "yes" :
                    "NO")
              << '\n';
    const RunResult b
      = run_coaxfit("gs",
                    "--set 'Output/Print timing=false' "
                      + std::string(COAXFIT_SOURCE_DIR) + "/prm/default.prm");
    std::cout << "  two bodies: exit code " << b.exit_code
              << ", housing.vtu and interface_Shaft-Sleeve.vtp gone "
              << (!std::filesystem::exists("gs/housing.vtu")
                      && !std::filesystem::exists(
                        "gs/interface_Shaft-Sleeve.vtp") ?
                    "yes" :
                    "NO")
              << '\n';
  }

  std::cout << "bodies A, B_C, A_B, C (two joints would share the block "
               "name contact_a_b_c):\n";
  {
    std::string text = example_text();
    // Shaft, Sleeve, Hub become A, B_C, A_B, and a ring C is added.
    replace_all(text, "Shaft, Sleeve, Hub", "A, B_C, A_B, C");
    replace_all(text,
                "Report surfaces = Hub outer",
                "Report surfaces = C outer");
    replace_all(text, "Shaft-Sleeve", "A-B_C");
    replace_all(text, "Sleeve-Hub", "B_C-A_B");
    replace_all(text, "subsection Shaft\n", "subsection A\n");
    replace_all(text, "subsection Sleeve\n", "subsection B_C\n");
    replace_all(text, "subsection Hub\n", "subsection A_B\n");
    replace_all(text,
                "subsection Geometry\n",
                "subsection Geometry\n  subsection C\n    set Inner "
                "diameter = 160\n    set Outer diameter = 200\n    set "
                "Length = 60\n  end\n");
    replace_all(text,
                "subsection Material\n",
                "subsection Material\n  subsection C\n    set E = 70000\n "
                "   set nu = 0.33\n  end\n");
    replace_all(text,
                "subsection Fit\n",
                "subsection Fit\n  subsection A_B-C\n    set Diametral "
                "interference = 0.1\n  end\n");
    std::ofstream("names.prm") << text;
    std::filesystem::remove_all("names");
    const RunResult r = run_coaxfit("names", "names.prm");
    std::cout << "  exit code " << r.exit_code << "; solution.pvd blocks:";
    std::ifstream pvd("names/solution.pvd");
    std::string   line;
    while (std::getline(pvd, line))
      {
        const std::size_t at = line.find("name=\"");
        if (at != std::string::npos)
          std::cout << ' '
                    << line.substr(at + 6, line.find('"', at + 6) - at - 6);
      }
    std::cout << '\n';
  }

  std::cout << "bad input:\n";
  for (const std::string &arguments :
       {std::string("--set 'Assembly/Bodies=Shaft, Sleeve, Shaft'"),
        std::string("--set 'Assembly/Bodies=Shaft, Sle-eve, Hub'"),
        std::string("--set 'Assembly/Bodies=Shaft'"),
        std::string("--set 'Assembly/Bodies='"),
        std::string("--set 'Assembly/Bodies=Shaft, "
                    "Sleeve_of_a_very_long_name_that_goes_on_and_on, Hub'"),
        std::string("--set 'Assembly/Bodies=Shaft, Bushing, Hub'"),
        std::string("--set 'Geometry/Sleeve/Inner diameter=59.9'"),
        std::string("--set 'Geometry/Sleeve/Inner diameter=60.5'"),
        std::string("--set 'Geometry/Sleeve/Length=0'"),
        std::string("--set 'Geometry/Sleeve/Inner diameter=0'"),
        std::string("--set 'Fit/Shaft-Hub/Diametral interference=0.03'"),
        std::string("--set 'Fit/Sleeve-Hub/Diametral interference=1'"),
        std::string("--set 'Assembly/Report surfaces=Sleeve inside'"),
        std::string("--set 'Assembly/Report surfaces=Shaft bore'"),
        std::string("--set 'Design/Required torque=500'"),
        std::string("--set 'Fit/Shaft-Sleeve/ISO fit=H7/s6'"),
        std::string("--set 'Fit/Sleeve-Hub/ISO fit=H7/z9'"),
        std::string("--set 'Design/Slip safety=0.5'"),
        std::string("--set 'Design/Required axial force=2000'"),
        std::string("--set 'Design/Application factor=0.8'"),
        std::string("--set 'Fit/Friction coefficient=auto' --set "
                    "'Material/Sleeve/Name=CuSn8' --set 'Material/Hub/Name=EN "
                    "AW-6082 T6'"),
        std::string("--set 'Fit/Sleeve-Hub/Friction coefficient=0.5x'"),
        std::string("--set 'Fit/Friction coefficient=auto'"),
        std::string("--set 'Design/Joining=glued'"),
        std::string("--set 'Fit/Sleeve-Hub/Outer roughness Rz=-1'"),
        std::string("--set 'Fit/Shaft-Sleeve/Diametral interference=-0.5' "
                    "--set 'Fit/Inner roughness Rz=400'"),
        std::string("--set 'Design/Fracture safety=nan'"),
        std::string("--sweep 'Assembly/Bodies=Shaft, Hub'")})
    {
      std::filesystem::remove_all("bad");
      const RunResult r       = run_coaxfit("bad", arguments + " " + example);
      std::string     message = r.message;
      // The example's path differs between machines.
      const std::size_t at = message.find(example);
      if (at != std::string::npos)
        message.replace(at, example.size(), "three_rings.prm");
      std::cout << "  " << arguments << ": exit " << r.exit_code << ", "
                << r.lines << " line, no directory "
                << !std::filesystem::exists("bad") << "\n    " << message;
    }
}
