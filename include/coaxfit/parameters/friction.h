#ifndef coaxfit_friction_h
#define coaxfit_friction_h

#include <coaxfit/parameters/material_library.h>

#include <string>

namespace coaxfit
{
  /**
   * How the joint is made (`Design/Joining`), which decides DIN 7190-1's
   * coefficient of friction against slip: heating the hub (shrink fit) or
   * widening it by pressure oil, each with the surfaces as machined (oiled,
   * "normal") or degreased, or pressing the shaft in lengthwise.
   */
  enum class JoiningMethod
  {
    shrink,
    shrink_degreased,
    pressure_oil,
    pressure_oil_degreased,
    press
  };

  /** The names `Design/Joining` accepts, separated by '|'. */
  std::string
  joining_method_names();

  /** The method of a name of joining_method_names(). */
  JoiningMethod
  joining_method(const std::string &name);

  /** The name of @p method as the parameter file spells it. */
  std::string
  to_string(JoiningMethod method);

  /**
   * A coefficient of friction against slip and where it comes from (for
   * the report: "DIN 7190-1, steel on steel, shrink fit").
   */
  struct FrictionValue
  {
    double      coefficient;
    std::string source;
  };

  /**
   * DIN 7190-1's coefficient of friction against slip (nu_r) of a joint
   * between a shaft of @p shaft and a hub of @p hub (in either order) made
   * by @p method. The standard tabulates steel with steel, cast iron,
   * light alloys and copper alloys; a material without a Name (unknown)
   * is taken as steel, and the source says so. Where the standard gives a
   * range, the lower end (the safe side against slip); where it gives no
   * value for the method (a shrink fit on cast iron, the light and copper
   * alloys' dry values for every method, the lengthwise press fit), the
   * nearest tabulated one, named in the source. A pairing without steel
   * has no value: InputError naming Design/Friction coefficient. The
   * source names the bodies taken as steel @p shaft_name and @p hub_name
   * (a stack's joint: its two bodies).
   */
  FrictionValue
  din7190_friction(MaterialFamily     shaft,
                   MaterialFamily     hub,
                   JoiningMethod      method,
                   const std::string &shaft_name = "shaft",
                   const std::string &hub_name   = "hub");
} // namespace coaxfit

#endif
