// Rings of different lengths: prm/examples/stepped_rings.prm (a steel
// shaft 100 mm long, a bronze sleeve 60 mm and an aluminium hub 40 mm on
// it) against an independent CalculiX solution (not in the repository:
// CAX8, one structured mesh per body with coinciding joint nodes, each
// joint tied radially with its interference through a dummy node and free
// axially, cells down to 0.0125 mm at the joints' ends, 32 across each
// wall; the pressure from the nodal radial stresses of both sides;
// converged to about 2e-4 between its two finest meshes): the mean of
// each joint and the pressure at interior points within 1e-3; the
// staggered process and the monolithic solver; a thin bronze sleeve
// between a shaft and a shorter hub, held by the hub alone: it lifts off
// the shaft beside the hub and touches again at its end (staggered =
// monolithic, the points that opened), and against a CalculiX model of
// it with unilateral contact (not in the repository: CAX8, structured
// meshes of 0.5, 0.25 and 0.125 mm at the hub's and the sleeve's ends, 8
// to 32 cells across the sleeve's wall; the shaft's joint solved by an
// active set of radial node-pair ties until no tie pulls and no open pair
// overlaps, cross-checked by penalty contact; the hub's joint tied with
// its interference, all in compression): the pressures at points of both
// joints within 3e-3 and 1e-3 (its meshes agree within 1e-3), the means
// within 1e-3 and 3e-3 (the hub's joint's mean creeps up with its edge
// singularity: 59.15, 59.23, 59.28 MPa), where the joint opens, the
// largest gap within 2 % (the coarse rings' 1 %).

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
  const std::string example
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/stepped_rings.prm";

  /** The pressure of @p csv (z, p, ...) at @p z, linear between points. */
  double
  pressure_at(const std::string &csv, const double z)
  {
    std::ifstream in(csv);
    std::string   line;
    std::getline(in, line);
    double z0 = 0., p0 = 0.;
    bool   first = true;
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        std::string        a, b;
        std::getline(row, a, ',');
        std::getline(row, b, ',');
        const double z1 = std::stod(a), p1 = std::stod(b);
        if (!first && z1 >= z)
          return p0 + (p1 - p0) * (z - z0) / (z1 - z0);
        if (first && z1 >= z)
          return p1;
        z0 = z1, p0 = p1, first = false;
      }
    return p0;
  }

  struct Reference
  {
    const char         *joint;
    double              mean;
    std::vector<double> z, p;
  };

  const std::vector<Reference> calculix
    = {{"Shaft-Sleeve",
        42.1148,
        {0., 10., 20., 25., 28.},
        {51.4522, 49.5967, 38.2252, 29.4249, 25.5754}},
       {"Sleeve-Hub",
        27.2040,
        {0., 5., 10., 15., 18.},
        {24.9254, 25.0184, 25.5053, 27.3454, 31.3242}}};

  const std::string thin_sleeve = R"(subsection Assembly
  set Bodies = Shaft, Sleeve, Hub
end
subsection Geometry
  subsection Shaft
    set Inner diameter = 0
    set Outer diameter = 60
    set Length = 80
  end
  subsection Sleeve
    set Inner diameter = 60
    set Outer diameter = 64
    set Length = 80
  end
  subsection Hub
    set Inner diameter = 64
    set Outer diameter = 120
    set Length = 40
  end
end
subsection Material
  subsection Shaft
    set Name = C45
  end
  subsection Sleeve
    set Name = CuSn8
  end
  subsection Hub
    set Name = S355
  end
end
subsection Fit
  subsection Shaft-Sleeve
    set Diametral interference = 0
  end
  subsection Sleeve-Hub
    set Diametral interference = 0.05
  end
end
subsection Mesh
  set Axial cells = 12
  set Radial cells = 4
  set Global refinements = 1
end
)";
} // namespace

