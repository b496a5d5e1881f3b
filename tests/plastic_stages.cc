// The stages of an elastic-plastic fit's load path after joining
// (Load path/Stages = joining, operation, unloading, disassembly), on the
// scene of prm/examples/yielding_hub.prm (a solid elastic steel shaft D 50
// mm in a steel hub D 50-100 mm yielding at 300 MPa, perfectly plastic,
// both 40 mm long):
// - Exact: both parts heated alike (same E, nu and thermal expansion) grow
//   by alpha dT r without any stress, so operation and unloading leave the
//   joined state (pressures and plastic zones) unchanged, to 1e-8.
// - The loads of operation in the plastic bodies against the elastic code:
//   a fit that stays elastic (U 0.05 mm) under speed, an outer pressure on
//   the hub and a hot shaft gives the elastic code's operating pressures
//   (1e-7) and after unloading the joined state again (1e-8).
// - Disassembly of the long fit (800 mm, eight outer diameters) at its
//   mid-length: the hub unloads elastically (the joined pressure is below
//   twice the pressure of first yield), and the mid-length section is
//   in generalized plane strain with zero axial force, so the residual
//   bore diameter is the joined one less the open-ended Lame recovery
//   2 p r_i / E ((r_o^2 + r_i^2) / (r_o^2 - r_i^2) + nu) at the joined
//   mid-length pressure p: within 0.5 % of that recovery; the elastic
//   shaft returns to its size (1e-9 mm).
// - prm/examples/hot_shaft_in_yielding_hub.prm: a hot shaft (120 C, hub
//   40 C) makes the hub yield further in operation, as joining at the
//   interference grown by D_F (alpha_s dT_s - alpha_h dT_h) does (1e-3:
//   the load paths differ); cooling down unloads elastically, so the
//   pressure falls by exactly the elastic fit's at that growth (1e-7) and
//   the pressure that remains lies below the joined one; staggered =
//   monolithic in every stage (1e-6).
// - Taken apart after it stayed elastic: the joint open everywhere, both
//   parts back to their sizes (1e-9 mm), no increment halved; a clearance
//   keeps its clearance; a hub driven to its bursting speed ends with exit
//   2 naming the stage and the body (before, the increments crept towards
//   the limit load without end, or a singular tangent was an internal
//   error, exit 3).
// - Bad input: unknown or misordered stages, operation without
//   loads, unloading without operation, disassembly without unilateral
//   contact, Stages in an elastic file: exit 1, one line naming the entry.

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>

using namespace coaxfit_test;

namespace
{
  const std::string example
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/yielding_hub.prm";

  const std::string all_stages
    = "--set 'Load path/Stages=joining, operation, unloading, disassembly' ";

  /** Run the example with @p arguments in @p dir; its summary.json. */
  nlohmann::json
  run_example(const std::string &dir, const std::string &arguments)
  {
    std::filesystem::remove_all(dir);
    const RunResult r = run_coaxfit(dir, "-q " + arguments + " " + example);
    std::cout << "  " << dir << ": exit code " << r.exit_code;
    if (!r.message.empty())
      std::cout << ", " << r.lines << " line(s): " << r.message;
    else
      std::cout << '\n';
    return read_summary(dir);
  }

  /** "agrees" if |a - b| <= @p tolerance * |b|. */
  std::string
  same(const double a, const double b, const double tolerance)
  {
    if (std::abs(a - b) <= tolerance * std::abs(b))
      return "agrees";
    std::ostringstream s;
    s << "DIFFERS (" << std::setprecision(10) << a << " against " << b << ")";
    return s.str();
  }

  /** The stage named @p name of summary @p s. */
  const nlohmann::json &
  stage(const nlohmann::json &s, const std::string &name)
  {
    for (const auto &st : s["stages"])
      if (st["name"] == name)
        return st;
    static const nlohmann::json none;
    return none;
  }

  /** A bad input: exit 1, one line naming @p entry. */
  void
  refused(const std::string &name,
          const std::string &arguments,
          const std::string &entry)
  {
    std::filesystem::remove_all("bad");
    const RunResult r = run_coaxfit("bad", "-q " + arguments + " " + example);
    std::cout << "  " << name << ": exit " << r.exit_code << ", "
              << (r.lines == 1 ? "one line" : "SEVERAL LINES") << ", "
              << (r.message.find(entry) != std::string::npos ? "names " :
                                                               "DOES NOT NAME ")
              << entry << ", "
              << (std::filesystem::exists("bad/summary.json") ? "WRITTEN" :
                                                                "nothing "
                                                                "written")
              << '\n';
  }
} // namespace



