#include <coaxfit/coaxial_fit.h>
#include <coaxfit/input_error.h>
#include <coaxfit/parameters.h>

#include <cstring>
#include <iostream>

namespace
{
  const char *usage
    = "Usage: coaxfit [--quiet] [--set Section/Name=value]... FILE.prm\n"
      "       coaxfit --print-parameters\n"
      "       coaxfit --help\n"
      "\n"
      "Computes the contact of an interference fit between a shaft (or tube)\n"
      "and a hub, two coaxial elastic cylinders, by the principle of\n"
      "alternating continuity (staggered Dirichlet-Neumann coupling).\n"
      "\n"
      "  --set Section/Name=value   override a parameter of FILE.prm, e.g.\n"
      "                             --set Mesh/Global\\ refinements=2\n"
      "                             --set Material/Hub/E=7e4\n"
      "  --quiet                    print only the final report and errors\n"
      "  --print-parameters         list every parameter with its default,\n"
      "                             allowed values and documentation\n"
      "  --help                     this text\n"
      "\n"
      "Results go to Output/Directory (default output/<FILE's base name>):\n"
      "contact_pressure.csv, convergence.csv, summary.json, parameters.prm\n"
      "(repeats the run), parameters.json, shaft.vtu, hub.vtu,\n"
      "interface.vtp and solution.pvd. Exit code 0: converged; 1: bad\n"
      "input; 2: the coupling did not converge or diverged; 3: internal\n"
      "or system error.\n";
} // namespace

int
main(int argc, char **argv)
{
  using namespace coaxfit;
  try
    {
      std::vector<std::pair<std::string, std::string>> overrides;
      std::string                                      filename;
      bool                                             quiet = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--help" || arg == "-h")
            {
              std::cout << usage;
              return 0;
            }
          else if (arg == "--print-parameters")
            {
              print_parameters(std::cout);
              return 0;
            }
          else if (arg == "--quiet" || arg == "-q")
            quiet = true;
          else if (arg == "--set")
            {
              if (i + 1 >= argc)
                throw InputError("--set needs an argument Section/Name=value");
              const std::string setting = argv[++i];
              const auto        eq      = setting.find('=');
              if (eq == std::string::npos)
                throw InputError("--set " + setting
                                 + ": expected Section/Name=value");
              overrides.emplace_back(setting.substr(0, eq),
                                     setting.substr(eq + 1));
            }
          else if (arg.size() > 1 && arg[0] == '-')
            throw InputError("unknown option '" + arg
                             + "' (see coaxfit --help)");
          else if (filename.empty())
            filename = arg;
          else
            throw InputError("more than one parameter file given ('" + filename
                             + "' and '" + arg + "')");
        }
      if (filename.empty())
        throw InputError("no parameter file given (see coaxfit --help)");

      const Parameters parameters = read_parameters(filename, overrides);
      CoaxialFit       fit(parameters, std::cout, !quiet);
      return fit.run() ? 0 : 2;
    }
  catch (const InputError &e)
    {
      std::cerr << "coaxfit: error: " << e.what() << std::endl;
      return 1;
    }
  catch (const SolverError &e)
    {
      std::cerr << "coaxfit: error: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "coaxfit: internal error: " << e.what() << std::endl;
      return 3;
    }
}
