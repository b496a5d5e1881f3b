// Sections from gmsh files (Geometry/Shaft section or Hub section = a .geo
// or .msh path, relative to the parameter file), through the executable:
// 1. A plain hub (.msh, written here) on a shaft of the same length, and
//    a plain shaft (.msh) in a hub: frictionless bodies of equal length are
//    in Lame's plane-stress state, so the pressure is Lame's everywhere,
//    whatever the meshes (the two sides do not match).
// 2. prm/examples/rounded_gear.prm (the hub a .geo with fillets) against
//    the same section written as an outline with fillets (half model,
//    shared joint nodes), staggered and monolithic; the written
//    parameters.prm repeats the run from another directory.
// 3. (The refinement study of rounded_gear.prm, Global refinements 0..2
//    against its reference, is in benchmarks/sections_benchmark.py.)
// 4. Bad files: exit 1, one line naming the entry, nothing written.
#include "run_summary.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace
{
  using coaxfit_test::close;
  using coaxfit_test::quiet;
  using coaxfit_test::Result;
  using coaxfit_test::run;

  const std::string example
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/rounded_gear.prm";

  const std::string materials
    = coaxfit_test::fit_and_materials("70000", "0.33");

  std::string
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
    return name;
  }

  /**
   * A gmsh 2.2 mesh of the ring r_in..r_out, z -20..20, in n_r x n_z
   * quadrilaterals (x = r, y = z); its surface at r = r_joint is the
   * physical curve "joint", the others "end" (z = +-20) and "free".
   * r_in = 0: a solid cylinder (its axis untagged).
   */
  std::string
  ring_msh(const double       r_in,
           const double       r_out,
           const double       r_joint,
           const unsigned int n_r,
           const unsigned int n_z)
  {
    const auto node
      = [&](unsigned int i, unsigned int k) { return 1 + i + k * (n_r + 1); };
    std::ostringstream nodes, elements;
    unsigned int       n_elements = 0;
    for (unsigned int k = 0; k <= n_z; ++k)
      for (unsigned int i = 0; i <= n_r; ++i)
        nodes << node(i, k) << ' ' << std::setprecision(17)
              << r_in + (r_out - r_in) * i / n_r << ' ' << -20. + 40. * k / n_z
              << " 0\n";
    const auto line = [&](unsigned int tag, unsigned int a, unsigned int b) {
      elements << ++n_elements << " 1 2 " << tag << ' ' << tag << ' ' << a
               << ' ' << b << '\n';
    };
    for (unsigned int k = 0; k < n_z; ++k)
      for (const unsigned int i : {0u, n_r})
        {
          const double r = i == 0 ? r_in : r_out;
          if (r == 0.)
            continue;
          line(r == r_joint ? 1 : 3, node(i, k), node(i, k + 1));
        }
    for (unsigned int i = 0; i < n_r; ++i)
      for (const unsigned int k : {0u, n_z})
        line(2, node(i, k), node(i + 1, k));
    for (unsigned int k = 0; k < n_z; ++k)
      for (unsigned int i = 0; i < n_r; ++i)
        elements << ++n_elements << " 3 2 4 4 " << node(i, k) << ' '
                 << node(i + 1, k) << ' ' << node(i + 1, k + 1) << ' '
                 << node(i, k + 1) << '\n';
    std::ostringstream text;
    text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n"
         << "1 1 \"joint\"\n1 2 \"end\"\n1 3 \"free\"\n2 4 \"ring\"\n"
         << "$EndPhysicalNames\n$Nodes\n"
         << (n_r + 1) * (n_z + 1) << '\n'
         << nodes.str() << "$EndNodes\n$Elements\n"
         << n_elements << '\n'
         << elements.str() << "$EndElements\n";
    return text.str();
  }

  void
  show_lame(const std::string &what, const Result &r)
  {
    if (r.summary.is_null())
      {
        std::cout << "  " << what << ": exit " << r.exit_code
                  << ", no summary.json\n";
        return;
      }
    const double lame  = r.summary["pressure"]["lame"];
    double       worst = 0.;
    for (const auto &[z, p] : r.profile)
      worst = std::max(worst, std::abs(p - lame));
    std::cout << "  " << what << ": exit " << r.exit_code << ", model "
              << r.summary["geometry"]["sections"]["model"].get<std::string>()
              << ", joint coupling " << r.coupling << ", Lame "
              << std::setprecision(4) << lame << " MPa; |p - Lame| / Lame: "
              << "mean " << std::scientific << std::setprecision(1)
              << std::abs(r.mean - lame) / lame << ", at every point "
              << worst / lame << "; below 2e-6 and 1e-3: "
              << (std::abs(r.mean - lame) <= 2e-6 * lame
                      && worst <= 1e-3 * lame ?
                    "yes" :
                    "NO")
              << std::fixed << std::setprecision(4) << '\n';
  }
} // namespace

