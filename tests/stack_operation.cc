// Loads of operation in a stack (Operation/<body> temperature, Speed,
// <innermost> bore pressure, <outermost> outer pressure), run as a user
// runs them, checked against solutions that do not use the stack code:
//
// 1. A stack of two with every load (a hot thin tube in a cooler hub,
//    rotating, pressures on its bore and outside: variant 17's scene) is
//    the two-body problem: the two-body code's operating and assembly
//    states (its scene, its loads, its staggered coupling) and its
//    plane-stress estimate (with the rotating-disc formulas), to 1e-8, in
//    both orderings and monolithically.
// 2. Rings of equal length at different uniform temperatures with
//    pressures on the free surfaces are in a plane-stress Lame state: a
//    free ring grows by alpha dT r without stress, so the exact pressures
//    are the compound cylinders' with each joint's interference less
//    2 R (alpha_o dT_o - alpha_i dT_i) (computed here), to 1e-6 at the
//    stated mesh (the accuracy of stack_lame); the state of assembly is
//    the unloaded closed form.
// 3. A hub heated until its joint opens: the run exits 0, the verdict
//    fails on the joint that lost contact in operation, the gap left is
//    the closed form's, the inner joint carries the closed form's
//    pressure.
// 4. Bad loads: one line naming the entry, exit 1, nothing written.
// 5. The joining temperatures of a joint against DIN 7190's formula.
// 6. The loosening speed of each joint (bisected on the condensed
//    compliances): the two-body code's for the stack of two (1e-5), and
//    for three rings confirmed by the staggered process 0.1 % below and
//    above it.

#include <coaxfit/design/compound_cylinders.h>

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace coaxfit_test;

namespace
{
  /** One ring of a test stack with its operating temperature. */
  struct Ring
  {
    std::string name;
    double      d_in, d_out, length, E, nu, alpha, density, temperature;
  };

  /** A parameter file of the stack @p rings with interferences @p U. */
  std::string
  stack_prm(const std::vector<Ring>   &rings,
            const std::vector<double> &U,
            const std::string         &operation,
            const std::string         &mesh)
  {
    std::ostringstream s;
    s.precision(12);
    s << "subsection Assembly\n  set Bodies = ";
    for (const Ring &r : rings)
      s << (&r == &rings[0] ? "" : ", ") << r.name;
    s << "\nend\nsubsection Geometry\n";
    for (const Ring &r : rings)
      s << "  subsection " << r.name << "\n    set Inner diameter = " << r.d_in
        << "\n    set Outer diameter = " << r.d_out
        << "\n    set Length = " << r.length << "\n  end\n";
    s << "end\nsubsection Material\n";
    for (const Ring &r : rings)
      s << "  subsection " << r.name << "\n    set E = " << r.E
        << "\n    set nu = " << r.nu
        << "\n    set Thermal expansion = " << r.alpha
        << "\n    set Density = " << r.density << "\n  end\n";
    s << "end\nsubsection Fit\n";
    for (unsigned int k = 0; k < U.size(); ++k)
      s << "  subsection " << rings[k].name << '-' << rings[k + 1].name
        << "\n    set Diametral interference = " << U[k] << "\n  end\n";
    s << "end\nsubsection Operation\n";
    for (const Ring &r : rings)
      s << "  set " << r.name << " temperature = " << r.temperature << '\n';
    s << operation << "end\n" << mesh;
    return s.str();
  }

