// Design/Mode = select for a stack: the ISO fits of all joints chosen
// together, checked against the plane-stress closed form.
//
// Three rings of equal length (a steel shaft, a bronze sleeve, an
// aluminium hub) with frictionless joints are each in a plane-stress Lame
// state, so the compound cylinders (CompoundCylinders, tested on its own
// against an independent flexibility-method solution) are exact in the FE
// limit. The hub runs 25 K warmer in service, which takes 23e-6 * 25 * 90
// = 0.05175 mm off the Sleeve-Hub joint. The test
// 1. judges every combination of the same candidate fits (ISO 286, the
//    library's tables) by the closed form at every corner of their bands
//    in both states (slip of each joint with the required torque, yield of
//    each ring at its bore and outside) and ranks them by the documented
//    rule (preferred fits, widest bands, largest margin): the run must
//    choose the closed form's first combination;
// 2. compares the run's FE margins at the corners of the chosen bands and
//    each joint's allowed band (the others in their chosen fits) with the
//    closed form's;
//    and repeats the run from its parameters.prm;
// 3. selects only Sleeve-Hub (Shaft-Sleeve keeps its 0.04 mm) the same
//    way;
// 3b. (2d-2f in the output) joins by temperature with the parts joined
//    before: the hub limited to 150 C, the shaft's fit widening the
//    sleeve it is heated onto (the compound cylinders of shaft and
//    sleeve); then the shaft and sleeve cooled to -196 C as well (both at
//    once: the inner part's temperature against the closed form of its
//    thermal mismatch); a joint that keeps a Diametral interference judged
//    too; pressed in: no heat;
// 4. asks for a torque no fit carries: exit 0, the verdict FAILED naming
//    the conflict, the selection written and no field;
// 5. bad input: exit 1, one line naming the entry, nothing written.

#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/parameters/iso286.h>

#include "run_executable.h"
#include "run_summary.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

using namespace coaxfit_test;

namespace
{
  const std::vector<coaxfit::CompoundCylinders::Ring> rings
    = {{0., 60., 210000., 0.3},
       {60., 90., 110000., 0.34},
       {90., 160., 70000., 0.33}};
  const double yield[3]      = {650., 250., 200.};
  const double mu            = 0.12;
  const double length        = 60.;
  const double slip_safety   = 1.5;
  const double yield_safety  = 1.25;
  const double hub_shrinkage = 23e-6 * 25. * 90.; // mm, in service
  /** Design/Running clearance of a shaft given a clearance (mm); 0: none. */
  double running = 0.;

  /**
   * The hub's Temperature limit (C; 0: none): with one, a hub fit that
   * heating the hub from 20 C to it does not open by its largest
   * interference, plus what the shaft's fit adds to the sleeve's outside
   * (made first: Assembly/Order inside out), plus the joining clearance
   * 0.001 D, cannot be joined by temperature (case 2d).
   */
  double hub_limit = 0.;
  /**
   * Whether the shaft and the sleeve have expansion coefficients (heating
   * 11.5e-6 and 18e-6, cooling 8.5e-6 and 14e-6 1/K), so that the shaft
   * with the sleeve on it may be cooled to -196 C while the hub is heated
   * to its limit (case 2e).
   */
  bool inner_cooled = false;

  /**
   * Design/Required axial force (N) and Application factor of the scene
   * and the closed form (case 1b).
   */
  double axial_force = 0., application_factor = 1.;