int
main()
{
  std::cout << std::fixed << std::setprecision(4);

  // 1. Lame's state through .msh files (D 50 joint, D 100 hub, 40 long).
  std::cout << "plain bodies of equal length (Lame exact), steel shaft, "
               "aluminium hub, Global refinements 1 (the corners converge "
               "at order 3, the mean at 4):\n";
  write("hub.msh", ring_msh(25., 50., 25., 20, 40));
  write("shaft.msh", ring_msh(0., 25., 25., 10, 40));
  write("coarse_hub.msh", ring_msh(25., 50., 25., 6, 10));
  const std::string outline_shaft = "-20, 0; 20, 0; 20, 50; -20, 50; -20, 0";
  const std::string outline_hub = "-20, 50; 20, 50; 20, 100; -20, 100; -20, 50";
  const std::string mesh        = "subsection Mesh\n  set Cell size = 1\n"
                                  "  set Global refinements = 1\n"
                                  "  set Degree = 2\nend\n";
  write("hub_file.prm",
        "subsection Geometry\n  set Shaft section = " + outline_shaft
          + "\n  set Hub section = hub.msh\nend\n" + materials + mesh);
  write("shaft_file.prm",
        "subsection Geometry\n  set Shaft section = shaft.msh\n"
        "  set Hub section = "
          + outline_hub + "\nend\n" + materials + mesh);
  write("both_files.prm",
        "subsection Geometry\n  set Shaft section = shaft.msh\n"
        "  set Hub section = hub.msh\nend\n"
          + materials + mesh);
  show_lame("hub .msh (20 x 40 cells), shaft outline",
            run("hub_file", "hub_file.prm"));
  show_lame("shaft .msh (10 x 40 cells), hub outline",
            run("shaft_file", "shaft_file.prm"));
  show_lame("both .msh", run("both_files", "both_files.prm"));

  // 1b. Pressures of operation: 20 MPa on the hub's outer surface, as
  // the named face "free" of the .msh (Operation/Face pressures) and as
  // Hub outer pressure on an outline (its largest diameter). Compound
  // cylinders of equal length in plane stress: with the hub's radial
  // displacement under the outer pressure q at its bore,
  // -2 q a b^2 / (E_h (b^2 - a^2)), the joint pressure is
  // p = (delta + 2 q a b^2 / (E_h (b^2 - a^2)))
  //     / (a / E_h ((b^2 + a^2) / (b^2 - a^2) + nu_h) + a (1 - nu_s) / E_s).
  {
    const double a = 25., b = 50., delta = 0.025, q = 20., E_h = 70000.,
                 nu_h = 0.33, E_s = 210000., nu_s = 0.3;
    const double exact = (delta + 2. * q * a * b * b / (E_h * (b * b - a * a)))
                         / (a / E_h * ((b * b + a * a) / (b * b - a * a) + nu_h)
                            + a * (1. - nu_s) / E_s);
    std::cout << "20 MPa on the hub's outer surface in operation, the "
                 "compound cylinders' exact joint pressure "
              << exact << " MPa:\n";
    for (const auto &[what, arguments] :
         {std::make_pair(std::string("Face pressures = free: 20 on the hub "
                                     ".msh"),
                         std::string("--set \"Operation/Face pressures=free: "
                                     "20\" hub_file.prm")),
          std::make_pair(std::string("Hub outer pressure = 20 on the hub "
                                     "outline"),
                         std::string("--set \"Operation/Hub outer "
                                     "pressure=20\" shaft_file.prm"))})
      {
        const Result r = run("operation", arguments);
        if (r.summary.is_null())
          {
            std::cout << "  " << what << ": exit " << r.exit_code << '\n';
            continue;
          }
        const auto  &o    = r.summary["operation"];
        const double mean = o["operating"]["pressure_mean"];
        const double mid  = o["operating"]["pressure_at_mid_plane"];
        std::cout << "  " << what << ": exit " << r.exit_code
                  << ", at assembly "
                  << o["assembly"]["pressure_mean"].get<double>()
                  << ", in operation mean " << mean << ", p(0) " << mid
                  << " MPa, within 1e-5 and 5e-4 (the outline's mesh is "
                     "coarser in the middle): "
                  << (close(mean, exact, 1e-5) && close(mid, exact, 5e-4) ?
                        "yes" :
                        "NO")
                  << ", in summary.json: "
                  << (o["loads"].contains("face_pressures") ?
                        o["loads"]["face_pressures"].dump() :
                        std::string("-"))
                  << '\n';
      }
  }

  // 2. The example against the same section as an outline.
  const Result geo = run("geo", example);
  const Result outline
    = run("outline",
          "--set \"Geometry/Hub section=-25, 50; 25, 50; 25, 80; 6, 80, 4; "
          "6, 150, 4; 15, 150; 15, 180; -15, 180; -15, 150; -6, 150, 4; "
          "-6, 80, 4; -25, 80; -25, 50\" "
            + example);
  const Result mono
    = run("geo_monolithic", "--set \"Solver/Method=monolithic\" " + example);
  std::cout
    << "rounded_gear.prm (.geo, whole model, joint coupling " << geo.coupling
    << ", exit " << geo.exit_code << ") against its outline (model "
    << outline.summary["geometry"]["sections"]["model"].get<std::string>()
    << ", joint coupling " << outline.coupling << ", exit " << outline.exit_code
    << "), p in MPa:\n";
  for (const auto &[name, a, b, m] :
       {std::make_tuple(
          "p(0)", geo.at_mid_plane, outline.at_mid_plane, mono.at_mid_plane),
        std::make_tuple("mean", geo.mean, outline.mean, mono.mean),
        std::make_tuple("p(5)", geo.at(5.), outline.at(5.), mono.at(5.)),
        std::make_tuple("p(-10)", geo.at(-10.), outline.at(10.), mono.at(-10.)),
        std::make_tuple("p(15)", geo.at(15.), outline.at(15.), mono.at(15.))})
    std::cout << "  " << name << ": .geo " << a << ", outline " << b
              << ", within 3e-4: " << (close(a, b, 3e-4) ? "yes" : "NO")
              << "; monolithic within 1e-8: "
              << (close(m, a, 1e-8) ? "yes" : "NO") << '\n';
  {
    // The written parameters.prm names the file by its absolute path.
    std::filesystem::create_directories("elsewhere");
    std::filesystem::copy_file(
      "geo/parameters.prm",
      "elsewhere/again.prm",
      std::filesystem::copy_options::overwrite_existing);
    const Result again = run("again", "elsewhere/again.prm");
    std::cout << "  its parameters.prm run again from another directory: "
                 "exit "
              << again.exit_code
              << ", the same mean: " << (again.mean == geo.mean ? "yes" : "NO")
              << '\n';
  }

  std::cout << std::setprecision(6);

  // 4. Bad files.
  write("no_joint.msh", [] {
    std::string text = ring_msh(25., 50., 25., 2, 2);
    return text.replace(text.find("\"joint\""), 7, "\"bore\"");
  }());
  write("triangles.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 1 "
        "\"joint\"\n$EndPhysicalNames\n$Nodes\n3\n1 25 0 0\n2 50 0 0\n"
        "3 25 20 0\n$EndNodes\n$Elements\n2\n1 1 2 1 1 1 3\n"
        "2 2 2 2 2 1 2 3\n$EndElements\n");
  write("broken.geo", "Point(1) = {25, 0, 0;\n");
  write("long_joint.msh", ring_msh(25., 50., 25., 2, 4));
  write("rounded_edge.geo",
        "Point(1) = {25, -17, 0, 1}; Point(2) = {25, 17, 0, 1};\n"
        "Point(3) = {28, 17, 0}; Point(4) = {28, 20, 0, 1};\n"
        "Point(5) = {50, 20, 0, 2}; Point(6) = {50, -20, 0, 2};\n"
        "Point(7) = {28, -20, 0, 1}; Point(8) = {28, -17, 0};\n"
        "Line(1) = {1, 2}; Circle(2) = {2, 3, 4}; Line(3) = {4, 5};\n"
        "Line(4) = {5, 6}; Line(5) = {6, 7}; Circle(6) = {7, 8, 1};\n"
        "Curve Loop(1) = {1:6}; Plane Surface(1) = {1};\n"
        "Recombine Surface{1}; Physical Curve(\"joint\") = {1};\n");
  write("holed.geo",
        "Point(1) = {25, -20, 0, 2}; Point(2) = {50, -20, 0, 2};\n"
        "Point(3) = {50, 20, 0, 2}; Point(4) = {25, 20, 0, 2};\n"
        "Point(5) = {35, -5, 0, 2}; Point(6) = {40, -5, 0, 2};\n"
        "Point(7) = {40, 5, 0, 2}; Point(8) = {35, 5, 0, 2};\n"
        "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
        "Line(4) = {4, 1}; Line(5) = {5, 6}; Line(6) = {6, 7};\n"
        "Line(7) = {7, 8}; Line(8) = {8, 5}; Curve Loop(1) = {1:4};\n"
        "Curve Loop(2) = {5:8}; Plane Surface(1) = {1, 2};\n"
        "Recombine Surface{1}; Physical Curve(\"joint\") = {4};\n");
  const std::string shorter = "--set \"Geometry/Shaft section=-10, 0; 10, 0; "
                              "10, 50; -10, 50; -10, 0\" ";
  std::cout << "bad files (exit code, lines, output written, message):\n";
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"no such file",
        "--set \"Geometry/Hub section=missing.geo\" hub_file.prm"},
       {"a .msh without a joint curve",
        "--set \"Geometry/Hub section=no_joint.msh\" hub_file.prm"},
       {"a .msh of triangles",
        "--set \"Geometry/Hub section=triangles.msh\" hub_file.prm"},
       {"a .geo gmsh cannot read",
        "--set \"Geometry/Hub section=broken.geo\" hub_file.prm"},
       {"a joint curve longer than the joint (shaft z -10..10)",
        shorter + "--set \"Geometry/Hub section=long_joint.msh\" hub_file.prm"},
       {"a rounded bore edge over a shaft that ends under the fillet",
        "--set \"Geometry/Shaft section=-19, 0; 19, 0; 19, 50; -19, 50; "
        "-19, 0\" --set \"Geometry/Hub section=rounded_edge.geo\" "
        "hub_file.prm"},
       {"a section with a hole",
        "--set \"Geometry/Hub section=holed.geo\" hub_file.prm"},
       {"AMG with a file (its joint nodes are its own)",
        "--set \"Solver/Linear solver=amg\" hub_file.prm"},
       {"a face pressure on a name no file has",
        "--set \"Operation/Face pressures=rim: 5\" hub_file.prm"},
       {"a face pressure on the joint",
        "--set \"Operation/Face pressures=joint: 5\" hub_file.prm"},
       {"a face pressure without its value",
        "--set \"Operation/Face pressures=free\" hub_file.prm"},
       {"Hub outer pressure on a file whose outer face is named",
        "--set \"Operation/Hub outer pressure=10\" hub_file.prm"},
       {"a face pressure with plain cylinders",
        "--set \"Operation/Face pressures=free: 5\" "
          + std::string(COAXFIT_SOURCE_DIR) + "/prm/default.prm"},
       {"a file's mesh coarser than the graded outline in the joint's middle",
        "--set \"Geometry/Hub section=coarse_hub.msh\" hub_file.prm"}};
  for (const auto &[what, arguments] : bad)
    {
      std::filesystem::remove_all("bad");
      auto r = coaxfit_test::run_coaxfit("bad", quiet + arguments);
      // The test's directory differs from run to run.
      const std::string here = std::filesystem::current_path().string() + "/";
      for (std::size_t at; (at = r.message.find(here)) != std::string::npos;)
        r.message.erase(at, here.size());
      std::cout << "  " << what << ": " << r.exit_code << ", " << r.lines
                << ", " << (std::filesystem::exists("bad") ? "YES" : "no")
                << ", " << coaxfit_test::gist(r.message, 16) << '\n';
    }
}
