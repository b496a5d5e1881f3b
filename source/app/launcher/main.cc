// The coaxfit command: a launcher that answers --help itself and loads the
// program (libcoaxfit_app.so beside it, with deal.II and its ~200 libraries)
// only for everything else. Loading and relocating those libraries takes
// about 0.2 s before main(); --help does not need them.

#include <coaxfit/app/usage.h>
#include <coaxfit/base/interruption.h>

#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <string>
#include <unistd.h>

namespace
{
  /** The directory of this executable (symbolic links resolved). */
  std::string
  own_directory()
  {
    char      path[PATH_MAX];
    const int n = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
    if (n <= 0)
      return ".";
    path[n]                 = '\0';
    const std::string whole = path;
    return whole.substr(0, whole.find_last_of('/'));
  }

  /**
   * SIGINT, SIGTERM or SIGHUP while the program loads (about 0.3 s; before
   * the program installs its own handlers, see interruption.h): the same
   * line and exit code (128 + signal) as later, when nothing was staged.
   * Nothing has been written yet. Only async-signal-safe calls.
   */
  extern "C" void
  interrupted_while_loading(const int signal)
  {
    const char *text   = coaxfit::Interruption::interrupted_line(signal);
    std::size_t length = 0;
    while (text[length] != '\0')
      ++length;
    (void)!::write(STDERR_FILENO, text, length);
    (void)!::write(STDERR_FILENO, "\n", 1);
    ::_exit(128 + signal);
  }
} // namespace



int
main(int argc, char **argv)
{
  if (argc == 2
      && (std::strcmp(argv[1], "--help") == 0
          || std::strcmp(argv[1], "-h") == 0))
    {
      const bool ok
        = std::fputs(coaxfit::usage, stdout) >= 0 && std::fflush(stdout) == 0;
      if (!ok)
        std::fputs("coaxfit: error: cannot write to standard output\n", stderr);
      return ok ? 0 : 3;
    }

  struct sigaction action = {};
  action.sa_handler       = interrupted_while_loading;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP})
    ::sigaction(signal, &action, nullptr);

  const std::string module = own_directory() + "/" COAXFIT_APP_MODULE;
  void             *handle = ::dlopen(module.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (handle == nullptr)
    {
      std::fprintf(stderr,
                   "coaxfit: internal error: cannot load the program %s: %s\n",
                   module.c_str(),
                   ::dlerror());
      return 3;
    }
  using Main  = int (*)(int, char **);
  auto *entry = reinterpret_cast<Main>(::dlsym(handle, "coaxfit_app_main"));
  if (entry == nullptr)
    {
      std::fprintf(stderr,
                   "coaxfit: internal error: %s has no coaxfit_app_main\n",
                   module.c_str());
      return 3;
    }
  // coaxfit_app_main ends the process itself (std::_Exit, see there).
  return entry(argc, argv);
}
