#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/parameter_sweep.h>
#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/app/run_guard.h>
#include <coaxfit/app/stack_batch.h>
#include <coaxfit/app/stack_case_study.h>
#include <coaxfit/app/stack_fit.h>
#include <coaxfit/app/stack_sweep.h>
#include <coaxfit/app/usage.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace
{

  /** Standard output must have taken everything written to it. */
  void
  check_standard_output()
  {
    std::cout.flush();
    if (!std::cout)
      throw coaxfit::ResourceError("cannot write to standard output");
  }



  /**
   * Standard output must be able to take the report before any work: it is
   * not /dev/full (also what a closed standard output is opened on, see
   * ensure_standard_descriptors()). Other failures to write show when the
   * results are committed (ResultDirectory::commit), which then does not
   * happen.
   */
  void
  check_standard_output_usable()
  {
    struct stat out = {}, full = {};
    if (::fstat(STDOUT_FILENO, &out) == 0 && S_ISCHR(out.st_mode)
        && ::stat("/dev/full", &full) == 0 && out.st_rdev == full.st_rdev)
      throw coaxfit::ResourceError(
        "standard output is /dev/full (or was closed): the report could not "
        "be shown; nothing was run or written");
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
    std::vector<std::string>                         filenames;
    bool                                             quiet = false;
    std::optional<std::string>                       sweep;
    std::string                                      table;
    unsigned int                                     jobs = 0; ///< 0: cores
  };

  /** The argument of option @p option at argv[i + 1]. */
  std::string
  option_argument(int &i, const int argc, char **argv, const char *what)
  {
    if (i + 1 >= argc)
      throw coaxfit::InputError(std::string(argv[i]) + " needs an argument "
                                + what);
    return argv[++i];
  }

  /**
   * Standard input, output and error open: a closed one is opened on
   * /dev/null (input) or /dev/full (output: writing fails and is reported
   * by the exit code), so that no file or pipe of the program takes its
   * number and receives what was meant for the console.
   */
  void
  ensure_standard_descriptors()
  {
    for (int fd = 0; fd < 3; ++fd)
      if (::fcntl(fd, F_GETFD) < 0 && errno == EBADF)
        ::open(fd == 0 ? "/dev/null" : "/dev/full",
               fd == 0 ? O_RDONLY : O_WRONLY);
  }

  /** @p path made absolute, normalized, symbolic links resolved. */
  std::filesystem::path
  resolved(const std::string &path)
  {
    std::error_code error;
    return std::filesystem::weakly_canonical(
      std::filesystem::absolute(coaxfit::normalized_directory(path)), error);
  }

  /** The output directory of a case of several files. */
  struct Target
  {
    std::filesystem::path resolved; ///< see resolved()
    std::string           given;    ///< as the parameters say
    std::string           file;     ///< the case's parameter file
  };

  /** Whether @p inner is @p outer or lies inside it. */
  bool
  is_within(const std::filesystem::path &inner,
            const std::filesystem::path &outer)
  {
    auto i = inner.begin();
    for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
      if (i == inner.end() || *i != *o)
        return false;
    return true;
  }

  /**
   * Check the table's file before any case runs: not an input file, not
   * in a case's output directory (each is replaced as a whole), not a
   * directory or device, and in a directory that can be written.
   */
  void
  check_table(const std::string              &table,
              const std::vector<std::string> &inputs,
              const std::vector<Target>      &targets)
  {
    using coaxfit::InputError;
    namespace fs           = std::filesystem;
    const fs::path    path = resolved(table);
    const std::string said = "--table " + table + ": ";
    std::error_code   error;
    const auto        status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status))
      throw InputError(said + "exists and is not a regular file");
    for (const std::string &input : inputs)
      if (fs::equivalent(path, input, error))
        throw InputError(said + "is the parameter file " + input
                         + ", read by this run");
    for (const Target &target : targets)
      if (is_within(path, target.resolved))
        throw InputError(said + "lies in " + target.given
                         + ", the output directory of " + target.file
                         + ", which its results replace as a whole");
    fs::path existing = path.parent_path();
    while (!existing.empty() && !fs::exists(existing, error))
      existing = existing.parent_path();
    // A file is really created there and removed (access() says yes to
    // root in /proc and on read-only mounts).
    std::string probe = (existing / ".coaxfit-table-probe-XXXXXX").string();
    const int   fd    = existing.empty() || !fs::is_directory(existing, error) ?
                          -1 :
                          ::mkstemp(probe.data());
    if (fd < 0)
      throw InputError(said + "cannot be written (" + existing.string()
                       + " is not a writable directory); nothing was run");
    ::close(fd);
    ::unlink(probe.c_str());
  }

  /**
   * The table of several files (--table, else cases.csv beside the first
   * readable case's output directory), checked before any case runs; and
   * the cases' directories: two that are one or lie in each other would
   * replace each other's results, so the whole batch is refused.
   */
  std::string
  batch_table(const CommandLine              &line,
              const std::vector<Target>      &targets,
              const std::vector<std::string> &inputs)
  {
    using coaxfit::InputError;
    for (unsigned int i = 0; i < targets.size(); ++i)
      for (unsigned int j = 0; j < i; ++j)
        {
          const Target &a = targets[i], &b = targets[j];
          if (is_within(a.resolved, b.resolved)
              || is_within(b.resolved, a.resolved))
            throw InputError(
              "parameter Output/Directory = " + a.given + " of " + a.file
              + (a.resolved == b.resolved          ? " is also that of " :
                 is_within(a.resolved, b.resolved) ? " lies in that of " :
                                                     " contains that of ")
              + b.file + " (" + b.given
              + "); each case needs a directory of its own, none inside "
                "another's; nothing was run");
        }
    std::string table = line.table;
    if (table.empty() && !targets.empty())
      {
        const std::filesystem::path first(
          coaxfit::normalized_directory(targets.front().given));
        table = (first.has_parent_path() ? first.parent_path() / "cases.csv" :
                                           std::filesystem::path("cases.csv"))
                  .string();
      }
    if (!table.empty())
      check_table(table, inputs, targets);
    return table;
  }



  /** Write the table @p text of several files to @p table (if any). */
  void
  write_table(const std::string &table, const std::string &text)
  {
    if (table.empty())
      {
        // No case could be read, so no output directory tells where.
        std::cout << "  table not written: no case could be read (give "
                     "--table FILE.csv to write it)"
                  << std::endl;
        return;
      }
    std::error_code error;
    std::filesystem::create_directories(
      std::filesystem::path(table).parent_path(), error);
    try
      {
        coaxfit::write_file_atomically(table, text);
      }
    catch (const std::exception &e)
      {
        throw coaxfit::ResourceError(
          std::string(e.what())
          + "; the table was not written, but the cases' own results "
            "are in place in their output directories");
      }
    std::cout << "  table in " << table << std::endl;
  }



  /** Whether @p file can be opened as a parameter file. */
  bool
  readable_file(const std::string &file)
  {
    return std::ifstream(file) && !std::filesystem::is_directory(file);
  }

  /** The cases of several files read, their directories and inputs. */
  template <typename Case>
  struct PreparedBatch
  {
    std::vector<Case>        cases;
    std::vector<Target>      targets;
    std::vector<std::string> inputs; ///< the files and their includes
  };

  /** Read the files of two bodies of @p line, one case each. */
  PreparedBatch<coaxfit::BatchCase>
  prepare_files(const CommandLine &line)
  {
    using namespace coaxfit;
    PreparedBatch<BatchCase> batch;
    batch.cases.resize(line.filenames.size());
    batch.inputs = line.filenames;
    for (unsigned int i = 0; i < batch.cases.size(); ++i)
      {
        BatchCase &c = batch.cases[i];
        c.label      = line.filenames[i];
        try
          {
            auto p = std::make_shared<Parameters>(
              read_parameters(line.filenames[i], line.overrides));
            batch.targets.push_back({resolved(p->output_directory()),
                                     p->output_directory(),
                                     line.filenames[i]});
            batch.inputs.insert(batch.inputs.end(),
                                p->files_read.begin(),
                                p->files_read.end());
            c.parameters = p;
          }
        catch (const InputError &e)
          {
            c.input_error = e.what();
          }
      }
    return batch;
  }

  /** Read the stack files (Assembly/Bodies) of @p line, one case each. */
  PreparedBatch<coaxfit::StackCase>
  prepare_stack_files(const CommandLine &line)
  {
    using namespace coaxfit;
    PreparedBatch<StackCase> batch;
    batch.cases.resize(line.filenames.size());
    batch.inputs = line.filenames;
    for (unsigned int i = 0; i < batch.cases.size(); ++i)
      {
        StackCase &c = batch.cases[i];
        c.label      = line.filenames[i];
        if (!readable_file(c.label))
          {
            c.input_error = "cannot read parameter file '" + c.label + "'";
            continue;
          }
        try
          {
            auto p = std::make_shared<StackParameters>(
              read_stack_parameters(line.filenames[i], line.overrides));
            batch.targets.push_back({resolved(p->output_directory()),
                                     p->output_directory(),
                                     line.filenames[i]});
            c.parameters = p;
          }
        catch (const InputError &e)
          {
            c.input_error = e.what();
          }
      }
    return batch;
  }

  /**
   * Run the cases @p batch by a @p Batch (CaseBatch for files of two
   * bodies, StackBatch for stacks: a row per joint) at most @p jobs at a
   * time, called @p what in the heading; the table printed and written to
   * @p table; the batch's exit code.
   */
  template <typename Batch, typename Case>
  int
  run_batch(const CommandLine         &line,
            const unsigned int         jobs,
            const PreparedBatch<Case> &batch,
            const std::string         &table,
            const std::string         &what)
  {
    const auto outcomes
      = Batch(jobs, !line.quiet, std::cout, std::cerr).run(batch.cases);
    std::cout << "\ncoaxfit: " << batch.cases.size() << ' ' << what << '\n';
    Batch::print_table(std::cout, batch.cases, outcomes);
    write_table(table, Batch::table_csv(batch.cases, outcomes));
    return Batch::exit_code(outcomes);
  }

  /**
   * Several files of two bodies: one case each, run by a CaseBatch; the
   * table printed and written; the batch's exit code.
   */
  int
  run_files(const CommandLine &line, const unsigned int jobs)
  {
    const auto batch = prepare_files(line);
    return run_batch<coaxfit::CaseBatch>(line,
                                         jobs,
                                         batch,
                                         batch_table(line,
                                                     batch.targets,
                                                     batch.inputs),
                                         "cases");
  }

  /**
   * Several stack files (Assembly/Bodies): one case each, run by a
   * StackBatch (at most @p jobs at a time); the table printed and written;
   * the batch's exit code.
   */
  int
  run_stack_files(const CommandLine &line, const unsigned int jobs)
  {
    const auto batch = prepare_stack_files(line);
    return run_batch<coaxfit::StackBatch>(line,
                                          jobs,
                                          batch,
                                          batch_table(line,
                                                      batch.targets,
                                                      batch.inputs),
                                          "stack cases");
  }

  /**
   * Files of two bodies @p plain and stack files @p stacks in one command:
   * every file read and every directory checked against all others first;
   * then the cases of two bodies run (their table in cases.csv or
   * --table) and the stacks (their table, a row per joint, beside it with
   * `_stacks` added to its name); the gravest exit code of both.
   */
  int
  run_mixed_files(const CommandLine              &line,
                  const unsigned int              jobs,
                  const std::vector<std::string> &plain,
                  const std::vector<std::string> &stacks)
  {
    CommandLine plain_line = line, stack_line = line;
    plain_line.filenames         = plain;
    stack_line.filenames         = stacks;
    const auto          two_body = prepare_files(plain_line);
    const auto          stack    = prepare_stack_files(stack_line);
    std::vector<Target> targets  = two_body.targets;
    targets.insert(targets.end(), stack.targets.begin(), stack.targets.end());
    std::vector<std::string> inputs = two_body.inputs;
    inputs.insert(inputs.end(), stack.inputs.begin(), stack.inputs.end());
    const std::string table = batch_table(line, targets, inputs);
    std::string       stack_table;
    if (!table.empty())
      {
        const std::filesystem::path path(table);
        stack_table
          = (path.parent_path()
             / (path.stem().string() + "_stacks" + path.extension().string()))
              .string();
        check_table(stack_table, inputs, targets);
      }
    const int a
      = run_batch<coaxfit::CaseBatch>(line, jobs, two_body, table, "cases");
    const int b = run_batch<coaxfit::StackBatch>(
      line, jobs, stack, stack_table, "stack cases");
    return std::max(a, b);
  }



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
        else if (arg == "--sweep")
          {
            if (line.sweep)
              throw InputError("--sweep given twice (one parameter is swept "
                               "at a time)");
            line.sweep
              = option_argument(i, argc, argv, "Section/Name=v1,v2,...");
          }
        else if (arg == "--table")
          line.table = option_argument(i, argc, argv, "FILE.csv");
        else if (arg == "--jobs" || arg == "-j")
          {
            const std::string n = option_argument(i, argc, argv, "N");
            if (n.empty() || n.size() > 4
                || n.find_first_not_of("0123456789") != std::string::npos
                || std::stoi(n) < 1 || std::stoi(n) > 1024)
              throw InputError("--jobs " + n
                               + ": expected a whole number from 1 to 1024");
            line.jobs = std::stoi(n);
          }
        else if (arg.size() > 1 && arg[0] == '-')
          throw InputError("unknown option '" + arg + "' (see coaxfit --help)");
        else
          line.filenames.push_back(arg);
      }
    if (line.action == CommandLine::Action::run && line.filenames.empty())
      throw InputError("no parameter file given (see coaxfit --help)");
    if (line.sweep && line.filenames.size() > 1)
      throw InputError("--sweep runs one parameter file ("
                       + std::to_string(line.filenames.size()) + " given)");
    if (!line.table.empty() && line.filenames.size() < 2)
      throw InputError("--table is the table of several parameter files "
                       "(a sweep writes sweep.csv into its directory)");
    return line;
  }
} // namespace



