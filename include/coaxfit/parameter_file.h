#ifndef coaxfit_parameter_file_h
#define coaxfit_parameter_file_h

#include <string>

namespace coaxfit
{
  /**
   * Checks of a parameter file that deal.II's ParameterHandler does not
   * make before it parses the file recursively: `include` statements of a
   * .prm file are followed (as deal.II does: the path as written, relative
   * to the working directory) and a cycle or more than 16 levels of
   * inclusion is refused; a .json or .xml file may nest at most 32 levels.
   * Throws InputError naming the file and the line.
   */
  void
  check_parameter_file(const std::string &filename);
} // namespace coaxfit

#endif
