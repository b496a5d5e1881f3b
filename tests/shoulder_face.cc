// Faces across the axis: a hub against a shaft shoulder, and axial loads.
// 1. prm/examples/hub_against_shoulder.prm: the face where the hub lies on
//    the shoulder is reported (summary.json geometry.sections.
//    shoulder_face) and modelled free; the joint's pressure against an
//    independent CalculiX solution with contact on both the cylinder and
//    the face (not in the repository), at interior points and in the
//    mean; staggered = monolithic; meshes of their own; the shaft without
//    its shoulder for comparison (the refinement study is in
//    benchmarks/sections_benchmark.py).
// 2. Face pressures: on both end faces of a plain hub of the shaft's length
//    (a .geo with named faces) they add a uniform axial stress -p, whose
//    Poisson expansion nu p R / E takes that much off the radial
//    interference: Lame's pressure of the smaller interference, exact. On
//    one end face alone they would push the hub along a frictionless
//    cylinder that cannot hold it: refused; so is a pressure on a face
//    that lies on the shoulder.
// 3. Bad scenes: a hub held between a shoulder and a collar, a taper
//    against a shoulder.
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace
{
  using coaxfit_test::close;
  using coaxfit_test::Result;
  using coaxfit_test::run;

  const std::string example = std::string(COAXFIT_SOURCE_DIR)
                              + "/prm/examples/hub_against_shoulder.prm";
  const std::vector<double> points = {-15., -10., 0., 10., 20., 25.};

  void
  show(const std::string &what, const Result &r)
  {
    std::cout << "  " << what << ": exit " << r.exit_code;
    for (const double z : points)
      std::cout << ", p(" << std::defaultfloat << z << ") " << std::fixed
                << std::setprecision(3) << r.at(z);
    std::cout << ", mean " << r.mean << '\n';
  }
} // namespace

