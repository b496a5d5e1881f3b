// Stacks with bodies drawn as sections (Geometry/<body> section), run as a
// user runs them:
//
// 1. Exact: sections that are rectangles of equal length (a ring drawn as
//    an outline, meshed by gmsh instead of the ring mesher) with
//    frictionless joints are in a plane-stress Lame state, so every
//    joint's pressure (at the mid-plane and its mean) is the compound
//    cylinders' (closed form, computed here) to 1e-5 at Mesh/Global
//    refinements = 1: three bodies with the sleeve a section, five with a
//    hollow core and two more bodies as sections, mixed with rings; and
//    three bodies modelled whole (the sleeve's outline has one more
//    corner on its outside, so that no plane of symmetry is found).
// 2. A gear wheel with a web (a section with fillets) between a shaft and
//    a rim: the staggered process in both orderings against the
//    monolithic solution of the same discrete problem (1e-8 of the
//    largest pressure); the web carries the wheel's seat on the shaft, so
//    the pressure at the mid-plane exceeds the mean and the plane-stress
//    estimate (printed to 1e-4: the values of a run checked against an
//    independent axisymmetric CalculiX model, doc/several_bodies.md).
//    A --sweep of the wheel's outline (values separated by '|'): the
//    first value's row equals the single run (1e-12), a thinner web
//    carries less.
//    The same gear with its web offset to one side (no plane of
//    symmetry: modelled whole): staggered = monolithic, the figures
//    printed (at the joint's middle, the mean).
// 3. The same gear in operation (speed, a hot rim, an outer pressure):
//    the rim seat's last point is at the edge of contact (next to no force
//    and no gap); the staggered process converges (it once flipped that
//    point forever) and agrees with the monolithic solution.
// 4. Bad input: both a section and a ring's entries, a cone, sections
//    that do not meet or overlap (also aligned corner on edge), bodies
//    that are not neighbours touching or overlapping (a hub's flanges
//    reaching the shaft past the sleeve), a stepped seat (two diameters),
//    Mesh/Cell size without sections or out of range, a grading too
//    steep: exit 1, one line naming the entries, nothing written.

#include "run_executable.h"
#include "run_summary.h"
#include "stack_lame_check.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace coaxfit_test;

namespace
{
  /** One body of a test stack: a ring, drawn as a section if @p section. */
  struct Body
  {
    std::string name;
    double      d_in, d_out, E, nu;
    bool        section;
  };

  const double length = 40.;

  /**
   * A parameter file of @p bodies with interferences @p U; @p extra_corner:
   * each section has a corner in the middle of its outer edge's half
   * z > 0 (the same outline, but no plane of symmetry is found).
   */
  std::string
  stack_prm(const std::vector<Body>   &bodies,
            const std::vector<double> &U,
            const bool                 extra_corner = false)
  {
    return lame_stack_prm(bodies, U, length, [&](const Body &b) {
      if (!b.section)
        return std::string();
      std::ostringstream s;
      s.precision(12);
      const double z = length / 2.;
      s << -z << ", " << b.d_in << "; " << z << ", " << b.d_in << "; " << z
        << ", " << b.d_out << "; ";
      if (extra_corner)
        s << z / 2. << ", " << b.d_out << "; ";
      s << -z << ", " << b.d_out << "; " << -z << ", " << b.d_in;
      return s.str();
    });
  }

  /** Part 1: @p bodies against the compound cylinders. */
  void
  check_lame(const std::string         &name,
             const std::vector<Body>   &bodies,
             const std::vector<double> &U,
             const bool                 whole = false)
  {
    std::ofstream(name + ".prm") << stack_prm(bodies, U, whole);
    check_against_compound_cylinders(name, name + ".prm", rings_of(bodies), U);
  }

  const std::string gear_body
    = "-25, 50; 25, 50; 25, 80; 8, 80, 4; 8, 140, 4; 25, 140; 25, 160; "
      "-25, 160; -25, 140; -8, 140, 4; -8, 80, 4; -25, 80; -25, 50";

