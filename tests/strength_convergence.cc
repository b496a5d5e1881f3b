// The strength figure converges under refinement, the corner does not: the
// example prm/examples/steel_hub_H7s6.prm (case mean) is run at Mesh/Global
// refinements 0 to 3. Printed per level: the largest von Mises stress of
// hub bore and shaft surface over the middle half of the joint (the
// strength figure behind the yield safeties, away from the singular ends)
// and the stress at the end of the joint (the corner). Between levels the
// strength figure changes less and less (a convergent sequence; its
// changes shrink by a factor printed), the corner value keeps growing
// (a singularity: it has no limit). DIN 7190's Lame value at the bore is
// printed beside the hub's figure: a hub shorter than the shaft is
// squeezed harder towards its ends, so the FE figure lies above it.

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

int
main()
{
  std::vector<double> hub, shaft, corner;
  std::cout << std::setprecision(6);
  for (unsigned int level = 0; level <= 3; ++level)
    {
      const std::string dir = "level_" + std::to_string(level);
      std::filesystem::remove_all(dir);
      const auto run = coaxfit_test::run_coaxfit(
        dir,
        "--set \"Output/Write vtu=false\" --set \"Output/Write plots=false\" "
        "--set Fit/Case=mean --set \"Mesh/Global refinements="
          + std::to_string(level) + "\" " + std::string(COAXFIT_SOURCE_DIR)
          + "/prm/examples/steel_hub_H7s6.prm");
      std::ifstream in(dir + "/summary.json");
      const auto    summary = nlohmann::json::parse(in);
      const auto   &design  = summary["design"];
      hub.push_back(design["strength_stress_hub"].get<double>());
      shaft.push_back(design["strength_stress_shaft"].get<double>());
      corner.push_back(
        design["surface_maxima"]["hub bore"]["at_joint_end_singular"]
          .get<double>());
      std::cout
        << "level " << level << " (exit code " << run.exit_code
        << "): strength figure hub " << hub.back() << " MPa (DIN 7190 "
        << design["check_points_mid_plane"]["hub bore"]["din"]["equivalent"]
             .get<double>()
        << "), shaft " << shaft.back() << " MPa; at the end of the "
        << "joint, hub bore " << corner.back() << " MPa\n";
    }
  for (unsigned int level = 2; level <= 3; ++level)
    {
      const auto ratio = [level](const std::vector<double> &v) {
        return std::abs(v[level - 1] - v[level - 2])
               / std::abs(v[level] - v[level - 1]);
      };
      std::cout << std::setprecision(3) << "levels " << level - 2 << "-"
                << level << ": changes of the strength figure shrink by x"
                << ratio(hub) << " (hub), x" << ratio(shaft)
                << " (shaft) per level; the corner value grows by x"
                << corner[level] / corner[level - 1] << '\n';
    }
  std::cout << "strength figure, hub, levels 2 to 3: relative change "
            << std::abs(hub[3] - hub[2]) / hub[3] << '\n';
}