int
main()
{
  std::cout << std::fixed << std::setprecision(3);

  // 1. The example.
  const Result example_run = run("shoulder", example);
  const Result mono
    = run("monolithic", "--set \"Solver/Method=monolithic\" " + example);
  const Result own = run("own",
                         "--set \"Mesh/Joint nodes=own\" --set \"Mesh/Hub "
                         "cell size=0.8\" "
                           + example);
  const Result plain
    = run("no_shoulder",
          "--set \"Geometry/Shaft section=-100, 0; 100, 0; 100, 50; -100, "
          "50; -100, 0\" "
            + example);
  std::cout << "hub_against_shoulder.prm (p in MPa at z in mm):\n";
  const auto &sections = example_run.summary["geometry"]["sections"];
  if (sections.contains("shoulder_face"))
    std::cout << "  shoulder face: z " << std::setprecision(1)
              << sections["shoulder_face"]["z"].get<double>() << ", D "
              << sections["shoulder_face"]["diameter_inner"].get<double>()
              << " to "
              << sections["shoulder_face"]["diameter_outer"].get<double>()
              << std::setprecision(3) << "; joint from z "
              << sections["joint_start"].get<double>() << " to "
              << sections["joint_end"].get<double>() << '\n';
  else
    std::cout << "  shoulder face: NOT REPORTED\n";
  show("shared joint nodes", example_run);
  show("monolithic", mono);
  show("meshes of their own", own);
  show("the shaft without its shoulder", plain);
  std::cout << "  monolithic = staggered within 1e-8: "
            << (close(mono.mean, example_run.mean, 1e-8)
                    && close(mono.at(25.), example_run.at(25.), 1e-8) ?
                  "yes" :
                  "NO")
            << "; meshes of their own within 2e-4 (mean, p(-10..20)): "
            << (close(own.mean, example_run.mean, 2e-4)
                    && close(own.at(-10.), example_run.at(-10.), 2e-4)
                    && close(own.at(20.), example_run.at(20.), 2e-4) ?
                  "yes" :
                  "NO")
            << '\n';
  // The independent solution: CalculiX 2.20, CAX8, frictionless
  // surface-to-surface penalty contact on the cylinder and on the face
  // (1e8 and 1e9 MPa/mm), meshes of 0.25 to 0.0625 mm along the bore
  // (0.05 to 0.0125 mm at its ends), the interference drawn into the
  // shaft's radius (25.025 mm), the hub held axially by a spring of 1 N/mm
  // (0.011 N): the face carries no force (its nodal pressures alternate in
  // sign about zero; without the face's contact pair it opens, the
  // shoulder moving away with the shaft's axial expansion). The
  // values at the finest mesh, then the spread over meshes,
  // penalties and nodal stresses; the mean from the hub's hoop stresses
  // (total radial force / (pi D_F l_F), l_F = 48.5 mm).
  const std::vector<std::tuple<double, double, double>> with_shoulder
    = {{-15., 79.45, 0.06},
       {-10., 76.26, 0.06},
       {0., 76.73, 0.07},
       {10., 76.89, 0.06},
       {20., 77.55, 0.06},
       {25., 85.40, 0.12}};
  const std::vector<std::tuple<double, double, double>> without_shoulder
    = {{-15., 79.23, 0.04},
       {-10., 76.13, 0.02},
       {0., 76.70, 0.02},
       {10., 76.97, 0.01},
       {20., 77.55, 0.02},
       {25., 84.80, 0.10}};
  std::cout << "against CalculiX (relative differences; p(-15..20) interior, "
               "p(25) 3.5 mm from the joint's end):\n";
  for (const auto &[name, r, reference, mean] :
       {std::make_tuple(
          "with the shoulder", &example_run, &with_shoulder, 82.83),
        std::make_tuple("without it", &plain, &without_shoulder, 82.53)})
    {
      std::cout << "  " << name << ":";
      bool interior = true, near_end = true;
      for (const auto &[z, p, spread] : *reference)
        {
          const double difference = (r->at(z) - p) / p;
          std::cout << " p(" << std::defaultfloat << z << ") " << std::fixed
                    << std::showpos << std::setprecision(4) << difference
                    << std::noshowpos;
          if (z <= 20.)
            interior = interior && std::abs(difference) <= 1e-3;
          else
            near_end = near_end && std::abs(difference) <= 2e-3;
        }
      std::cout << ", mean " << std::showpos << (r->mean - mean) / mean
                << std::noshowpos
                << "; interior within 0.1 %: " << (interior ? "yes" : "NO")
                << ", p(25) within 0.2 %: " << (near_end ? "yes" : "NO")
                << ", mean within 0.1 %: "
                << (close(r->mean, mean, 1e-3) ? "yes" : "NO")
                << std::setprecision(3) << '\n';
    }

  // 2. Face pressures on a plain hub of the shaft's length.
  {
    std::ofstream geo("plain_hub.geo");
    geo << "// A plain hub D 50-100, z -25..25; its faces named.\n"
           "Point(1) = {25, -25, 0, 1};\n"
           "Point(2) = {50, -25, 0, 4};\n"
           "Point(3) = {50,  25, 0, 4};\n"
           "Point(4) = {25,  25, 0, 1};\n"
           "Line(1) = {1, 2};\nLine(2) = {2, 3};\n"
           "Line(3) = {3, 4};\nLine(4) = {4, 1};\n"
           "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
           "Recombine Surface{1};\n"
           "Physical Curve(\"joint\") = {4};\n"
           "Physical Curve(\"left\") = {1};\n"
           "Physical Curve(\"right\") = {3};\n"
           "Physical Curve(\"outside\") = {2};\n"
           "Physical Surface(\"hub\") = {1};\n";
    std::ofstream prm("plain_hub.prm");
    prm << "subsection Geometry\n"
           "  set Shaft section = -25, 0; 25, 0; 25, 50; -25, 50; -25, 0\n"
           "  set Hub section = plain_hub.geo\n"
           "end\n"
        << coaxfit_test::fit_and_materials("210000", "0.3")
        << "subsection Mesh\n"
           "  set Cell size = 1\n"
           "  set Global refinements = 1\n"
           "end\n";
  }
  {
    // The example's hub as a .geo with named faces, against the shoulder.
    std::ofstream geo("shoulder_hub.geo");
    geo << "Point(1) = {25, -20, 0, 0.5};\nPoint(2) = {25, 28.5, 0, 0.5};\n"
           "Point(3) = {26.5, 30, 0, 0.5};\nPoint(4) = {50, 30, 0, 3};\n"
           "Point(5) = {50, -20, 0, 3};\n"
           "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
           "Line(4) = {4, 5};\nLine(5) = {5, 1};\n"
           "Curve Loop(1) = {1:5};\nPlane Surface(1) = {1};\n"
           "Recombine Surface{1};\n"
           "Physical Curve(\"joint\") = {1};\n"
           "Physical Curve(\"chamfer\") = {2};\n"
           "Physical Curve(\"right\") = {3};\n"
           "Physical Curve(\"left\") = {5};\n"
           "Physical Surface(\"hub\") = {1};\n";
  }
  const std::string shoulder_hub
    = "--set \"Geometry/Hub section="
      + (std::filesystem::current_path() / "shoulder_hub.geo").string() + "\" ";
  const std::string plain_hub
    = (std::filesystem::current_path() / "plain_hub.prm").string();
  const Result both_ends
    = run("both_ends",
          "--set \"Operation/Face pressures=left: 10; right: 10\" "
            + plain_hub);
  // Lame, equal materials, solid shaft: p = E U (1 - Q^2) / (2 D_F), Q =
  // 0.5, with U = 0.05 - 2 nu p R_F / E.
  const double U     = 0.05 - 2. * 0.3 * 10. * 25. / 210000.;
  const double exact = 210000. * U * 0.75 / 100.;
  std::cout << "10 MPa on both end faces of a plain hub of the shaft's "
               "length: exit "
            << both_ends.exit_code << ", p(0) " << std::setprecision(4)
            << both_ends.at_mid_plane << ", mean " << both_ends.mean
            << " MPa, exact " << exact << " (U_w = " << std::setprecision(6)
            << U << " mm): mean within 1e-6: "
            << (close(both_ends.mean, exact, 1e-6) ? "yes" : "NO")
            << std::setprecision(3) << '\n';

  // 3. Refused (exit code, lines, output written, message).
  std::cout << "refused (exit code, lines, output written, message):\n";
  const std::vector<std::pair<std::string, std::string>> bad
    = {{"10 MPa on one end face",
        "--set \"Operation/Face pressures=left: 10\" " + plain_hub},
       {"10 MPa on the faces of a .geo hub, one of them on the shoulder",
        "--set \"Operation/Face pressures=left: 10; right: 10; chamfer: 10\" "
          + shoulder_hub + example},
       {"a hub between a shoulder and a collar",
        "--set \"Geometry/Shaft section=-100, 0; 100, 0; 100, 70; 30, 70; 30, "
        "50; -20, 50; -20, 60; -100, 60; -100, 0\" --set \"Geometry/Hub "
        "section=-20, 50; 30, 50; 30, 100; -20, 100; -20, 50\" "
          + example},
       {"a taper against a shoulder",
        "--set \"Geometry/Shaft section=0, 0; 150, 0; 150, 70; 50, 70; 50, "
        "50; 0, 45; 0, 0\" --set \"Geometry/Hub section=5, 45.5; 50, 50; 50, "
        "100; 5, 100; 5, 45.5\" "
          + std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/taper_fit.prm"},
       {"a hub corner in the shoulder's fillet",
        "--set \"Geometry/Hub section=-20, 50; 30, 50; 30, 100; -20, 100; "
        "-20, 50\" "
          + example}};
  for (const auto &[what, arguments] : bad)
    {
      std::filesystem::remove_all("bad");
      const auto r
        = coaxfit_test::run_coaxfit("bad", coaxfit_test::quiet + arguments);
      std::cout << "  " << what << ": " << r.exit_code << ", " << r.lines
                << ", " << (std::filesystem::exists("bad") ? "YES" : "no")
                << ", " << coaxfit_test::gist(r.message, 24) << '\n';
    }
}
