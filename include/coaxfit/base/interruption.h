#ifndef coaxfit_interruption_h
#define coaxfit_interruption_h

#include <csignal>
#include <mutex>
#include <string>

namespace coaxfit
{
  /**
   * SIGINT, SIGTERM and SIGHUP, handled so that an interrupted run never
   * leaves a half-written result.
   *
   * install() sets a handler for these signals that only writes the signal
   * number into a pipe (the one async-signal-safe step; any thread may
   * receive the signal, including the libraries' own threads started before
   * main), and starts one watcher thread that reads the pipe. On a signal
   * the watcher takes the commit mutex (so a ResultDirectory that is
   * moving its files into place finishes first), removes the staging
   * directory of the run if there is one, prints one line and ends the
   * process with exit code 128 + the signal number (130 for SIGINT, 143
   * for SIGTERM). install() also ignores SIGXFSZ, so that exceeding a file
   * size limit is a write error that the writers report rather than a
   * signal that kills the run.
   */
  namespace Interruption
  {
    /**
     * The line printed when @p signal (SIGINT, SIGTERM or SIGHUP) ends the
     * process, without its newline; a string literal, so that the
     * launcher's async-signal-safe handler can write it too.
     */
    constexpr const char *
    interrupted_line(const int signal)
    {
      return signal == SIGINT  ? "coaxfit: interrupted by SIGINT" :
             signal == SIGTERM ? "coaxfit: interrupted by SIGTERM" :
                                 "coaxfit: interrupted by SIGHUP";
    }

    /** Set the handlers and start the watcher (once, first in main). */
    void
    install();

    /**
     * The mutex held while the staging directory is created, moved into
     * place or removed; the watcher takes it before it cleans up.
     */
    std::mutex &
    mutex();

    /**
     * The staging directory to remove on a signal (empty: none) and the
     * target its results go to, for the message. Call with mutex() held.
     */
    void
    set_staging(const std::string &staging, const std::string &target);

    /** Note that the results are in place (for the message). */
    void
    set_committed();

    /**
     * In a child process made by fork(): a watcher and a pipe of its own
     * (threads do not survive fork, and the parent's pipe is the
     * parent's), no staging directory and no children yet. The child is
     * ended by SIGTERM (handled as any SIGTERM) when its parent @p parent
     * dies, even by SIGKILL: fork from a thread that outlives the child.
     */
    void
    restart_after_fork(int parent);

    /**
     * Note a child process running a case (call with mutex() held): on a
     * signal the watcher passes the signal on to it and waits for it to
     * end before it cleans up and ends this process.
     */
    void
    add_child(int pid);

    /** The child has ended (call with mutex() held). */
    void
    remove_child(int pid);
  } // namespace Interruption
} // namespace coaxfit

#endif