int
main()
{
  std::cout << "parts heated alike (exact: no stress from the heat):\n";
  {
    const nlohmann::json s
      = run_example("heated",
                    all_stages
                      + "--set 'Load path/Increments=2' "
                        "--set 'Material/Shaft/Thermal expansion=1.2e-5' "
                        "--set 'Material/Hub/Thermal expansion=1.2e-5' "
                        "--set 'Operation/Shaft temperature=150' "
                        "--set 'Operation/Hub temperature=150'");
    const nlohmann::json &j = stage(s, "joining");
    for (const char *name : {"operation", "unloading"})
      {
        const nlohmann::json &o = stage(s, name);
        std::cout
          << "  " << name << ": p(0) "
          << same(o["pressure"]["at_mid_plane"],
                  j["pressure"]["at_mid_plane"],
                  1e-8)
          << ", mean "
          << same(o["pressure"]["mean"], j["pressure"]["mean"], 1e-8)
          << ", hub plastic zone "
          << same(o["bodies"][1]["plastic_zone"]["diameter_at_mid_plane"],
                  j["bodies"][1]["plastic_zone"]["diameter_at_mid_plane"],
                  1e-8)
          << '\n';
      }
    const nlohmann::json &d = stage(s, "disassembly");
    std::cout << "  disassembly: joint open everywhere "
              << (d["contact"]["open_everywhere"] ? "yes" : "NO")
              << ", hub bore grew by " << std::fixed << std::setprecision(4)
              << d["hub_bore_diameter_change"].get<double>() << " mm"
              << std::defaultfloat << ", shaft "
              << (std::abs(d["shaft_diameter_change"].get<double>()) < 1e-9 ?
                    "back to its size" :
                    "CHANGED")
              << '\n';
  }

  std::cout << "a fit that stays elastic under loads, against the elastic "
               "code:\n";
  {
    const std::string    loads = "--set 'Fit/Diametral interference=0.05' "
                                 "--set 'Material/Shaft/Thermal expansion=1.2e-5' "
                                 "--set 'Material/Shaft/Density=7850' "
                                 "--set 'Material/Hub/Density=7850' "
                                 "--set 'Operation/Speed=8000' "
                                 "--set 'Operation/Hub outer pressure=20' "
                                 "--set 'Operation/Shaft temperature=60' ";
    const nlohmann::json p     = run_example(
      "loads_plastic",
      loads
        + "--set 'Load path/Stages=joining, operation, unloading, "
              "disassembly'");
    const nlohmann::json e
      = run_example("loads_elastic",
                    loads + "--set 'Material/Hub/Plasticity=none'");
    const nlohmann::json &o = stage(p, "operation");
    std::cout << "  operation: p(0) "
              << same(o["pressure"]["at_mid_plane"],
                      e["operation"]["operating"]["pressure_at_mid_plane"],
                      1e-7)
              << ", mean "
              << same(o["pressure"]["mean"],
                      e["operation"]["operating"]["pressure_mean"],
                      1e-7)
              << ", nothing yields "
              << (o["bodies"][1]["yields"] ? "NO" : "yes") << '\n';
    const nlohmann::json &u = stage(p, "unloading");
    std::cout << "  unloading: mean "
              << same(u["pressure"]["mean"],
                      stage(p, "joining")["pressure"]["mean"],
                      1e-8)
              << " with the joined state, "
              << same(u["pressure"]["mean"],
                      e["operation"]["assembly"]["pressure_mean"],
                      1e-7)
              << " with the elastic code's state of assembly\n";
    // Nothing yielded: the parts come apart at their drawn sizes, the
    // joint open at every point, without a halved increment (the force
    // that vanishes at U = 0 has no scale of its own).
    const nlohmann::json &d = stage(p, "disassembly");
    std::cout << "  disassembly: joint open everywhere "
              << (d["contact"]["open_everywhere"] ? "yes" : "NO")
              << ", the hub's bore and the shaft back to their sizes "
              << (std::abs(d["hub_bore_diameter_change"].get<double>()) < 1e-9
                      && std::abs(d["shaft_diameter_change"].get<double>())
                           < 1e-9 ?
                    "yes" :
                    "NO")
              << ", halved increments " << p["load_path"]["halvings"] << '\n';
  }

  std::cout << "a clearance (U -0.02 mm) taken apart:\n";
  {
    const nlohmann::json s
      = run_example("clearance",
                    "--set 'Fit/Diametral interference=-0.02' "
                    "--set 'Load path/Stages=joining, disassembly'");
    const nlohmann::json &d = stage(s, "disassembly");
    std::cout << "  disassembly keeps the clearance: U " << d["U"]
              << " mm, joint open everywhere "
              << (d["contact"]["open_everywhere"] ? "yes" : "NO") << '\n';
  }

  std::cout << "the hub at its bursting speed (60000 1/min, a coarse mesh, "
               "Max bisections 3):\n";
  {
    std::filesystem::remove_all("burst");
    const RunResult r = run_coaxfit(
      "burst",
      "-q --set 'Load path/Stages=joining, operation' "
      "--set Operation/Speed=60000 --set Material/Shaft/Density=7850 "
      "--set Material/Hub/Density=7850 --set 'Load path/Increments=2' "
      "--set 'Load path/Max bisections=3' --set 'Mesh/Radial cells=4' "
      "--set 'Mesh/Axial cells=4' "
        + example);
    const nlohmann::json s = read_summary("burst");
    std::cout << "  exit code " << r.exit_code << ", one line "
              << (r.lines == 1 ? "yes" : "NO") << ", names the stage "
              << (r.message.find("operation increment") != std::string::npos ?
                    "yes" :
                    "NO")
              << " and the body "
              << (r.message.find("body Hub") != std::string::npos ? "yes" :
                                                                    "NO")
              << "; the last converged state written, not converged "
              << (!s.is_null() && !s["converged"].get<bool>() ? "yes" : "NO")
              << '\n';
  }

  std::cout << "disassembly of the long fit at its mid-length:\n";
  {
    const nlohmann::json s
      = run_example("long",
                    "--set 'Load path/Stages=joining, disassembly' "
                    "--set 'Geometry/Hub length=800' "
                    "--set 'Geometry/Shaft length=800' "
                    "--set 'Mesh/Radial cells=20' "
                    "--set 'Mesh/Grading ratio=1' "
                    "--set 'Mesh/Axial cells=8'");
    const nlohmann::json &j  = stage(s, "joining");
    const nlohmann::json &d  = stage(s, "disassembly");
    const double          p  = j["pressure"]["at_mid_plane"];
    const double          ri = 25., ro = 50., E = 210000., nu = 0.3;
    const double          recovery
      = 2. * p * ri / E * ((ro * ro + ri * ri) / (ro * ro - ri * ri) + nu);
    const double joined   = j["hub_bore_diameter_change"];
    const double residual = d["hub_bore_diameter_change"];
    std::cout << "  elastic recovery of the bore "
              << agreement(joined - residual, recovery, 0.001)
              << " with the open-ended Lame formula, residual growth > 0 "
              << (residual > 0. ? "yes" : "NO") << ", no reverse yielding "
              << same(d["bodies"][1]["max_equivalent_plastic_strain"],
                      j["bodies"][1]["max_equivalent_plastic_strain"],
                      1e-12)
              << ", shaft "
              << (std::abs(d["shaft_diameter_change"].get<double>()) < 1e-9 ?
                    "back to its size" :
                    "CHANGED")
              << '\n';
  }

  std::cout << "prm/examples/hot_shaft_in_yielding_hub.prm (the shaft at "
               "120 C, the hub at 40 C in operation):\n";
  {
    const std::string hot = std::string(COAXFIT_SOURCE_DIR)
                            + "/prm/examples/hot_shaft_in_yielding_hub.prm";
    const auto run_hot
      = [&](const std::string &dir, const std::string &arguments) {
          std::filesystem::remove_all(dir);
          const RunResult r = run_coaxfit(dir, "-q " + arguments + " " + hot);
          std::cout << "  " << dir << ": exit code " << r.exit_code
                    << (r.message.empty() ? "\n" : ", " + r.message);
          return read_summary(dir);
        };
    const nlohmann::json s = run_hot("hot", "");
    const nlohmann::json m
      = run_hot("hot_monolithic", "--set Solver/Method=monolithic");
    const nlohmann::json &joined = stage(s, "joining");
    const nlohmann::json &hot_op = stage(s, "operation");
    const nlohmann::json &cooled = stage(s, "unloading");
    // Uniform temperatures in free bodies strain without stress; at a
    // frictionless joint only the radial difference acts: the interference
    // grows by D_F (alpha_s dT_s - alpha_h dT_h) = 50 * 1.2e-5 * 80 mm.
    const nlohmann::json direct
      = run_example("direct", "--set 'Fit/Diametral interference=0.208'");
    std::cout
      << "  operation against joining at U 0.208 mm: mean "
      << agreement(hot_op["pressure"]["mean"], direct["pressure"]["mean"], 1e-3)
      << ", p(0) "
      << agreement(hot_op["pressure"]["at_mid_plane"],
                   direct["pressure"]["at_mid_plane"],
                   1e-3)
      << ", hub plastic zone "
      << agreement(hot_op["bodies"][1]["plastic_zone"]["diameter_at_mid_plane"],
                   direct["plasticity"]["bodies"][1]["plastic_zone"]
                         ["diameter_at_mid_plane"],
                   0.005)
      << '\n';
    // Cooling unloads elastically (no point yields again, the joint stays
    // closed): the pressure falls by the elastic fit's at U 0.048 mm.
    const nlohmann::json elastic
      = run_example("elastic_0048",
                    "--set 'Fit/Diametral interference=0.048' "
                    "--set 'Material/Hub/Plasticity=none'");
    std::cout << "  cooling: the pressure falls by the elastic fit's at U "
                 "0.048 mm: mean "
              << same(hot_op["pressure"]["mean"].get<double>()
                        - cooled["pressure"]["mean"].get<double>(),
                      elastic["pressure"]["mean"],
                      1e-7)
              << ", p(0) "
              << same(hot_op["pressure"]["at_mid_plane"].get<double>()
                        - cooled["pressure"]["at_mid_plane"].get<double>(),
                      elastic["pressure"]["at_mid_plane"],
                      1e-7)
              << "; no point yields again "
              << same(cooled["bodies"][1]["max_equivalent_plastic_strain"],
                      hot_op["bodies"][1]["max_equivalent_plastic_strain"],
                      1e-12)
              << '\n';
    std::cout << "  the pressure that remains lies below the joined one "
              << (cooled["pressure"]["mean"].get<double>()
                      < joined["pressure"]["mean"].get<double>() - 1. ?
                    "yes" :
                    "NO")
              << '\n';
    for (const char *name :
         {"joining", "operation", "unloading", "disassembly"})
      std::cout << "  " << name << ": monolithic "
                << (std::string(name) == "disassembly" ?
                      std::string(stage(m, name)["contact"]["open_everywhere"] ?
                                    "open as the staggered" :
                                    "NOT OPEN") :
                      "mean pressure "
                        + same(stage(m, name)["pressure"]["mean"],
                               stage(s, name)["pressure"]["mean"],
                               1e-6))
                << ", bore "
                << same(stage(m, name)["hub_bore_diameter_change"],
                        stage(s, name)["hub_bore_diameter_change"],
                        1e-6)
                << '\n';
  }

  std::cout << "bad input:\n";
  refused("unknown stage",
          "--set 'Load path/Stages=joining, cooling'",
          "Load path/Stages");
  refused("wrong order",
          "--set 'Load path/Stages=disassembly, joining'",
          "Load path/Stages");
  refused("operation without loads",
          "--set 'Load path/Stages=joining, operation'",
          "Load path/Stages");
  refused("unloading without operation",
          "--set 'Operation/Speed=3000' --set 'Material/Hub/Density=7850' "
          "--set 'Material/Shaft/Density=7850' "
          "--set 'Load path/Stages=joining, unloading'",
          "Load path/Stages");
  refused("disassembly without unilateral contact",
          "--set 'Load path/Stages=joining, disassembly' "
          "--set 'Contact/Unilateral=false'",
          "Load path/Stages");
  refused("stages in an elastic file",
          "--set 'Material/Hub/Plasticity=none' "
          "--set 'Load path/Stages=joining, disassembly'",
          "Load path/Stages");
  return 0;
}
