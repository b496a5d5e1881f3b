#ifndef coaxfit_resources_h
#define coaxfit_resources_h

#include <coaxfit/parameters/parameters.h>

#include <cstddef>

namespace coaxfit
{
  /**
   * The memory (bytes) a run with @p n_dofs DoFs in both bodies together
   * and FE_Q(@p degree) allocates for its matrices and sparse factors, whose
   * fill grows like n log n in 2D. The constants are
   * calibrated against the measured peak resident size of runs of the
   * default case (see benchmarks/README.md, "Memory"), with a margin.
   */
  double
  estimated_memory(std::size_t n_dofs, unsigned int degree);

  /**
   * The memory (bytes) of a run of @p parameters with the direct solver:
   * estimated_memory() of its DoFs and, for the staggered solver, the
   * dense interface blocks of the bodies' factors, which grow with the
   * square of the interface points.
   */
  double
  estimated_memory_direct(const Parameters &parameters);

  /**
   * The memory this process may still give to matrices (bytes): the
   * smaller of the system's available memory (/proc/meminfo, MemAvailable)
   * and what the address space limit (ulimit -v) leaves, each less what
   * the libraries and threads need besides.
   */
  double
  available_memory();

  /**
   * Refuse a run whose estimated memory exceeds the available memory, before
   * any mesh is built: throws InputError naming Mesh/Global refinements.
   */
  void
  check_memory(const Parameters &parameters);

  /**
   * Whether the bodies are solved with AMG (Solver/Linear solver; auto:
   * when the direct solver's estimated memory exceeds the available
   * memory and AMG's does not).
   */
  bool
  use_amg(const Parameters &parameters);

  /** Estimated peak memory (bytes) of an AMG run with @p n_dofs. */
  double
  estimated_memory_amg(std::size_t n_dofs, unsigned int degree);
} // namespace coaxfit

#endif
