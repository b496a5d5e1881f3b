// Design/Mode = select on a taper fit: the band of push-on distances.
//
// prm/examples/taper_fit.prm (steel shaft end with a taper 1:10, C = 0.1,
// steel hub D_aA 100 mm on it from z = 5 to 45: l_F 40 mm, D_F 47.5 mm at
// the cone's middle; E 210000, nu 0.3) asked to carry 1500 N m (K_A 1,
// slip safety 1, mu 0.14 of DIN 7190 for steel on steel) with both parts'
// yield strength 350 MPa (yield safety 1).
//
// 1. DIN 7190's ends by hand (plane-stress Lame rings at D_F, Q = 0.475,
//    tan(beta) = C / 2), the hub held on the cone by friction alone
//    (Coulomb: the friction force in the cone's surface at most mu N, N the
//    normal force; the cone pushes the hub off with N sin(beta), so the
//    friction along the generatrix carries (N sin(beta) + F) / cos(beta)
//    of a pull F, and the torque's circumferential force 2 T / D_F =
//    63157.9 N adds to it as a vector): for the torque alone N = 2 T / D_F
//    / sqrt(mu^2 - tan^2) = 482980 N, p = N cos / (pi D_F l_F) = 80.8135
//    MPa, U_w = 2 D_F p / (E (1 - Q^2)) = 0.0472103 mm, a_min = U / C =
//    0.472103 mm; the hub bore's von Mises p sqrt(3 + Q^4) / (1 - Q^2) =
//    350 MPa gives U_max = 2 D_F R_e / (E sqrt(3 + Q^4)) = 0.0906479 mm,
//    a_max = 0.906479 mm. With 1000 N m and a pull of 20000 N together,
//    N is found here by bisection of the friction condition.
//    Required: to 1e-5 (the selection bisects its own closed forms).
// 2. The finite element ends checked by running the example in check mode
//    at them (Fit/Push-on distance a_min and a_max): the governing safety
//    must be the required one to 0.5 % and not below it; and by the
//    linearity of the assembled state in a (the contact stays closed): the
//    check run at a = 0.5 mm predicts a_min = 0.5 / S_slip(0.5) and a_max =
//    0.5 S_yield(0.5), within 0.2 %.
// 3. The case study of the band (subdirectories min, mean, max): push-on
//    distances a_min, the middle, a_max; verdict OK; the min case's
//    parameters.prm repeats it to the last digit.
// 4. Without yield strengths the model's limit ends the band (a <= l_F /
//    10 = 4 mm); a torque no push-on distance carries within yield (3500 N
//    m) is a conflict (exit 0, the verdict says so), so is a taper 3:10
//    with mu = 0.14 (not self-locking); bad input (a push-on distance
//    beyond the limit, an interference given): exit 1.

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

namespace
{
  const std::string quiet = " --set \"Output/Write vtu=false\" --set "
                            "\"Output/Write plots=false\" --set "
                            "\"Output/Print timing=false\" ";

  const std::string taper
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/taper_fit.prm";

  const std::string design_strengths
    = " --set \"Material/Hub/Yield strength=350\" --set "
      "\"Material/Shaft/Yield strength=350\" ";

  const std::string design
    = " --set \"Design/Required torque=1500\"" + design_strengths;

  using coaxfit_test::read_summary;

  using coaxfit_test::agreement;

  /** A check-mode run of the example pushed on by @p a (mm). */
  nlohmann::json
  check_at(const std::string &dir, const double a)
  {
    std::ostringstream value;
    value << std::setprecision(17) << a;
    std::filesystem::remove_all(dir);
    coaxfit_test::run_coaxfit(dir,
                              "--set \"Fit/Push-on distance=" + value.str()
                                + "\"" + design + quiet + taper);
    return read_summary(dir);
  }

  /** Whether a safety is the required 1 to 0.5 % and not below it. */
  std::string
  at_required(const double safety)
  {
    return safety >= 1. && safety <= 1.005 ? "at the required 1" :
                                             "NOT at the required 1";
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);