  /** The scene, selecting with @p torque (N m) and @p extra entries. */
  std::string
  scene(const double torque, const std::string &extra = "")
  {
    std::ostringstream s;
    s << "subsection Assembly\n  set Bodies = Shaft, Sleeve, Hub\nend\n"
         "subsection Geometry\n";
    const char *names[3] = {"Shaft", "Sleeve", "Hub"};
    for (unsigned int b = 0; b < 3; ++b)
      s << "  subsection " << names[b]
        << "\n    set Inner diameter = " << rings[b].inner_diameter
        << "\n    set Outer diameter = " << rings[b].outer_diameter
        << "\n    set Length = " << length << "\n  end\n";
    s << "end\nsubsection Material\n";
    for (unsigned int b = 0; b < 3; ++b)
      s << "  subsection " << names[b] << "\n    set E = " << rings[b].E
        << "\n    set nu = " << rings[b].nu
        << "\n    set Yield strength = " << yield[b]
        << (b == 2 ? "\n    set Thermal expansion = 23e-6" : "")
        << (b < 2 && inner_cooled ?
              std::string("\n    set Thermal expansion = ")
                + (b == 0 ? "11.5e-6" : "18e-6")
                + "\n    set Cooling expansion = "
                + (b == 0 ? "8.5e-6" : "14e-6") :
              std::string())
        << (b == 2 && hub_limit > 0. ?
              "\n    set Temperature limit = " + std::to_string(hub_limit) :
              "")
        << "\n  end\n";
    s << "end\nsubsection Fit\n  set Friction coefficient = " << mu
      << "\n  subsection Shaft-Sleeve\n    set Diametral interference = "
         "0.04\n  end\nend\n"
         "subsection Operation\n  set Hub temperature = 45\nend\n"
         "subsection Design\n  set Mode = select\n  set Required torque = "
      << torque << "\n  set Slip safety = " << slip_safety
      << "\n  set Yield safety = " << yield_safety
      << "\n  set Required axial force = " << axial_force
      << "\n  set Application factor = " << application_factor << "\n"
      << extra
      << "end\n"
         "subsection Mesh\n  set Axial cells = 8\n  set Radial cells = 8\n"
         "  set Global refinements = 1\nend\n";
    return s.str();
  }

  /**
   * The least margin (a safety over its requirement) of the closed form at
   * the measured interferences @p U (mm), both states.
   */
  double
  closed_form_margin(const std::vector<double> &U, const double torque)
  {
    double margin = std::numeric_limits<double>::infinity();
    for (const bool service : {false, true})
      {
        std::vector<double> U_state = U;
        if (service)
          U_state[1] -= hub_shrinkage;
        const coaxfit::CompoundCylinders cc(rings, U_state, 0., 0., true);
        for (unsigned int k = 0; k < 2; ++k)
          {
            // A running fit: its diametral gap against the clearance.
            if (U[k] < 0.)
              {
                margin = std::min(margin, 2. * cc.gap(k) / running);
                continue;
              }
            const double D = rings[k].outer_diameter;
            const double T
              = mu * cc.pressure(k) * M_PI * D * D * length / 2. / 1000.;
            if (!(cc.pressure(k) > 0.))
              return -std::numeric_limits<double>::infinity();
            // DIN 7190's resultant of both loads, as a torque at D.
            const double required
              = application_factor
                * std::hypot(torque, axial_force * D / 2000.);
            if (required > 0.)
              margin = std::min(margin, T / (required * slip_safety));
          }
        for (unsigned int b = 0; b < 3; ++b)
          for (const double d :
               {rings[b].inner_diameter, rings[b].outer_diameter})
            if (d > 0.)
              {
                const double sr = cc.radial_stress(b, d / 2.),
                             st = cc.hoop_stress(b, d / 2.);
                const double vm = std::sqrt(sr * sr + st * st - sr * st);
                margin = std::min(margin, yield[b] / (vm * yield_safety));
              }
      }
    return margin;
  }

  /**
   * The closed form's heating of the hub for joining (C) with the shaft's
   * and the hub's largest measured interferences @p U_shaft and @p U_hub
   * (mm): the hub's bore opened by U_hub, the growth 2 u_r(45 mm) of the
   * sleeve's outside on the shaft alone (the compound cylinders of those
   * two rings), and the joining clearance 0.09 mm.
   */
  double
  hub_joining_temperature(const double U_shaft, const double U_hub)
  {
    const coaxfit::CompoundCylinders shaft_and_sleeve(
      {rings[0], rings[1]}, {U_shaft}, 0., 0., true);
    const double growth = 2. * shaft_and_sleeve.radial_displacement(1, 45.);
    return 20. + (U_hub + growth + 0.09) / (90. * 23e-6);
  }

