// Shared by the tests that drive the coaxfit executable: run it with an
// output directory and arguments, capture its standard error.
#ifndef coaxfit_tests_run_executable_h
#define coaxfit_tests_run_executable_h

#include <cstdio>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace coaxfit_test
{
  /** The coaxfit executable of this test's own build flavour. */
#ifdef DEBUG
  inline const char *const coaxfit_executable = COAXFIT_EXECUTABLE_DEBUG;
#else
  inline const char *const coaxfit_executable = COAXFIT_EXECUTABLE_RELEASE;
#endif

  /** What one run of the executable left behind. */
  struct RunResult
  {
    int          exit_code; ///< -1 if killed by a signal
    std::string  message;   ///< standard error
    unsigned int lines;     ///< lines of standard error
  };

  /**
   * Run a shell @p command whose standard output is the text to capture
   * (redirect as needed); return its exit code and that text.
   */
  inline RunResult
  run_command(const std::string &command)
  {
    FILE       *pipe = popen(command.c_str(), "r");
    std::string message;
    char        buffer[4096];
    while (fgets(buffer, sizeof(buffer), pipe))
      message += buffer;
    const int    status = pclose(pipe);
    unsigned int lines  = 0;
    for (const char c : message)
      lines += (c == '\n');
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, message, lines};
  }

  /**
   * Run `timeout 60 coaxfit --set Output/Directory=DIR ARGUMENTS`, discard
   * standard output, return exit code and standard error.
   */
  inline RunResult
  run_coaxfit(const std::string &directory, const std::string &arguments)
  {
    return run_command("timeout 60 " + std::string(coaxfit_executable)
                       + " --set Output/Directory=" + directory + " "
                       + arguments + " 2>&1 >/dev/null");
  }

  /**
   * The first @p words words of @p message: what a message says, without
   * the paths and numbers that follow.
   */
  inline std::string
  gist(const std::string &message, const std::size_t words)
  {
    std::istringstream in(message);
    std::string        word, out;
    for (std::size_t i = 0; i < words && in >> word; ++i)
      out += (i ? " " : "") + word;
    return out;
  }
} // namespace coaxfit_test

#endif
