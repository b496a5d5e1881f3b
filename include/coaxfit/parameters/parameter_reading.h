#ifndef coaxfit_parameter_reading_h
#define coaxfit_parameter_reading_h

#include <deal.II/base/parameter_handler.h>

#include <coaxfit/parameters/parameters.h>

#include <set>
#include <string>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The entries of @p prm declared as required (has_to_be_set) that no
   * file or override set, with their paths as deal.II joins them
   * (`Geometry.Hub length`): deal.II writes characters other than letters
   * and digits as _XX (hexadecimal), turned back here.
   */
  std::set<std::string>
  entries_not_set(const ParameterHandler &prm);

  /**
   * The entries @p entries (as entries_not_set() gives them) with their
   * paths as a parameter file writes them (`Geometry/Hub length`), joined
   * by commas.
   */
  std::string
  entry_list(const std::set<std::string> &entries);

  /**
   * Whether `Section/Name` @p path is declared in @p prm (whose value it
   * does not change: an empty value is tried, and refused by the pattern
   * of an entry that exists).
   */
  bool
  declares_entry(ParameterHandler &prm, const std::string &path);

  /** Split `A/B/Name` into its parts. */
  std::vector<std::string>
  split_path(const std::string &path);

  /**
   * Set @p path = @p value in @p prm as `--set` does; an InputError naming
   * the entry if it is not declared or its value not allowed.
   */
  void
  set_entry(ParameterHandler  &prm,
            const std::string &path,
            const std::string &value);

  /**
   * Parse the parameter file @p filename into @p prm; deal.II's errors
   * become one-line InputErrors that name the entry with its subsection.
   */
  void
  parse_parameter_file(ParameterHandler &prm, const std::string &filename);

  /**
   * Write the values of @p material that its Name filled in into the
   * entries of `Material/@p path` of @p prm (a material of the library
   * only), so that the parameters printed from @p prm repeat the run.
   */
  void
  set_material_entries(ParameterHandler  &prm,
                       const std::string &path,
                       const Material    &material);

  /**
   * Fill the entries of @p material (Material/@p path) that @p missing
   * lists (E, nu) or that are unknown (0) from its Name; drop E and nu
   * from @p missing.
   */
  void
  fill_material(Material              &material,
                const std::string     &path,
                std::set<std::string> &missing);
} // namespace coaxfit

#endif
