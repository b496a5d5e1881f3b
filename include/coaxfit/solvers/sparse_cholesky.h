#ifndef coaxfit_sparse_cholesky_h
#define coaxfit_sparse_cholesky_h

#include <deal.II/base/config.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

// CHOLMOD's types, so that this header does not need cholmod.h.
struct cholmod_factor_struct;
struct cholmod_common_struct;

namespace coaxfit
{
  using namespace dealii;

  /**
   * Sparse Cholesky factorization of symmetric positive definite matrices
   * with SuiteSparse's CHOLMOD (supernodal, fill-reducing ordering chosen by
   * CHOLMOD).
   *
   * The symbolic analysis (ordering, elimination tree, supernodes) depends
   * only on the sparsity pattern. It is done once by analyze(); every
   * factorize() of a matrix with the same pattern but other values (for a
   * body: another set of prescribed interface points, whose rows and columns
   * are zeroed but stay in the pattern) costs only the numeric
   * factorization. Each factorize() returns an independent Factor, so
   * several can be kept at once.
   *
   * Only the upper triangle of the deal.II matrix is read; the matrix must be
   * symmetric. A matrix that is not positive definite is reported with an
   * exception naming the failing column. Objects of this class are not
   * thread safe; use one per thread (one per body).
   */
  class SparseCholesky
  {
  public:
    /**
     * A numeric factorization made by factorize(). It must not outlive the
     * SparseCholesky that made it.
     */
    class Factor
    {
    public:
      ~Factor();
      Factor(const Factor &) = delete;
      Factor &
      operator=(const Factor &)
        = delete;

    private:
      Factor(cholmod_factor_struct *L, cholmod_common_struct *common);
      friend class SparseCholesky;
      cholmod_factor_struct *L;
      cholmod_common_struct *common;
    };

    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &)
      = delete;

    /**
     * Symbolic analysis of the pattern of @p matrix (upper triangle). If
     * @p last is not empty, the fill-reducing ordering (CAMD, constrained)
     * eliminates these unknowns after all others, so that the trailing
     * block of every factor is the Cholesky factor of the Schur complement
     * onto them (see trailing_inverse()).
     */
    void
    analyze(const SparseMatrix<double>                 &matrix,
            const std::vector<types::global_dof_index> &last = {});

    /**
     * For an analysis with unknowns ordered @p last: the block of A^{-1}
     * belonging to them, (A^{-1})(last[a], last[b]) = inverse(a, b), from
     * the trailing block L_SS of the factor as (L_SS L_SS^T)^{-1} (dense,
     * LAPACK). Costs O(n^3) for n unknowns instead of n sparse solves.
     */
    void
    trailing_inverse(const Factor &factor, FullMatrix<double> &inverse) const;

    /**
     * Numeric factorization of @p matrix, which must have the pattern given
     * to analyze().
     */
    std::unique_ptr<Factor>
    factorize(const SparseMatrix<double> &matrix);

    /** Solve A x = b in place: @p rhs holds b on entry, x on return. */
    void
    solve(const Factor &factor, Vector<double> &rhs) const;


  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };
} // namespace coaxfit

#endif
