#ifndef coaxfit_material_library_h
#define coaxfit_material_library_h

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * How a material is assessed: a ductile metal against its yield strength,
   * a brittle one (grey cast iron) by DIN 7190's criterion for brittle
   * materials (the largest hoop stress against the tensile strength R_m),
   * a polymer as a metal but without the check of E for a unit slip.
   */
  enum class MaterialKind
  {
    metal,
    brittle,
    polymer
  };

  /** "metal", "brittle" or "polymer". */
  std::string
  to_string(MaterialKind kind);

  /**
   * The group of materials by which DIN 7190-1 tabulates the coefficient
   * of friction of a joint (steel with steel, with cast iron, with light
   * alloys, with copper alloys); unknown for a material without a Name.
   */
  enum class MaterialFamily
  {
    steel,
    cast_iron,
    light_alloy,
    copper_alloy,
    unknown
  };

  /** "steel", "cast iron", "light alloy", "copper alloy" or "unknown". */
  std::string
  to_string(MaterialFamily family);

  /**
   * One entry of the named materials (`Material/Shaft/Name`): room
   * temperature values in MPa, kg/m^3 and 1/K, with where they come from.
   * The yield and tensile strengths are the standard's minima for the
   * smallest size class; larger sections are weaker, so a design should
   * set `Yield strength` and `Tensile strength` for its own size.
   */
  struct MaterialData
  {
    std::string    name;
    double         E, nu;
    double         yield_strength;    ///< R_eH or R_p0.2 (R_p0.1 for grey iron)
    double         tensile_strength;  ///< R_m, MPa
    double         density;           ///< kg/m^3
    double         thermal_expansion; ///< 1/K, heating (20-100 C)
    double         cooling_expansion; ///< 1/K, undercooling (DIN 7190), > 0
    double         temperature_limit; ///< degrees C, see limit_reason
    std::string    limit_reason;      ///< what happens above the limit
    MaterialKind   kind;
    MaterialFamily family; ///< for the friction coefficient of a pairing
    std::string    source;
  };

  /** Every named material, in the order of the documentation. */
  const std::vector<MaterialData> &
  material_library();

  /** The names, separated by @p separator. */
  std::string
  material_names(const std::string &separator);

  /** The entry named @p name (exact match); nullptr if there is none. */
  const MaterialData *
  find_material(const std::string &name);
} // namespace coaxfit

#endif
