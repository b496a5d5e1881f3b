// Press-in forces of a stack (Assembly/Order, Fit/Press-in friction
// coefficient), run as a user runs them, checked against solutions that do
// not use the stack code:
//
// 1. A stack of two is the two-body problem: its press-in force is the
//    two-body code's (its scene, its design figures) to 1e-8, variant 17
//    (a joint that opens near the hub's end) included.
// 2. Rings of equal length with frictionless joints are in a plane-stress
//    Lame state, so each joint's pressure in the part-assembly present when
//    it is pressed is the compound cylinders' of exactly those rings
//    (computed here): to 1e-6 at the mesh of stack_lame, the force
//    nu_e p pi D l to the same, the plane-stress estimate to 1e-12. Three
//    rings (solid core) inside out and outside in, five rings (hollow core)
//    in an order that joins two part-assemblies of two rings each, one
//    joint with its own nu_e.
// 3. What the order must give in any stack: the joint made last is pressed
//    into the whole assembly (its pressure there), the joint made first
//    into its two bodies alone (the pressure of the joint alone), to 1e-12.
//    The joining temperatures take what the parts joined before add to
//    the interference (the inner part's outside grown, the outer part's
//    bore closed): against the closed form's displacements of those parts,
//    to 1e-5.
// 4. ISO fits at Fit/Case = min: the force at the interferences in use and
//    the force at every joint's largest interference (what the press must
//    give), each against the closed form with ISO 286's limits (H7/s6 at
//    D 60: 23 to 72 um; H7/u6 at D 90: 89 to 146 um), to 1e-6.
// 5. Bad orders and coefficients: one line naming the entry, exit 1,
//    nothing written.

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
  /** One ring of a test stack. */
  struct Ring
  {
    std::string name;
    double      d_in, d_out, E, nu;
  };

  const double length = 40.;

  const std::string lame_mesh = "subsection Mesh\n  set Axial cells = 4\n"
                                "  set Radial cells = 6\n"
                                "  set Grading ratio = 1\n"
                                "  set Global refinements = 1\n"
                                "  set Degree = 2\nend\n"
                                "subsection Coupling\n"
                                "  set Tolerance = 1e-12\nend\n";

  /** A parameter file of the rings @p rings with interferences @p U. */
  std::string
  stack_prm(const std::vector<Ring>   &rings,
            const std::vector<double> &U,
            const std::string         &order,
            const std::string         &fit)
  {
    std::ostringstream s;
    s.precision(12);
    s << "subsection Assembly\n  set Bodies = ";
    for (const Ring &r : rings)
      s << (&r == &rings[0] ? "" : ", ") << r.name;
    s << "\n  set Order = " << order << "\nend\nsubsection Geometry\n";
    for (const Ring &r : rings)
      s << "  subsection " << r.name << "\n    set Inner diameter = " << r.d_in
        << "\n    set Outer diameter = " << r.d_out
        << "\n    set Length = " << length << "\n  end\n";
    s << "end\nsubsection Material\n";
    for (const Ring &r : rings)
      s << "  subsection " << r.name << "\n    set E = " << r.E
        << "\n    set nu = " << r.nu << "\n  end\n";
    s << "end\nsubsection Fit\n" << fit;
    for (unsigned int k = 0; k < U.size(); ++k)
      s << "  subsection " << rings[k].name << '-' << rings[k + 1].name
        << "\n    set Diametral interference = " << U[k] << "\n  end\n";
    s << "end\n" << lame_mesh;
    return s.str();
  }

  /** The compound cylinders of rings @p first to @p last. */
  coaxfit::CompoundCylinders
  part(const std::vector<Ring>   &rings,
       const std::vector<double> &U,
       const unsigned int         first,
       const unsigned int         last)
  {
    std::vector<coaxfit::CompoundCylinders::Ring> cylinders;
    for (unsigned int b = first; b <= last; ++b)
      cylinders.push_back(
        {rings[b].d_in, rings[b].d_out, rings[b].E, rings[b].nu});
    return coaxfit::CompoundCylinders(cylinders,
                                      std::vector<double>(U.begin() + first,
                                                          U.begin() + last),
                                      0.,
                                      0.);
  }

  /** The names of a JSON list joined by ` + `. */
  std::string
  names(const nlohmann::json &list)
  {
    std::string s;
    for (const auto &n : list)
      s += (s.empty() ? "" : " + ") + n.get<std::string>();
    return s;
  }

  /**
   * Part 2 and 3: @p rings pressed in the order @p order; @p parts gives
   * each joint's part-assembly (its first and last ring) as the order
   * implies it, @p nu_e each joint's coefficient.
   */
  void
  check_order(const std::string                                        &name,
              const std::vector<Ring>                                  &rings,
              const std::vector<double>                                &U,
              const std::string                                        &order,
              const std::string                                        &fit,
              const std::vector<std::pair<unsigned int, unsigned int>> &parts,
              const std::vector<double>                                &nu_e)
  {
    std::ofstream(name + ".prm") << stack_prm(rings, U, order, fit);
    std::filesystem::remove_all(name);
    const RunResult      r = run_coaxfit(name, quiet + name + ".prm");
    const nlohmann::json s = read_summary(name);
    std::cout << name << " (Assembly/Order = " << order << "): exit "
              << r.exit_code << '\n';
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        const nlohmann::json &j  = s["joints"][k];
        const nlohmann::json &p  = j["press_in"];
        const auto [first, last] = parts[k];
        const double exact = part(rings, U, first, last).pressure(k - first);
        const double force = nu_e[k] * exact * M_PI * rings[k].d_out * length;
        std::cout << "  " << j["name"].get<std::string>() << " made "
                  << p["order"].get<unsigned int>() << ": "
                  << names(p["inner_part"]) << " into "
                  << names(p["outer_part"]) << ", nu_e "
                  << p["friction_coefficient"].get<double>() << ", "
                  << std::setprecision(6) << exact << " MPa exact: p_mean "
                  << agreement(p["pressure_mean"], exact, 1e-6) << ", force "
                  << force << " N " << agreement(p["force"], force, 1e-6)
                  << ", estimate "
                  << agreement(p["force_plane_stress"], force, 1e-12) << '\n';
        // What the parts add to the interference before the joint is made:
        // the inner part's outside grown, the outer part's bore closed.
        const double R      = rings[k].d_out / 2.;
        double       growth = 0.;
        if (k > first)
          growth
            += 2. * part(rings, U, first, k).radial_displacement(k - first, R);
        if (last > k + 1)
          growth -= 2. * part(rings, U, k + 1, last).radial_displacement(0, R);
        std::cout << "    joining: the parts add " << growth << " mm exact: "
                  << (growth == 0. ?
                        (j["joining"]["interference_from_parts"] == 0. ?
                           std::string("agrees") :
                           std::string("DIFFERS")) :
                        agreement(j["joining"]["interference_from_parts"],
                                  growth,
                                  1e-5))
                  << '\n';
      }
    // Part 3: the last joint made is pressed into the whole assembly, the
    // first into its two bodies alone.
    for (const auto &j : s["joints"])
      {
        const unsigned int made = j["press_in"]["order"];
        if (made == U.size())
          std::cout << "  " << j["name"].get<std::string>()
                    << " made last: its pressure in the assembly "
                    << agreement(j["press_in"]["pressure_mean"],
                                 j["pressure"]["mean"],
                                 1e-12)
                    << '\n';
        if (made == 1)
          std::cout << "  " << j["name"].get<std::string>()
                    << " made first: the pressure of the joint alone "
                    << agreement(j["press_in"]["pressure_mean"],
                                 j["alone"]["pressure"]["mean"],
                                 1e-12)
                    << '\n';
      }
  }

  /** Part 1: variant 17 through the two-body code and as a stack. */
  void
  check_two_body()
  {
    {
      std::ifstream in(std::string(COAXFIT_SOURCE_DIR) + "/prm/variant_17.prm");
      std::stringstream text;
      text << in.rdbuf();
      std::ofstream("two_body.prm")
        << text.str()
        << "subsection Design\n  set Press-in friction coefficient = 0.11\n"
           "end\n";
    }
    std::ofstream("two_body_stack.prm") << R"(subsection Assembly
  set Bodies = Shaft, Hub
end
subsection Geometry
  subsection Shaft
    set Inner diameter = 197.6
    set Outer diameter = 200
    set Length = 600
  end
  subsection Hub
    set Inner diameter = 200
    set Outer diameter = 400
    set Length = 400
  end
end
subsection Fit
  set Diametral interference = 1
  set Press-in friction coefficient = 0.11
end
subsection Material
  subsection Shaft
    set E  = 2e5
    set nu = 0.33
  end
  subsection Hub
    set E  = 2e5
    set nu = 0.33
  end
end
subsection Mesh
  set Axial cells        = 12
  set Radial cells       = 10
  set Grading ratio      = 1.4
  set Global refinements = 1
  set Degree             = 2
end
)";
    const RunResult      r   = run_coaxfit("two_body", quiet + "two_body.prm");
    const nlohmann::json two = read_summary("two_body")["design"];
    const RunResult rs     = run_coaxfit("stack", quiet + "two_body_stack.prm");
    const nlohmann::json j = read_summary("stack")["joints"][0];
    std::cout << "variant 17: two-body code exit " << r.exit_code
              << ", stack exit " << rs.exit_code << "; press-in force "
              << std::setprecision(6) << two["press_in_force"].get<double>()
              << " N (nu_e "
              << two["press_in_friction_coefficient"].get<double>()
              << "): the stack's "
              << agreement(j["press_in"]["force"], two["press_in_force"], 1e-8)
              << ", its pressure "
              << agreement(j["press_in"]["pressure_mean"],
                           two["pressure_mean_fe"],
                           1e-8)
              << '\n';
  }
} // namespace



