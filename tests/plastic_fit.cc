// prm/examples/yielding_hub.prm run as a user runs it (a hub yielding at
// 300 MPa, perfectly plastic, on an elastic shaft, U twice the elastic
// limit): against an independent CalculiX solution (CAX8, shaft and hub
// meshed apart, the joint tied radially with the interference through a
// dummy node, *PLASTIC 300, 20 increments; 106 x 86 cells per body at
// 0.05 mm at the joint's end, converged to 0.2 MPa over four meshes: mean
// pressure 203.92 MPa, p(z = 0, 5, 10, 15, 18 mm) = 206.81, 206.64, 206.03,
// 203.74, 197.80 MPa, the plastic zone at the mid-plane to D 71.3-71.7 mm),
// the mean and the interior pressures within 0.5 %, the plastic zone
// within 2 % (the example's mesh has 10 graded cells across the hub's
// wall); the staggered process against the monolithic Newton solver (every
// point's pressure within 1e-6 on the same load path), the files of the
// run; the same scene below the yield strength (U 0.05 mm) against
// Plasticity = none (the elastic code's results unchanged, 1e-10); a Newton
// solve that cannot converge (exit 2 naming the body and the increment, the
// last converged state written, marked not converged); bad input (exit 1,
// one line naming the entry).

#include "run_executable.h"
#include "run_summary.h"
#include "yielding_hub_example.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace coaxfit_test;

namespace
{
  /** The pressure column of contact_pressure.csv in @p dir (and z). */
  std::vector<double>
  pressures(const std::string &dir, std::vector<double> *z_out = nullptr)
  {
    std::ifstream       in(dir + "/contact_pressure.csv");
    std::string         line;
    std::vector<double> p;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        std::string        z, value;
        std::getline(row, z, ',');
        std::getline(row, value, ',');
        p.push_back(std::stod(value));
        if (z_out)
          z_out->push_back(std::stod(z));
      }
    return p;
  }

  /** @p p at @p z, linearly interpolated between the points @p zs. */
  double
  at(const std::vector<double> &zs, const std::vector<double> &p, double z)
  {
    for (unsigned int i = 0; i + 1 < zs.size(); ++i)
      if (zs[i] <= z && z <= zs[i + 1])
        return p[i] + (p[i + 1] - p[i]) * (z - zs[i]) / (zs[i + 1] - zs[i]);
    return std::nan("");
  }
} // namespace

