// Bodies drawn as sections (Geometry/Shaft section, Hub section), run
// through the executable:
//
// 1. The plain cylinders of a drawing (shaft D 50, z -100..100; hub
//    D 50-100, z -25..25; steel, U = 0.05 mm) as outlines, meshed by gmsh,
//    beside the plain builder of the same drawing: the pressure at the
//    mid-plane and the mean pressure agree within 0.1 %.
// 2. prm/examples/gear_on_shaft.prm against an independent CalculiX
//    solution (not in the repository: CAX8 elements, u_r of the two
//    bodies tied with the interference at coinciding nodes, u_z free, the
//    pressure compressive everywhere; four meshes down to 0.0125 mm at the
//    joint ends, the figures below changing by less than 5e-5 between the
//    last two): mean pressure 75.455 MPa, p(0) 86.431, p(5) 83.513,
//    p(10) 76.384, p(15) 69.023, p(20) 64.934 MPa. Required: within
//    0.5 % at the shipped mesh (points of contact_pressure.csv
//    interpolated linearly).
// 3. The gear hub's mean pressure lies between those of plain hubs D 80
//    and D 180 of the joint's length. prm/examples/flush_pulley.prm (not
//    symmetric: modelled whole) against an independent CalculiX solution
//    (the same method, one axial pin per body): mean 31.5515 MPa, p(0)
//    31.834 (the flush end), p(5) 31.665, p(10) 31.495, p(20) 31.088,
//    p(30) 30.747, p(35) 31.260 MPa, within 0.5 %. Both examples solved
//    staggered and monolithic: the pressures agree to 1e-8.
// 4. (The refinement study of the gear example, Global refinements 0..2
//    against the CalculiX solution, is in benchmarks/sections_benchmark.py.)
// 5. Bad scenes: exit code 1, one line naming the entry, nothing written.

#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace
{
  using coaxfit_test::close;
  using coaxfit_test::profile_difference;
  using coaxfit_test::Result;
  using coaxfit_test::run;

  const std::string gear
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/gear_on_shaft.prm";

  const std::string materials
    = coaxfit_test::fit_and_materials("210000", "0.3")
      + "subsection Mesh\n  set Global refinements = 1\nend\n";

  using coaxfit_test::quiet;

  std::string
  write_prm(const std::string &name, const std::string &text)
  {
    const std::string file = name + ".prm";
    std::ofstream(file) << text;
    return file;
  }

  /** A plain drawing: shaft D 50 x 200, hub D 50-@p D_aA x 50. */
  std::string
  plain(const std::string &name, const double D_aA)
  {
    std::ostringstream text;
    text << "subsection Geometry\n"
         << "  set Joint diameter = 50\n  set Shaft bore diameter = 0\n"
         << "  set Hub outer diameter = " << D_aA << "\n"
         << "  set Shaft length = 200\n  set Hub length = 50\nend\n"
         << materials;
    return write_prm(name, text.str());
  }

  std::string
  within(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance * std::abs(b) ? "yes" : "NO";
  }
} // namespace