  /**
   * How far (mm, diametral) cooling the shaft with the sleeve on it from
   * 20 C to -196 C shrinks the sleeve's outside: its free shrinkage
   * 14e-6 * 216 * 45 mm, less what the shaft's joint pushes it out as the
   * sleeve shrinks onto the shaft by (14e-6 - 8.5e-6) * 216 * 30 mm more
   * (the compound cylinders of those two rings at that interference).
   */
  double
  inner_cooling_opening()
  {
    const double                     dT = 216.;
    const coaxfit::CompoundCylinders pushed(
      {rings[0], rings[1]}, {2. * (14e-6 - 8.5e-6) * dT * 30.}, 0., 0., true);
    return 2. * (14e-6 * dT * 45. - pushed.radial_displacement(1, 45.));
  }

  /**
   * Whether the closed form joins Sleeve-Hub by temperature with the
   * largest interferences @p U_shaft and @p U_hub (mm): the hub heated to
   * its limit, and with inner_cooled the inner part cooled to -196 C at
   * once, open more than it needs (hub_joining_temperature()).
   */
  bool
  hub_joinable(const double U_shaft, const double U_hub)
  {
    const double need
      = (hub_joining_temperature(U_shaft, U_hub) - 20.) * 90. * 23e-6;
    return need <= (hub_limit - 20.) * 90. * 23e-6
                     + (inner_cooled ? inner_cooling_opening() : 0.);
  }

  /** A combination of fits judged by the closed form. */
  struct Choice
  {
    std::vector<coaxfit::IsoFit> fits;
    unsigned int                 unjoinable    = 0;
    unsigned int                 not_preferred = 0;
    double                       width = 0., margin = 0.;
  };

  /**
   * Every combination of the candidates of the joints @p chosen (the
   * others at @p fixed mm), judged at each corner; the feasible ones
   * ranked by the documented rule.
   */
  std::vector<Choice>
  closed_form_ranking(const std::vector<bool>   &chosen,
                      const std::vector<double> &fixed,
                      const double               torque,
                      unsigned long             &n_combinations,
                      const std::string         &kept = "")
  {
    std::vector<std::vector<coaxfit::IsoFit>> lists(2);
    for (unsigned int k = 0; k < 2; ++k)
      {
        if (!chosen[k])
          lists[k].push_back({"fixed", 0., 0., 0., 0.});
        else
          for (const coaxfit::IsoFit &f :
               coaxfit::candidate_fits(rings[k].outer_diameter))
            if (k == 1 && !kept.empty() ? f.name == kept :
                                          f.min_interference() > 0.)
              lists[k].push_back(f);
      }
    std::vector<Choice> feasible;
    n_combinations = 0;
    for (const coaxfit::IsoFit &a : lists[0])
      for (const coaxfit::IsoFit &b : lists[1])
        {
          ++n_combinations;
          const coaxfit::IsoFit *f[2] = {&a, &b};
          double margin               = std::numeric_limits<double>::infinity();
          for (unsigned int corner = 0; corner < 4; ++corner)
            {
              std::vector<double> U(2);
              for (unsigned int k = 0; k < 2; ++k)
                U[k] = chosen[k] ?
                         1e-3
                           * ((corner >> k) & 1 ? f[k]->max_interference() :
                                                  f[k]->min_interference()) :
                         fixed[k];
              margin = std::min(margin, closed_form_margin(U, torque));
            }
          if (margin >= 1.)
            {
              Choice c;
              for (unsigned int k = 0; k < 2; ++k)
                if (chosen[k])
                  {
                    c.fits.push_back(*f[k]);
                    c.not_preferred
                      += coaxfit::is_preferred_fit(f[k]->name) ? 0 : 1;
                    c.width
                      += f[k]->max_interference() - f[k]->min_interference();
                  }
              c.margin = margin;
              if (hub_limit > 0. && (chosen[1] || fixed[1] > 0.))
                c.unjoinable = !hub_joinable(
                  chosen[0] ? 1e-3 * a.max_interference() : fixed[0],
                  chosen[1] ? 1e-3 * b.max_interference() : fixed[1]);
              feasible.push_back(c);
            }
        }
    std::sort(feasible.begin(),
              feasible.end(),
              [](const Choice &a, const Choice &b) {
                if (a.unjoinable != b.unjoinable)
                  return a.unjoinable < b.unjoinable;
                if (a.not_preferred != b.not_preferred)
                  return a.not_preferred < b.not_preferred;
                if (a.width != b.width)
                  return a.width > b.width;
                if (a.margin != b.margin)
                  return a.margin > b.margin;
                // Equal bands (H7/u6 and U7/h6): hole basis first.
                for (unsigned int k = 0; k < a.fits.size(); ++k)
                  if (a.fits[k].name != b.fits[k].name)
                    return a.fits[k].name < b.fits[k].name;
                return false;
              });
    return feasible;
  }

