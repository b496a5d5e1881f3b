#ifndef coaxfit_banded_cholesky_h
#define coaxfit_banded_cholesky_h

#include <deal.II/lac/vector.h>

#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * A symmetric positive definite band matrix (entries (i, j) with
   * |i - j| <= bandwidth) and its Cholesky factorization A = L L^T, which
   * has the same band. For the mass matrix of an interface whose nodes are
   * numbered along the curve: a face of degree p couples nodes at most p
   * apart, so the bandwidth is p, and assembly, factorization and a solve
   * cost O(n p^2).
   *
   * Only the lower band is stored, row by row: entry (i, j), j <= i, at
   * i * (bandwidth + 1) + (i - j).
   */
  class BandedCholesky
  {
  public:
    /** The zero n x n matrix of half bandwidth @p bandwidth. */
    BandedCholesky(unsigned int n = 0, unsigned int bandwidth = 0);

    /** Number of rows. */
    unsigned int
    size() const
    {
      return n;
    }

    /**
     * Add @p value to entry (i, j) and, the matrix being symmetric, so to
     * (j, i): call it once per pair with i >= j, or for both orders with
     * half the value each time. Throws if |i - j| exceeds the bandwidth.
     */
    void
    add(unsigned int i, unsigned int j, double value);

    /** Entry (i, j) (before factorize(); zero outside the band). */
    double
    operator()(unsigned int i, unsigned int j) const;

    /**
     * Replace the matrix by its Cholesky factor L (in place). Throws
     * std::logic_error, naming the row, if the matrix is not positive
     * definite.
     */
    void
    factorize();

    /** Solve A x = b in place after factorize(): @p b holds x on return. */
    void
    solve(Vector<double> &b) const;

  private:
    unsigned int        n;
    unsigned int        bandwidth;
    std::vector<double> band;
    bool                factorized;

    /** Position of (i, j), j <= i, i - j <= bandwidth, in band. */
    std::size_t
    index(const unsigned int i, const unsigned int j) const
    {
      return static_cast<std::size_t>(i) * (bandwidth + 1) + (i - j);
    }
  };
} // namespace coaxfit

#endif
