// Solver/Linear solver = amg (conjugate gradients with Trilinos' algebraic
// multigrid) against the direct solver (CHOLMOD): the same contact answer
// to the accuracy of the iteration, on the Lame case (187.5 MPa exactly)
// and on a thin tube that separates (variant 14: the same active set).
// auto picks the direct solver where its memory fits; amg with the
// monolithic method or the condensed interface operator is refused.

#include "run_executable.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace
{
  nlohmann::json
  run(const std::string &directory, const std::string &arguments)
  {
    std::filesystem::remove_all(directory);
    const coaxfit_test::RunResult r = coaxfit_test::run_command(
      "timeout 300 " + std::string(coaxfit_test::coaxfit_executable)
      + " --quiet --set Output/Directory=" + directory + " " + arguments
      + " 2>&1 >/dev/null");
    if (r.exit_code != 0)
      {
        std::cout << "  exit code " << r.exit_code << ": " << r.message;
        return {};
      }
    std::ifstream in(directory + "/summary.json");
    return nlohmann::json::parse(in);
  }

  std::string
  agreement(const double a, const double b)
  {
    const double e = std::abs(a - b) / std::abs(b);
    for (const double bound : {1e-10, 1e-8, 1e-6, 1e-4})
      if (e < bound)
        {
          std::ostringstream s;
          s << "below " << bound;
          return s.str();
        }
    return "NOT within 1e-4 (" + std::to_string(e) + ")";
  }
} // namespace



int
main()
{
  const std::string prm = std::string(COAXFIT_SOURCE_DIR) + "/prm/";
  for (const std::string name : {"lame", "variant_14"})
    {
      const std::string common
        = "--set 'Mesh/Global refinements=0' " + prm + name + ".prm";
      const nlohmann::json direct
        = run("direct_" + name,
              "--set 'Solver/Linear solver=direct' " + common);
      const nlohmann::json amg
        = run("amg_" + name, "--set 'Solver/Linear solver=amg' " + common);
      if (direct.empty() || amg.empty())
        continue;
      std::cout << name << ": linear solvers "
                << direct["solver"]["linear_solver"] << " and "
                << amg["solver"]["linear_solver"] << '\n'
                << "  amg against direct: p(0) "
                << agreement(amg["pressure"]["at_mid_plane"].get<double>(),
                             direct["pressure"]["at_mid_plane"].get<double>())
                << ", mean "
                << agreement(amg["pressure"]["mean"].get<double>(),
                             direct["pressure"]["mean"].get<double>())
                << ", separated length " << amg["contact"]["separated_length"]
                << " and " << direct["contact"]["separated_length"] << " mm\n"
                << "  converged: " << amg["converged"] << ", CG iterations "
                << (amg["solver"]["solves"]["shaft_cg_iterations"].get<int>()
                        > 0 ?
                      "counted" :
                      "MISSING")
                << '\n';
      if (name == "lame")
        std::cout << "  amg against Lame (187.5 MPa): "
                  << agreement(amg["pressure"]["mean"].get<double>(), 187.5)
                  << '\n';
    }

  const nlohmann::json automatic
    = run("auto_lame", "--set 'Mesh/Global refinements=0' " + prm + "lame.prm");
  std::cout << "auto on a small mesh: " << automatic["solver"]["linear_solver"]
            << '\n';
  std::cout << "amg with the monolithic method:\n";
  run("refused_1",
      "--set 'Solver/Linear solver=amg' --set Solver/Method=monolithic " + prm
        + "lame.prm");
  std::cout << "amg with the condensed interface operator:\n";
  run("refused_2",
      "--set 'Solver/Linear solver=amg' --set 'Coupling/Interface "
      "operator=condensed' "
        + prm + "lame.prm");
}
