#include <coaxfit/app/run_guard.h>
#include <coaxfit/base/input_error.h>

#include <new>

namespace coaxfit
{
  int
  exit_code_of(const std::function<int()> &job, std::ostream &err)
  {
    try
      {
        return job();
      }
    catch (const InputError &e)
      {
        err << "coaxfit: error: " << e.what() << std::endl;
        return 1;
      }
    catch (const SolverError &e)
      {
        err << "coaxfit: error: " << e.what() << std::endl;
        return 2;
      }
    catch (const ResourceError &e)
      {
        err << "coaxfit: error: " << e.what() << std::endl;
        return 3;
      }
    catch (const std::bad_alloc &)
      {
        err << "coaxfit: error: out of memory (try fewer "
               "Mesh/Global refinements)"
            << std::endl;
        return 3;
      }
    catch (const std::exception &e)
      {
        err << "coaxfit: internal error: " << one_line_message(e) << std::endl;
        return 3;
      }
    catch (...)
      {
        err << "coaxfit: internal error: unknown exception" << std::endl;
        return 3;
      }
  }



  std::string
  not_converged_message(const Parameters &parameters)
  {
    return "coaxfit: error: the coupling did not converge within "
           "Coupling/Max steps = "
           + std::to_string(parameters.coupling.max_steps)
           + " (the state is written, marked \"converged\": false)";
  }
} // namespace coaxfit
