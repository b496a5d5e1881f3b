// Design/Mode = select on the three shipped designs, against hand
// calculations (DIN 7190, plane stress Lame rings; K = ((1 + Q^2)/(1 - Q^2)
// + nu_A)/E_A + (1 - nu_I)/E_I for a solid shaft, smoothing loss 0.8 (Rz_I
// + Rz_A)), and the finite element ends checked by running each design in
// check mode at them: the governing safety must then be the required one
// (1 in these files) to 0.5 %.
//
// steel_hub_H7s6 (D_F 40, D_aA 80: Q 0.5, l 40 mm, E 210000, nu 0.3, mu
// 0.12 by pressure oil, 150 N m x K_A 1.25, Rz 4 + 6.3 um, hub R_e 345):
// p_min = 1.25 x 7500 N / (0.12 pi 40 x 40 mm^2) = 15.5423 MPa, K =
// 2.66667 / 210000 = 1.26984e-5 1/MPa, U_min_din = p D K + 0.00824 =
// 0.0161346 mm; the hub bore's von Mises 1.75 / 0.75 p = 345 MPa gives p =
// 147.857 MPa, U_max_din = 0.0833420 mm.
// aluminium_hub_at_120C (D_F 50, D_aA 90, l 30, 42CrMo4 shaft, EN AW-6082
// T6 hub: E 70000, nu 0.33, R_e 250, alpha 23.4e-6 against the shaft's
// 11.5e-6, both at 120 C; mu 0.10; 300 N m and 2000 N x 1.25; Rz 2.5 +
// 6.3): resultant 1.25 sqrt(2000^2 + 12000^2) = 15206.9 N, p = 32.2701
// MPa, K = 2.22286 / 70000 + 0.7 / 210000 = 3.50884e-5, the hub's thermal
// loosening 50 (23.4 - 11.5) 1e-6 x 100 = 0.0595 mm: U_min_din (in
// service) = 0.0566159 + 0.0595 + 0.00704 = 0.123156 mm; at assembly the
// hub bore's von Mises 2.54475 p = 250 MPa gives U_max_din = 0.179397 mm.
// rotor_hub_at_speed (D_F 80, D_aA 200: Q 0.4, l 50, steel, 6000 1/min,
// density 7850, mu 0.12, 400 N m x 1.25, Rz 2.5 + 4, hub R_e 500): the
// rotating discs (plane stress) loosen the joint by 2 (u_hub - u_shaft) =
// 0.00973989 mm (rho omega^2 = 3.09906e-3 N/mm^4); p = 8.28932 MPa, K =
// 2.38095 / 210000: U_min_din (in service) = 0.00751865 + 0.00973989 +
// 0.0052 = 0.0224585 mm; in service the hub bore carries the rotation's
// hoop stress 26.435 MPa besides the pressure's, and its von Mises = 500
// MPa at p = 229.804 MPa gives U_max_din = 0.223379 mm (at assembly
// 0.224210 mm: service governs).
// The first fits by hand from ISO 286-2: H7/u6 at 40 mm (H7 +25/0, u6 over
// 30 to 40 mm +76/+60) gives 35 to 76 um; at 80 mm (H7 +30/0, u6 over 65
// to 80 mm +121/+102) 72 to 121 um. The aluminium hub's band (U_min 0.1224
// to U_max 0.178 mm, 56 um) holds no ISO fit of 50 mm: the run says so.
#include "run_executable.h"
#include "run_summary.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

namespace
{
  const std::string quiet = " --set \"Output/Write vtu=false\" --set "
                            "\"Output/Write plots=false\" --set "
                            "\"Output/Print timing=false\" ";

  using coaxfit_test::read_summary;

  using coaxfit_test::agreement;

  /**
   * The safety of the criterion @p criterion in state @p state from the
   * check-mode summary @p s.
   */
  double
  safety(const nlohmann::json &s,
         const std::string    &criterion,
         const std::string    &state)
  {
    const nlohmann::json &d = s["design"];
    if (criterion == "slip")
      return d["safety_slip"].get<double>();
    const std::string part
      = criterion.find("hub") != std::string::npos ? "hub" : "shaft";
    return d["safety_yield_" + part
             + (state == "at assembly" ? "_assembly" : "")]
      .get<double>();
  }

  void
  check(const std::string &name, const double U_min_din, const double U_max_din)
  {
    const std::string file
      = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/" + name + ".prm";
    const std::string dir = "select_" + name;
    std::filesystem::remove_all(dir);
    const coaxfit_test::RunResult r
      = coaxfit_test::run_coaxfit(dir,
                                  "--set Design/Mode=select" + quiet + file);
    const nlohmann::json s = read_summary(dir)["selection"];
    std::cout << name << " (exit code " << r.exit_code << "):\n"
              << std::setprecision(6) << "  U_min_din "
              << s["U_min_din"].get<double>() << " mm, by hand " << U_min_din
              << ": "
              << agreement(s["U_min_din"].get<double>(), U_min_din, 1e-5)
              << "\n  U_max_din " << s["U_max_din"].get<double>()
              << " mm, by hand " << U_max_din << ": "
              << agreement(s["U_max_din"].get<double>(), U_max_din, 1e-5)
              << '\n';
    for (const std::string end : {"U_min", "U_max"})
      {
        const double          U         = s[end].get<double>();
        const nlohmann::json &g         = s["governing"][end];
        const std::string     criterion = g["criterion"].get<std::string>();
        const std::string     state     = g["state"].get<std::string>();
        const std::string     check_dir = "check_" + name + "_" + end;
        std::filesystem::remove_all(check_dir);
        std::ostringstream interference;
        interference << std::setprecision(17) << U;
        const coaxfit_test::RunResult c = coaxfit_test::run_coaxfit(
          check_dir,
          "--set \"Fit/ISO fit=\" --set Fit/Case=mean --set \"Fit/Diametral "
          "interference="
            + interference.str() + "\"" + quiet + file);
        const double S = safety(read_summary(check_dir), criterion, state);
        std::cout << "  " << end << " (FE) " << std::setprecision(5) << U
                  << " mm, governed by " << criterion << " " << state
                  << "; in check mode there (exit code " << c.exit_code
                  << ") its safety " << std::setprecision(4) << S
                  << ", required 1: " << agreement(S, 1., 5e-3) << '\n';
      }
    std::cout << "  fits: " << s["fits"].size();
    if (!s["fits"].empty())
      std::cout << ", the first " << s["fits"][0]["fit"].get<std::string>()
                << " (" << s["fits"][0]["U_min"].get<double>() << " to "
                << s["fits"][0]["U_max"].get<double>() << " mm)";
    std::cout << '\n';
  }
} // namespace



int
main()
{
  check("steel_hub_H7s6", 0.0161346, 0.0833420);
  check("aluminium_hub_at_120C", 0.123156, 0.179397);
  check("rotor_hub_at_speed", 0.0224585, 0.223379);
}
