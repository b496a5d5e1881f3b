#include <coaxfit/coupling/banded_cholesky.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  BandedCholesky::BandedCholesky(const unsigned int n,
                                 const unsigned int bandwidth)
    : n(n)
    , bandwidth(bandwidth)
    , band(static_cast<std::size_t>(n) * (bandwidth + 1), 0.)
    , factorized(false)
  {}



  void
  BandedCholesky::add(const unsigned int i,
                      const unsigned int j,
                      const double       value)
  {
    const unsigned int row = std::max(i, j), column = std::min(i, j);
    if (row >= n || row - column > bandwidth || factorized)
      throw std::logic_error("BandedCholesky: entry (" + std::to_string(i)
                             + ", " + std::to_string(j)
                             + ") outside the band or matrix factorized");
    band[index(row, column)] += value;
  }



  double
  BandedCholesky::operator()(const unsigned int i, const unsigned int j) const
  {
    const unsigned int row = std::max(i, j), column = std::min(i, j);
    AssertIndexRange(row, n);
    return row - column > bandwidth ? 0. : band[index(row, column)];
  }



  void
  BandedCholesky::factorize()
  {
    if (factorized)
      return;
    // Row by row: L(i, j) = (A(i, j) - sum_k L(i, k) L(j, k)) / L(j, j),
    // k over the columns both rows have in the band.
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int first = i > bandwidth ? i - bandwidth : 0;
        for (unsigned int j = first; j <= i; ++j)
          {
            const unsigned int first_j = j > bandwidth ? j - bandwidth : 0;
            double             sum     = band[index(i, j)];
            for (unsigned int k = std::max(first, first_j); k < j; ++k)
              sum -= band[index(i, k)] * band[index(j, k)];
            if (j < i)
              band[index(i, j)] = sum / band[index(j, j)];
            else if (!(sum > 0.))
              throw std::logic_error(
                "BandedCholesky: the matrix is not positive definite (row "
                + std::to_string(i) + ")");
            else
              band[index(i, i)] = std::sqrt(sum);
          }
      }
    factorized = true;
  }



  void
  BandedCholesky::solve(Vector<double> &b) const
  {
    Assert(factorized, ExcMessage("BandedCholesky: factorize() first"));
    AssertDimension(b.size(), n);
    // L y = b, then L^T x = y.
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int first = i > bandwidth ? i - bandwidth : 0;
        double             sum   = b[i];
        for (unsigned int k = first; k < i; ++k)
          sum -= band[index(i, k)] * b[k];
        b[i] = sum / band[index(i, i)];
      }
    for (unsigned int i = n; i-- > 0;)
      {
        const unsigned int last = std::min(n - 1, i + bandwidth);
        double             sum  = b[i];
        for (unsigned int k = i + 1; k <= last; ++k)
          sum -= band[index(k, i)] * b[k];
        b[i] = sum / band[index(i, i)];
      }
  }
} // namespace coaxfit