int
main()
{
  std::cout << "yielding_hub.prm, staggered:\n";
  run_example("staggered", "");
  const nlohmann::json s = read_summary("staggered");
  std::cout << "  converged " << s["converged"] << ", hub yields "
            << s["plasticity"]["bodies"][1]["yields"] << ", shaft yields "
            << s["plasticity"]["bodies"][0]["yields"] << ", fully plastic "
            << s["plasticity"]["bodies"][1]["fully_plastic"] << '\n';
  std::cout << "  files:";
  for (const char *f : {"summary.json",
                        "parameters.prm",
                        "contact_pressure.csv",
                        "load_path.csv",
                        "shaft.vtu",
                        "hub.vtu",
                        "solution.pvd"})
    std::cout << ' ' << f
              << (std::filesystem::exists("staggered/" + std::string(f)) ?
                    "" :
                    " (MISSING)");
  std::cout << '\n';

  std::cout << "against CalculiX:\n";
  {
    std::vector<double>       zs;
    const std::vector<double> p = pressures("staggered", &zs);
    std::cout << "  mean pressure: "
              << agreement(s["pressure"]["mean"], 203.92, 0.005) << '\n';
    const double z_ccx[5] = {0., 5., 10., 15., 18.};
    const double p_ccx[5] = {206.81, 206.64, 206.03, 203.74, 197.80};
    for (unsigned int k = 0; k < 5; ++k)
      std::cout << "  p(z = " << z_ccx[k]
                << " mm): " << agreement(at(zs, p, z_ccx[k]), p_ccx[k], 0.005)
                << '\n';
    std::cout << "  plastic zone at the mid-plane: "
              << agreement(s["plasticity"]["bodies"][1]["plastic_zone"]
                            ["diameter_at_mid_plane"],
                           71.5,
                           0.02)
              << '\n';
  }

  std::cout << "monolithic:\n";
  run_example("monolithic", "--set Solver/Method=monolithic");
  const std::vector<double> a = pressures("staggered"),
                            b = pressures("monolithic");
  double largest = 0., difference = a.size() == b.size() ? 0. : 1.;
  for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
    {
      largest    = std::max(largest, std::abs(b[i]));
      difference = std::max(difference, std::abs(a[i] - b[i]));
    }
  std::cout << "  " << a.size() << " points, every pressure "
            << (difference <= 1e-6 * largest ? "agrees with the staggered "
                                               "one within 1e-6" :
                                               "DIFFERS")
            << '\n';

  std::cout << "below the yield strength (U 0.05 mm), von Mises against "
               "none:\n";
  run_example("elastic", "--set 'Fit/Diametral interference=0.05'");
  run_example("none",
              "--set 'Fit/Diametral interference=0.05' "
              "--set 'Material/Hub/Plasticity=none'");
  const nlohmann::json e = read_summary("elastic"), n = read_summary("none");
  for (const char *key : {"at_mid_plane", "mean", "min", "max"})
    std::cout << "  " << key << ": "
              << agreement(e["pressure"][key], n["pressure"][key], 1e-10)
              << '\n';
  std::cout << "  the elastic run has no load path: "
            << (e.contains("load_path") ? "NO" : "yes") << '\n';

  std::cout << "a Newton solve that cannot converge (2 iterations, no "
               "halving):\n";
  const RunResult failed
    = run_example("failed",
                  "--set 'Load path/Max Newton iterations=2' "
                  "--set 'Load path/Max bisections=0'");
  const nlohmann::json f = read_summary("failed");
  std::cout << "  written: converged " << f["converged"]
            << ", reached fraction below 1: "
            << (f["load_path"]["reached_fraction"].get<double>() < 1. ? "yes" :
                                                                        "NO")
            << '\n';
  (void)failed;

  std::cout << "a clearance (U -0.1 mm): stays elastic, no pressure:\n";
  run_example("clearance", "--set 'Fit/Diametral interference=-0.1'");
  std::cout << "  mean pressure "
            << read_summary("clearance")["pressure"]["mean"] << '\n';

  std::cout << "a yielding shaft (R_e 200 MPa) in an elastic hub: the hub "
               "takes the Neumann step; staggered against monolithic:\n";
  const std::string shaft = "--set 'Material/Shaft/Plasticity=von Mises' "
                            "--set 'Material/Shaft/Yield strength=200' "
                            "--set 'Material/Hub/Plasticity=none' ";
  run_example("shaft_s", shaft);
  run_example("shaft_m", shaft + "--set Solver/Method=monolithic");
  const nlohmann::json ss = read_summary("shaft_s"),
                       sm = read_summary("shaft_m");
  std::cout << "  mean pressure (a solid shaft yields at p = R_e in plane "
               "stress): "
            << agreement(ss["pressure"]["mean"], 200., 1e-6) << ", monolithic "
            << agreement(sm["pressure"]["mean"], ss["pressure"]["mean"], 1e-6)
            << ", shaft fully plastic "
            << ss["plasticity"]["bodies"][0]["fully_plastic"] << '\n';

  std::cout << "bad input:\n";
  run_example("bad", "--set 'Material/Hub/Hardening modulus=-5'");
  run_example("bad", "--set 'Material/Hub/Yield strength=0'");
  run_example("bad", "--set 'Material/Hub/Hardening modulus=210000'");
  run_example("bad", "--set 'Material/Hub/Plasticity=tresca'");
  run_example("bad", "--set 'Fit/ISO fit=H7/s6' --set 'Fit/Case=all'");
  {
    // The message names the file by its path: not printed.
    const RunResult r
      = run_coaxfit("bad",
                    "--sweep 'Fit/Diametral interference=0.1,0.2' "
                      + yielding_hub_example);
    std::cout << "  --sweep: exit code " << r.exit_code << ", " << r.lines
              << " line(s), "
              << (r.message.find("runs on its own") != std::string::npos ?
                    "says it runs on its own" :
                    "DOES NOT SAY WHY")
              << '\n';
  }
  std::cout << "  directory left: " << std::filesystem::exists("bad") << '\n';
  return 0;
}