  /** The gear wheel with a web between a shaft and a rim. */
  std::string
  gear_prm(const std::string &body = gear_body)
  {
    return "subsection Assembly\n  set Bodies = Shaft, Wheel, Rim\n"
           "  set Report surfaces = Rim outer, Wheel bore\nend\n"
           "subsection Geometry\n"
           "  subsection Shaft\n    set Inner diameter = 0\n"
           "    set Outer diameter = 50\n    set Length = 80\n  end\n"
           "  set Wheel section = "
           + body
           + "\n"
             "  subsection Rim\n    set Inner diameter = 160\n"
             "    set Outer diameter = 200\n    set Length = 50\n  end\n"
             "end\n"
             "subsection Material\n"
             "  subsection Shaft\n    set E = 210000\n    set nu = 0.3\n"
             "    set Density = 7850\n    set Thermal expansion = 1.1e-5\n"
             "  end\n"
             "  subsection Wheel\n    set E = 169000\n    set nu = 0.275\n"
             "    set Density = 7100\n    set Thermal expansion = 1.25e-5\n"
             "  end\n"
             "  subsection Rim\n    set E = 210000\n    set nu = 0.3\n"
             "    set Density = 7850\n    set Thermal expansion = 1.1e-5\n"
             "  end\n"
             "end\n"
             "subsection Fit\n"
             "  subsection Shaft-Wheel\n"
             "    set Diametral interference = 0.05\n  end\n"
             "  subsection Wheel-Rim\n"
             "    set Diametral interference = 0.16\n  end\n"
             "end\n"
             "subsection Mesh\n  set Global refinements = 1\nend\n"
             "subsection Coupling\n  set Tolerance = 1e-10\nend\n";
  }

  /** Parts 2 and 3: the gear with @p loads (--set options). */
  void
  check_gear(const std::string &name,
             const std::string &loads,
             const std::string &body = gear_body)
  {
    std::ofstream("gear.prm") << gear_prm(body);
    std::vector<std::vector<double>> runs;
    for (const std::string method : {"--set Solver/Method=monolithic",
                                     "--set Coupling/Ordering=gauss-seidel",
                                     "--set Coupling/Ordering=jacobi"})
      {
        const std::string dir = name + "_" + std::to_string(runs.size());
        std::filesystem::remove_all(dir);
        const RunResult r
          = run_coaxfit(dir, quiet + method + loads + " gear.prm");
        const nlohmann::json s = read_summary(dir);
        std::cout << name << ", " << method.substr(6) << ": exit "
                  << r.exit_code << ", converged " << s["converged"]
                  << ", model " << s["mesh"]["model"].get<std::string>()
                  << '\n';
        runs.push_back(joint_pressures(s));
        if (runs.size() > 1)
          {
            const double d = difference(runs.back(), runs.front());
            std::cout << "  against the monolithic solution: "
                      << (d <= 1e-8 ? "agrees" : "DIFFERS") << " (1e-8)\n";
            continue;
          }
        for (const auto &j : s["joints"])
          std::cout << "  " << j["name"].get<std::string>() << ": p(0) "
                    << std::setprecision(5)
                    << j["pressure"]["at_mid_plane"].get<double>()
                    << " MPa, mean " << j["pressure"]["mean"].get<double>()
                    << " MPa, plane-stress estimate "
                    << j["plane_stress_estimate"]["pressure"].get<double>()
                    << " MPa, " << j["contact"]["separated_points"]
                    << " points open\n";
      }
  }