int
main()
{
  check_two_body();

  // Part 2 and 3: three rings with a solid core, five with a hollow one.
  const std::vector<Ring>   three = {{"Shaft", 0., 60., 210000., 0.3},
                                     {"Sleeve", 60., 90., 110000., 0.34},
                                     {"Hub", 90., 160., 70000., 0.33}};
  const std::vector<double> U3    = {0.04, 0.06};
  check_order(
    "inside_out", three, U3, "inside out", "", {{0, 1}, {0, 2}}, {0.08, 0.08});
  check_order("outside_in",
              three,
              U3,
              "outside in",
              "  subsection Shaft-Sleeve\n"
              "    set Press-in friction coefficient = 0.12\n  end\n",
              {{0, 2}, {1, 2}},
              {0.12, 0.08});

  const std::vector<Ring> five = {{"R0", 10., 20., 210000., 0.3},
                                  {"R1", 20., 30., 110000., 0.34},
                                  {"R2", 30., 45., 70000., 0.33},
                                  {"R3", 45., 60., 210000., 0.3},
                                  {"R4", 60., 80., 120000., 0.28}};
  // R1-R2 and R3-R4 first, then the two pairs joined, then R0 pressed in.
  check_order("five_rings",
              five,
              {0.02, 0.03, 0.05, 0.04},
              "R1-R2, R3-R4, R2-R3, R0-R1",
              "  set Press-in friction coefficient = 0.1\n",
              {{0, 4}, {1, 2}, {1, 4}, {3, 4}},
              {0.1, 0.1, 0.1, 0.1});

  // Part 4: ISO fits, the smallest interferences in use, inside out.
  {
    std::ofstream("iso.prm")
      << stack_prm(three,
                   {},
                   "inside out",
                   "  set Case = min\n  subsection Shaft-Sleeve\n"
                   "    set ISO fit = H7/s6\n  end\n"
                   "  subsection Sleeve-Hub\n    set ISO fit = H7/u6\n  end\n");
    std::filesystem::remove_all("iso");
    const RunResult      r = run_coaxfit("iso", quiet + "iso.prm");
    const nlohmann::json s = read_summary("iso");
    std::cout << "iso (H7/s6, H7/u6, Case min): exit " << r.exit_code << '\n';
    const std::vector<double> U_min = {0.023, 0.089}, U_max = {0.072, 0.146};
    for (unsigned int k = 0; k < 2; ++k)
      {
        const nlohmann::json &p    = s["joints"][k]["press_in"];
        const double          area = 0.08 * M_PI * three[k].d_out * length;
        const double used    = area * part(three, U_min, 0, k + 1).pressure(k);
        const double largest = area * part(three, U_max, 0, k + 1).pressure(k);
        std::cout << "  " << s["joints"][k]["name"].get<std::string>()
                  << ": force " << used << " N "
                  << agreement(p["force"], used, 1e-6)
                  << ", at the largest interferences " << largest << " N "
                  << agreement(p["force_largest"], largest, 1e-6) << '\n';
      }
  }

  // Joining a part of two bodies that expand differently: the shaft into
  // the sleeve and the hub (outside in), the sleeve of bronze (18e-6/K)
  // and the hub of aluminium (23e-6/K) heated as a whole. The sleeve's
  // bore grows by 18e-6 dT 30 and by what its joint with the hub loses
  // (the interference less 90 (23e-6 - 18e-6) dT; the closed form, linear
  // while it stays closed); the steel shaft alone is cooled by DIN 7190's
  // formula.
  {
    std::filesystem::remove_all("heated_part");
    const RunResult r = run_coaxfit(
      "heated_part",
      quiet
        + "--set 'Material/Shaft/Thermal expansion=11.5e-6' "
          "--set 'Material/Sleeve/Thermal expansion=18e-6' "
          "--set 'Material/Hub/Thermal expansion=23e-6' outside_in.prm");
    const nlohmann::json j    = read_summary("heated_part")["joints"][0];
    const auto           bore = [&](const double heated) {
      return part(three, {0.04, 0.06 - 90. * (23e-6 - 18e-6) * heated}, 1, 2)
               .radial_displacement(0, 30.)
             + 18e-6 * heated * 30.;
    };
    const double growth    = -2. * bore(0.);
    const double need      = 0.04 + growth + 0.06;
    const double heated_by = need / (2. * (bore(1.) - bore(0.)));
    std::cout << "heated part (Sleeve + Hub, outside in): exit " << r.exit_code
              << "; the bore closed by " << growth << " mm "
              << agreement(j["joining"]["interference_from_parts"],
                           growth,
                           1e-5)
              << "; heated by " << heated_by << " K (the sleeve alone "
              << need / (18e-6 * 60.) << " K) "
              << agreement(j["joining"]["heat_outer_to"], 20. + heated_by, 1e-5)
              << "; the shaft cooled by DIN 7190's formula "
              << agreement(j["joining"]["cool_inner_to"],
                           20. - need / (11.5e-6 * 60.),
                           1e-5)
              << '\n';
  }

  // Bilateral joints (Contact/Unilateral = false): a clearance pressed in
  // does not bond, its force is 0 and the next joint's is that of its
  // outer part alone.
  {
    std::filesystem::remove_all("bilateral");
    const RunResult r = run_coaxfit(
      "bilateral",
      quiet
        + "--set Contact/Unilateral=false --set "
          "'Fit/Shaft-Sleeve/Diametral interference=-0.03' inside_out.prm");
    const nlohmann::json s = read_summary("bilateral");
    std::cout << "bilateral with a clearance: exit " << r.exit_code
              << "; Shaft-Sleeve force "
              << s["joints"][0]["press_in"]["force"].get<double>()
              << " N; Sleeve-Hub p_mean "
              << agreement(s["joints"][1]["press_in"]["pressure_mean"],
                           part(three, U3, 1, 2).pressure(0),
                           1e-6)
              << '\n';
  }

  // Part 5: bad orders and coefficients.
  const std::vector<std::pair<std::string, std::string>> bad = {
    {"a joint missing", "--set 'Assembly/Order=Shaft-Sleeve' inside_out.prm"},
    {"a joint twice",
     "--set 'Assembly/Order=Shaft-Sleeve, Sleeve-Hub, Shaft-Sleeve' "
     "inside_out.prm"},
    {"no such joint",
     "--set 'Assembly/Order=Shaft-Hub, Sleeve-Hub' inside_out.prm"},
    {"a misspelt keyword", "--set 'Assembly/Order=outside-in' inside_out.prm"},
    {"a trailing comma",
     "--set 'Assembly/Order=Shaft-Sleeve, Sleeve-Hub,' inside_out.prm"},
    {"Fit/Case max without an ISO fit", "--set Fit/Case=max inside_out.prm"},
    {"Fit/Case all without an ISO fit", "--set Fit/Case=all inside_out.prm"},
    {"a joint's coefficient below 1e-6",
     "--set 'Fit/Sleeve-Hub/Press-in friction coefficient=1e-9' "
     "inside_out.prm"},
    {"no friction while pressing",
     "--set 'Fit/Press-in friction coefficient=0' inside_out.prm"},
    {"a joint's coefficient above 1",
     "--set 'Fit/Sleeve-Hub/Press-in friction coefficient=1.5' "
     "inside_out.prm"}};
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
