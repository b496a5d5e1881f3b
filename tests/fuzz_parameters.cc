// Fuzz-style robustness: 40 random mutations (fixed seed) of a valid
// parameter file, each run through the coaxfit executable with a 60 s
// limit; the values tried include subnormal and huge numbers, white space
// and control characters, Max steps 0-3, extreme cell counts, a file
// that includes itself, and include lines naming a directory or a device. Every
// run must end either as a valid run (exit 0 or 2 with a summary.json that
// parses and no NaN or infinity in any output file) or with a clean one-line
// "coaxfit: error:" message and exit 1 and no output directory: never a crash
// (signal, exit 3), a hang or a multi-line error. Release only
// (fuzz_parameters.release.output): the 40 runs are mostly process start-up,
// and the paths they reach are those of bad_input.

#include "run_executable.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /** A valid parameter file, line by line. */
  const std::vector<std::string> lines = {"subsection Geometry",
                                          "  set Joint diameter = 200",
                                          "  set Shaft bore diameter = 0",
                                          "  set Hub outer diameter = 400",
                                          "  set Shaft length = 400",
                                          "  set Hub length = 200",
                                          "end",
                                          "subsection Fit",
                                          "  set Diametral interference = 0.5",
                                          "  set ISO fit = H7/s6",
                                          "  set Case = mean",
                                          "  set Shaft roughness Rz = 4",
                                          "end",
                                          "subsection Mesh",
                                          "  set Axial cells = 6",
                                          "  set Radial cells = 4",
                                          "  set Global refinements = 0",
                                          "end",
                                          "subsection Coupling",
                                          "  set Alpha = 0.8",
                                          "  set Max steps = 100",
                                          "end",
                                          "subsection Output",
                                          "  set Write vtu = false",
                                          "end",
                                          "subsection Material",
                                          "  subsection Shaft",
                                          "    set Name = C45",
                                          "    set E  = 2e5",
                                          "    set nu = 0.33",
                                          "  end",
                                          "  subsection Hub",
                                          "    set E  = 2e5",
                                          "    set nu = 0.33",
                                          "  end",
                                          "end"};

  /** Values a mutation puts in place of a valid one. */
  const std::vector<std::string> tokens
    = {"",
       "-1",
       "0",
       "0.5",
       "1e300",
       "-1e-300",
       "nan",
       "inf",
       "abc",
       "1,5",
       "0x10",
       "true",
       "2e5x",
       "= 3",
       "99",
       "1e-9",
       "1e-320",
       "4.9e-324",
       "1e308",
       "-0",
       " 0.5\t",
       "0.5\x01",
       "\x7f",
       "1",
       "2",
       "3",
       "10000",
       "include SELF",
       "all",
       "min",
       "H7/zc11",
       "h7/S6",
       "S355",
       "EN AW-6082 T6",
       // Huge and tiny absolute sizes, include targets that are a
       // directory or a device.
       "2e42",
       "1e5",
       "1e-4",
       "include .",
       "include /dev/zero",
       "include /tmp"};



  /** One random mutation of the valid file: replace, delete or copy. */
  std::vector<std::string>
  mutate(std::mt19937 &random)
  {
    std::vector<std::string> mutated = lines;
    const unsigned int       kind    = random() % 4;
    const unsigned int       i       = random() % mutated.size();
    if (kind == 0 || kind == 1) // replace a value
      {
        const auto eq = mutated[i].find('=');
        if (eq != std::string::npos)
          mutated[i] = mutated[i].substr(0, eq + 1) + " "
                       + tokens[random() % tokens.size()];
        else
          mutated[i] = tokens[random() % tokens.size()];
      }
    else if (kind == 2) // delete a line
      mutated.erase(mutated.begin() + i);
    else // duplicate a line elsewhere
      mutated.insert(mutated.begin() + random() % mutated.size(), mutated[i]);

    return mutated;
  }

  constexpr unsigned int n_mutations = 40;

  /**
   * summary.json exists and parses as JSON (for Fit/Case = all: in each of
   * the subdirectories min, mean and max).
   */
  bool
  summary_is_valid(const std::string &directory)
  {
    if (std::filesystem::exists(directory + "/fit_cases.csv"))
      return summary_is_valid(directory + "/min")
             && summary_is_valid(directory + "/mean")
             && summary_is_valid(directory + "/max");
    std::ifstream in(directory + "/summary.json");
    return in && nlohmann::json::accept(in);
  }

  /** No output file holds a NaN or an infinity as a number. */
  bool
  all_finite(const std::string &directory)
  {
    for (const auto &entry :
         std::filesystem::recursive_directory_iterator(directory))
      {
        if (entry.is_directory())
          continue;
        std::ifstream      in(entry.path());
        std::ostringstream text;
        text << in.rdbuf();
        std::string content = text.str();
        for (char &c : content)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (const std::string bad : {"nan", "inf"})
          for (std::size_t at = content.find(bad); at != std::string::npos;
               at             = content.find(bad, at + 1))
            {
                          // A number, not a word such as "information" or "snan...".
              const bool before
                = at == 0
                  || !std::isalpha(static_cast<unsigned char>(content[at - 1]));
              const bool after
                = at + 3 >= content.size()
                  || !std::isalpha(static_cast<unsigned char>(content[at + 3]));
              if (before && after)
                return false;
            }
      }
    return true;
  }
} // namespace



int
main()
{
  std::mt19937 random(20261121);
  unsigned int valid = 0, rejected = 0, bad = 0;
  for (unsigned int k = 0; k < n_mutations; ++k)
    {
      const std::vector<std::string> mutated = mutate(random);

      const std::string name = "fuzz_" + std::to_string(k) + ".prm";
      const std::string dir  = "fuzz_out_" + std::to_string(k);
      {
        std::ofstream out(name);
        for (const auto &line : mutated)
          out << (line == "include SELF" ? "include " + name : line) << '\n';
      }
      std::filesystem::remove_all(dir);
      const coaxfit_test::RunResult r    = coaxfit_test::run_coaxfit(dir, name);
      const int                     code = r.exit_code;
      const unsigned int            n_lines = r.lines;
      const std::string            &message = r.message;
      const bool                    ran
        = (code == 0 || code == 2) && summary_is_valid(dir) && all_finite(dir);
      const bool clean_error = code == 1 && n_lines == 1
                               && message.rfind("coaxfit: error: ", 0) == 0
                               && !std::filesystem::exists(dir);
      if (ran)
        ++valid;
      else if (clean_error)
        ++rejected;
      else
        {
          ++bad;
          std::cout << "mutation " << k << ": exit code " << code << ", "
                    << n_lines << " line(s): " << message << std::endl;
        }
    }
  std::cout << n_mutations << " mutations: " << valid << " valid runs, "
            << rejected << " clean rejections, " << bad
            << " crashes, hangs or unclear "
            << "errors" << std::endl;
}
