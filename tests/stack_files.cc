// Stacks with bodies whose sections are gmsh files (Geometry/<body>
// section = a .geo file), run as a user runs them. The file's mesh is kept;
// its neighbours are meshed with its nodes on their joints.
//
// 1. Exact: rings of equal length with frictionless joints are in a
//    plane-stress Lame state, so every joint's pressure (at the mid-plane
//    and its mean) is the compound cylinders' (closed form) to 1e-5 at
//    Mesh/Global refinements = 1, the files' rings structured meshes
//    (transfinite, 1 mm along the axis): three bodies with the sleeve a
//    file; three with the shaft a file (solid: on the axis); three with
//    the sleeve and the hub files that have the same
//    nodes on their joint; five with a hollow core and two files that are
//    not neighbours.
// 2. The gear wheel with a web of prm/examples/gear_wheel_with_web.prm
//    drawn in gmsh (prm/examples/gear_wheel_from_file.prm): its figures
//    against the outline's at the same refinement (the means 2e-5, the
//    mid-plane pressures 1e-3, the rim's outside 2e-5) and against both
//    drawings refined three times (1e-4; there they agree to 3e-5:
//    Shaft-Wheel p(0) 139.339 and 139.343, mean 99.6282 and 99.6281 MPa;
//    Wheel-Rim 60.1541 and 60.1565, 33.0996 both). Staggered in both
//    orderings = monolithic (1e-8).
// 3. Bad input: a rim whose ends lie on a face of the file between its
//    nodes, two files whose joint nodes differ, a ring whose end lies
//    1e-5 mm beside a file's node (it must be the node), a file name with
//    '#' (parameters.prm could not repeat it), a file that does not
//    exist: exit 1, one line naming the entry, nothing written.

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
  const std::string examples
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/";

  /**
   * One body of a test stack of rings 40 mm long; a gmsh file of
   * @p axial_cells along the axis if @p axial_cells > 0.
   */
  struct Body
  {
    std::string  name;
    double       d_in, d_out, E, nu;
    unsigned int axial_cells;
  };

  const double length = 40.;

  /** A .geo file of a ring (x = r, y = z): a structured mesh. */
  std::string
  ring_geo(const Body &b)
  {
    std::ostringstream s;
    s.precision(12);
    const double z = length / 2.;
    s << "Point(1) = {" << b.d_in / 2. << ", " << -z << ", 0};\n"
      << "Point(2) = {" << b.d_out / 2. << ", " << -z << ", 0};\n"
      << "Point(3) = {" << b.d_out / 2. << ", " << z << ", 0};\n"
      << "Point(4) = {" << b.d_in / 2. << ", " << z << ", 0};\n"
      << "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
      << "Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4};\n"
      << "Plane Surface(1) = {1};\n"
      << "Transfinite Curve{1, 3} = "
      << 1 + static_cast<unsigned int>(std::ceil((b.d_out - b.d_in) / 2.))
      << ";\nTransfinite Curve{2, 4} = " << b.axial_cells + 1 << ";\n"
      << "Transfinite Surface{1};\nRecombine Surface{1};\n";
    return s.str();
  }

  /** A parameter file of @p bodies with interferences @p U. */
  std::string
  stack_prm(const std::string         &name,
            const std::vector<Body>   &bodies,
            const std::vector<double> &U)
  {
    return lame_stack_prm(bodies, U, length, [&](const Body &b) {
      if (b.axial_cells == 0)
        return std::string();
      const std::string file = name + "_" + b.name + ".geo";
      std::ofstream(file) << ring_geo(b);
      return file;
    });
  }

  /** Part 1: @p bodies against the compound cylinders. */
  void
  check_lame(const std::string         &name,
             const std::vector<Body>   &bodies,
             const std::vector<double> &U)
  {
    std::ofstream(name + ".prm") << stack_prm(name, bodies, U);
    check_against_compound_cylinders(name, name + ".prm", rings_of(bodies), U);
  }

  /** The mean radial displacement of the report surface @p name (mm). */
  double
  surface_mean(const nlohmann::json &s, const std::string &name)
  {
    for (const auto &f : s["surfaces"])
      if (f["name"] == name)
        return f["u_r"]["mean"];
    return std::nan("");
  }

  /** Part 3: a bad input is refused in one line, nothing written. */
  void
  refuse(const std::string &what, const std::string &prm)
  {
    std::filesystem::remove_all("refused");
    const RunResult r = run_coaxfit("refused", quiet + prm);
    // No machine's paths in the reference.
    std::string message = r.message;
    for (const auto &[path, name] :
         {std::make_pair(std::filesystem::current_path().string(),
                         std::string("DIR")),
          std::make_pair(std::string(COAXFIT_SOURCE_DIR), std::string("SRC"))})
      for (std::size_t at; (at = message.find(path)) != std::string::npos;)
        message.replace(at, path.size(), name);
    std::cout << what << ": exit " << r.exit_code << ", "
              << (std::filesystem::exists("refused") ? "written" :
                                                       "nothing written")
              << "\n  " << gist(message, 70) << " (" << r.lines << " line)"
              << '\n';
  }
} // namespace