  /**
   * The exact pressures of @p rings at their temperatures (assembly at
   * 20 C) with the pressures @p p_bore and @p p_outer: the closed form
   * with the thermal growth taken off each joint's interference.
   */
  coaxfit::CompoundCylinders
  exact(const std::vector<Ring>   &rings,
        const std::vector<double> &U,
        const double               p_bore,
        const double               p_outer,
        const bool                 loaded)
  {
    std::vector<coaxfit::CompoundCylinders::Ring> cylinders;
    std::vector<double>                           U_left;
    for (const Ring &r : rings)
      cylinders.push_back({r.d_in, r.d_out, r.E, r.nu});
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        const double D = rings[k].d_out;
        const double growth
          = rings[k + 1].alpha * (rings[k + 1].temperature - 20.)
            - rings[k].alpha * (rings[k].temperature - 20.);
        U_left.push_back(U[k] - (loaded ? D * growth : 0.));
      }
    return coaxfit::CompoundCylinders(cylinders,
                                      U_left,
                                      loaded ? p_bore : 0.,
                                      loaded ? p_outer : 0.);
  }

  const std::string lame_mesh = "subsection Mesh\n  set Axial cells = 4\n"
                                "  set Radial cells = 6\n"
                                "  set Grading ratio = 1\n"
                                "  set Global refinements = 1\n"
                                "  set Degree = 2\nend\n"
                                "subsection Coupling\n"
                                "  set Tolerance = 1e-12\nend\n";

  /** Part 2: @p rings against the closed form in both states. */
  void
  check_lame_state(const std::string         &name,
                   const std::vector<Ring>   &rings,
                   const std::vector<double> &U,
                   const double               p_bore,
                   const double               p_outer)
  {
    std::ostringstream operation;
    if (p_bore > 0.)
      operation << "  set " << rings.front().name
                << " bore pressure = " << p_bore << '\n';
    if (p_outer > 0.)
      operation << "  set " << rings.back().name
                << " outer pressure = " << p_outer << '\n';
    std::ofstream(name + ".prm")
      << stack_prm(rings, U, operation.str(), lame_mesh);
    std::filesystem::remove_all(name);
    const RunResult      r = run_coaxfit(name, quiet + name + ".prm");
    const nlohmann::json s = read_summary(name);
    std::cout << name << ": exit " << r.exit_code << ", "
              << s["operation"]["conditions"].get<std::string>() << '\n';
    const coaxfit::CompoundCylinders hot
      = exact(rings, U, p_bore, p_outer, true);
    const coaxfit::CompoundCylinders cold = exact(rings, U, 0., 0., false);
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        const nlohmann::json &j = s["joints"][k];
        std::cout << "  " << j["name"].get<std::string>() << ": in operation "
                  << std::setprecision(6) << hot.pressure(k)
                  << " MPa exact (at assembly " << cold.pressure(k)
                  << "): p(0) "
                  << agreement(j["pressure"]["at_mid_plane"],
                               hot.pressure(k),
                               1e-6)
                  << ", mean "
                  << agreement(j["pressure"]["mean"], hot.pressure(k), 1e-6)
                  << ", estimate "
                  << agreement(j["plane_stress_estimate"]["pressure"],
                               hot.pressure(k),
                               1e-12)
                  << "; at assembly p(0) "
                  << agreement(j["assembly"]["pressure"]["at_mid_plane"],
                               cold.pressure(k),
                               1e-6)
                  << ", mean "
                  << agreement(j["assembly"]["pressure"]["mean"],
                               cold.pressure(k),
                               1e-6)
                  << '\n';
      }
  }

  /** Part 1: the two-body file and the same scene as a stack. */
  void
  check_two_body()
  {
    const std::string loads = R"(subsection Operation
  set Shaft temperature = 70
  set Hub temperature = 50
  set Speed = 2000
  set Shaft bore pressure = 10
  set Hub outer pressure = 4
end
)";
    const std::string materials
      = "subsection Material\n  subsection Shaft\n"
        "    set Thermal expansion = 11.5e-6\n    set Density = 7850\n"
        "  end\n  subsection Hub\n    set Thermal expansion = 23e-6\n"
        "    set Density = 2700\n  end\nend\n";
    {
      std::ifstream in(std::string(COAXFIT_SOURCE_DIR) + "/prm/variant_17.prm");
      std::stringstream text;
      text << in.rdbuf();
      std::ofstream("two_body.prm") << text.str() << materials << loads;
    }
    const std::vector<Ring> rings
      = {{"Shaft", 197.6, 200., 600., 2e5, 0.33, 11.5e-6, 7850., 70.},
         {"Hub", 200., 400., 400., 2e5, 0.33, 23e-6, 2700., 50.}};
    const std::string mesh = "subsection Mesh\n  set Axial cells = 12\n"
                             "  set Radial cells = 10\n"
                             "  set Grading ratio = 1.4\n"
                             "  set Global refinements = 1\n"
                             "  set Degree = 2\nend\n";
    std::ofstream("two_body_stack.prm")
      << stack_prm(rings,
                   {1.},
                   "  set Speed = 2000\n  set Shaft bore pressure = 10\n"
                   "  set Hub outer pressure = 4\n",
                   mesh);

    RunResult            r   = run_coaxfit("two_body", quiet + "two_body.prm");
    const nlohmann::json two = read_summary("two_body");
    const nlohmann::json in_service  = two["pressure"];
    const nlohmann::json at_assembly = two["operation"]["assembly"];
    std::cout << "variant 17 with loads (two-body code): exit " << r.exit_code
              << '\n'
              << std::setprecision(6) << "  in operation p(0) "
              << in_service["at_mid_plane"].get<double>() << " MPa, mean "
              << in_service["mean"].get<double>() << " MPa; at assembly p(0) "
              << at_assembly["pressure_at_mid_plane"].get<double>()
              << " MPa, mean " << at_assembly["pressure_mean"].get<double>()
              << " MPa\n";
    for (const std::string method : {"--set Coupling/Ordering=gauss-seidel",
                                     "--set Coupling/Ordering=jacobi",
                                     "--set Solver/Method=monolithic"})
      {
        std::filesystem::remove_all("stack");
        r = run_coaxfit("stack", quiet + method + " two_body_stack.prm");
        const nlohmann::json j = read_summary("stack")["joints"][0];
        std::cout << "  stack, " << method.substr(6) << ": exit " << r.exit_code
                  << "; in operation p(0) "
                  << agreement(j["pressure"]["at_mid_plane"],
                               in_service["at_mid_plane"],
                               1e-8)
                  << ", mean "
                  << agreement(j["pressure"]["mean"], in_service["mean"], 1e-8)
                  << ", max "
                  << agreement(j["pressure"]["max"], in_service["max"], 1e-8)
                  << ", plane stress "
                  << agreement(j["plane_stress_estimate"]["pressure"],
                               in_service["lame"],
                               1e-9)
                  << "; at assembly p(0) "
                  << agreement(j["assembly"]["pressure"]["at_mid_plane"],
                               at_assembly["pressure_at_mid_plane"],
                               1e-8)
                  << ", mean "
                  << agreement(j["assembly"]["pressure"]["mean"],
                               at_assembly["pressure_mean"],
                               1e-8)
                  << ", loosening speed "
                  << agreement(j["loosening_speed"],
                               two["operation"]["loosening_speed"],
                               1e-5)
                  << '\n';
      }
  }

  /**
   * The loosening speeds of a rotating stack confirmed by the staggered
   * process: 0.1 % below each joint's speed it touches, 0.1 % above it is
   * open over its whole length.
   */
  void
  check_loosening(const std::string &file)
  {
    std::filesystem::remove_all("spin");
    run_coaxfit("spin", quiet + file);
    const nlohmann::json joints = read_summary("spin")["joints"];
    for (unsigned int k = 0; k < joints.size(); ++k)
      {
        const double n = joints[k]["loosening_speed"];
        std::cout << "  " << joints[k]["name"].get<std::string>()
                  << ": loosening speed " << std::setprecision(4) << n
                  << " 1/min; the staggered process at";
        for (const double factor : {0.999, 1.001})
          {
            std::filesystem::remove_all("spin_at");
            std::ostringstream speed;
            speed << std::setprecision(12) << factor * n;
            run_coaxfit("spin_at",
                        quiet + "--set Operation/Speed=" + speed.str() + " "
                          + file);
            const nlohmann::json c
              = read_summary("spin_at")["joints"][k]["contact"];
            std::cout << (factor < 1. ? " 0.999 x: " : ", 1.001 x: ")
                      << (c["length"].get<double>() > 0. ? "touches" : "open");
          }
        std::cout << '\n';
      }
  }
} // namespace

