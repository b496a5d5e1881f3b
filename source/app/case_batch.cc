#include <deal.II/base/multithread_info.h>

#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/fit_selection_study.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/app/run_guard.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sched.h>
#include <sstream>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

namespace coaxfit
{
  std::vector<std::string>
  CaseFigures::column_names()
  {
    return {"pressure_mid_plane_MPa",
            "pressure_mean_MPa",
            "pressure_din_MPa",
            "torque_capacity_Nm",
            "torque_capacity_din_Nm",
            "safety_slip",
            "safety_yield_hub",
            "safety_yield_shaft",
            "safety_yield_hub_assembly",
            "safety_yield_shaft_assembly"};
  }



  std::string
  CaseFigures::serialize() const
  {
    std::ostringstream s;
    s << std::setprecision(17) << (converged ? 1 : 0) << ' ' << steps << ' '
      << (no_fit ? 1 : 0);
    for (const double v : values)
      s << ' ' << (std::isfinite(v) ? v : std::nan(""));
    return s.str();
  }



  CaseFigures
  CaseFigures::parse(const std::string &text)
  {
    std::istringstream s(text);
    CaseFigures        f;
    int                converged = 0, no_fit = 0;
    s >> converged >> f.steps >> no_fit;
    f.converged = converged == 1;
    f.no_fit    = no_fit == 1;
    std::string word;
    while (s >> word)
      f.values.push_back(word == "nan" || word == "-nan" ? std::nan("") :
                                                           std::stod(word));
    if (!s.eof() || f.values.size() != column_names().size())
      throw std::runtime_error("unreadable figures from a case: '" + text
                               + "'");
    return f;
  }



  CaseFigures
  run_case(const Parameters  &parameters,
           std::ostream      &out,
           const bool         verbose,
           const std::string &directory,
           CoaxialFit        *prepared)
  {
    CaseFigures figures;
    // A selection of a fit whose hub may yield is one of a single file
    // (main refuses it in a study up front).
    if ((parameters.shaft.plastic || parameters.hub.plastic)
        && parameters.design.mode != DesignMode::select)
      throw InputError(
        "parameter Material/"
        + std::string(parameters.hub.plastic ? "Hub" : "Shaft")
        + "/Plasticity = von Mises: an elastic-plastic fit runs on its own "
          "in this version (one parameter file, no --sweep, not one case of "
          "several files); allowed in a study is Plasticity = none");
    if (parameters.design.mode == DesignMode::select)
      {
        // A case of a sweep: into the sweep's directory; a prepared case
        // is not used (the selection sets up its own).
        if (!directory.empty())
          check_memory(parameters);
        FitSelectionStudy study(parameters, out, verbose);
        figures.converged
          = directory.empty() ? study.run() : study.run_in(directory);
        figures.steps  = study.mean_case_steps();
        figures.values = study.mean_case_values();
        figures.no_fit = figures.values.empty();
        if (figures.values.empty())
          figures.values.assign(CaseFigures::column_names().size(),
                                std::nan(""));
        return figures;
      }
    if (parameters.fit.fit_case == FitCase::all)
      {
        if (!directory.empty())
          throw InputError("Fit/Case = all cannot be a case of a study; "
                           "give Fit/Case = min, mean or max");
        FitCaseStudy study(parameters, out, verbose);
        figures.converged = study.run();
        for (const FitCaseStudy::Row &row : study.get_rows())
          if (row.fit_case == FitCase::mean)
            {
              figures.steps = row.steps;
              figures.values
                = FitCaseStudy::values_of(row, CaseFigures::column_names());
            }
        return figures;
      }
    std::unique_ptr<CoaxialFit> own;
    if (prepared)
      prepared->reuse_for(parameters);
    else
      {
        if (!directory.empty())
          check_memory(parameters);
        own = std::make_unique<CoaxialFit>(parameters, out, verbose);
      }
    CoaxialFit &fit    = prepared ? *prepared : *own;
    figures.converged  = directory.empty() ? fit.run() : fit.run_in(directory);
    const FitDesign &d = fit.get_design();
    figures.steps      = fit.get_coupling().n_steps();
    figures.values     = {fit.pressure_summary().at_mid_plane,
                          d.mean_pressure,
                          d.pressure_din,
                          d.torque_capacity,
                          d.torque_capacity_din,
                          d.safety_slip,
                          d.safety_yield_hub,
                          d.safety_yield_shaft,
                          d.safety_yield_hub_assembly,
                          d.safety_yield_shaft_assembly};
    return figures;
  }



