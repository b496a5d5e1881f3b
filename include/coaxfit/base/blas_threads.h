#ifndef coaxfit_blas_threads_h
#define coaxfit_blas_threads_h

namespace coaxfit
{
  /**
   * Set the number of threads of the BLAS library that CHOLMOD's supernodal
   * kernels call, if that library can be told (OpenBLAS and its
   * openblas_set_num_threads, found at run time). The staggered solver
   * already runs the two bodies on two threads; a threaded BLAS under each
   * would oversubscribe the cores (benchmarks/README.md has the figures), so
   * it asks for one BLAS thread, while the monolithic solver, which has one
   * system, lets the BLAS use every core.
   *
   * Returns false (and changes nothing) when the BLAS has no such control,
   * e.g. the reference BLAS, which is single threaded anyway.
   */
  bool
  set_blas_threads(int n_threads);

} // namespace coaxfit

#endif
