// Capacity from the finite element pressure against the hand integral of
// contact_pressure.csv: the example prm/examples/steel_hub_H7s6.prm (all
// three cases of the fit H7/s6) is run through the executable; for each
// case the normal force N = 2 * 2 pi R_F int_0^{l/2} p dz is integrated by
// Simpson's rule over the quadratic elements (three nodes each, as the
// file lists them) and the torque mu R_F N and axial force mu N must equal
// summary.json's and fit_cases.csv's to round-off. DIN 7190's figures of
// the same case and their ratio to the FE figures are printed (the end
// effects of a hub shorter than the shaft raise the FE mean pressure by a
// few per cent).

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /** Columns z_mm and pressure_MPa of contact_pressure.csv. */
  std::vector<std::pair<double, double>>
  read_pressure(const std::string &file)
  {
    std::ifstream                          in(file);
    std::string                            line;
    std::vector<std::pair<double, double>> points;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        std::string        z, p;
        std::getline(row, z, ',');
        std::getline(row, p, ',');
        points.emplace_back(std::stod(z), std::stod(p));
      }
    return points;
  }

  std::string
  agreement(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-9 * std::abs(b) ? "equal (< 1e-9)" :
                                                   "DIFFERENT";
  }
} // namespace



int
main()
{
  const std::string dir = "capacity";
  std::filesystem::remove_all(dir);
  const auto run = coaxfit_test::run_coaxfit(
    dir,
    "--set \"Output/Write vtu=false\" --set \"Output/Write plots=false\" "
      + std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/steel_hub_H7s6.prm");
  std::cout << "steel_hub_H7s6.prm: exit code " << run.exit_code << '\n';

  std::ifstream table_file(dir + "/fit_cases.csv");
  std::string   header, row;
  std::getline(table_file, header);
  for (const std::string c : {"min", "mean", "max"})
    {
      std::ifstream in(dir + "/" + c + "/summary.json");
      const auto    summary = nlohmann::json::parse(in);
      const auto   &design  = summary["design"];
      const double  R_F     = summary["geometry"]["R1"];
      const double  mu      = design["friction_coefficient"];
      const auto    points
        = read_pressure(dir + "/" + c + "/contact_pressure.csv");
      double integral = 0.;
      for (std::size_t k = 0; k + 2 < points.size(); k += 2)
        integral += (points[k + 2].first - points[k].first) / 6.
                    * (points[k].second + 4. * points[k + 1].second
                       + points[k + 2].second);
      const double N      = 4. * M_PI * R_F * integral;
      const double torque = 1e-3 * mu * R_F * N;
      std::getline(table_file, row);
      std::istringstream       fields(row);
      std::string              field;
      std::vector<std::string> values;
      while (std::getline(fields, field, ','))
        values.push_back(field);
      const double table_torque = std::stod(values.at(8));

      std::cout
        << std::setprecision(5) << c
        << ": U = " << summary["fit"]["U_used"].get<double>() << " mm, "
        << points.size() << " interface points\n"
        << "  torque by Simpson " << torque << " N m, summary.json "
        << agreement(design["torque_capacity"].get<double>(), torque)
        << ", fit_cases.csv "
        << (c == values.at(0) ? agreement(table_torque, torque) : "WRONG ROW")
        << "\n  axial force by Simpson " << mu * N << " N, summary.json "
        << agreement(design["axial_force_capacity"].get<double>(), mu * N)
        << "\n  DIN 7190: torque "
        << design["torque_capacity_din"].get<double>() << " N m, FE/DIN "
        << torque / design["torque_capacity_din"].get<double>() << '\n';
    }
}