  unsigned int
  available_cores()
  {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof(set), &set) == 0)
      return std::max(1, CPU_COUNT(&set));
    return std::max(1u, dealii::MultithreadInfo::n_cores());
  }



  void
  write_file_atomically(const std::string &filename, const std::string &text)
  {
    const std::string temporary
      = filename + ".partial-" + std::to_string(::getpid());
    const int fd = ::open(temporary.c_str(),
                          O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC,
                          0644);
    if (fd < 0)
      throw ResourceError("cannot write '" + filename
                          + "': " + std::strerror(errno));
    std::size_t written = 0;
    while (written < text.size())
      {
        const ssize_t n
          = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          break;
        written += n;
      }
    const bool ok = written == text.size() && ::fsync(fd) == 0;
    ::close(fd);
    if (!ok || std::rename(temporary.c_str(), filename.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw ResourceError("writing '" + filename
                            + "' failed: disk full, quota or file size limit "
                              "reached (the earlier file is untouched)");
      }
  }



  namespace
  {
    /** An anonymous file for what a child prints and reports. */
    int
    anonymous_file(const char *name)
    {
      const int fd = ::memfd_create(name, MFD_CLOEXEC);
      if (fd < 0)
        throw ResourceError(std::string("cannot create a buffer for a case: ")
                            + std::strerror(errno));
      return fd;
    }

    /** Everything written to @p fd, from its start. */
    std::string
    contents(const int fd)
    {
      std::string text;
      char        buffer[65536];
      ::lseek(fd, 0, SEEK_SET);
      for (;;)
        {
          const ssize_t n = ::read(fd, buffer, sizeof(buffer));
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            break;
          text.append(buffer, n);
        }
      return text;
    }

    /** The last non-empty line of @p text. */
    std::string
    last_line(const std::string &text)
    {
      std::istringstream s(text);
      std::string        line, last;
      while (std::getline(s, line))
        if (!line.empty())
          last = line;
      return last;
    }

    /**
     * The child's work: run the case with its output going to @p out_fd,
     * @p err_fd and its figures to @p row_fd; never returns. It ends when
     * the process @p parent does.
     */
    [[noreturn]] void
    run_child(const BatchCase &c,
              const int        parent,
              const bool       one_thread,
              const bool       verbose,
              const int        out_fd,
              const int        err_fd,
              const int        row_fd)
    {
      int code = 3;
      try
        {
          Interruption::restart_after_fork(parent);
          if (::dup2(out_fd, STDOUT_FILENO) < 0
              || ::dup2(err_fd, STDERR_FILENO) < 0)
            _exit(3);
          if (one_thread)
            dealii::MultithreadInfo::set_thread_limit(1);
          code = exit_code_of(
            [&]() {
              const CaseFigures figures = run_case(
                *c.parameters, std::cout, verbose, c.directory, c.prepared);
              std::cout.flush();
              const std::string row = figures.serialize();
              if (::write(row_fd, row.data(), row.size())
                  != static_cast<ssize_t>(row.size()))
                throw ResourceError("cannot pass the figures of the case on");
              if (!figures.converged)
                std::cerr << not_converged_message(*c.parameters) << std::endl;
              return figures.converged ? 0 : 2;
            },
            std::cerr);
        }
      catch (...)
        {
          code = 3;
        }
      std::cout.flush();
      std::cerr.flush();
      _exit(code);
    }
  } // namespace



  CaseBatch::CaseBatch(const unsigned int jobs,
                       const bool         verbose,
                       std::ostream      &out,
                       std::ostream      &err)
    : jobs(std::max(1u, jobs))
    , verbose(verbose)
    , out(out)
    , err(err)
  {}



  std::vector<CaseOutcome>
  CaseBatch::run(const std::vector<BatchCase> &cases)
  {
    using Clock = std::chrono::steady_clock;
    struct Running
    {
      unsigned int      index;
      int               out_fd, err_fd, row_fd;
      Clock::time_point start;
    };
    std::vector<CaseOutcome> outcomes(cases.size());
    std::vector<std::string> printed_out(cases.size()),
      printed_err(cases.size());
    std::vector<bool>      done(cases.size(), false);
    std::map<int, Running> running; // by process id
    unsigned int           next = 0, next_to_print = 0;
    const bool             one_thread = jobs > 1 && cases.size() > 1;

    auto print_finished = [&]() {
      while (next_to_print < cases.size() && done[next_to_print])
        {
          if (verbose)
            out << printed_out[next_to_print];
          out.flush();
          std::istringstream lines(printed_err[next_to_print]);
          for (std::string line; std::getline(lines, line);)
            err << cases[next_to_print].label << ": " << line << '\n';
          err.flush();
          ++next_to_print;
        }
    };

    while (next < cases.size() || !running.empty())
      {
        // Start cases while there are cores for them.
        while (next < cases.size() && running.size() < jobs)
          {
            const unsigned int i = next++;
            const BatchCase   &c = cases[i];
            if (!c.parameters)
              {
                outcomes[i].exit_code = 1;
                outcomes[i].error     = "coaxfit: error: " + c.input_error;
                printed_err[i]        = outcomes[i].error + '\n';
                done[i]               = true;
                continue;
              }
            Running r{i,
                      anonymous_file("coaxfit-case-out"),
                      anonymous_file("coaxfit-case-err"),
                      anonymous_file("coaxfit-case-row"),
                      Clock::now()};
            out.flush();
            err.flush();
            std::cout.flush();
            std::cerr.flush();
            std::unique_lock<std::mutex> lock(Interruption::mutex());
            const pid_t                  parent = ::getpid();
            const pid_t                  pid    = ::fork();
            if (pid == 0)
              {
                lock.unlock();
                run_child(
                  c, parent, one_thread, verbose, r.out_fd, r.err_fd, r.row_fd);
              }
            if (pid < 0)
              {
                const int error = errno;
                lock.unlock();
                for (const int fd : {r.out_fd, r.err_fd, r.row_fd})
                  ::close(fd);
                outcomes[i].exit_code = 3;
                outcomes[i].error = std::string("coaxfit: error: cannot start "
                                                "a process for the case: ")
                                    + std::strerror(error);
                printed_err[i] = outcomes[i].error + '\n';
                done[i]        = true;
                continue;
              }
            Interruption::add_child(pid);
            lock.unlock();
            running.emplace(pid, r);
          }
        print_finished();
        if (running.empty())
          continue;

        // Wait for any case to end.
        int         status = 0;
        const pid_t pid    = ::waitpid(-1, &status, 0);
        if (pid < 0)
          {
            if (errno == EINTR)
              continue;
            throw std::runtime_error(std::string("waiting for a case: ")
                                     + std::strerror(errno));
          }
        const auto found = running.find(pid);
        if (found == running.end())
          continue; // not a case (e.g. a helper of the libraries)
        {
          std::lock_guard<std::mutex> lock(Interruption::mutex());
          Interruption::remove_child(pid);
        }
        const Running r       = found->second;
        CaseOutcome  &outcome = outcomes[r.index];
        running.erase(found);
        outcome.wall
          = std::chrono::duration<double>(Clock::now() - r.start).count();
        printed_out[r.index]  = contents(r.out_fd);
        printed_err[r.index]  = contents(r.err_fd);
        const std::string row = contents(r.row_fd);
        for (const int fd : {r.out_fd, r.err_fd, r.row_fd})
          ::close(fd);
        if (WIFEXITED(status))
          outcome.exit_code = WEXITSTATUS(status);
        else
          {
            // Killed (e.g. by the kernel's out-of-memory killer): the case
            // could not clean up; its staging directory is removed here (a
            // case of a study writes into the study's, removed below).
            outcome.exit_code  = 3;
            const BatchCase &c = cases[r.index];
            if (c.directory.empty())
              {
                std::error_code ignored;
                std::filesystem::remove_all(
                  staging_directory_of(c.parameters->output_directory(), pid),
                  ignored);
              }
            printed_err[r.index]
              += "coaxfit: error: the case's process was killed by signal "
                 + std::to_string(WTERMSIG(status)) + " ("
                 + strsignal(WTERMSIG(status)) + ")\n";
          }
        outcome.error = last_line(printed_err[r.index]);
        if (!row.empty())
          outcome.figures = CaseFigures::parse(row);
        done[r.index] = true;
        print_finished();
      }
    print_finished();
    return outcomes;
  }



  int
  CaseBatch::exit_code(const std::vector<CaseOutcome> &outcomes)
  {
    int worst = 0;
    for (const int code : {1, 2, 3})
      for (const CaseOutcome &o : outcomes)
        if (o.exit_code == code)
          worst = code;
    for (const CaseOutcome &o : outcomes)
      if (o.exit_code != 0 && o.exit_code != 1 && o.exit_code != 2)
        worst = 3;
    return worst;
  }



  namespace
  {
    std::string
    status_of(const CaseOutcome &o)
    {
      switch (o.exit_code)
        {
          case 0:
            return o.figures.no_fit ? "no fit" : "converged";
          case 1:
            return "bad input";
          case 2:
            return o.figures.values.empty() ? "diverged" : "not converged";
          default:
            return "failed";
        }
    }

  } // namespace



  std::string
  CaseBatch::table_csv(const std::vector<BatchCase>   &cases,
                       const std::vector<CaseOutcome> &outcomes,
                       const std::string              &key_name,
                       const std::vector<std::string> &keys)
  {
    std::ostringstream csv;
    csv << std::setprecision(15);
    if (!key_name.empty())
      csv << csv_field(key_name) << ',';
    csv << "case,exit_code,status,steps";
    for (const std::string &name : CaseFigures::column_names())
      csv << ',' << name;
    csv << ",wall_s,directory,error\n";
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const CaseOutcome &o = outcomes[i];
        if (!key_name.empty())
          csv << csv_field(keys[i]) << ',';
        csv << csv_field(cases[i].label) << ',' << o.exit_code << ','
            << status_of(o) << ',';
        if (!o.figures.values.empty())
          csv << o.figures.steps;
        for (unsigned int k = 0; k < CaseFigures::column_names().size(); ++k)
          {
            csv << ',';
            if (k < o.figures.values.size()
                && std::isfinite(o.figures.values[k]))
              csv << o.figures.values[k];
          }
        csv << ',' << std::setprecision(4) << o.wall << std::setprecision(15)
            << ','
            << csv_field(!cases[i].parameters || o.figures.values.empty() ?
                           "" :
                         cases[i].directory.empty() ?
                           cases[i].parameters->output_directory() :
                           cases[i].parameters->output.directory)
            << ',' << csv_field(o.exit_code == 0 ? "" : o.error) << '\n';
      }
    return csv.str();
  }



  void
  CaseBatch::print_table(std::ostream                   &out,
                         const std::vector<BatchCase>   &cases,
                         const std::vector<CaseOutcome> &outcomes)
  {
    std::size_t width = 4;
    for (const BatchCase &c : cases)
      width = std::max(width, c.label.size());
    width = std::min<std::size_t>(width, 40);
    out << std::left << std::setw(width + 2) << "case" << std::right
        << std::setw(5) << "exit" << std::setw(15) << "status" << std::setw(6)
        << "steps" << std::setw(11) << "p(0) MPa" << std::setw(11) << "p_m MPa"
        << std::setw(11) << "p_DIN MPa" << std::setw(12) << "T N m"
        << std::setw(8) << "S_slip" << std::setw(8) << "wall s" << '\n';
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const CaseOutcome &o = outcomes[i];
        const std::string  label
          = cases[i].label.size() > width ?
              "..." + cases[i].label.substr(cases[i].label.size() - width + 3) :
              cases[i].label;
        out << std::left << std::setw(width + 2) << label << std::right
            << std::setw(5) << o.exit_code << std::setw(15) << status_of(o);
        if (o.figures.values.empty())
          out << std::setw(6) << "-" << std::setw(11) << "-" << std::setw(11)
              << "-" << std::setw(11) << "-" << std::setw(12) << "-"
              << std::setw(8) << "-";
        else
          {
            const std::vector<double> &v = o.figures.values;
            // p(0), mean, DIN, torque, slip safety: "-" where undefined.
            const std::vector<std::pair<unsigned int, int>> shown{
              {0, 11}, {1, 11}, {2, 11}, {3, 12}, {5, 8}};
            out << std::setw(6) << o.figures.steps;
            for (const auto &[k, width] : shown)
              if (std::isfinite(v[k]))
                out << std::fixed << std::setprecision(k == 3 ? 1 : 2)
                    << std::setw(width) << v[k];
              else
                out << std::setw(width) << "-";
          }
        out << std::fixed << std::setprecision(2) << std::setw(8) << o.wall
            << '\n';
        out.unsetf(std::ios::floatfield);
      }
  }
} // namespace coaxfit
