#ifndef coaxfit_mpi_session_h
#define coaxfit_mpi_session_h

namespace coaxfit
{
  /**
   * Initialize MPI for Trilinos (one process, MPI_COMM_SELF), once, when a
   * run first needs it (Solver/Linear solver = amg); no other run pays
   * for it. deal.II's threads are limited to one then: Trilinos' objects
   * share timers that are not safe between threads (two bodies solved at
   * once printed "Overlapping timers detected").
   * The process ends with std::_Exit (see main.cc), without
   * MPI_Finalize: nothing of MPI is left to flush for one process.
   */
  void
  ensure_mpi_initialized();
} // namespace coaxfit

#endif
