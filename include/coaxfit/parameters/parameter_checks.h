#ifndef coaxfit_parameter_checks_h
#define coaxfit_parameter_checks_h

#include <coaxfit/base/input_error.h>

#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

namespace coaxfit
{
  /**
   * Throw InputError "parameter NAME = VALUE is out of range: allowed is
   * RANGE." unless @p condition holds.
   */
  inline void
  require(const bool         condition,
          const std::string &name,
          const double       value,
          const std::string &range)
  {
    if (!condition)
      {
        std::ostringstream msg;
        msg.precision(15);
        msg << "parameter " << name << " = " << value
            << " is out of range: allowed is " << range << '.';
        throw InputError(msg.str());
      }
  }

  /** @p text without leading and trailing blanks and tabs. */
  inline std::string
  trimmed(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
      return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
  }

  /**
   * @p text as a plain decimal number (digits, '.', an exponent; no
   * hexadecimal, no words, nothing after it), else NaN.
   */
  inline double
  plain_number(const std::string &text)
  {
    if (text.empty()
        || text.find_first_not_of("0123456789.eE+-") != std::string::npos)
      return std::numeric_limits<double>::quiet_NaN();
    const char  *begin = text.c_str();
    char        *end   = nullptr;
    const double x     = std::strtod(begin, &end);
    return *end == '\0' ? x : std::numeric_limits<double>::quiet_NaN();
  }

  /** @p x with @p precision significant digits, for messages. */
  inline std::string
  number(const double x, const int precision = 10)
  {
    std::ostringstream s;
    s.precision(precision);
    s << x;
    return s.str();
  }
} // namespace coaxfit

#endif