  // 1. DIN 7190's ends by hand.
  const double D = 47.5, l = 40., E = 210000., C = 0.1, mu = 0.14;
  const double Q = D / 100., R_e = 350., T = 1500.;
  const double tan_b = C / 2., cos_b = 1. / std::sqrt(1. + tan_b * tan_b),
               sin_b = tan_b * cos_b;
  // The push-on distance of the normal force N (N).
  const auto a_of = [&](const double N) {
    const double p = N * cos_b / (M_PI * D * l);
    return 2. * D * p / (E * (1. - Q * Q)) / C;
  };
  const double a_min_din
    = a_of(2e3 * T / D / std::sqrt(mu * mu - tan_b * tan_b));
  const double a_max_din
    = 2. * D * R_e / (E * std::sqrt(3. + Q * Q * Q * Q)) / C;
  // Torque and pull together: the least N whose friction holds both.
  const double f_c = 2e3 * 1000. / D, pull = 20000.;
  double       lo = 0., hi = 1e8;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double N                             = 0.5 * (lo + hi);
      const double f_g                           = (N * sin_b + pull) / cos_b;
      (std::hypot(f_g, f_c) <= mu * N ? hi : lo) = N;
    }
  const double a_min_combined_din = a_of(hi);

  const std::string dir = "select_taper";
  std::filesystem::remove_all(dir);
  const coaxfit_test::RunResult r = coaxfit_test::run_coaxfit(
    dir,
    "--set Design/Mode=select --set \"Fit/Push-on distance=0\"" + design + quiet
      + taper);
  const nlohmann::json s = read_summary(dir);
  const nlohmann::json b = s["selection"]["push_on"];
  std::cout << "taper_fit.prm selected (exit code " << r.exit_code
            << "), taper C = " << b["taper"].get<double>() << ":\n"
            << "  a_min_din " << b["a_min_din"].get<double>() << " mm, by hand "
            << a_min_din << ": "
            << agreement(b["a_min_din"].get<double>(), a_min_din, 1e-5) << '\n'
            << "  a_max_din " << b["a_max_din"].get<double>() << " mm, by hand "
            << a_max_din << ": "
            << agreement(b["a_max_din"].get<double>(), a_max_din, 1e-5) << '\n';

  {
    const std::string d = "select_taper_combined";
    std::filesystem::remove_all(d);
    const coaxfit_test::RunResult rc = coaxfit_test::run_coaxfit(
      d,
      "--set Design/Mode=select --set \"Design/Required torque=1000\" --set "
      "\"Design/Required axial force=20000\""
        + design_strengths + quiet + taper);
    const double a = read_summary(d)["selection"]["push_on"]["a_min_din"];
    std::cout << "  1000 N m and 20000 N (exit code " << rc.exit_code
              << "): a_min_din " << a << " mm, by hand " << a_min_combined_din
              << ": " << agreement(a, a_min_combined_din, 1e-5) << '\n';
  }

  // 2. The finite element ends.
  const double a_min = b["a_min"].get<double>(),
               a_max = b["a_max"].get<double>();
  std::cout
    << std::setprecision(4) << "  FE band: a from " << a_min << " to " << a_max
    << " mm (governed by "
    << s["selection"]["governing"]["U_min"]["criterion"].get<std::string>()
    << " and "
    << s["selection"]["governing"]["U_max"]["criterion"].get<std::string>()
    << ")\n";
  const nlohmann::json at_min = check_at("check_taper_a_min", a_min);
  const nlohmann::json at_max = check_at("check_taper_a_max", a_max);
  std::cout << "  check at a_min: safety against slip "
            << at_required(at_min["design"]["safety_slip"].get<double>())
            << "\n  check at a_max: safety against yield of the hub "
            << at_required(
                 at_max["design"]["safety_yield_hub_assembly"].get<double>())
            << '\n';
  const nlohmann::json at_half = check_at("check_taper_a_0.5", 0.5);
  const double         predicted_min
    = 0.5 / at_half["design"]["safety_slip"].get<double>();
  const double predicted_max
    = 0.5 * at_half["design"]["safety_yield_hub_assembly"].get<double>();
  std::cout << "  linear in a from the check at a = 0.5 mm: a_min "
            << agreement(a_min, predicted_min, 2e-3) << ", a_max "
            << agreement(a_max, predicted_max, 2e-3) << '\n'
            << "  FE against DIN 7190's plain-cylinder estimate: a_min x "
            << a_min / b["a_min_din"].get<double>() << ", a_max x "
            << a_max / b["a_max_din"].get<double>() << '\n';

  // 3. The case study of the band.
  std::cout << "  cases:";
  for (const std::string c : {"min", "mean", "max"})
    {
      const nlohmann::json cs = read_summary(dir + "/" + c);
      std::cout << ' ' << c
                << " a = " << cs["taper"]["push_on_distance"].get<double>()
                << " mm ("
                << (cs["verdict"]["ok"].get<bool>() ? "OK" : "FAILED") << ")";
    }
  std::cout << "\n  verdict ok: " << s["verdict"]["ok"].get<bool>() << '\n';
  {
    // The min case's parameters.prm repeats it to the last digit.
    const std::string d = "repeat_taper_min";
    std::filesystem::remove_all(d);
    coaxfit_test::run_coaxfit(d, quiet + dir + "/min/parameters.prm");
    std::cout << "  min/parameters.prm repeats the min case: "
              << (read_summary(d)["pressure"]["mean"]
                      == read_summary(dir + "/min")["pressure"]["mean"] ?
                    "yes, to the last digit" :
                    "NO")
              << '\n';
  }

  // 4. The model's limit, a conflict, bad input.
  {
    const std::string d = "select_taper_limit";
    std::filesystem::remove_all(d);
    const coaxfit_test::RunResult l_run = coaxfit_test::run_coaxfit(
      d,
      "--set Design/Mode=select --set \"Design/Required torque=1500\"" + quiet
        + taper);
    const nlohmann::json ls = read_summary(d)["selection"];
    std::cout << "no yield strengths (exit code " << l_run.exit_code
              << "): a_max " << ls["push_on"]["a_max"].get<double>()
              << " mm, governed by "
              << ls["governing"]["U_max"]["criterion"].get<std::string>()
              << '\n';
  }
  {
    const std::string d = "select_taper_conflict";
    std::filesystem::remove_all(d);
    const coaxfit_test::RunResult c_run = coaxfit_test::run_coaxfit(
      d,
      "--set Design/Mode=select --set \"Design/Required torque=3500\" --set "
      "\"Material/Hub/Yield strength=350\""
        + quiet + taper);
    const nlohmann::json cs = read_summary(d);
    std::cout << "3500 N m (exit code " << c_run.exit_code << "): verdict ok "
              << cs["verdict"]["ok"].get<bool>() << ", conflict: "
              << cs["selection"]["conflict"].get<std::string>() << '\n';
  }
  {
    // A taper 3:10: tan(beta) = 0.15 > mu = 0.14, not self-locking.
    const std::string d = "select_taper_steep";
    std::filesystem::remove_all(d);
    const coaxfit_test::RunResult s_run = coaxfit_test::run_coaxfit(
      d,
      "--set Design/Mode=select --set \"Design/Required torque=1500\" --set "
      "\"Geometry/Shaft section=0,0; 150,0; 150,50; 40,50; 0,38; 0,0\" "
      "--set \"Geometry/Hub section=5,39.5; 35,48.5; 35,100; 5,100; "
      "5,39.5\""
        + design_strengths + quiet + taper);
    const nlohmann::json ss = read_summary(d);
    std::cout
      << "taper 3:10 (exit code " << s_run.exit_code << "): verdict ok "
      << ss["verdict"]["ok"].get<bool>() << ", conflict: "
      << coaxfit_test::gist(ss["selection"]["conflict"].get<std::string>(), 12)
      << '\n';
  }
  for (const std::string bad : {"--set \"Fit/Push-on distance=5\"",
                                "--set \"Fit/Diametral interference=0.05\""})
    {
      const std::string d = "select_taper_bad";
      std::filesystem::remove_all(d);
      const coaxfit_test::RunResult b_run = coaxfit_test::run_coaxfit(
        d,
        "--set Design/Mode=select --set \"Design/Required torque=1500\" " + bad
          + quiet + taper);
      std::cout << "exit code " << b_run.exit_code << ", written "
                << std::filesystem::exists(d) << ": "
                << coaxfit_test::gist(b_run.message, 14) << '\n';
    }
}
