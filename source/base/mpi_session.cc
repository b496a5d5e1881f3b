#include <deal.II/base/multithread_info.h>

#include <coaxfit/base/mpi_session.h>

#include <mpi.h>
#include <stdexcept>

namespace coaxfit
{
  void
  ensure_mpi_initialized()
  {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (initialized)
      return;
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided)
        != MPI_SUCCESS)
      throw std::runtime_error("MPI could not be initialized for Trilinos "
                               "(Solver/Linear solver = amg)");
    // Trilinos' objects share timers and counters that are not safe
    // between threads: the bodies are solved one after the other.
    dealii::MultithreadInfo::set_thread_limit(1);
  }
} // namespace coaxfit
