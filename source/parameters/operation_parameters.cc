#include <coaxfit/parameters/operation_entries.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/scene_parameters.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /**
     * The number in @p text, or NaN if @p text is not one number (an empty
     * text is not a number either).
     */
    double
    parse_number(const std::string &text)
    {
      const char  *begin = text.c_str();
      char        *end   = nullptr;
      const double value = std::strtod(begin, &end);
      if (end == begin)
        return std::nan("");
      while (*end == ' ' || *end == '\t')
        ++end;
      return *end == '\0' ? value : std::nan("");
    }
  } // namespace



  double
  temperature_entry(const std::string &text, const double assembly)
  {
    const auto first = text.find_first_not_of(" \t");
    return first == std::string::npos ? assembly : parse_number(text);
  }



  double
  joining_clearance_entry(const std::string &text, const double D)
  {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text.compare(first, 4, "auto") == 0)
      return 1e-3 * D;
    return parse_number(text);
  }



  void
  check_temperature_entry(const double       value,
                          const std::string &text,
                          const std::string &name)
  {
    if (std::isnan(value))
      throw InputError("parameter " + name + " = '" + text
                       + "' is not a temperature: allowed is empty (the "
                         "assembly temperature) or a number of degrees C "
                         "above -273.15 and at most 1000.");
    require(value > absolute_zero && value <= hottest_temperature,
            name,
            value,
            "-273.15 < T <= 1000 degrees C");
  }



  void
  OperationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Operation");
    prm.add_parameter("Assembly temperature",
                      assembly_temperature,
                      "Temperature in degrees C at which the parts are "
                      "joined and at which the interference is measured "
                      "(the state of assembly). Allowed: -273.15 < T <= "
                      "1000.",
                      Patterns::Double(absolute_zero, hottest_temperature));
    prm.add_parameter("Shaft temperature",
                      shaft_temperature_text,
                      "Uniform temperature of the shaft in operation, in "
                      "degrees C; the shaft expands by Material/Shaft/"
                      "Thermal expansion times the difference to the "
                      "assembly temperature (a thermal eigenstrain). Empty: "
                      "the assembly temperature. Allowed: -273.15 < T <= "
                      "1000.",
                      Patterns::Anything());
    prm.add_parameter("Hub temperature",
                      hub_temperature_text,
                      "Uniform temperature of the hub in operation, in "
                      "degrees C (see Shaft temperature). Empty: the "
                      "assembly temperature. Allowed: -273.15 < T <= 1000.",
                      Patterns::Anything());
    prm.add_parameter("Speed",
                      speed,
                      "Rotational speed in operation, in 1/min: the "
                      "centrifugal body force rho omega^2 r of each body "
                      "(Material/*/Density). 0: at rest. Allowed: 0 to "
                      "1e7.",
                      Patterns::Double(0., 1e7));
    prm.add_parameter("Shaft bore pressure",
                      shaft_bore_pressure,
                      "Pressure in MPa on the bore of a hollow shaft in "
                      "operation (pushes the shaft against the hub). "
                      "Allowed: 0 to 1e4; needs Geometry/Shaft bore "
                      "diameter > 0 unless 0.",
                      Patterns::Double(0., 1e4));
    prm.add_parameter("Hub outer pressure",
                      hub_outer_pressure,
                      "Pressure in MPa on the outer surface of the hub in "
                      "operation (pushes the hub onto the shaft). Allowed: "
                      "0 to 1e4.",
                      Patterns::Double(0., 1e4));
    prm.add_parameter("Face pressures",
                      face_pressures_text,
                      "Pressures in MPa in operation on named faces of "
                      "sections from gmsh files: 'name: p; name: p', each "
                      "name a physical curve of the shaft's or the hub's "
                      "file (both, if both have it; not joint or axis), the "
                      "traction -p n on it. Not in the DIN 7190 column (a "
                      "plain cylinder has no such faces). Allowed: 0 to 1e4 "
                      "MPa each, with no axial resultant on either body (a "
                      "frictionless cylindrical joint holds no axial force); "
                      "empty: none.",
                      Patterns::Anything());
    prm.add_parameter("Joining clearance",
                      joining_clearance_text,
                      "Diametral clearance in mm that a shrink or expansion "
                      "fit needs while it is joined (DIN 7190's joining "
                      "clearance), for the joining temperatures: heat the "
                      "hub or cool the shaft until the largest interference "
                      "plus this clearance is gone. auto: 0.001 D_F, DIN "
                      "7190's guide value. Allowed: auto or 0 <= clearance "
                      "<= 0.1 D_F.",
                      Patterns::Anything());
    prm.leave_subsection();
  }



  double
  OperationParameters::shaft_temperature() const
  {
    return temperature_entry(shaft_temperature_text, assembly_temperature);
  }



  double
  OperationParameters::hub_temperature() const
  {
    return temperature_entry(hub_temperature_text, assembly_temperature);
  }



  double
  OperationParameters::omega() const
  {
    return 2. * M_PI * speed / 60.;
  }



  double
  OperationParameters::joining_clearance(const double joint_diameter) const
  {
    return joining_clearance_entry(joining_clearance_text, joint_diameter);
  }



  std::vector<std::pair<std::string, double>>
  OperationParameters::face_pressures() const
  {
    const std::string entry
      = "parameter Operation/Face pressures = '" + face_pressures_text + "'";
    std::vector<std::pair<std::string, double>> result;
    std::istringstream                          items(face_pressures_text);
    std::string                                 item;
    while (std::getline(items, item, ';'))
      {
        if (trimmed(item).empty())
          continue;
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw InputError(entry + ": '" + trimmed(item)
                           + "' is not 'name: p'; allowed: 'name: p; name: "
                             "p' (p in MPa)");
        const std::string name  = trimmed(item.substr(0, colon));
        const double      value = parse_number(trimmed(item.substr(colon + 1)));
        if (name.empty() || std::isnan(value))
          throw InputError(entry + ": '" + trimmed(item)
                           + "' is not 'name: p'; allowed: 'name: p; name: "
                             "p' (p in MPa)");
        require(value >= 0. && value <= 1e4,
                "Operation/Face pressures (" + name + ")",
                value,
                "0 to 1e4 MPa");
        for (const auto &[other, p] : result)
          if (other == name)
            throw InputError(entry + ": the face '" + name
                             + "' is given twice; allowed: each name once");
        result.emplace_back(name, value);
      }
    return result;
  }



  bool
  OperationParameters::has_loads() const
  {
    bool faces = false;
    for (const auto &[name, p] : face_pressures())
      faces = faces || p > 0.;
    return shaft_temperature() != assembly_temperature
           || hub_temperature() != assembly_temperature || speed > 0.
           || shaft_bore_pressure > 0. || hub_outer_pressure > 0. || faces;
  }



  void
  OperationParameters::validate(const double joint_diameter,
                                const bool   solid_shaft) const
  {
    require(assembly_temperature > absolute_zero,
            "Operation/Assembly temperature",
            assembly_temperature,
            "-273.15 < T <= 1000 degrees C");
    check_temperature_entry(shaft_temperature(),
                            shaft_temperature_text,
                            "Operation/Shaft temperature");
    check_temperature_entry(hub_temperature(),
                            hub_temperature_text,
                            "Operation/Hub temperature");
    const double clearance = joining_clearance(joint_diameter);
    if (std::isnan(clearance))
      throw InputError("parameter Operation/Joining clearance = '"
                       + joining_clearance_text
                       + "' is not a clearance: allowed is auto or a number "
                         "of mm from 0 to 0.1 D_F.");
    require(clearance >= 0. && clearance <= 0.1 * joint_diameter,
            "Operation/Joining clearance",
            clearance,
            "auto or 0 <= clearance <= 0.1 D_F (D_F = " + number(joint_diameter)
              + " mm)");
    face_pressures(); // throws on a malformed entry
    if (solid_shaft && shaft_bore_pressure > 0.)
      throw InputError("parameter Operation/Shaft bore pressure = "
                       + number(shaft_bore_pressure)
                       + " MPa needs a bore: Geometry/Shaft bore diameter is "
                         "0 (a solid shaft); allowed is 0 for a solid shaft.");
  }
} // namespace coaxfit