  /**
   * A sweep of the wheel's outline (values separated by '|', since an
   * outline has commas and ';'): the web 16 mm thick as in gear_0 to 2,
   * then 8 mm. sweep.csv's first row equals the single run, and the
   * thinner web carries less.
   */
  void
  check_sweep()
  {
    const std::string thin
      = "-25, 50; 25, 50; 25, 80; 4, 80, 4; 4, 140, 4; 25, 140; 25, 160; "
        "-25, 160; -25, 140; -4, 140, 4; -4, 80, 4; -25, 80; -25, 50";
    std::filesystem::remove_all("web_sweep");
    const RunResult r = run_coaxfit("web",
                                    quiet + "--sweep \"Geometry/Wheel section="
                                      + gear_body + "|" + thin + "\" gear.prm");
    // The rows: the quoted outline, then the figures.
    std::ifstream            in("web_sweep/sweep.csv");
    std::string              line;
    std::vector<std::string> header;
    std::getline(in, line);
    {
      std::istringstream h(line.substr(line.find(',') + 1));
      for (std::string field; std::getline(h, field, ',');)
        header.push_back(field);
    }
    std::vector<double> mean;
    while (std::getline(in, line))
      {
        std::istringstream f(line.substr(line.rfind('"') + 2));
        std::string        field;
        for (unsigned int c = 0; std::getline(f, field, ','); ++c)
          if (header[c] == "Shaft-Wheel_pressure_mean_MPa")
            mean.push_back(std::stod(field));
      }
    const nlohmann::json single = read_summary("gear_1");
    std::cout << "a sweep of the wheel's outline (web 16 and 8 mm): exit "
              << r.exit_code << ", " << mean.size() << " rows\n";
    if (mean.size() == 2)
      std::cout << "  web 16 mm: Shaft-Wheel mean = the single run's "
                << agreement(mean[0],
                             single["joints"][0]["pressure"]["mean"],
                             1e-12)
                << "\n  web 8 mm: " << std::setprecision(5) << mean[1]
                << " MPa, " << (mean[1] < mean[0] ? "less" : "NOT less")
                << " than with the 16 mm web\n";
  }

  /** Part 4: a bad input is refused in one line, nothing written. */
  void
  refuse(const std::string &what, const std::string &options)
  {
    std::filesystem::remove_all("refused");
    const RunResult r = run_coaxfit("refused", quiet + options + " gear.prm");
    std::cout << what << ": exit " << r.exit_code << ", "
              << (std::filesystem::exists("refused") ? "written" :
                                                       "nothing written")
              << "\n  " << gist(r.message, 60) << " (" << r.lines << " line)"
              << '\n';
  }
} // namespace