int
main()
{
  std::cout << "1. Rings from gmsh files against the compound cylinders\n";
  check_lame("three",
             {{"Shaft", 0., 60., 210000., 0.3, 0},
              {"Sleeve", 60., 90., 110000., 0.34, 40},
              {"Hub", 90., 160., 70000., 0.33, 0}},
             {0.04, 0.06});
  check_lame("shaft_file",
             {{"Shaft", 0., 60., 210000., 0.3, 40},
              {"Sleeve", 60., 90., 110000., 0.34, 0},
              {"Hub", 90., 160., 70000., 0.33, 0}},
             {0.04, 0.06});
  check_lame("two_files",
             {{"Shaft", 0., 60., 210000., 0.3, 0},
              {"Sleeve", 60., 90., 110000., 0.34, 40},
              {"Hub", 90., 160., 70000., 0.33, 40}},
             {0.04, 0.06});
  check_lame("five",
             {{"Core", 20., 50., 210000., 0.3, 0},
              {"R1", 50., 70., 110000., 0.34, 40},
              {"R2", 70., 95., 70000., 0.33, 0},
              {"R3", 95., 120., 210000., 0.3, 40},
              {"R4", 120., 160., 169000., 0.275, 0}},
             {0.03, 0.02, 0.07, 0.05});

  std::cout << "\n2. The gear wheel drawn in gmsh against its outline\n";
  nlohmann::json outline, file;
  for (const std::string name : {"gear_wheel_with_web", "gear_wheel_from_file"})
    {
      // The file's run (Gauss-Seidel, to Coupling/Tolerance 1e-10) is also
      // checked against the monolithic solution below (1e-8).
      std::filesystem::remove_all(name);
      const RunResult r                                 = run_coaxfit(name,
                                      quiet + "--set Coupling/Tolerance=1e-10 "
                                        + examples + name + ".prm");
      (name == "gear_wheel_from_file" ? file : outline) = read_summary(name);
      const nlohmann::json &s = name == "gear_wheel_from_file" ? file : outline;
      std::cout << name << ": exit " << r.exit_code << ", converged "
                << s["converged"] << ", model "
                << s["mesh"]["model"].get<std::string>() << '\n';
    }
  // Both drawings at Mesh/Global refinements = 3 (see the top).
  const double refined[2][2] = {{139.339, 99.6282}, {60.1541, 33.0996}};
  for (unsigned int k = 0; k < 2; ++k)
    {
      const nlohmann::json &f = file["joints"][k]["pressure"],
                           &o = outline["joints"][k]["pressure"];
      std::cout << "  " << file["joints"][k]["name"].get<std::string>()
                << ": p(0) " << std::setprecision(5)
                << f["at_mid_plane"].get<double>() << " MPa, mean "
                << f["mean"].get<double>()
                << " MPa\n    against the outline: p(0) "
                << agreement(f["at_mid_plane"], o["at_mid_plane"], 1e-3)
                << ", mean " << agreement(f["mean"], o["mean"], 2e-5)
                << "\n    against both refined: p(0) "
                << agreement(f["at_mid_plane"], refined[k][0], 1e-4)
                << ", mean " << agreement(f["mean"], refined[k][1], 1e-4)
                << '\n';
    }
  std::cout << "  Rim outer u_r mean: "
            << agreement(surface_mean(file, "Rim outer"),
                         surface_mean(outline, "Rim outer"),
                         2e-5)
            << " with the outline's\n";
  // The run above (Gauss-Seidel) and Jacobi against the monolithic
  // solution.
  std::vector<std::vector<double>> p;
  for (const std::string method :
       {"--set Solver/Method=monolithic", "--set Coupling/Ordering=jacobi"})
    {
      std::filesystem::remove_all("method");
      const RunResult r
        = run_coaxfit("method",
                      quiet + method + " --set Coupling/Tolerance=1e-10 "
                        + examples + "gear_wheel_from_file.prm");
      p.push_back(joint_pressures(read_summary("method")));
      std::cout << "  " << method.substr(6) << ": exit " << r.exit_code << '\n';
    }
  std::cout << "  against the monolithic solution: Gauss-Seidel "
            << (difference(joint_pressures(file), p[0]) <= 1e-8 ? "agrees" :
                                                                  "DIFFERS")
            << ", Jacobi "
            << (difference(p[1], p[0]) <= 1e-8 ? "agrees" : "DIFFERS")
            << " (1e-8)\n";

  std::cout << "\n3. Bad input\n";
  {
    // The rim 40 mm long: its ends at z = -20 and 20 lie on the wheel's
    // outside between the file's nodes.
    std::ifstream      in(examples + "gear_wheel_from_file.prm");
    std::ostringstream text;
    text << in.rdbuf();
    std::string       prm   = text.str();
    const std::string entry = "section = gear_wheel.geo";
    prm.replace(prm.find(entry),
                entry.size(),
                "section = " + examples + "gear_wheel.geo");
    const std::string rim = "set Length         = 50\n  end\nend";
    prm.replace(prm.find(rim), rim.size(), "set Length = 40\n  end\nend");
    std::ofstream("short_rim.prm") << prm;
    refuse("a rim whose ends lie between the file's nodes", "short_rim.prm");
  }
  std::ofstream("mismatch.prm")
    << stack_prm("mismatch",
                 {{"Shaft", 0., 60., 210000., 0.3, 0},
                  {"Sleeve", 60., 90., 110000., 0.34, 40},
                  {"Hub", 90., 160., 70000., 0.33, 30}},
                 {0.04, 0.06});
  refuse("two files with other nodes on their joint", "mismatch.prm");
  refuse("a hub ending 1e-5 mm beside the sleeve file's last node",
         "--set Geometry/Hub/Length=39.99998 three.prm");
  refuse("a file name with '#'",
         "--set \"Geometry/Sleeve section=a#b.geo\" three.prm");
  std::ofstream("missing.prm")
    << stack_prm("missing",
                 {{"Shaft", 0., 60., 210000., 0.3, 0},
                  {"Sleeve", 60., 90., 110000., 0.34, 40},
                  {"Hub", 90., 160., 70000., 0.33, 0}},
                 {0.04, 0.06});
  std::filesystem::remove("missing_Sleeve.geo");
  refuse("a file that does not exist", "missing.prm");
  return 0;
}
