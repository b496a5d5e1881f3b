// A stack of two bodies is the two-body problem: the paper's variant 17 (a
// thin tube, wall 1.2 mm, in a shorter hub: the joint opens near the hub's
// end) run as prm/variant_17.prm through the two-body code (its scene,
// ContactInterface, StaggeredCoupling) and as Assembly/Bodies = Shaft, Hub
// through the stack code (StackFit, StackCoupling in both orderings,
// solve_stack_contact). The two build the same meshes, so they must agree
// to round-off and the solvers' tolerance: p(0), mean and max and the
// pressure at every point of the joint, the points that opened.

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
  const std::string stack_prm = R"(subsection Assembly
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

  /** Column @p column of a CSV file (after its header). */
  std::vector<double>
  csv_column(const std::string &file, const unsigned int column)
  {
    std::ifstream       in(file);
    std::string         line;
    std::vector<double> values;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        std::string        cell;
        for (unsigned int c = 0; c <= column; ++c)
          std::getline(row, cell, ',');
        values.push_back(std::stod(cell));
      }
    return values;
  }
} // namespace

int
main()
{
  std::ofstream("variant_17_stack.prm") << stack_prm;
  const std::string quiet_run = "--set 'Output/Write vtu=false' ";
  RunResult         r
    = run_coaxfit("two_body",
                  quiet_run + "--set 'Output/Write plots=false' "
                    + std::string(COAXFIT_SOURCE_DIR) + "/prm/variant_17.prm");
  std::cout << "variant_17.prm (two-body code): exit " << r.exit_code << '\n';
  const nlohmann::json two    = read_summary("two_body");
  const double         p0     = two["pressure"]["at_mid_plane"];
  const double         mean   = two["pressure"]["mean"];
  const double         max    = two["pressure"]["max"];
  const auto           z_two  = csv_column("two_body/contact_pressure.csv", 0);
  const auto           p_two  = csv_column("two_body/contact_pressure.csv", 1);
  unsigned int         n_open = 0;
  for (const double p : p_two)
    n_open += (p == 0.);
  std::cout << "  p(0) " << p0 << " MPa, mean " << mean << " MPa, max " << max
            << " MPa, " << n_open << " of " << p_two.size() << " points open\n";

  for (const std::string method : {"--set Coupling/Ordering=gauss-seidel",
                                   "--set Coupling/Ordering=jacobi",
                                   "--set Solver/Method=monolithic"})
    {
      std::filesystem::remove_all("stack");
      r = run_coaxfit("stack", quiet_run + method + " variant_17_stack.prm");
      const nlohmann::json s   = read_summary("stack")["joints"][0];
      const std::string    csv = "stack/contact_pressure_Shaft-Hub.csv";
      const auto           z   = csv_column(csv, 0);
      const auto           p   = csv_column(csv, 1);
      double               dz = 0., dp = 0.;
      for (unsigned int i = 0; i < std::min(z.size(), z_two.size()); ++i)
        {
          dz = std::max(dz, std::abs(z[i] - z_two[i]));
          dp = std::max(dp, std::abs(p[i] - p_two[i]));
        }
      std::cout << "stack, " << method.substr(6) << ": exit " << r.exit_code
                << "\n  p(0) "
                << agreement(s["pressure"]["at_mid_plane"], p0, 1e-8)
                << ", mean " << agreement(s["pressure"]["mean"], mean, 1e-8)
                << ", max " << agreement(s["pressure"]["max"], max, 1e-8)
                << "; " << s["contact"]["separated_points"] << " points open"
                << "; the same " << z.size() << " points "
                << (z.size() == z_two.size() && dz < 1e-9 ? "yes" : "NO")
                << ", their pressures within 1e-8 of the peak "
                << (dp < 1e-8 * max ? "yes" : "NO") << '\n';
    }
}
