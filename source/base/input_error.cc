#include <deal.II/base/exceptions.h>

#include <coaxfit/base/input_error.h>

#include <cctype>
#include <sstream>

namespace coaxfit
{
  std::string
  one_line_message(const std::exception &exc)
  {
    std::ostringstream text;
    if (const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&exc))
      deal->print_info(text);
    else
      text << exc.what();
    std::string out;
    bool        space = false;
    for (const char c : text.str())
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !out.empty();
      else
        {
          if (space)
            out += ' ';
          out += c;
          space = false;
        }
    return out;
  }
} // namespace coaxfit
