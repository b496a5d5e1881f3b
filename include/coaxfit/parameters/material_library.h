#ifndef coaxfit_material_library_h
#define coaxfit_material_library_h

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * One entry of the named materials (`Material/Shaft/Name`): room
   * temperature values in MPa, kg/m^3 and 1/K, with where they come from.
   * The yield strength is the standard's minimum for the smallest size
   * class; larger sections are weaker, so a design should set
   * `Yield strength` for its own size.
   */
  struct MaterialData
  {
    std::string name;
    double      E, nu;
    double      yield_strength;    ///< R_eH or R_p0.2 (R_p0.1 for grey iron)
    double      density;           ///< kg/m^3
    double      thermal_expansion; ///< 1/K, 20-100 C
    std::string source;
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
