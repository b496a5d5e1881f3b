#ifndef coaxfit_input_error_h
#define coaxfit_input_error_h

#include <stdexcept>
#include <string>

namespace coaxfit
{
  /**
   * An error in what the user gave us: a parameter out of range, a file that
   * cannot be read, an unknown option. main() prints its one-line message
   * and exits with a non-zero code before any output is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * A failure of the computation itself (a diverging coupling iteration, a
   * step limit reached). main() reports it and exits with a non-zero code.
   */
  class SolverError : public std::runtime_error
  {
  public:
    explicit SolverError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * A failure of the machine rather than of the input or the method: memory
   * or disk exhausted (exit code 3, message "out of memory: ..." etc.).
   */
  class ResourceError : public std::runtime_error
  {
  public:
    explicit ResourceError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * The message of @p exc on one line: for deal.II's exceptions the
   * "Additional information" text (ExceptionBase::print_info), without the
   * banner and stack trace; white space runs collapsed to one blank.
   */
  std::string
  one_line_message(const std::exception &exc);
} // namespace coaxfit

#endif