int
main()
{
  for (const std::string method : {"--set Coupling/Ordering=gauss-seidel",
                                   "--set Solver/Method=monolithic"})
    {
      std::filesystem::remove_all("run");
      const RunResult r = run_coaxfit("run", method + " " + example);
      std::cout << "stepped_rings.prm, " << method.substr(6) << ": exit "
                << r.exit_code << '\n';
      const nlohmann::json s = read_summary("run");
      for (unsigned int k = 0; k < 2; ++k)
        {
          const Reference  &ref = calculix[k];
          const std::string csv
            = "run/contact_pressure_" + std::string(ref.joint) + ".csv";
          std::cout << "  " << ref.joint << ": mean "
                    << agreement(s["joints"][k]["pressure"]["mean"],
                                 ref.mean,
                                 1e-3);
          for (unsigned int i = 0; i < ref.z.size(); ++i)
            std::cout << ", p(" << ref.z[i] << ") "
                      << agreement(pressure_at(csv, ref.z[i]), ref.p[i], 1e-3);
          std::cout << ", closed " << s["joints"][k]["contact"]["closed"]
                    << '\n';
        }
    }

  std::ofstream("thin_sleeve.prm") << thin_sleeve;
  std::vector<nlohmann::json> runs;
  for (const std::string method : {"--set Coupling/Ordering=gauss-seidel",
                                   "--set Coupling/Ordering=jacobi",
                                   "--set Solver/Method=monolithic"})
    {
      std::filesystem::remove_all("thin");
      const RunResult r = run_coaxfit("thin", method + " thin_sleeve.prm");
      runs.push_back(read_summary("thin")["joints"][0]);
      const nlohmann::json &j = runs.back();
      std::cout
        << "thin sleeve, " << method.substr(6) << ": exit " << r.exit_code
        << ", the shaft's joint open at " << j["contact"]["separated_points"]
        << " points, p(0) "
        << agreement(j["pressure"]["at_mid_plane"],
                     runs[0]["pressure"]["at_mid_plane"],
                     1e-7)
        << ", mean "
        << agreement(j["pressure"]["mean"], runs[0]["pressure"]["mean"], 1e-7)
        << " (of the first), gap left at most "
        << (j["contact"]["gap_max"].get<double>() > 1e-3 ? "above" : "below")
        << " 0.001 mm\n";
    }
  std::filesystem::remove_all("thin");
  run_coaxfit("thin", "thin_sleeve.prm");
  std::ifstream csv("thin/contact_pressure_Shaft-Sleeve.csv");
  std::string   line, last;
  std::getline(csv, line);
  bool opened_beside_hub = false;
  while (std::getline(csv, line))
    {
      std::istringstream row(line);
      std::string        z, p, c;
      std::getline(row, z, ',');
      std::getline(row, p, ',');
      std::getline(row, c, ',');
      if (std::stod(z) > 20. && std::stod(z) < 40. && c == "0")
        opened_beside_hub = true;
      last = c;
    }
  std::cout << "  beside the hub (20 < z < 40 mm) the sleeve "
            << (opened_beside_hub ? "lifts off" : "STAYS ON")
            << " the shaft; at its end (z = 40 mm) it "
            << (last == "1" ? "touches" : "is off") << '\n';

  // Against CalculiX with unilateral contact (see the top): its finest
  // mesh's figures.
  const nlohmann::json s = read_summary("thin");
  std::cout << "  against CalculiX: Shaft-Sleeve mean "
            << agreement(s["joints"][0]["pressure"]["mean"], 30.22, 1e-3);
  const std::vector<std::pair<double, double>> shaft_sleeve
    = {{0., 55.55}, {5., 55.73}, {10., 56.65}, {15., 60.70}, {18., 68.89}};
  for (const auto &[z, p] : shaft_sleeve)
    std::cout << ", p(" << z << ") "
              << agreement(pressure_at("thin/contact_pressure_Shaft-Sleeve.csv",
                                       z),
                           p,
                           3e-3);
  std::cout << "\n    Sleeve-Hub mean "
            << agreement(s["joints"][1]["pressure"]["mean"], 59.28, 3e-3);
  const std::vector<std::pair<double, double>> sleeve_hub
    = {{0., 54.65}, {5., 54.80}, {10., 55.63}, {15., 58.74}};
  for (const auto &[z, p] : sleeve_hub)
    std::cout << ", p(" << z << ") "
              << agreement(pressure_at("thin/contact_pressure_Sleeve-Hub.csv",
                                       z),
                           p,
                           1e-3);
  // Where the joint opens: between its last closed point and its first
  // open one, which must overlap CalculiX's 21.47 to 21.60 mm; the
  // largest radial gap 8.863e-4 mm (half the diametral gap).
  std::ifstream again("thin/contact_pressure_Shaft-Sleeve.csv");
  std::getline(again, line);
  double last_closed = 0., first_open = 0.;
  while (std::getline(again, line) && first_open == 0.)
    {
      std::istringstream row(line);
      std::string        z, p, c;
      std::getline(row, z, ',');
      std::getline(row, p, ',');
      std::getline(row, c, ',');
      (c == "1" ? last_closed : first_open) = std::stod(z);
    }
  std::cout << "\n    opens between z " << std::setprecision(4) << last_closed
            << " and " << first_open << ": "
            << (last_closed <= 21.60 && first_open >= 21.47 ?
                  "overlaps" :
                  "DOES NOT overlap")
            << " CalculiX's 21.47 to 21.60, largest radial gap "
            << agreement(s["joints"][0]["contact"]["gap_max"].get<double>()
                           / 2.,
                         8.863e-4,
                         2e-2)
            << '\n';
}