int
main()
{
  std::cout << std::fixed << std::setprecision(3);

  // 1. Plain cylinders as outlines.
  {
    const Result      builder  = run("plain_builder", plain("plain", 100.));
    const std::string outlines = write_prm(
      "outlines",
      "subsection Geometry\n"
      "  set Shaft section = -100, 0; 100, 0; 100, 50; -100, 50; -100, 0\n"
      "  set Hub section = -25, 50; 25, 50; 25, 100; -25, 100; -25, 50\n"
      "end\n"
        + materials);
    const Result sections = run("plain_outlines", outlines);
    // No plane of symmetry (the shaft 0.001 mm longer on one side): the
    // whole model of the same scene.
    const std::string lopsided = write_prm(
      "lopsided",
      "subsection Geometry\n"
      "  set Shaft section = -100, 0; 100.001, 0; 100.001, 50; -100, 50; "
      "-100, 0\n"
      "  set Hub section = -25, 50; 25, 50; 25, 100; -25, 100; -25, 50\n"
      "end\n"
        + materials);
    const Result whole = run("plain_whole", lopsided);
    std::cout << "plain cylinders, exit codes " << builder.exit_code << ", "
              << sections.exit_code << '\n';
    for (const auto &[name, a, b] :
         {std::make_tuple("p(0)", sections.at_mid_plane, builder.at_mid_plane),
          std::make_tuple("mean", sections.mean, builder.mean)})
      std::cout << "  " << name << ": outlines " << a << " MPa, plain builder "
                << b << " MPa, within 0.1 %: " << within(a, b, 1e-3) << '\n';
    std::ifstream in("plain_whole/summary.json");
    std::cout << "  modelled whole (no plane of symmetry): "
              << (nlohmann::json::parse(in)["geometry"]["sections"]["model"]
                      == "whole" ?
                    "yes" :
                    "NO")
              << ", exit code " << whole.exit_code << '\n';
    for (const auto &[name, a, b] :
         {std::make_tuple("p(0)", whole.at_mid_plane, sections.at_mid_plane),
          std::make_tuple("mean", whole.mean, sections.mean)})
      std::cout << "  " << name << ": whole " << a << " MPa, half " << b
                << " MPa, within 1e-4: " << within(a, b, 1e-4) << '\n';
  }

  // 2. The gear example against CalculiX; 3. between the plain hubs.
  const Result g = run("gear", gear);
  std::cout << "gear_on_shaft.prm, exit code " << g.exit_code << '\n';
  std::cout << "  mean: " << g.mean << " MPa, CalculiX 75.455, within 0.5 %: "
            << within(g.mean, 75.455, 5e-3) << '\n';
  const std::vector<std::pair<double, double>> reference
    = {{0., 86.431}, {5., 83.513}, {10., 76.384}, {15., 69.023}, {20., 64.934}};
  for (const auto &[z, p] : reference)
    std::cout << "  p(" << z << "): " << g.at(z) << " MPa, CalculiX " << p
              << ", within 0.5 %: " << within(g.at(z), p, 5e-3) << '\n';
  const Result d80  = run("hub_80", plain("hub_80", 80.)),
               d180 = run("hub_180", plain("hub_180", 180.));
  std::cout << "  mean between the plain hubs D 80 (" << d80.mean
            << " MPa) and D 180 (" << d180.mean << " MPa): "
            << (d80.mean < g.mean && g.mean < d180.mean ? "yes" : "NO") << '\n';

  // The flush pulley, whole.
  const std::string pulley
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/flush_pulley.prm";
  const Result f = run("pulley", pulley);
  std::cout << "flush_pulley.prm, exit code " << f.exit_code << '\n';
  std::cout << "  mean: " << f.mean << " MPa, CalculiX 31.5515, within 0.5 %: "
            << within(f.mean, 31.5515, 5e-3) << '\n';
  std::cout << "  at_mid_plane (z = 20): " << f.at_mid_plane
            << " MPa, CalculiX 31.088, within 0.5 %: "
            << within(f.at_mid_plane, 31.088, 5e-3) << '\n';
  for (const auto &[z, p] :
       std::vector<std::pair<double, double>>{{0., 31.834},
                                              {5., 31.665},
                                              {10., 31.495},
                                              {30., 30.747},
                                              {35., 31.260}})
    std::cout << "  p(" << z << "): " << f.at(z) << " MPa, CalculiX " << p
              << ", within 0.5 %: " << within(f.at(z), p, 5e-3) << '\n';

  // The other section examples: a relief groove in the hub's faces lowers
  // the peak at the joint's end (against the plain hub at the same cell
  // size); a shoulder 5 mm beside the hub leaves the middle of the joint
  // as it is (the whole model against the plain half).
  {
    const Result groove = run("relief_groove",
                              std::string(COAXFIT_SOURCE_DIR)
                                + "/prm/examples/relief_groove.prm");
    const Result plain_hub
      = run("plain_hub", "--set \"Mesh/Cell size=0.5\" outlines.prm");
    const auto peak = [](const Result &r) { return r.profile.back().second; };
    std::cout << "relief_groove.prm: exit " << groove.exit_code
              << ", pressure at the joint's end " << peak(groove)
              << " MPa, below the plain hub's " << peak(plain_hub)
              << " MPa: " << (peak(groove) < peak(plain_hub) ? "yes" : "NO")
              << '\n';
    const Result shoulder = run("shoulder",
                                std::string(COAXFIT_SOURCE_DIR)
                                  + "/prm/examples/shoulder_beside_hub.prm");
    std::cout << "shoulder_beside_hub.prm: exit " << shoulder.exit_code
              << ", p(0) " << shoulder.at_mid_plane
              << " MPa, within 0.1 % of the plain half's "
              << plain_hub.at_mid_plane << ": "
              << within(shoulder.at_mid_plane, plain_hub.at_mid_plane, 1e-3)
              << '\n';
  }

  // Drawings that once failed: each must give the pressures of the
  // drawing it differs from by round-off or by points that change nothing.
  {
    const Result reference = run("reference", "outlines.prm");
    std::string  axis      = "-100, 0; ";
    for (int k = 1; k < 100; ++k)
      axis += std::to_string(-100 + 2 * k) + ", 0; ";
    const std::vector<std::pair<std::string, std::string>> same
      = {{"the shaft 1e-6 mm below the bore (snapped onto one cylinder)",
          "--set \"Geometry/Shaft section=-100, 0; 100, 0; 100, 49.999999; "
          "-100, 49.999999; -100, 0\""},
         {"a collinear point on the joint",
          "--set \"Geometry/Shaft section=-100, 0; 100, 0; 100, 50; 10, 50; "
          "-100, 50; -100, 0\""},
         {"the shaft's axis drawn with 100 points",
          "--set \"Geometry/Shaft section=" + axis
            + "100, 0; 100, 50; -100, 50; -100, 0\""}};
    for (const auto &[what, arguments] : same)
      {
        const Result r = run("same", arguments + " outlines.prm");
        std::cout << what << ": exit " << r.exit_code
                  << ", p(0) and mean within 1e-4 of the plain outline: "
                  << (close(r.at_mid_plane, reference.at_mid_plane, 1e-4)
                          && close(r.mean, reference.mean, 1e-4) ?
                        "yes" :
                        "NO")
                  << '\n';
      }
  }
  {
    const std::string pulley
      = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/flush_pulley.prm";
    const Result base = run("pulley_base", pulley);
    const std::vector<std::pair<std::string, std::string>> moved = {
      {"the flush pulley mirrored (joint z -40..0)",
       "--set \"Geometry/Shaft section=-150, 0; 0, 0; 0, 50; -150, 50; "
       "-150, 0\" --set \"Geometry/Hub section=-40, 50; 0, 50; 0, 100; "
       "-40, 100; -40, 50\" "},
      {"the flush pulley moved by 0.7 mm",
       "--set \"Geometry/Shaft section=0.7, 0; 150.7, 0; 150.7, 50; 0.7, 50; "
       "0.7, 0\" --set \"Geometry/Hub section=0.7, 50; 40.7, 50; 40.7, 100; "
       "0.7, 100; 0.7, 50\" "}};
    for (const auto &[what, arguments] : moved)
      {
        const Result r = run("moved", arguments + pulley);
        std::cout << what << ": exit " << r.exit_code
                  << ", mean and pressure at the joint's middle within 1e-4: "
                  << (close(r.mean, base.mean, 1e-4)
                          && close(r.at_mid_plane, base.at_mid_plane, 1e-4) ?
                        "yes" :
                        "NO")
                  << '\n';
      }
  }

  // Meshes of their own (Mesh/Joint nodes = own, the hub coarser or
  // finer than the shaft): the joint nodes do not match, the mortar
  // projection couples them; against the shared nodes of the same scene.
  for (const auto &[name, staggered, file] :
       {std::make_tuple("gear", &g, gear),
        std::make_tuple("pulley", &f, pulley)})
    for (const std::string hub_cells : {"0.4", "0.15"})
      {
        const Result own
          = run(std::string(name) + "_own",
                "--set \"Mesh/Joint nodes=own\" --set \"Mesh/Hub cell size="
                  + hub_cells + "\" " + file);
        const Result own_monolithic
          = run(std::string(name) + "_own_monolithic",
                "--set \"Mesh/Joint nodes=own\" --set \"Mesh/Hub cell size="
                  + hub_cells + "\" --set Solver/Method=monolithic " + file);
        std::cout << name << ", own joint nodes, hub cell size " << hub_cells
                  << " mm: exit " << own.exit_code << ", " << own.coupling
                  << ", p at the joint's middle and mean within 0.1 % of the "
                     "shared nodes': "
                  << (close(own.at_mid_plane, staggered->at_mid_plane, 1e-3)
                          && close(own.mean, staggered->mean, 1e-3) ?
                        "yes" :
                        "NO")
                  << "; monolithic (tied by M) exit "
                  << own_monolithic.exit_code << ", within 1e-8: "
                  << (profile_difference(own_monolithic, own) <= 1e-8 ? "yes" :
                                                                        "NO")
                  << '\n';
      }

  // Staggered against monolithic.
  for (const auto &[name, staggered, file] :
       {std::make_tuple("gear", &g, gear),
        std::make_tuple("pulley", &f, pulley)})
    {
      const Result mono = run(std::string(name) + "_monolithic",
                              "--set Solver/Method=monolithic " + file);
      std::cout << name << ": monolithic exit " << mono.exit_code << ", "
                << mono.profile.size() << " points as staggered: "
                << (mono.profile.size() == staggered->profile.size() ? "yes" :
                                                                       "NO")
                << ", pressures within 1e-8: "
                << (profile_difference(mono, *staggered) <= 1e-8 ? "yes" : "NO")
                << '\n';
    }

  std::cout << std::setprecision(3);

  // 5. Bad scenes.
  std::cout << "bad scenes (exit code, lines, output written, message):\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
    {"only a hub section", "--set \"Geometry/Shaft section=\" " + gear},
    {"a plain entry with sections",
     "--set \"Geometry/Joint diameter=50\" " + gear},
    {"a taper with a diametral interference (not a push-on distance)",
     "--set \"Geometry/Shaft section=-50, 0; 50, 0; 50, 52; -50, 48; -50, 0\" "
     "--set \"Geometry/Hub section=-20, 49.2; 20, 50.8; 20, 100; -20, 100; "
     "-20, 49.2\" "
       + gear},
    {"a relief groove in the bore",
     "--set \"Geometry/Hub section=-25, 50; -5, 50; -5, 52; 5, 52; 5, 50; "
     "25, 50; 25, 100; -25, 100; -25, 50\" "
       + gear},
    {"a rounded bore edge over a shaft that ends under the fillet",
     "--set \"Geometry/Hub section=-25, 50, 3; 25, 50, 3; 25, 100; "
     "-25, 100; -25, 50, 3\" --set \"Geometry/Shaft section=-23, 0; 23, 0; "
     "23, 50; -23, 50; -23, 0\" "
       + gear},
    {"an open outline",
     "--set \"Geometry/Shaft section=-100, 0; 100, 0; 100, 50; -100, 50\" "
       + gear},
    {"a hub bore inside the shaft",
     "--set \"Geometry/Hub section=-25, 49; 25, 49; 25, 100; -25, 100; "
     "-25, 49\" "
       + gear},
    {"a ring on the hub's outer surface as the shaft",
     "--set \"Geometry/Shaft section=-25, 100; 25, 100; 25, 150; "
     "-25, 150; -25, 100\" "
       + gear},
    {"a sweep over a section",
     "--sweep \"Geometry/Hub section=-25, 50; 25, 50; 25, 100; -25, 100; "
     "-25, 50\" "
       + gear},
    {"a cell size beyond a quarter of the joint length",
     "--set \"Mesh/Cell size=20\" " + gear},
    {"a bore pressure on a solid shaft's section",
     "--set \"Operation/Shaft bore pressure=10\" " + gear}};
  for (const auto &[what, arguments] : bad)
    {
      std::filesystem::remove_all("bad");
      const auto r = coaxfit_test::run_coaxfit("bad", quiet + arguments);
      std::cout << "  " << what << ": " << r.exit_code << ", " << r.lines
                << ", " << (std::filesystem::exists("bad") ? "YES" : "no")
                << ", " << coaxfit_test::gist(r.message, 14) << '\n';
    }
}