  /** Write @p text as @p dir/NAME.prm; its path. */
  std::string
  write_scene(const std::string &dir, const std::string &text)
  {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "_in");
    const std::string file = dir + "_in/stack.prm";
    std::ofstream(file) << text;
    return file;
  }

  /** Run @p file into @p dir; print the exit code; the summary. */
  nlohmann::json
  run_scene(const std::string &dir, const std::string &file)
  {
    const RunResult r = run_coaxfit(dir, quiet + file);
    std::cout << "  exit code " << r.exit_code
              << (r.message.empty() ? "" : ", " + gist(r.message, 30)) << '\n';
    return read_summary(dir);
  }

  /** Compare the run's FE checks with the closed form. */
  void
  compare_checks(const nlohmann::json      &j,
                 const std::vector<bool>   &chosen,
                 const std::vector<double> &fixed,
                 const double               torque,
                 const double               tolerance = 1e-4)
  {
    double       worst = 0., least = std::numeric_limits<double>::infinity();
    unsigned int n = 0;
    for (const auto &check : j["selection"]["checks"])
      {
        std::vector<double> U = fixed;
        unsigned int        i = 0;
        for (unsigned int k = 0; k < 2; ++k)
          if (chosen[k])
            U[k] = check["U"][i++].get<double>();
        const double exact = closed_form_margin(U, torque);
        const double fe    = check["margin"].get<double>();
        worst              = std::max(worst, std::abs(fe / exact - 1.));
        least              = std::min(least, fe);
        ++n;
      }
    std::cout << "  FE check at " << n
              << " corners: every margin >= 1: " << (least >= 1. ? "yes" : "NO")
              << "; against the closed form: "
              << (worst < tolerance ? "within " : "DIFFERS from ")
              << std::setprecision(1) << tolerance << " ("
              << std::setprecision(2) << worst << ")\n"
              << std::setprecision(6);
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  const std::string base   = std::filesystem::current_path().string();
  const double      torque = 1000.;

  // 1. Both joints chosen.
  {
    std::cout << "1. both joints selected, required torque " << torque
              << " N m, slip safety " << slip_safety << ", yield safety "
              << yield_safety << ", the hub 25 K warmer in service\n";
    const std::string    dir = base + "/both";
    const nlohmann::json j   = run_scene(dir, write_scene(dir, scene(torque)));
    unsigned long        n   = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({true, true}, {0., 0.}, torque, n);
    std::cout << "  combinations judged: run "
              << j["selection"]["combinations"].get<unsigned long>()
              << ", closed form " << n << "; feasible: run "
              << j["selection"]["feasible"].get<unsigned long>()
              << ", closed form " << ranking.size() << '\n';
    const std::string first = ranking.empty() ? "none" :
                                                ranking[0].fits[0].name + " + "
                                                  + ranking[0].fits[1].name;
    std::cout << "  chosen: " << fits_of(j)
              << "; the closed form's first: " << first
              << (fits_of(j) == first ? " (the same)" : " (DIFFERS)") << '\n';
    compare_checks(j, {true, true}, {0., 0.}, torque);
    // Each joint's allowed band, the other anywhere in its chosen fit:
    // the closed form's by bisection of the least margin over the other's
    // two ends.
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto &joint = j["selection"]["joints"][k];
        const auto  other = coaxfit::iso_fit(
          j["selection"]["joints"][1 - k]["fit"].get<std::string>(),
          rings[1 - k].outer_diameter);
        const auto margin = [&](const double U_k) {
          double m = std::numeric_limits<double>::infinity();
          for (const double U_o : {1e-3 * other.min_interference(),
                                   1e-3 * other.max_interference()})
            {
              std::vector<double> U(2);
              U[k]     = U_k;
              U[1 - k] = U_o;
              m        = std::min(m, closed_form_margin(U, torque));
            }
          return m;
        };
        const auto bisect = [&](double inside, double outside) {
          for (unsigned int i = 0; i < 60; ++i)
            {
              const double mid                       = 0.5 * (inside + outside);
              (margin(mid) >= 1. ? inside : outside) = mid;
            }
          return 0.5 * (inside + outside);
        };
        const double mid
          = 0.5e-3
            * (coaxfit::iso_fit(joint["fit"], rings[k].outer_diameter)
                 .min_interference()
               + coaxfit::iso_fit(joint["fit"], rings[k].outer_diameter)
                   .max_interference());
        const double low  = bisect(mid, 0.),
                     high = bisect(mid, 0.2 * rings[k].outer_diameter);
        std::cout << "  " << joint["name"].get<std::string>() << " "
                  << joint["fit"].get<std::string>() << ": allowed "
                  << std::setprecision(4) << low << " to " << high
                  << " mm (closed form); the run's band "
                  << agreement(joint["allowed_min"].get<double>(), low, 1e-3)
                  << " and "
                  << agreement(joint["allowed_max"].get<double>(), high, 1e-3)
                  << ", ended by " << joint["allowed_min_by"].get<std::string>()
                  << "; " << joint["allowed_max_by"].get<std::string>()
                  << std::setprecision(6) << '\n';
      }
    std::cout << "  the run of the chosen fits (Fit/Case mean): "
              << j["verdict"]["ok"] << ", the joints' fits: "
              << j["joints"][0]["fit"].get<std::string>() << "; "
              << j["joints"][1]["fit"].get<std::string>() << '\n';

    // The run again from its parameters.prm.
    const nlohmann::json again
      = run_scene(base + "/again", dir + "/parameters.prm");
    std::cout
      << "  again from parameters.prm: " << fits_of(again)
      << (fits_of(again) == fits_of(j) ? " (the same)" : " (DIFFERS)")
      << ", margin of the first check "
      << agreement(again["selection"]["checks"][0]["margin"].get<double>(),
                   j["selection"]["checks"][0]["margin"].get<double>(),
                   1e-12)
      << '\n';
  }

  // 1b. Both joints chosen, with an axial force and K_A (DIN 7190's
  // resultant per joint: it weighs more on the larger joint).
  {
    axial_force        = 10000.;
    application_factor = 1.1;
    std::cout << "1b. and Required axial force " << axial_force
              << " N, Application factor " << application_factor << '\n';
    const std::string    dir = base + "/axial";
    const nlohmann::json j   = run_scene(dir, write_scene(dir, scene(torque)));
    unsigned long        n   = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({true, true}, {0., 0.}, torque, n);
    std::cout << "  combinations judged: run "
              << j["selection"]["combinations"].get<unsigned long>()
              << ", closed form " << n << "; feasible: run "
              << j["selection"]["feasible"].get<unsigned long>()
              << ", closed form " << ranking.size() << '\n';
    const std::string first = ranking.empty() ? "none" :
                                                ranking[0].fits[0].name + " + "
                                                  + ranking[0].fits[1].name;
    std::cout << "  chosen: " << fits_of(j)
              << "; the closed form's first: " << first
              << (fits_of(j) == first ? " (the same)" : " (DIFFERS)") << '\n';
    // A corner governed by the sleeve's yield: its surface von Mises
    // stress carries the FE's discretization error, 2.4e-4 (stack_runs).
    compare_checks(j, {true, true}, {0., 0.}, torque, 3e-4);
    axial_force        = 0.;
    application_factor = 1.;
  }

  // 2. Only Sleeve-Hub chosen: Shaft-Sleeve keeps 0.04 mm.
  {
    std::cout << "2. Design/Selected joints = Sleeve-Hub\n";
    const std::string    dir = base + "/outer";
    const nlohmann::json j   = run_scene(
      dir,
      write_scene(dir, scene(torque, "  set Selected joints = Sleeve-Hub\n")));
    unsigned long             n = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({false, true}, {0.04, 0.}, torque, n);
    const std::string first
      = ranking.empty() ? "none" : ranking[0].fits[0].name;
    std::cout << "  " << n << " candidates; chosen: " << fits_of(j)
              << "; the closed form's first: " << first
              << (fits_of(j) == first ? " (the same)" : " (DIFFERS)")
              << "; Shaft-Sleeve: " << j["joints"][0]["fit"].get<std::string>()
              << '\n';
    compare_checks(j, {false, true}, {0.04, 0.}, torque);
  }

  // 2b. Only Shaft-Sleeve chosen, Sleeve-Hub keeps H7/s6: its band's
  // corners are part of every combination's box.
  {
    std::cout << "2b. Design/Selected joints = Shaft-Sleeve, Sleeve-Hub "
                 "keeps ISO fit H7/s6 (0.036 to 0.093 mm)\n";
    const std::string dir = base + "/kept";
    std::string text = scene(torque, "  set Selected joints = Shaft-Sleeve\n");
    text.replace(text.find("  set Friction"),
                 0,
                 "  subsection Sleeve-Hub\n    set ISO fit = H7/s6\n  end\n");
    const nlohmann::json      j = run_scene(dir, write_scene(dir, text));
    unsigned long             n = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({true, true}, {0., 0.}, torque, n, "H7/s6");
    std::cout << "  combinations: run "
              << j["selection"]["combinations"].get<unsigned long>()
              << ", closed form " << n << "; feasible: run "
              << j["selection"]["feasible"].get<unsigned long>()
              << ", closed form " << ranking.size() << "; found "
              << j["selection"]["found"] << '\n';
  }

  // 2c. The shaft runs in the sleeve with 0.06 mm clearance, which must
  // keep 0.01 mm (Design/Running clearance) while Sleeve-Hub is chosen:
  // the sleeve's bore closes as the hub squeezes it.
  {
    std::cout << "2c. Shaft-Sleeve a running fit (-0.06 mm), Design/Running "
                 "clearance 0.01 mm, no torque\n";
    const std::string dir  = base + "/running";
    std::string       text = scene(0., "  set Running clearance = 0.01\n");
    const std::string from = "Diametral interference = 0.04";
    text.replace(text.find(from),
                 from.size(),
                 "Diametral interference = -0.06");
    const nlohmann::json j      = run_scene(dir, write_scene(dir, text));
    running                     = 0.01;
    unsigned long             n = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({false, true}, {-0.06, 0.}, 0., n);
    const std::string first
      = ranking.empty() ? "none" : ranking[0].fits[0].name;
    std::cout << "  feasible: run "
              << j["selection"]["feasible"].get<unsigned long>()
              << ", closed form " << ranking.size()
              << "; chosen: " << fits_of(j)
              << "; the closed form's first: " << first
              << (fits_of(j) == first ? " (the same)" : " (DIFFERS)") << '\n';
    compare_checks(j, {false, true}, {-0.06, 0.}, 0.);
    running           = 0.;
    const auto &joint = j["selection"]["joints"][0];
    std::cout << "  allowed up to " << std::setprecision(4)
              << joint["allowed_max"].get<double>() << " mm ("
              << joint["allowed_max_by"].get<std::string>() << ")"
              << std::setprecision(6) << "; the run's verdict "
              << j["verdict"]["ok"] << ", running clearance left "
              << j["joints"][0]["contact"]["gap_min"].get<double>() << " mm\n";
  }

  // 2d. The hub may be heated to 150 C only: a combination is joinable by
  // temperature if the hub's bore, heated, opens by its fit's largest
  // interference plus what the shaft's fit (made first) adds to the
  // sleeve's outside, plus the joining clearance. Without the growth the
  // first of case 1 (H6/s6 + H7/u6: 134.0 C) would pass; with it, it
  // needs 159.3 C.
  {
    hub_limit = 150.;
    std::cout << "2d. both joints selected, the hub's Temperature limit "
              << hub_limit << " C\n";
    const std::string    dir = base + "/joinable";
    const nlohmann::json j   = run_scene(dir, write_scene(dir, scene(torque)));
    unsigned long        n   = 0;
    const std::vector<Choice> ranking
      = closed_form_ranking({true, true}, {0., 0.}, torque, n);
    const std::string first      = ranking.empty() ? "none" :
                                                     ranking[0].fits[0].name + " + "
                                                  + ranking[0].fits[1].name;
    unsigned int      unjoinable = 0;
    for (const Choice &c : ranking)
      unjoinable += c.unjoinable;
    std::cout << "  feasible: run "
              << j["selection"]["feasible"].get<unsigned long>()
              << ", closed form " << ranking.size() << ", of which "
              << unjoinable << " cannot be joined by heating the hub\n"
              << "  chosen: " << fits_of(j)
              << "; the closed form's first: " << first
              << (fits_of(j) == first ? " (the same)" : " (DIFFERS)") << '\n';
    compare_checks(j, {true, true}, {0., 0.}, torque, 3e-4);
    if (!ranking.empty())
      {
        const auto  &joining = j["joints"][1]["joining"];
        const double exact   = hub_joining_temperature(
          1e-3 * ranking[0].fits[0].max_interference(),
          1e-3 * ranking[0].fits[1].max_interference());
        std::cout << "  the run's joining of Sleeve-Hub: heat the hub to "
                  << std::setprecision(5)
                  << joining["heat_outer_to"].get<double>()
                  << " C (closed form " << exact << " C, "
                  << agreement(joining["heat_outer_to"].get<double>(),
                               exact,
                               1e-5)
                  << "), above its limit: " << joining["heat_above_limit"]
                  << std::setprecision(6) << '\n';
      }
    const auto u6 = coaxfit::iso_fit("H7/u6", 90.),
               s6 = coaxfit::iso_fit("H6/s6", 60.);
    std::cout << "  H6/s6 + H7/u6 would need " << std::setprecision(5)
              << hub_joining_temperature(1e-3 * s6.max_interference(),
                                         1e-3 * u6.max_interference())
              << " C (without the sleeve's growth "
              << 20. + (1e-3 * u6.max_interference() + 0.09) / (90. * 23e-6)
              << " C)" << std::setprecision(6) << '\n';
    // 2e. The shaft with the sleeve on it may be cooled to -196 C as well
    // (both at once, DIN 7190): more combinations join; where the hub at
    // its limit is not enough alone, the run gives the inner part's
    // temperature for both at once.
    inner_cooled = true;
    {
      std::cout << "2e. and the shaft and the sleeve cooled to -196 C as "
                   "well: the inner part opens "
                << std::setprecision(5) << inner_cooling_opening()
                << " mm (closed form)" << std::setprecision(6) << '\n';
      const std::string    cooled = base + "/cooled";
      const nlohmann::json c
        = run_scene(cooled, write_scene(cooled, scene(torque)));
      const std::vector<Choice> cooled_ranking
        = closed_form_ranking({true, true}, {0., 0.}, torque, n);
      unsigned int cannot = 0;
      for (const Choice &choice : cooled_ranking)
        cannot += choice.unjoinable;
      const std::string cooled_first = cooled_ranking.empty() ?
                                         "none" :
                                         cooled_ranking[0].fits[0].name + " + "
                                           + cooled_ranking[0].fits[1].name;
      std::cout << "  " << cannot
                << " feasible combinations cannot be joined (closed form)\n"
                << "  chosen: " << fits_of(c)
                << "; the closed form's first: " << cooled_first
                << (fits_of(c) == cooled_first ? " (the same)" : " (DIFFERS)")
                << '\n';
      const auto &joining = c["joints"][1]["joining"];
      const auto  largest = [&](const unsigned int k) {
        return 1e-3
               * coaxfit::iso_fit(
                   c["selection"]["joints"][k]["fit"].get<std::string>(),
                   rings[k].outer_diameter)
                   .max_interference();
      };
      const double need
        = (hub_joining_temperature(largest(0), largest(1)) - 20.) * 90. * 23e-6;
      const double left = need - (hub_limit - 20.) * 90. * 23e-6;
      std::cout << "  the run heats the hub to " << std::setprecision(5)
                << joining["heat_outer_to"].get<double>()
                << " C alone, above its limit: " << joining["heat_above_limit"];
      if (left > 0.)
        {
          const double exact = 20. - left / (inner_cooling_opening() / 216.);
          std::cout << "; both at once: the hub at " << hub_limit
                    << " C and the inner part cooled to "
                    << joining["both_cool_inner_to"].get<double>()
                    << " C (closed form " << exact << " C, "
                    << agreement(joining["both_cool_inner_to"].get<double>(),
                                 exact,
                                 1e-4)
                    << ")";
        }
      std::cout << std::setprecision(6) << '\n';
      // The caution says what joins it.
      for (const auto &w : c["warnings"])
        if (w.get<std::string>().rfind("joining Sleeve-Hub", 0) == 0)
          std::cout << "  caution: "
                    << w.get<std::string>().substr(
                         w.get<std::string>().find("; ") + 2, 46)
                    << '\n';
    }
    inner_cooled = false;

    // 2f. Only Shaft-Sleeve chosen, Sleeve-Hub keeps 0.104 mm: the hub's
    // joint is judged too, its growth set by the shaft's fit.
    {
      const std::string kept = base + "/kept_plain";
      std::string       text
        = scene(torque, "  set Selected joints = Shaft-Sleeve\n");
      text.replace(text.find("  set Friction"),
                   0,
                   "  subsection Sleeve-Hub\n    set Diametral interference = "
                   "0.104\n  end\n");
      std::cout << "2f. Design/Selected joints = Shaft-Sleeve, Sleeve-Hub "
                   "keeps 0.104 mm\n";
      const nlohmann::json      k = run_scene(kept, write_scene(kept, text));
      const std::vector<Choice> kept_ranking
        = closed_form_ranking({true, false}, {0., 0.104}, torque, n);
      const std::string kept_first
        = kept_ranking.empty() ? "none" : kept_ranking[0].fits[0].name;
      std::cout << "  chosen: " << fits_of(k)
                << "; the closed form's first: " << kept_first
                << (fits_of(k) == kept_first ? " (the same)" : " (DIFFERS)")
                << "; the run heats the hub to " << std::setprecision(5)
                << k["joints"][1]["joining"]["heat_outer_to"].get<double>()
                << " C" << std::setprecision(6) << '\n';
    }

    // Pressed in (Design/Joining = press): no heat, so the ranking of
    // case 1, whatever the hub's limit.
    const std::string    pressed = base + "/pressed";
    const nlohmann::json p       = run_scene(
      pressed, write_scene(pressed, scene(torque, "  set Joining = press\n")));
    std::cout << "  Design/Joining = press: chosen " << fits_of(p) << ", notes "
              << p["selection"]["notes"].size() << '\n';
    hub_limit = 0.;
  }

  // 3. A torque no fit carries.
  {
    std::cout << "3. required torque 1e6 N m\n";
    const std::string    dir = base + "/none";
    const nlohmann::json j   = run_scene(dir, write_scene(dir, scene(1e6)));
    std::cout << "  found " << j["selection"]["found"] << ", verdict ok "
              << j["verdict"]["ok"] << ": "
              << gist(j["verdict"]["failed"][0].get<std::string>(), 12)
              << "\n  files:";
    std::vector<std::string> files;
    for (const auto &e : std::filesystem::directory_iterator(dir))
      files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    for (const std::string &f : files)
      std::cout << ' ' << f;
    std::cout << '\n';
  }

  // 4. Bad input (the test's directory taken out of the messages).
  std::cout << "4. bad input\n";
  const auto message = [&base](std::string text) {
    for (std::size_t at; (at = text.find(base)) != std::string::npos;)
      text.replace(at, base.size(), "DIR");
    return gist(text, 14);
  };
  for (const std::string &extra :
       {std::string("  set Selected joints = Shaft-Hub\n"),
        std::string("  set Selected joints = Sleeve-Hub, Sleeve-Hub\n"),
        std::string("  set Mode = choose\n")})
    {
      const std::string dir = base + "/bad";
      const RunResult   r
        = run_coaxfit(dir, quiet + write_scene(dir, scene(torque, extra)));
      std::cout << "  exit code " << r.exit_code << ", " << r.lines
                << " line: " << message(r.message) << "; written: "
                << (std::filesystem::exists(dir) ? "yes" : "nothing") << '\n';
    }
  {
    // Every joint given a clearance: nothing to choose.
    std::string       text = scene(torque);
    const std::string from = "Diametral interference = 0.04";
    text.replace(text.find(from),
                 from.size(),
                 "Diametral interference = -0.01");
    text.replace(text.find("  set Friction"),
                 0,
                 "  set Diametral interference = -0.02\n");
    const std::string dir = base + "/bad";
    const RunResult   r   = run_coaxfit(dir, quiet + write_scene(dir, text));
    std::cout << "  exit code " << r.exit_code << ", " << r.lines
              << " line: " << message(r.message) << "; written: "
              << (std::filesystem::exists(dir) ? "yes" : "nothing") << '\n';
  }
  return 0;
}
