// The figures of a run of the executable that the section tests compare:
// summary.json's pressures and contact_pressure.csv's profile.
#ifndef coaxfit_tests_run_summary_h
#define coaxfit_tests_run_summary_h

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit_test
{
  /** The largest difference of @p a and @p b over the largest of @p b. */
  inline double
  difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0., scale = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        d     = std::max(d, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
    return d / scale;
  }

  /** summary.json of the run in @p directory (null if there is none). */
  inline nlohmann::json
  read_summary(const std::string &directory)
  {
    std::ifstream in(directory + "/summary.json");
    if (!in)
      return nlohmann::json();
    return nlohmann::json::parse(in);
  }

  /** "agrees" within @p tolerance (relative), else the deviation. */
  inline std::string
  agreement(const double value, const double expected, const double tolerance)
  {
    const double deviation = std::abs(value / expected - 1.);
    if (deviation <= tolerance)
      return "agrees";
    std::ostringstream s;
    s << "DIFFERS by " << std::setprecision(3) << 100. * deviation << " %";
    return s.str();
  }

  /**
   * The Fit and Material subsections of a test scene: U = 0.05 mm, a steel
   * shaft (E 210000 MPa, nu 0.3) and a hub of @p E_hub (MPa) and @p nu_hub.
   */
  inline std::string
  fit_and_materials(const std::string &E_hub, const std::string &nu_hub)
  {
    return "subsection Fit\n"
           "  set Diametral interference = 0.05\n"
           "end\n"
           "subsection Material\n"
           "  subsection Shaft\n"
           "    set E = 210000\n"
           "    set nu = 0.3\n"
           "  end\n"
           "  subsection Hub\n"
           "    set E = "
           + E_hub + "\n    set nu = " + nu_hub
           + "\n"
             "  end\n"
             "end\n";
  }

  /** The comma-separated fields of @p line (no quoting). */
  inline std::vector<std::string>
  csv_fields(const std::string &line)
  {
    std::istringstream       f(line);
    std::vector<std::string> fields;
    for (std::string field; std::getline(f, field, ',');)
      fields.push_back(field);
    return fields;
  }

  /**
   * The fields of the first line of the CSV file @p file that begins with
   * @p start; empty if none does.
   */
  inline std::vector<std::string>
  csv_row(const std::string &file, const std::string &start)
  {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
      if (line.rfind(start, 0) == 0)
        return csv_fields(line);
    return {};
  }

  /** Options that keep a test run to summary.json and the CSV files. */
  inline const std::string quiet
    = " --set \"Output/Write vtu=false\" --set \"Output/Write plots=false\" ";

  /** p at @p z, linear between the points (z, p) of @p profile. */
  inline double
  profile_at(const std::vector<std::pair<double, double>> &profile,
             const double                                  z)
  {
    for (unsigned int i = 1; i < profile.size(); ++i)
      if (profile[i].first >= z)
        {
          const auto &[z0, p0] = profile[i - 1];
          const auto &[z1, p1] = profile[i];
          return p0 + (p1 - p0) * (z - z0) / (z1 - z0);
        }
    return NAN;
  }

  /** The pressures of every joint of a stack's summary (middle, mean). */
  inline std::vector<double>
  joint_pressures(const nlohmann::json &summary)
  {
    std::vector<double> p;
    for (const auto &j : summary["joints"])
      {
        p.push_back(j["pressure"]["at_mid_plane"]);
        p.push_back(j["pressure"]["mean"]);
      }
    return p;
  }

  struct Result
  {
    int                                    exit_code;
    double                                 mean = 0., at_mid_plane = 0.;
    std::string                            coupling; ///< of the joint
    std::vector<std::pair<double, double>> profile;  // z, p
    nlohmann::json                         summary;  ///< summary.json
    /** p at @p z, linear between the points of contact_pressure.csv. */
    double
    at(const double z) const
    {
      return profile_at(profile, z);
    }
  };

  inline Result
  run(const std::string &dir, const std::string &arguments)
  {
    std::filesystem::remove_all(dir);
    Result result;
    result.exit_code
      = coaxfit_test::run_coaxfit(dir, quiet + arguments).exit_code;
    std::ifstream in(dir + "/summary.json");
    if (!in)
      return result;
    const auto summary  = nlohmann::json::parse(in);
    result.mean         = summary["pressure"]["mean"];
    result.at_mid_plane = summary["pressure"]["at_mid_plane"];
    if (summary["mesh"].contains("joint_coupling"))
      result.coupling = summary["mesh"]["joint_coupling"];
    result.summary = summary;
    std::ifstream csv(dir + "/contact_pressure.csv");
    std::string   line;
    std::getline(csv, line);
    while (std::getline(csv, line))
      {
        std::istringstream row(line);
        std::string        z, p;
        std::getline(row, z, ',');
        std::getline(row, p, ',');
        result.profile.emplace_back(std::stod(z), std::stod(p));
      }
    return result;
  }

  inline bool
  close(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance * std::abs(b);
  }


  /** The largest difference of two pressure profiles over the largest. */
  inline double
  profile_difference(const Result &a, const Result &b)
  {
    if (a.profile.size() != b.profile.size() || a.profile.empty())
      return INFINITY;
    double difference = 0., largest = 0.;
    for (unsigned int i = 0; i < a.profile.size(); ++i)
      {
        difference
          = std::max(difference,
                     std::abs(a.profile[i].second - b.profile[i].second));
        largest = std::max(largest, std::abs(b.profile[i].second));
      }
    return difference / largest;
  }

  /** The fits a stack's selection chose (summary.json), joined by " + ". */
  inline std::string
  fits_of(const nlohmann::json &j)
  {
    std::string text;
    for (const auto &joint : j["selection"]["joints"])
      text += (text.empty() ? "" : " + ") + joint["fit"].get<std::string>();
    return text;
  }
} // namespace coaxfit_test

#endif
