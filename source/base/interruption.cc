#include <coaxfit/base/interruption.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace coaxfit
{
  namespace Interruption
  {
    namespace
    {
      std::string   staging_directory;
      std::string   target_directory;
      bool          committed = false;
      std::set<int> children;

      /** Written by the signal handler, read by the watcher thread. */
      int signal_pipe[2] = {-1, -1};

      /**
       * The handler does the one async-signal-safe thing: pass the signal
       * number on to the watcher thread through the pipe.
       */
      extern "C" void
      handle_signal(const int signal)
      {
        const unsigned char number = static_cast<unsigned char>(signal);
        (void)!::write(signal_pipe[1], &number, 1);
      }

      /** Remove @p path, retrying while the main thread still adds files. */
      void
      remove_directory(const std::string &path)
      {
        for (unsigned int attempt = 0; attempt < 10; ++attempt)
          {
            std::error_code error;
            std::filesystem::remove_all(path, error);
            if (!error)
              return;
          }
      }

      [[noreturn]] void
      watch()
      {
        unsigned char number = 0;
        while (::read(signal_pipe[0], &number, 1) != 1)
          ;
        const int                   signal = number;
        std::lock_guard<std::mutex> lock(mutex());
        std::string                 message = interrupted_line(signal);
        // Running cases end first, each removing its own staging.
        for (const int child : children)
          ::kill(child, signal);
        for (const int child : children)
          {
            int status = 0;
            while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
              ;
          }
        if (committed)
          message += "; the results are complete in " + target_directory;
        else if (!staging_directory.empty())
          message += "; nothing written, the earlier results in "
                     + target_directory + " are untouched";
        if (!staging_directory.empty())
          remove_directory(staging_directory);
        message += '\n';
        // The main thread may be writing to std::cout: bypass the streams.
        (void)!write(STDERR_FILENO, message.data(), message.size());
        _exit(128 + signal);
      }
    } // namespace



    std::mutex &
    mutex()
    {
      static std::mutex m;
      return m;
    }



    void
    set_staging(const std::string &staging, const std::string &target)
    {
      // A run begins (or ends): nothing of it is committed yet (a batch
      // runs several, one after the other).
      staging_directory = staging;
      target_directory  = target;
      committed         = false;
    }



    void
    set_committed()
    {
      committed = true;
    }



    void
    restart_after_fork(const int parent)
    {
      // A case dies with its parent (also by SIGKILL, which cannot pass
      // the signal on): SIGTERM when the parent's forking thread ends. That
      // thread waits for every case before it returns (CaseBatch::run), so
      // it ends before its cases only when the process dies. The watcher
      // of this process is started below, so the signal removes the
      // case's staging directory like any SIGTERM.
      if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0)
        throw std::runtime_error("cannot tie the case to its parent");
      ::close(signal_pipe[0]);
      ::close(signal_pipe[1]);
      staging_directory.clear();
      target_directory.clear();
      committed = false;
      children.clear();
      install();
      // The parent may have died before PR_SET_PDEATHSIG took effect.
      if (::getppid() != parent)
        handle_signal(SIGTERM);
    }



    void
    add_child(const int pid)
    {
      children.insert(pid);
    }



    void
    remove_child(const int pid)
    {
      children.erase(pid);
    }



    void
    install()
    {
      if (::pipe2(signal_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("cannot create the signal pipe");
      struct sigaction action = {};
      action.sa_handler       = handle_signal;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      for (const int signal : {SIGINT, SIGTERM, SIGHUP})
        if (::sigaction(signal, &action, nullptr) != 0)
          throw std::runtime_error("cannot install the signal handlers");
      std::signal(SIGXFSZ, SIG_IGN);
      // A closed standard output (`coaxfit ... | head -1`) is a failed write
      // the run reports (exit 3, its staging directory removed), not a
      // death by SIGPIPE that leaves the staging directory behind.
      std::signal(SIGPIPE, SIG_IGN);
      std::thread(watch).detach();
    }
  } // namespace Interruption
} // namespace coaxfit