namespace
{
  /** The program: its exit code. */
  int
  coaxfit_main(int argc, char **argv)
  {
    using namespace coaxfit;
    return exit_code_of(
      [&]() {
        ensure_standard_descriptors();
        Interruption::install();
        const CommandLine line = parse_command_line(argc, argv);
        if (line.action == CommandLine::Action::help)
          std::cout << coaxfit::usage;
        else if (line.action == CommandLine::Action::print_parameters)
          try
            {
              // With a file of several bodies: that stack's entries.
              if (!line.filenames.empty()
                  && !assembly_bodies(line.filenames[0], {}).empty())
                print_stack_parameters(std::cout, line.filenames[0]);
              else
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

        check_standard_output_usable();
        const unsigned int jobs = line.jobs > 0 ? line.jobs : available_cores();
        // Several files: stacks (Assembly/Bodies), files of two bodies,
        // or both kinds, each kind a batch of its own (their tables
        // differ).
        if (line.filenames.size() > 1)
          {
            // others: every file that is not a stack, those that cannot be
            // read included (the batch of two bodies reports them).
            std::vector<std::string> stacks, others;
            bool                     two_body = false;
            for (const std::string &file : line.filenames)
              {
                bool stack = false;
                // A file that cannot be read is its case's to report.
                if (readable_file(file))
                  try
                    {
                      stack    = !assembly_bodies(file, line.overrides).empty();
                      two_body = two_body || !stack;
                    }
                  catch (const InputError &)
                    {}
                (stack ? stacks : others).push_back(file);
              }
            if (!stacks.empty() && two_body)
              {
                const int code = run_mixed_files(line, jobs, others, stacks);
                check_standard_output();
                return code;
              }
            if (!stacks.empty())
              {
                const int code = run_stack_files(line, jobs);
                check_standard_output();
                return code;
              }
          }
        const std::vector<std::string> bodies
          = line.filenames.size() == 1 ?
              assembly_bodies(line.filenames[0], line.overrides) :
              std::vector<std::string>();
        if (!bodies.empty() && line.sweep)
          {
            const int code = StackSweep(line.filenames[0],
                                        line.overrides,
                                        SweepSpec::parse(*line.sweep),
                                        !line.quiet,
                                        std::cout)
                               .run();
            check_standard_output();
            return code;
          }
        if (!bodies.empty())
          {
            const StackParameters parameters
              = read_stack_parameters(line.filenames[0], line.overrides);
            if (parameters.fit_case == "all")
              {
                const int code = StackCaseStudy(line.filenames[0],
                                                line.overrides,
                                                !line.quiet,
                                                std::cout)
                                   .run();
                check_standard_output();
                return code;
              }
            StackFit  fit(parameters);
            const int code = fit.run(std::cout, !line.quiet);
            check_standard_output();
            if (code == 2)
              std::cerr << "coaxfit: the staggered process of the stack did "
                           "not converge in Coupling/Max steps = "
                        << parameters.max_steps
                        << " steps; raise it or set Solver/Method = "
                           "monolithic"
                        << std::endl;
            return code;
          }
        // An elastic-plastic fit runs on its own (checked up front, so
        // that a study is refused in one line).
        if (line.sweep || line.filenames.size() > 1)
          for (const std::string &file : line.filenames)
            {
              // A file that cannot be read is the study's to report, case
              // by case, as it does.
              bool plastic = false, hub = false;
              try
                {
                  const Parameters p = read_parameters(file, line.overrides);
                  plastic            = p.shaft.plastic || p.hub.plastic;
                  hub                = p.hub.plastic;
                }
              catch (const std::exception &)
                {}
              if (plastic)
                throw InputError(
                  "parameter Material/" + std::string(hub ? "Hub" : "Shaft")
                  + "/Plasticity = von Mises in '" + file
                  + "': an elastic-plastic fit runs on its own in this "
                    "version (one parameter file, no --sweep); allowed in "
                    "a study is Plasticity = none");
            }
        if (line.sweep)
          {
            const int code = ParameterSweep(line.filenames[0],
                                            line.overrides,
                                            SweepSpec::parse(*line.sweep),
                                            jobs,
                                            !line.quiet,
                                            std::cout,
                                            std::cerr)
                               .run();
            check_standard_output();
            return code;
          }
        if (line.filenames.size() > 1)
          {
            const int code = run_files(line, jobs);
            check_standard_output();
            return code;
          }

        const Parameters parameters
          = read_parameters(line.filenames[0], line.overrides);
        if ((parameters.shaft.plastic || parameters.hub.plastic)
            && parameters.design.mode == DesignMode::check)
          {
            // A body that may yield: the load path of PlasticFit (which
            // hands a fit that stays elastic to the elastic code).
            PlasticFit fit(parameters, std::cout, !line.quiet);
            const int  code = fit.run();
            check_standard_output();
            return code;
          }
        const CaseFigures figures
          = run_case(parameters, std::cout, !line.quiet);
        check_standard_output();
        if (!figures.converged)
          std::cerr << not_converged_message(parameters) << std::endl;
        return figures.converged ? 0 : 2;
      },
      std::cerr);
  }
} // namespace



/**
 * The program's entry, called by the launcher (source/app/launcher/main.cc)
 * once it has loaded this module. It ends the process with its exit code
 * (std::_Exit after flushing the streams, without the libraries' exit
 * handlers: OpenBLAS's never returns when its threads could not get their
 * buffers under an address space limit).
 */
extern "C" [[noreturn]] __attribute__((visibility("default"))) void
coaxfit_app_main(int argc, char **argv)
{
  const int code = coaxfit_main(argc, argv);
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(code);
}
