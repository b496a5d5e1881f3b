// The example prm/examples/three_rings.prm run as a user runs it: each
// joint's pressure at the mid-plane and mean against the compound-cylinder
// closed form (equal lengths, frictionless: exact in the FE limit; 1e-6 at
// the example's mesh) and alone against the two-ring closed form; the
// staggered process in Jacobi ordering and the monolithic solver against
// the Gauss-Seidel run (1e-8); the target (no more than twice the
// steps of the two-body sub-problems); the files of the run; the run
// repeated from its parameters.prm; a sleeve with clearance in the hub
// (contact lost, exit 0); bad input (exit 1, one line naming the entry).

#include <coaxfit/design/compound_cylinders.h>

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

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
                                 "contact_pressure_Sleeve-Hub.csv"})
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
    std::ifstream in(example);
    std::string   text((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
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

  std::cout << "bad input:\n";
  for (const std::string arguments :
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
        std::string(
          "--sweep 'Fit/Sleeve-Hub/Diametral interference=0.05:0.07:3'")})
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
