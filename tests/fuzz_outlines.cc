// Fuzz-style robustness of the section outlines ("z, D; z, D, R; ...") as
// a parameter entry gives them: 2000 random mutations (fixed seed) of five
// valid outlines (a plain hub, the gear hub of "Real parts", a shaft with a
// filleted shoulder, a taper, a hub with rounded corners): characters
// deleted, doubled or replaced (digits, separators, signs, exponents,
// 'nan', 'inf', huge and subnormal numbers, control characters), points
// dropped, repeated or swapped, numbers scaled. Each must either parse into
// an outline whose area and Pappus volume are finite and positive, or be
// refused with an InputError whose message is one line naming the entry;
// never another exception or a crash. Every parsed outline that still
// meets the plain shaft "-100, 0; 100, 0; 100, 50; -100, 50; -100, 0"
// goes through find_joint as well (the same rule). Printed: how many
// parsed, how many were refused, and any violation.
#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_joint.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
  using namespace coaxfit;

  const std::vector<std::string> valid
    = {"-20, 50; 20, 50; 20, 100; -20, 100; -20, 50",
       "-25, 50; 25, 50; 25, 80; 6, 80; 6, 150; 15, 150; 15, 180; -15, 180; "
       "-15, 150; -6, 150; -6, 80; -25, 80; -25, 50",
       "0, 0; 100, 0; 100, 70; 60, 70; 60, 50, 2; 0, 50; 0, 0",
       "0, 50; 40, 52; 40, 100; 0, 100; 0, 50",
       "-20, 50; 20, 50; 20, 100, 3; -20, 100, 3; -20, 50"};

  const std::vector<std::string> insertions
    = {"0",    "9",   ".",   ",",     ";",      "-",  "+",     "e",
       "e9",   "nan", "inf", "1e308", "1e-320", " ",  "\t",    "\n",
       "\x01", "#",   ",,",  ";;",    "1e-12",  "-0", "0x1p3", "R"};

  /** One random mutation of @p text. */
  std::string
  mutate(std::string text, std::mt19937 &random)
  {
    std::uniform_int_distribution<int> kind(0, 6);
    const auto                         position = [&](const std::size_t n) {
      return std::uniform_int_distribution<std::size_t>(0, n)(random);
    };
    switch (kind(random))
      {
        case 0: // delete a character
          if (!text.empty())
            text.erase(position(text.size() - 1), 1);
          break;
        case 1: // insert a token
          text.insert(position(text.size()),
                      insertions[position(insertions.size() - 1)]);
          break;
        case 2: // replace a character by a token
          if (!text.empty())
            text.replace(position(text.size() - 1),
                         1,
                         insertions[position(insertions.size() - 1)]);
          break;
          case 3: // drop a point
          {
            const std::size_t a = text.find(';', position(text.size()));
            if (a != std::string::npos)
              {
                const std::size_t b = text.find(';', a + 1);
                text.erase(a,
                           b == std::string::npos ? std::string::npos : b - a);
              }
            break;
          }
          case 4: // repeat a point
          {
            const std::size_t a = text.find(';');
            if (a != std::string::npos)
              text.insert(a, text.substr(0, a) + ";");
            break;
          }
          case 5: // scale the numbers by a factor
          {
            std::string out;
            const char  factor = "0123456789"[position(9)];
            for (const char c : text)
              {
                out += c;
                if (c == ',' && position(3) == 0)
                  out += factor;
              }
            text = out;
            break;
          }
          default: // swap two points
          {
            const std::size_t a = text.find(';');
            const std::size_t b
              = a == std::string::npos ? a : text.find(';', a + 1);
            if (b != std::string::npos)
              text = text.substr(a + 1, b - a - 1) + ";" + text.substr(0, a)
                     + text.substr(b);
            break;
          }
      }
    return text;
  }
} // namespace



int
main()
{
  std::mt19937         random(20261126);
  const std::string    entry = "Geometry/Hub section";
  const SectionOutline shaft
    = SectionOutline::parse("-100, 0; 100, 0; 100, 50; -100, 50; -100, 0",
                            "Geometry/Shaft section");
  unsigned int parsed = 0, refused = 0, violations = 0, joints = 0;
  for (unsigned int k = 0; k < 2000; ++k)
    {
      std::string        text = valid[k % valid.size()];
      const unsigned int n    = 1 + k % 3;
      for (unsigned int m = 0; m < n; ++m)
        text = mutate(text, random);
      try
        {
          const SectionOutline outline = SectionOutline::parse(text, entry);
          ++parsed;
          const double area = outline.area(), volume = outline.volume();
          if (!(std::isfinite(area) && area > 0. && std::isfinite(volume)
                && volume >= 0.))
            {
              ++violations;
              std::cout << "violation: area " << area << ", volume " << volume
                        << " for '" << text << "'\n";
            }
          try
            {
              find_joint(shaft, outline);
              ++joints;
            }
          catch (const InputError &e)
            {
              const std::string message = e.what();
              if (message.find('\n') != std::string::npos
                  || message.find(entry) == std::string::npos)
                {
                  ++violations;
                  std::cout << "violation: joint message '" << message << "'\n";
                }
            }
        }
      catch (const InputError &e)
        {
          ++refused;
          const std::string message = e.what();
          if (message.find('\n') != std::string::npos
              || message.find(entry) == std::string::npos)
            {
              ++violations;
              std::cout << "violation: message '" << message << "' for '"
                        << text << "'\n";
            }
        }
      catch (const std::exception &e)
        {
          ++violations;
          std::cout << "violation: " << e.what() << " for '" << text << "'\n";
        }
    }
  std::cout << "outlines tried: 2000, parsed " << parsed << " (of them "
            << joints << " meet the shaft), refused " << refused
            << " with one line naming the entry; violations: " << violations
            << '\n';
}
