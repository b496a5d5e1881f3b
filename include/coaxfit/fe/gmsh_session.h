#ifndef coaxfit_gmsh_session_h
#define coaxfit_gmsh_session_h

#include <functional>
#include <string>

namespace coaxfit
{
  /**
   * Run @p work with gmsh's API initialised and finalise it afterwards, also
   * when @p work throws.
   *
   * gmsh keeps one global model and is not thread-safe: every use of its API
   * in coaxfit goes through this function, which holds one process-wide
   * mutex for the whole session, so that bodies meshed concurrently are
   * meshed one after the other. The session starts from gmsh's defaults
   * (no configuration files read), prints nothing (General.Terminal = 0)
   * and meshes on one thread (General.NumThreads = 1).
   *
   * gmsh is told not to throw (General.AbortOnError = 0): an exception
   * thrown inside its OpenMP regions (while meshing) cannot be caught and
   * ends the process. It logs the error instead, and @p work calls
   * check_gmsh_error() after each step that can fail (reading, meshing);
   * the session checks once more at its end. An error gmsh reports becomes
   * an InputError "@p context: gmsh: <gmsh's message>"; an InputError of
   * @p work passes through unchanged.
   */
  void
  run_gmsh_session(const std::string           &context,
                   const std::function<void()> &work);

  /**
   * Inside run_gmsh_session(): throw InputError "@p context: gmsh: <its
   * message>" if gmsh has logged an error in this session.
   */
  void
  check_gmsh_error(const std::string &context);
} // namespace coaxfit

#endif
