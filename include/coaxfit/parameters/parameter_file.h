#ifndef coaxfit_parameter_file_h
#define coaxfit_parameter_file_h

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * Checks of a parameter file that deal.II's ParameterHandler does not
   * make before it parses the file recursively: `include` statements of a
   * .prm file are followed (as deal.II does: the path as written, relative
   * to the working directory) and a cycle or more than 16 levels of
   * inclusion is refused; a .json or .xml file may nest at most 32 levels.
   * The file and every included one must be a regular file (not a
   * directory or a device) of at most 16 MiB. Throws InputError naming the
   * file and the line. Returns every file read (canonical paths: the file
   * itself and the files it includes), which no output may overwrite.
   */
  std::vector<std::string>
  check_parameter_file(const std::string &filename);

  /**
   * The subsection path open at line @p line (counted from 1) of the .prm
   * file @p filename, joined with '/' ("Material/Hub"); empty at the top
   * level or if the file cannot be read. deal.II's messages about a line
   * name the entry without its subsection: this completes them.
   */
  std::string
  subsection_at_line(const std::string &filename, unsigned int line);
} // namespace coaxfit

#endif
