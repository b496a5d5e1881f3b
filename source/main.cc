#include <coaxfit/coaxial_fit.h>
#include <coaxfit/fit_case_study.h>
#include <coaxfit/input_error.h>
#include <coaxfit/interruption.h>
#include <coaxfit/parameters.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <utility>
#include <vector>

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
      "interface.vtp and solution.pvd, replacing that directory as a whole\n"
      "once every file is complete (a failed or interrupted run leaves the\n"
      "earlier results untouched).\n"
      "\n"
      "Exit codes: 0 converged; 1 bad input or a run refused for its\n"
      "resources; 2 the coupling did not converge (the state is written,\n"
      "marked \"converged\": false) or diverged (nothing written); 3 internal\n"
      "or system error (out of memory, disk full); 130, 143 interrupted by\n"
      "SIGINT, SIGTERM (earlier results untouched).\n";

  /** Standard output must have taken everything written to it. */
  void
  check_standard_output()
  {
    std::cout.flush();
    if (!std::cout)
      throw coaxfit::ResourceError("cannot write to standard output");
  }



  /** What the command line asks for. */
  struct CommandLine
  {
    enum class Action
    {
      run,
      help,
      print_parameters
    } action
      = Action::run;
    std::vector<std::pair<std::string, std::string>> overrides;
    std::string                                      filename;
    bool                                             quiet = false;
  };

  /** Parse the arguments; throws InputError on a malformed command line. */
  CommandLine
  parse_command_line(int argc, char **argv)
  {
    using coaxfit::InputError;
    CommandLine line;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          line.action = CommandLine::Action::help;
        else if (arg == "--print-parameters")
          line.action = CommandLine::Action::print_parameters;
        else if (arg == "--quiet" || arg == "-q")
          line.quiet = true;
        else if (arg == "--set")
          {
            if (i + 1 >= argc)
              throw InputError("--set needs an argument Section/Name=value");
            const std::string setting = argv[++i];
            const auto        eq      = setting.find('=');
            if (eq == std::string::npos)
              throw InputError("--set " + setting
                               + ": expected Section/Name=value");
            line.overrides.emplace_back(setting.substr(0, eq),
                                        setting.substr(eq + 1));
          }
        else if (arg.size() > 1 && arg[0] == '-')
          throw InputError("unknown option '" + arg + "' (see coaxfit --help)");
        else if (line.filename.empty())
          line.filename = arg;
        else
          throw InputError("more than one parameter file given ('"
                           + line.filename + "' and '" + arg + "')");
      }
    if (line.action == CommandLine::Action::run && line.filename.empty())
      throw InputError("no parameter file given (see coaxfit --help)");
    return line;
  }
} // namespace



/**
 * The program; main() ends the process with its exit code without running
 * the libraries' exit handlers (everything is written and flushed by then):
 * OpenBLAS's never returns when its threads could not get their buffers
 * under an address space limit.
 */
int
coaxfit_main(int argc, char **argv)
{
  using namespace coaxfit;
  try
    {
      Interruption::install();
      const CommandLine line = parse_command_line(argc, argv);
      if (line.action == CommandLine::Action::help)
        std::cout << usage;
      else if (line.action == CommandLine::Action::print_parameters)
        try
          {
            print_parameters(std::cout);
          }
        catch (const std::exception &) // deal.II's ExcIO
          {
            std::cout.setstate(std::ios::badbit);
          }
      if (line.action != CommandLine::Action::run)
        {
          check_standard_output();
          return 0;
        }

      const Parameters parameters
        = read_parameters(line.filename, line.overrides);
      bool converged = false;
      if (parameters.fit.fit_case == FitCase::all)
        converged = FitCaseStudy(parameters, std::cout, !line.quiet).run();
      else
        converged = CoaxialFit(parameters, std::cout, !line.quiet).run();
      check_standard_output();
      if (!converged)
        std::cerr << "coaxfit: error: the coupling did not converge within "
                     "Coupling/Max steps = "
                  << parameters.coupling.max_steps
                  << " (the state is written, marked \"converged\": false)"
                  << std::endl;
      return converged ? 0 : 2;
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
  catch (const ResourceError &e)
    {
      std::cerr << "coaxfit: error: " << e.what() << std::endl;
      return 3;
    }
  catch (const std::bad_alloc &)
    {
      std::cerr << "coaxfit: error: out of memory (try fewer "
                   "Mesh/Global refinements)"
                << std::endl;
      return 3;
    }
  catch (const std::exception &e)
    {
      std::cerr << "coaxfit: internal error: " << one_line_message(e)
                << std::endl;
      return 3;
    }
  catch (...)
    {
      std::cerr << "coaxfit: internal error: unknown exception" << std::endl;
      return 3;
    }
}



int
main(int argc, char **argv)
{
  const int code = coaxfit_main(argc, argv);
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(code);
}
