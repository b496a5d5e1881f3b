#include <deal.II/base/multithread_info.h>

#include <coaxfit/app/process_pool.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_directory.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

namespace coaxfit
{
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
     * The child's work: task @p index with its output going to @p out_fd,
     * @p err_fd and its row to @p row_fd; never returns. It ends when the
     * process @p parent does.
     */
    [[noreturn]] void
    run_child(const ProcessPool::Work &work,
              const unsigned int       index,
              const int                parent,
              const bool               one_thread,
              const int                out_fd,
              const int                err_fd,
              const int                row_fd)
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
          std::string row;
          code = work(index, row);
          std::cout.flush();
          if (!row.empty()
              && ::write(row_fd, row.data(), row.size())
                   != static_cast<ssize_t>(row.size()))
            {
              std::cerr << "coaxfit: error: cannot pass the figures of the "
                           "case on"
                        << std::endl;
              code = 3;
            }
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



  ProcessPool::ProcessPool(const unsigned int jobs,
                           const bool         verbose,
                           std::ostream      &out,
                           std::ostream      &err)
    : jobs(std::max(1u, jobs))
    , verbose(verbose)
    , out(out)
    , err(err)
  {}



  std::vector<PoolResult>
  ProcessPool::run(const std::vector<PoolTask> &tasks, const Work &work) const
  {
    using Clock = std::chrono::steady_clock;
    struct Running
    {
      unsigned int      index;
      int               out_fd, err_fd, row_fd;
      Clock::time_point start;
    };
    std::vector<PoolResult>  results(tasks.size());
    std::vector<std::string> printed_out(tasks.size()),
      printed_err(tasks.size());
    std::vector<bool>      done(tasks.size(), false);
    std::map<int, Running> running; // by process id
    unsigned int           next = 0, next_to_print = 0;
    const bool             one_thread = jobs > 1 && tasks.size() > 1;

    auto print_finished = [&]() {
      while (next_to_print < tasks.size() && done[next_to_print])
        {
          if (verbose)
            out << printed_out[next_to_print];
          out.flush();
          std::istringstream lines(printed_err[next_to_print]);
          for (std::string line; std::getline(lines, line);)
            err << tasks[next_to_print].label << ": " << line << '\n';
          err.flush();
          ++next_to_print;
        }
    };

    while (next < tasks.size() || !running.empty())
      {
        // Start tasks while there are cores for them.
        while (next < tasks.size() && running.size() < jobs)
          {
            const unsigned int i = next++;
            const PoolTask    &t = tasks[i];
            if (!t.refusal.empty())
              {
                results[i].exit_code = 1;
                results[i].error     = t.refusal;
                printed_err[i]       = t.refusal + '\n';
                done[i]              = true;
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
                  work, i, parent, one_thread, r.out_fd, r.err_fd, r.row_fd);
              }
            if (pid < 0)
              {
                const int error = errno;
                lock.unlock();
                for (const int fd : {r.out_fd, r.err_fd, r.row_fd})
                  ::close(fd);
                results[i].exit_code = 3;
                results[i].error = std::string("coaxfit: error: cannot start "
                                               "a process for the case: ")
                                   + std::strerror(error);
                printed_err[i] = results[i].error + '\n';
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

        // Wait for any task to end.
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
          continue; // not a task (e.g. a helper of the libraries)
        {
          std::lock_guard<std::mutex> lock(Interruption::mutex());
          Interruption::remove_child(pid);
        }
        const Running r      = found->second;
        PoolResult   &result = results[r.index];
        running.erase(found);
        result.wall
          = std::chrono::duration<double>(Clock::now() - r.start).count();
        printed_out[r.index] = contents(r.out_fd);
        printed_err[r.index] = contents(r.err_fd);
        result.row           = contents(r.row_fd);
        for (const int fd : {r.out_fd, r.err_fd, r.row_fd})
          ::close(fd);
        if (WIFEXITED(status))
          result.exit_code = WEXITSTATUS(status);
        else
          {
            // Killed (e.g. by the kernel's out-of-memory killer): the task
            // could not clean up; its staging directory is removed here (a
            // case of a study writes into the study's, removed by it).
            result.exit_code  = 3;
            const PoolTask &t = tasks[r.index];
            if (!t.output_directory.empty())
              {
                std::error_code ignored;
                std::filesystem::remove_all(
                  staging_directory_of(t.output_directory, pid), ignored);
              }
            printed_err[r.index]
              += "coaxfit: error: the case's process was killed by signal "
                 + std::to_string(WTERMSIG(status)) + " ("
                 + strsignal(WTERMSIG(status)) + ")\n";
          }
        result.error  = last_line(printed_err[r.index]);
        done[r.index] = true;
        print_finished();
      }
    print_finished();
    return results;
  }
} // namespace coaxfit
