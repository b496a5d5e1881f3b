#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/gmsh_session.h>

#include <gmsh.h>
#include <mutex>

namespace coaxfit
{
  namespace
  {
    std::mutex gmsh_mutex;

    /** Finalises gmsh when the session ends, however it ends. */
    struct Finaliser
    {
      ~Finaliser()
      {
        try
          {
            gmsh::finalize();
          }
        catch (...)
          {
            // Nothing to report: the model is discarded anyway.
          }
      }
    };

    /** gmsh's message on one line. */
    std::string
    one_line(std::string text)
    {
      for (char &c : text)
        if (c == '\n' || c == '\r')
          c = ' ';
      return text;
    }
  } // namespace



  void
  check_gmsh_error(const std::string &context)
  {
    std::string message;
    gmsh::logger::getLastError(message);
    if (!message.empty())
      throw InputError(context + ": gmsh: " + one_line(message));
  }



  void
  run_gmsh_session(const std::string           &context,
                   const std::function<void()> &work)
  {
    const std::lock_guard<std::mutex> lock(gmsh_mutex);
    try
      {
        gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
        const Finaliser finaliser;
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.NumThreads", 1);
        gmsh::option::setNumber("General.AbortOnError", 0);
        work();
        check_gmsh_error(context);
      }
    catch (const std::string &message) // how gmsh 4.8 reports an error
      {
        throw InputError(context + ": gmsh: " + one_line(message));
      }
    catch (const char *message)
      {
        throw InputError(context + ": gmsh: " + one_line(message));
      }
  }
} // namespace coaxfit
