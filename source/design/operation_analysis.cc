#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/design/din7190.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace coaxfit
{
  namespace
  {
    /** 1/min of an angular velocity in rad/s (infinite stays infinite). */
    double
    speed_of(const double omega)
    {
      return omega * 60. / (2. * M_PI);
    }

  } // namespace



  std::string
  celsius(const double T)
  {
    std::ostringstream t;
    t << std::fixed << std::setprecision(1) << T << " C";
    return t.str();
  }



  OperationAnalysis::State
  state_figures(const std::string &name, const SolvedState &state)
  {
    const PressureSummary   &pressure = state.pressure;
    const FitDesign         &design   = state.design;
    OperationAnalysis::State s;
    s.name                     = name;
    s.pressure_mid_plane       = pressure.at_mid_plane;
    s.pressure_mean            = pressure.mean;
    s.pressure_max             = pressure.max;
    s.pressure_din             = design.pressure_din;
    s.torque_capacity          = design.torque_capacity;
    s.torque_capacity_din      = design.torque_capacity_din;
    s.axial_force_capacity     = design.axial_force_capacity;
    s.axial_force_capacity_din = design.axial_force_capacity_din;
    s.safety_slip              = design.safety_slip;
    s.press_in_force           = design.press_in_force;
    s.press_in_force_din       = design.press_in_force_din;
    s.safety_slip_din          = design.safety_slip_din;
    s.safety_yield_shaft       = design.safety_yield_shaft;
    s.safety_yield_hub         = design.safety_yield_hub;
    s.safety_fracture_hub      = design.safety_fracture_hub;
    s.converged                = state.converged;
    s.iterations               = state.n_steps;
    for (const auto &[start, end] : state.separated_zones)
      s.separated_length += end - start;
    s.contact_lost = !(pressure.max > 0.);
    return s;
  }



  OperationAnalysis::OperationAnalysis(const Parameters &parameters,
                                       StateSolver      &fit)
    : has_loads(parameters.operation.has_loads())
    , joint_name(parameters.geometry.whole ? "joint" : "half joint")
  {
    std::ostringstream middle;
    middle << "z = " << parameters.geometry.joint_middle();
    middle_name = middle.str();
    operation   = state_figures("operation", fit.solved_state());
    if (has_loads)
      assembly
        = state_figures("assembly", fit.solve_state(at_assembly(parameters)));
    else
      assembly = operation;
    assembly.name = "assembly";

    const OperationParameters &o = parameters.operation;
    std::ostringstream         c;
    c << "assembly at " << o.assembly_temperature
      << " C, at rest, no pressures; in service the hub at "
      << o.hub_temperature() << " C, the shaft at " << o.shaft_temperature()
      << " C, speed " << o.speed << " 1/min, pressure " << o.hub_outer_pressure
      << " MPa on the hub's outer surface";
    if (parameters.geometry.R0 > 0.)
      c << " and " << o.shaft_bore_pressure << " MPa in the shaft's bore";
    for (const auto &[name, p] : o.face_pressures())
      c << ", " << p << " MPa on the face '" << name << "'";
    conditions = c.str();

    compute_loosening_speed(parameters, fit);
    compute_joining(parameters);

    const double       safety = operation.safety_slip;
    std::ostringstream line;
    line << std::setprecision(3);
    if (operation.contact_lost)
      {
        holds = false;
        line << "the fit does not hold: in operation the surfaces do not "
                "touch (no contact pressure)";
      }
    else if (std::isfinite(safety) && safety < 1.)
      {
        holds = false;
        line << "the fit slips in operation: safety against slip " << safety
             << " < 1 under the required loads";
      }
    else
      {
        holds = true;
        line << "the fit holds in operation: mean pressure "
             << operation.pressure_mean << " MPa";
        if (operation.separated_length > 0.)
          line << ", separated over " << operation.separated_length
               << " mm of the " << joint_name;
        if (std::isfinite(safety))
          line << ", safety against slip " << safety;
      }
    verdict = line.str();
  }



  void
  OperationAnalysis::compute_loosening_speed(const Parameters &parameters,
                                             StateSolver      &fit)
  {
    // A figure of rotating joints: computed when Operation/Speed is given
    // (the densities are then known, validate() asks for them).
    if (!(parameters.operation.speed > 0.))
      {
        loosening_note = "the joint does not rotate: Operation/Speed = 0";
        return;
      }
    loosening_speed_din = speed_of(Din7190(parameters.geometry,
                                           parameters.shaft,
                                           parameters.hub,
                                           operating_loads(parameters))
                                     .loosening_omega());

    // The interference at rest under the other loads, and its change per
    // (rad/s)^2, from free-body solves.
    std::vector<BodyLoad> static_loads, unit_rotation;
    for (const std::string &name : Scene::body_names(parameters))
      {
        static_loads.push_back(body_load(parameters, name));
        static_loads.back().omega_squared = 0.;
        unit_rotation.emplace_back();
        unit_rotation.back().omega_squared = 1.;
      }
    Vector<double> at_rest = fit.interference_change(static_loads);
    at_rest.add(parameters.geometry.d);
    const Vector<double> per_omega_squared
      = fit.interference_change(unit_rotation);
    const unsigned int n = at_rest.size();

    // Whole joint: every d_i <= 0.
    double whole = 0.;
    for (unsigned int i = 0; i < n; ++i)
      if (at_rest[i] > 0.)
        whole = per_omega_squared[i] < 0. ?
                  std::max(whole, at_rest[i] / -per_omega_squared[i]) :
                  std::numeric_limits<double>::infinity();
    loosening_speed_whole = speed_of(std::sqrt(whole));

    // First point: the bilateral contact force F^S + omega^2 F^R.
    const Vector<double> force_at_rest = fit.contact_force_for(at_rest, false);
    const Vector<double> force_per_omega_squared
      = fit.contact_force_for(per_omega_squared, false);
    double first = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < n; ++i)
      if (!(force_at_rest[i] > 0.))
        first = 0.;
      else if (force_per_omega_squared[i] < 0.)
        first = std::min(first, force_at_rest[i] / -force_per_omega_squared[i]);
    loosening_speed_first = speed_of(std::sqrt(first));

    // Confirmation by unilateral solves at those speeds.
    const ContactInterface &contact      = fit.get_interface();
    const auto              pressures_at = [&](const double omega_squared) {
      Vector<double> d(at_rest);
      d.add(omega_squared, per_omega_squared);
      return contact.pressure(fit.contact_force_for(d, true));
    };
    const auto separated_at = [&](const double omega_squared) {
      const Vector<double> p = pressures_at(omega_squared);
      return static_cast<unsigned int>(
        std::count_if(p.begin(), p.end(), [](double x) { return x <= 0.; }));
    };
    if (std::isfinite(first) && first > 0.)
      {
        const Vector<double> p = pressures_at(first);
        min_pressure_at_first  = *std::min_element(p.begin(), p.end());
        // 1 % below and above the speed (omega^2 * 0.99^2, 1.01^2).
        separated_below_first = separated_at(0.9801 * first);
        separated_above_first = separated_at(1.0201 * first);
      }
    if (std::isfinite(whole) && whole > 0.)
      {
        const Vector<double> p = pressures_at(whole);
        max_pressure_at_whole  = *std::max_element(p.begin(), p.end());
      }
  }



  void
  OperationAnalysis::compute_joining(const Parameters &parameters)
  {
    const OperationParameters &o   = parameters.operation;
    const double               D_F = parameters.drawing.joint_diameter;
    joining_interference           = parameters.fit_limits.U_max;
    joining_clearance              = o.joining_clearance(D_F);
    // A clearance fit needs no heating: the change is never negative.
    const double U = std::max(joining_interference, -joining_clearance);
    if (parameters.hub.thermal_expansion > 0.)
      joining_temperature_hub
        = joining_temperature(true,
                              U,
                              joining_clearance,
                              D_F,
                              parameters.hub.thermal_expansion,
                              o.assembly_temperature);
    // DIN 7190's smaller coefficient for undercooling; without it the
    // heating one (noted: the temperature is then too warm).
    const Material &shaft = parameters.shaft;
    if (shaft.joining_cooling_expansion() > 0.)
      {
        joining_cooling_expansion    = shaft.joining_cooling_expansion();
        joining_cooling_from_heating = !(shaft.cooling_expansion > 0.);
        joining_temperature_shaft
          = joining_temperature(false,
                                U,
                                joining_clearance,
                                D_F,
                                joining_cooling_expansion,
                                o.assembly_temperature);
        joining_cooling_reachable
          = joining_temperature_shaft >= coldest_coolant;
      }
    if (parameters.hub.temperature_limit > 0.)
      {
        hub_temperature_limit = parameters.hub.temperature_limit;
        joining_hub_above_limit
          = joining_temperature_hub > parameters.hub.temperature_limit;
      }
    // Both at once: the hub at its limit, the shaft in liquid nitrogen.
    if (joining_hub_above_limit && !joining_cooling_reachable
        && std::isfinite(joining_temperature_shaft))
      {
        joining_needed = U + joining_clearance;
        joining_by_both
          = D_F
            * (parameters.hub.thermal_expansion
                 * (parameters.hub.temperature_limit - o.assembly_temperature)
               + joining_cooling_expansion
                   * (o.assembly_temperature - coldest_coolant));
      }
  }



  std::vector<std::string>
  OperationAnalysis::warnings(const Parameters &parameters) const
  {
    std::vector<std::string> list;
    const JoiningMethod      joining = parameters.design.joining;
    if (joining_hub_above_limit
        && (joining == JoiningMethod::shrink
            || joining == JoiningMethod::shrink_degreased))
      {
        const Material &hub = parameters.hub;
        std::string     alternative;
        if (std::isnan(joining_temperature_shaft))
          alternative = "; join by pressing or with a smaller interference";
        else if (joining_cooling_reachable)
          alternative = "; cooling the shaft to "
                        + celsius(joining_temperature_shaft)
                        + " instead avoids it";
        else
          {
            const double       needed = joining_needed;
            const double       both   = joining_by_both;
            std::ostringstream a;
            a << std::setprecision(3)
              << "; cooling the shaft instead is not reachable ("
              << celsius(joining_temperature_shaft)
              << ", below liquid nitrogen), and the hub at its limit with "
                 "the shaft at -196 C together open "
              << both << " mm of the " << needed << " mm needed"
              << (both >= needed ? ": heating and cooling together suffice" :
                                   ": press the parts together or reduce "
                                   "the interference");
            alternative = a.str();
          }
        list.push_back("heating the hub (" + hub.name + ") to "
                       + celsius(joining_temperature_hub)
                       + " for joining exceeds its temperature limit "
                       + celsius(hub.temperature_limit) + ", "
                       + hub.temperature_limit_reason + alternative);
      }
    // In service: a part held above its limit loses its heat treatment.
    const OperationParameters &o = parameters.operation;
    for (const auto &[part, m, T] :
         {std::tuple<std::string, const Material *, double>{
            "shaft", &parameters.shaft, o.shaft_temperature()},
          {"hub", &parameters.hub, o.hub_temperature()}})
      if (m->temperature_limit > 0. && T > m->temperature_limit)
        list.push_back("in service the " + part + " (" + m->name + ") at "
                       + celsius(T) + " is above its temperature limit "
                       + celsius(m->temperature_limit) + ", "
                       + m->temperature_limit_reason
                       + ": its strength figures do not hold there");
    return list;
  }



  void
  OperationAnalysis::print_joining(std::ostream &s) const
  {
    if (std::isnan(joining_temperature_hub)
        && std::isnan(joining_temperature_shaft))
      return; // no thermal expansion known
    const auto temperature = [](const double T) {
      return std::isnan(T) ? std::string("- (no thermal expansion)") :
                             celsius(T);
    };
    std::ostringstream limit;
    if (joining_hub_above_limit)
      limit << std::fixed << std::setprecision(1) << " (above "
            << hub_temperature_limit << " C, the hub's temperature limit)";
    // Without a limit of the material: hubs of quenched and tempered steel
    // lose strength above their tempering temperature; 350 C is the usual
    // limit for heating.
    else if (std::isnan(hub_temperature_limit)
             && joining_temperature_hub > 350.)
      limit << " (above 350 C, the usual limit for heating a steel hub: "
               "tempering and scaling; check the material)";
    s << std::setprecision(4) << "    joining (U_max " << joining_interference
      << " mm + clearance " << joining_clearance
      << " mm, DIN 7190): heat the hub to "
      << temperature(joining_temperature_hub) << limit.str()
      << " or cool the shaft to " << temperature(joining_temperature_shaft)
      << (joining_temperature_shaft <= -273.15 ?
            " (not reachable: below absolute zero)" :
          !joining_cooling_reachable ?
            " (not reachable: below liquid nitrogen, -196 C)" :
            "")
      << (joining_cooling_from_heating ?
            " (with the heating coefficient: Material/Shaft/Cooling "
            "expansion not given, DIN 7190's undercooling coefficient is "
            "smaller and the shaft colder)" :
            "")
      << '\n'
      << std::defaultfloat;
  }



  void
  OperationAnalysis::print(std::ostream &out) const
  {
    std::ostringstream s;
    const auto figure = [](const double x) { return figure_text(x, 5); };
    const auto row
      = [&](const std::string &what, const double a, const double b) {
          s << "    " << std::left << std::setw(44) << what << std::right
            << std::setw(12) << figure(a) << std::setw(12) << figure(b) << '\n';
        };
    if (!has_loads)
      {
        print_joining(s);
        out << s.str();
        return;
      }
    s << "  operating conditions: " << conditions << '\n';
    s << "  operation:" << std::setw(50) << "assembly" << std::setw(12)
      << "in service" << '\n';
    row("joint pressure at " + middle_name + " (MPa)",
        assembly.pressure_mid_plane,
        operation.pressure_mid_plane);
    row("joint pressure, mean (MPa)",
        assembly.pressure_mean,
        operation.pressure_mean);
    row("joint pressure, DIN 7190 (MPa)",
        assembly.pressure_din,
        operation.pressure_din);
    row("torque capacity (N m)",
        assembly.torque_capacity,
        operation.torque_capacity);
    row("axial force capacity (N)",
        assembly.axial_force_capacity,
        operation.axial_force_capacity);
    row("safety against slip", assembly.safety_slip, operation.safety_slip);
    row("safety against yield, hub",
        assembly.safety_yield_hub,
        operation.safety_yield_hub);
    if (!std::isnan(assembly.safety_fracture_hub)
        || !std::isnan(operation.safety_fracture_hub))
      row("safety against fracture (brittle), hub",
          assembly.safety_fracture_hub,
          operation.safety_fracture_hub);
    row("safety against yield, shaft",
        assembly.safety_yield_shaft,
        operation.safety_yield_shaft);
    row("separated length of the " + joint_name + " (mm)",
        assembly.separated_length,
        operation.separated_length);
    if (loosening_note.empty())
      {
        const auto rpm = [&](const double n) {
          std::ostringstream f;
          if (std::isinf(n))
            f << "never";
          else
            f << std::fixed << std::setprecision(0) << n;
          return f.str();
        };
        s << "    loosening speed (1/min): the joint starts to open at "
          << rpm(loosening_speed_first) << " and is open over its whole "
          << "length at " << rpm(loosening_speed_whole)
          << "; DIN 7190 (plane stress, no pressure left): "
          << rpm(loosening_speed_din) << '\n';
        s << "    (confirmed by solves: at the first speed min pressure "
          << figure(min_pressure_at_first) << " MPa, separated points 1 % "
          << "below " << separated_below_first << ", 1 % above "
          << separated_above_first << "; at the whole-joint speed max pressure "
          << figure(max_pressure_at_whole) << " MPa)\n";
      }
    else
      s << "    loosening speed: not computed (" << loosening_note << ")\n";
    print_joining(s);
    s << "    " << verdict << '\n';
    out << s.str();
  }



  void
  OperationAnalysis::print_markdown(std::ostream &out) const
  {
    // The console text, its table rows turned into Markdown rows.
    std::ostringstream console;
    print(console);
    std::istringstream lines(console.str());
    std::string        line;
    bool               table = false;
    while (std::getline(lines, line))
      {
        const auto first = line.find_first_not_of(' ');
        if (first == std::string::npos)
          continue;
        line = line.substr(first);
        if (line.rfind("operation:", 0) == 0)
          {
            out << "| | assembly | in service |\n|---|---:|---:|\n";
            table = true;
            continue;
          }
        // A table row: a label, then two figures after a run of spaces.
        const auto gap2 = line.find_last_of(' ');
        const auto end1 = line.find_last_not_of(' ', gap2);
        const auto gap1 = line.find_last_of(' ', end1);
        const auto end0 = line.find_last_not_of(' ', gap1);
        if (table && gap1 != std::string::npos && end0 != std::string::npos
            && gap1 - end0 > 1 && line.find("  ") != std::string::npos
            && line.find("(1/min)") == std::string::npos)
          {
            out << "| " << line.substr(0, end0 + 1) << " | "
                << line.substr(gap1 + 1, end1 - gap1) << " | "
                << line.substr(gap2 + 1) << " |\n";
            continue;
          }
        if (table)
          out << '\n';
        table = false;
        out << line << "\n\n";
      }
  }



  Parameters
  at_assembly(const Parameters &parameters)
  {
    Parameters p                       = parameters;
    p.operation.shaft_temperature_text = "";
    p.operation.hub_temperature_text   = "";
    p.operation.speed                  = 0.;
    p.operation.shaft_bore_pressure    = 0.;
    p.operation.hub_outer_pressure     = 0.;
    p.operation.face_pressures_text    = "";
    p.design.corner_trend              = false;
    return p;
  }
} // namespace coaxfit
