#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/friction.h>

#include <array>
#include <utility>

namespace coaxfit
{
  namespace
  {
    /** The methods and their names, in the order of JoiningMethod. */
    const std::array<std::pair<JoiningMethod, const char *>, 5> methods{
      {{JoiningMethod::shrink, "shrink"},
       {JoiningMethod::shrink_degreased, "shrink degreased"},
       {JoiningMethod::pressure_oil, "pressure oil"},
       {JoiningMethod::pressure_oil_degreased, "pressure oil degreased"},
       {JoiningMethod::press, "press"}}};
  } // namespace



  std::string
  joining_method_names()
  {
    std::string names;
    for (const auto &m : methods)
      names += (names.empty() ? "" : "|") + std::string(m.second);
    return names;
  }



  JoiningMethod
  joining_method(const std::string &name)
  {
    for (const auto &m : methods)
      if (name == m.second)
        return m.first;
    throw InputError("parameter Design/Joining = '" + name
                     + "' is not a joining method: allowed are "
                     + joining_method_names());
  }



  std::string
  to_string(const JoiningMethod method)
  {
    for (const auto &m : methods)
      if (method == m.first)
        return m.second;
    return "shrink";
  }



  FrictionValue
  din7190_friction(const MaterialFamily shaft,
                   const MaterialFamily hub,
                   const JoiningMethod  method,
                   const std::string   &shaft_name,
                   const std::string   &hub_name)
  {
    // A material without a Name counts as steel, the common case.
    const bool        shaft_known = shaft != MaterialFamily::unknown;
    const bool        hub_known   = hub != MaterialFamily::unknown;
    MaterialFamily    a           = shaft_known ? shaft : MaterialFamily::steel;
    MaterialFamily    b           = hub_known ? hub : MaterialFamily::steel;
    const std::string assumed
      = shaft_known && hub_known ?
          "" :
          std::string("; ")
            + (!shaft_known && !hub_known ? shaft_name + " and " + hub_name :
               !shaft_known               ? shaft_name :
                                            hub_name)
            + " without a Material Name taken as steel";
    if (a != MaterialFamily::steel)
      std::swap(a, b);
    if (a != MaterialFamily::steel)
      throw InputError(
        "parameter Design/Friction coefficient = auto: DIN 7190-1 "
        "tabulates the coefficient of friction for pairings with steel, "
        "not for "
        + to_string(shaft) + " (shaft) on " + to_string(hub)
        + " (hub); allowed is a number from 1e-6 to 1 (the value of your "
          "tests)");
    const std::string pairing = "DIN 7190, steel on " + to_string(b);
    // DIN 7190, coefficients of friction against slip of transverse
    // press fits: steel-steel by pressure oil 0.12 (degreased, joined with
    // glycerine 0.18), shrunk 0.14 (DIN 7190:2001; DIN 7190-1:2017 is
    // reproduced with 0.15: the lower is taken), degreased 0.20;
    // steel-cast iron by pressure oil 0.10 (degreased 0.16); steel-MgAl
    // dry 0.10 to 0.15; steel-CuZn dry 0.17 to 0.25.
    const bool degreased = method == JoiningMethod::shrink_degreased
                           || method == JoiningMethod::pressure_oil_degreased;
    const bool oiled = method == JoiningMethod::pressure_oil
                       || method == JoiningMethod::pressure_oil_degreased
                       || method == JoiningMethod::press;
    switch (b)
      {
        case MaterialFamily::steel:
          switch (method)
            {
              case JoiningMethod::shrink:
                return {0.14,
                        pairing
                          + ", shrink fit (0.14 of the 2001 edition, "
                            "the lower of the editions)"
                          + assumed};
              case JoiningMethod::shrink_degreased:
                return {0.20, pairing + ", shrink fit, degreased" + assumed};
              case JoiningMethod::pressure_oil:
                return {0.12, pairing + ", pressure oil" + assumed};
              case JoiningMethod::pressure_oil_degreased:
                return {0.18, pairing + ", pressure oil, degreased" + assumed};
              default:
                return {0.12,
                        pairing
                          + ", pressed in lengthwise: the oiled value of "
                            "the pressure oil fit"
                          + assumed};
            }
        case MaterialFamily::cast_iron:
          return {degreased ? 0.16 : 0.10,
                  pairing + (degreased ? ", degreased" : "")
                    + (method == JoiningMethod::pressure_oil
                           || method == JoiningMethod::pressure_oil_degreased ?
                         ", pressure oil" :
                         ", the pressure oil value (the standard gives none "
                         "for this joining)")
                    + assumed};
          default: {
            // Dry values only: a joint joined oiled (pressure oil, pressed
            // in) takes the lower of the dry value and steel on steel's
            // oiled one (0.12, degreased 0.18).
            const bool        light = b == MaterialFamily::light_alloy;
            const double      dry   = light ? 0.10 : 0.17;
            const double      oil   = degreased ? 0.18 : 0.12;
            const std::string dry_text
              = light ? ", dry, lower end of 0.10 to 0.15" :
                        ", the dry value of brass (CuZn), lower end of 0.17 "
                        "to 0.25";
            if (oiled && oil < dry)
              return {oil,
                      pairing
                        + std::string(", joined oiled: steel on steel's "
                                      "oiled value, ")
                        + (degreased ? "0.18" : "0.12")
                        + ", below the dry value (the standard gives only "
                          "the dry value 0.17 to 0.25 of brass)"
                        + assumed};
            return {dry, pairing + dry_text + assumed};
          }
      }
  }
} // namespace coaxfit