int
main()
{
  check_two_body();

  // Part 2: a hollow core, a bronze sleeve, an aluminium hub at different
  // temperatures; a solid core in five rings.
  const std::vector<Ring> three
    = {{"Core", 20., 60., 40., 210000., 0.3, 11.5e-6, 7850., 60.},
       {"Sleeve", 60., 90., 40., 110000., 0.34, 18e-6, 8800., 45.},
       {"Hub", 90., 160., 40., 70000., 0.33, 23e-6, 2700., 35.}};
  check_lame_state("three_rings_hot", three, {0.04, 0.06}, 30., 5.);
  {
    // DIN 7190's joining temperatures of the hub's joint, made after the
    // core's (Assembly/Order inside out): the sleeve's outside has grown
    // by 2 u_r(45) of the core and sleeve alone (the closed form, at
    // assembly), which adds to U; the hub heated by (U + growth + 0.001 D)
    // / (alpha_hub D). The core and sleeve are cooled as a whole (no
    // cooling coefficient given: the heating ones): the sleeve's outside
    // shrinks by alpha_sleeve dT 45 and by what the core's joint changes,
    // its interference grown by 60 (alpha_sleeve - alpha_core) dT (the
    // closed form again; linear while it stays closed).
    const nlohmann::json j       = read_summary("three_rings_hot")["joints"][1];
    const auto           outside = [](const double cooled) {
      const coaxfit::CompoundCylinders core_and_sleeve(
        {{20., 60., 210000., 0.3}, {60., 90., 110000., 0.34}},
        {0.04 + 60. * (18e-6 - 11.5e-6) * cooled},
        0.,
        0.);
      return core_and_sleeve.radial_displacement(1, 45.) - 18e-6 * cooled * 45.;
    };
    const double growth    = 2. * outside(0.);
    const double open_up   = 0.06 + growth + 0.09;
    const double shrink    = outside(0.) - outside(1.); // per kelvin
    const double cooled_by = open_up / (2. * shrink);
    std::cout << "  Sleeve-Hub joining: the sleeve's outside grown by "
              << std::setprecision(6) << growth << " mm exact: "
              << agreement(j["joining"]["interference_from_parts"],
                           growth,
                           1e-6)
              << "; heat the hub to "
              << agreement(j["joining"]["heat_outer_to"],
                           20. + open_up / (23e-6 * 90.),
                           1e-6)
              << ", or cool the core and sleeve by " << cooled_by
              << " K (alone " << open_up / (18e-6 * 90.) << " K) to "
              << agreement(j["joining"]["cool_inner_to"], 20. - cooled_by, 1e-6)
              << '\n';
  }
  const std::vector<Ring> five
    = {{"R0", 0., 20., 40., 210000., 0.3, 11.5e-6, 7850., 80.},
       {"R1", 20., 30., 40., 110000., 0.34, 18e-6, 8800., -20.},
       {"R2", 30., 45., 40., 70000., 0.33, 23e-6, 2700., 100.},
       {"R3", 45., 60., 40., 210000., 0.3, 11.5e-6, 7850., 20.},
       {"R4", 60., 80., 40., 120000., 0.28, 10e-6, 7200., 50.}};
  check_lame_state("five_rings_hot", five, {0.02, 0.03, 0.05, 0.04}, 0., 12.);

  // The three rings at 3000 1/min: each joint's loosening speed.
  {
    std::ofstream("three_rings_spin.prm")
      << stack_prm(three, {0.04, 0.06}, "  set Speed = 3000\n", lame_mesh);
    std::cout << "three_rings_spin:\n";
    check_loosening("three_rings_spin.prm");
  }

  // Part 3: the hub at 120 C loses its joint (exact: the thermal growth
  // 90 mm x (23e-6 x 100 - 18e-6 x 25) = 0.1665 mm of diameter exceeds
  // the interference 0.06 mm, less what the inner joint squeezes).
  std::vector<Ring> hot_hub = three;
  hot_hub[0].d_in           = 0.;
  hot_hub[0].temperature    = 20.;
  hot_hub[2].temperature    = 120.;
  std::ofstream("hot_hub.prm")
    << stack_prm(hot_hub, {0.04, 0.06}, "", lame_mesh);
  const RunResult      r = run_coaxfit("hot_hub", quiet + "hot_hub.prm");
  const nlohmann::json s = read_summary("hot_hub");
  const coaxfit::CompoundCylinders e
    = exact(hot_hub, {0.04, 0.06}, 0., 0., true);
  const nlohmann::json &open = s["joints"][1];
  std::cout
    << "hot_hub: exit " << r.exit_code << ", verdict "
    << (s["verdict"]["ok"].get<bool>() ? "OK" : "FAILED") << ": "
    << s["verdict"]["failed"][0].get<std::string>() << '\n'
    << "  Sleeve-Hub open at " << open["contact"]["separated_points"]
    << " points, at assembly "
    << (open["assembly"]["contact"]["closed"].get<bool>() ? "closed" : "OPEN")
    << "; diametral gap " << std::setprecision(6) << 2. * e.gap(1)
    << " mm exact: least "
    << agreement(open["contact"]["gap_min"], 2. * e.gap(1), 1e-6)
    << ", largest "
    << agreement(open["contact"]["gap_max"], 2. * e.gap(1), 1e-6)
    << "\n  Core-Sleeve " << e.pressure(0) << " MPa exact: mean "
    << agreement(s["joints"][0]["pressure"]["mean"], e.pressure(0), 1e-6)
    << '\n';

  // Part 4: bad loads.
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"temperature without expansion",
        "--set 'Material/Sleeve/Thermal expansion=0' three_rings_hot.prm"},
       {"speed without density",
        "--set Material/Hub/Density=0 --set Operation/Speed=3000 "
        "three_rings_hot.prm"},
       {"bore pressure of a solid core",
        "--set 'Operation/R0 bore pressure=5' five_rings_hot.prm"},
       {"below absolute zero",
        "--set 'Operation/Hub temperature=-300' three_rings_hot.prm"},
       {"not a temperature",
        "--set 'Operation/Hub temperature=hot' three_rings_hot.prm"},
       {"no such body",
        "--set 'Operation/Hubb temperature=80' three_rings_hot.prm"},
       {"negative speed", "--set Operation/Speed=-1 three_rings_hot.prm"},
       {"joining clearance beyond 0.1 D",
        "--set 'Operation/Joining clearance=7' three_rings_hot.prm"},
       {"a body named Assembly",
        "--set 'Assembly/Bodies=Core, Assembly, Hub' three_rings_hot.prm"}};
  for (const auto &[what, arguments] : bad)
    {
      std::filesystem::remove_all("bad");
      const RunResult b = run_coaxfit("bad", arguments);
      std::cout << what << ": exit " << b.exit_code << ", " << b.lines
                << " line(s), nothing written "
                << (std::filesystem::exists("bad") ? "NO" : "yes") << "\n  "
                << b.message;
    }
}