int
main()
{
  std::cout << "1. Rectangles as sections against the compound cylinders\n";
  check_lame("three",
             {{"Shaft", 0., 60., 210000., 0.3, false},
              {"Sleeve", 60., 90., 110000., 0.34, true},
              {"Hub", 90., 160., 70000., 0.33, false}},
             {0.04, 0.06});
  check_lame("five",
             {{"Core", 20., 50., 210000., 0.3, true},
              {"R1", 50., 70., 110000., 0.34, false},
              {"R2", 70., 95., 70000., 0.33, true},
              {"R3", 95., 120., 210000., 0.3, false},
              {"R4", 120., 160., 169000., 0.275, true}},
             {0.03, 0.02, 0.07, 0.05});
  check_lame("three_whole",
             {{"Shaft", 0., 60., 210000., 0.3, false},
              {"Sleeve", 60., 90., 110000., 0.34, true},
              {"Hub", 90., 160., 70000., 0.33, false}},
             {0.04, 0.06},
             true);

  std::cout << "\n2. A gear wheel with a web between a shaft and a rim\n";
  check_gear("gear", "");
  check_sweep();
  check_gear("offset",
             "",
             "-25, 50; 25, 50; 25, 80; 16, 80, 4; 16, 140, 4; 25, 140; 25, "
             "160; -25, 160; -25, 140; 0, 140, 4; 0, 80, 4; -25, 80; -25, "
             "50");
  std::cout << "\n3. The gear in operation: a point at the edge of contact\n";
  check_gear("operation",
             " --set Operation/Speed=6000 --set \"Operation/Rim "
             "temperature=80\" --set \"Operation/Rim outer pressure=5\"");

  std::cout << "\n4. Bad input\n";
  refuse("a section and a ring's entries",
         "--set \"Geometry/Wheel section=-25, 50; 25, 50; 25, 160; -25, "
         "160; -25, 50\" --set Geometry/Wheel/Length=50");
  refuse("sections that do not meet",
         "--set \"Geometry/Wheel section=-25, 52; 25, 52; 25, 160; -25, "
         "160; -25, 52\"");
  refuse("sections that overlap, aligned (no corner inside)",
         "--set \"Geometry/Wheel section=-40, 48; 40, 48; 40, 160; -40, "
         "160; -40, 48\"");
  refuse("sections that overlap",
         "--set \"Geometry/Wheel section=-25, 48; 25, 48; 25, 160; -25, "
         "160; -25, 48\"");
  refuse("Mesh/Cell size out of range", "--set \"Mesh/Cell size=0.01\"");
  refuse("Mesh/Grading ratio too steep", "--set \"Mesh/Grading ratio=4\"");
  // A taper between two sections.
  std::ofstream("cone.prm")
    << stack_prm({{"A", 0., 60., 210000., 0.3, true},
                  {"B", 60., 90., 110000., 0.34, true}},
                 {0.04})
    << "subsection Geometry\n  set A section = -20, 0; 20, 0; 20, 62; -20, "
       "58; -20, 0\n  set B section = -20, 58; 20, 62; 20, 90; -20, 90; "
       "-20, 58\nend\n";
  std::filesystem::remove_all("refused");
  const RunResult cone = run_coaxfit("refused", quiet + "cone.prm");
  std::cout << "a cone: exit " << cone.exit_code << "\n  "
            << gist(cone.message, 60) << " (" << cone.lines << " line)\n";
  // A stepped seat: cylinders of D 60 and 62 (two pieces, two diameters).
  std::ofstream("stepped.prm")
    << stack_prm({{"A", 0., 60., 210000., 0.3, true},
                  {"B", 60., 90., 110000., 0.34, true}},
                 {0.04})
    << "subsection Geometry\n  set A section = -20, 0; 20, 0; 20, 62; 0, "
       "62; 0, 60; -20, 60; -20, 0\n  set B section = -20, 60; 0, 60; 0, "
       "62; 20, 62; 20, 90; -20, 90; -20, 60\nend\n";
  std::filesystem::remove_all("refused");
  const RunResult stepped = run_coaxfit("refused", quiet + "stepped.prm");
  std::cout << "a stepped seat: exit " << stepped.exit_code << "\n  "
            << gist(stepped.message, 60) << " (" << stepped.lines << " line)\n";
  // A hub whose flanges reach past the sleeve to the shaft (not its
  // neighbour): touching it, or cutting into it.
  for (const std::string flange : {"60", "50"})
    {
      std::ofstream("flange.prm")
        << stack_prm({{"Shaft", 0., 60., 210000., 0.3, false},
                      {"Sleeve", 60., 90., 110000., 0.34, true},
                      {"Hub", 90., 160., 70000., 0.33, true}},
                     {0.04, 0.06})
        << "subsection Geometry\n  subsection Shaft\n    set Length = 100\n"
           "  end\n  set Hub section = -30, "
        << flange << "; -22, " << flange << "; -22, 90; 22, 90; 22, " << flange
        << "; 30, " << flange << "; 30, 160; -30, 160; -30, " << flange
        << "\nend\n";
      std::filesystem::remove_all("refused");
      const RunResult f = run_coaxfit("refused", quiet + "flange.prm");
      std::cout << "a flange of the hub to D " << flange
                << " on the shaft, not its neighbour: exit " << f.exit_code
                << ", "
                << (std::filesystem::exists("refused") ? "written" :
                                                         "nothing written")
                << "\n  " << gist(f.message, 60) << " (" << f.lines
                << " line)\n";
    }
  std::ofstream("rings.prm")
    << stack_prm({{"A", 0., 60., 210000., 0.3, false},
                  {"B", 60., 90., 110000., 0.34, false}},
                 {0.04});
  std::filesystem::remove_all("refused");
  const RunResult r
    = run_coaxfit("refused", quiet + "--set \"Mesh/Cell size=1\" rings.prm");
  std::cout << "Mesh/Cell size without sections: exit " << r.exit_code << "\n  "
            << gist(r.message, 60) << " (" << r.lines << " line)" << '\n';
  return 0;
}
