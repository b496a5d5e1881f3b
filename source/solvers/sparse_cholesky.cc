#include <deal.II/lac/lapack_templates.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/solvers/sparse_cholesky.h>

#include <algorithm>
#include <cholmod.h>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  namespace
  {
    /**
     * Throw for a CHOLMOD call that failed in @p what: memory
     * exhausted is a ResourceError (exit 3, "out of memory"), anything else
     * an internal error.
     */
    [[noreturn]] void
    fail(const std::string &what, const cholmod_common &common)
    {
      if (common.status == CHOLMOD_OUT_OF_MEMORY
          || common.status == CHOLMOD_TOO_LARGE)
        throw ResourceError("out of memory: " + what
                            + " (try fewer Mesh/Global refinements)");
      throw std::runtime_error(what + " (CHOLMOD status "
                               + std::to_string(common.status) + ")");
    }
  } // namespace



  SparseCholesky::Factor::Factor(cholmod_factor *L, cholmod_common *common)
    : L(L)
    , common(common)
  {}



  SparseCholesky::Factor::~Factor()
  {
    cholmod_l_free_factor(&L, common);
  }



  struct SparseCholesky::Implementation
  {
    Implementation()
    {
      cholmod_l_start(&common);
      // Supernodal L L^T: dense kernels for the factorization and the
      // blocked solves; no messages on stdout.
      common.supernodal    = CHOLMOD_SUPERNODAL;
      common.print         = 0;
      common.error_handler = nullptr;
    }

    ~Implementation()
    {
      cholmod_l_free_factor(&symbolic, &common);
      cholmod_l_free_sparse(&upper, &common);
      cholmod_l_finish(&common);
    }

    /**
     * Visit the upper-triangle entries of the symmetric CSR matrix as CHOLMOD
     * columns with sorted row indices: row r of the deal.II matrix is column
     * r, the entries with column index c < r first (deal.II keeps them
     * sorted after the diagonal), then the diagonal.
     */
    template <typename Visitor>
    static void
    for_each_upper_entry(const SparseMatrix<double> &matrix, Visitor visit)
    {
      for (unsigned int r = 0; r < matrix.m(); ++r)
        {
          auto entry = matrix.begin(r);
          Assert(entry != matrix.end(r) && entry->column() == r,
                 ExcInternalError());
          const double diagonal = entry->value();
          for (++entry; entry != matrix.end(r); ++entry)
            if (entry->column() < r)
              visit(r, entry->column(), entry->value());
          visit(r, r, diagonal);
        }
    }

    void
    fill_values(const SparseMatrix<double> &matrix)
    {
      double     *x = static_cast<double *>(upper->x);
      std::size_t k = 0;
      for_each_upper_entry(matrix, [&](unsigned int, unsigned int, double v) {
        x[k++] = v;
      });
      AssertDimension(k, upper->nzmax);
    }

    cholmod_common  common;
    cholmod_sparse *upper    = nullptr;
    cholmod_factor *symbolic = nullptr;
    /**
     * For the unknowns analyze() was asked to order last, in the caller's
     * order: their position within the trailing block of the factor.
     */
    std::vector<std::size_t> trailing_position;
  };



  SparseCholesky::SparseCholesky()
    : impl(std::make_unique<Implementation>())
  {}



  SparseCholesky::~SparseCholesky() = default;



  void
  SparseCholesky::analyze(const SparseMatrix<double>                 &matrix,
                          const std::vector<types::global_dof_index> &last)
  {
    cholmod_common &common = impl->common;
    cholmod_l_free_factor(&impl->symbolic, &common);
    cholmod_l_free_sparse(&impl->upper, &common);

    const std::size_t n   = matrix.m();
    std::size_t       nnz = 0;
    Implementation::for_each_upper_entry(
      matrix, [&](unsigned int, unsigned int, double) { ++nnz; });
    impl->upper = cholmod_l_allocate_sparse(n,
                                            n,
                                            nnz,
                                            /*sorted*/ 1,
                                            /*packed*/ 1,
                                            /*stype*/ 1,
                                            CHOLMOD_REAL,
                                            &common);
    if (impl->upper == nullptr)
      throw ResourceError("out of memory: CHOLMOD could not allocate a "
                          "matrix of "
                          + std::to_string(nnz) + " entries");
    auto       *column_start = static_cast<SuiteSparse_long *>(impl->upper->p);
    auto       *row_index    = static_cast<SuiteSparse_long *>(impl->upper->i);
    std::size_t k            = 0;
    column_start[0]          = 0;
    Implementation::for_each_upper_entry(
      matrix, [&](unsigned int column, unsigned int row, double) {
        row_index[k++]           = row;
        column_start[column + 1] = k;
      });

    // The analysis reads the pattern only; factorize() fills the values.
    impl->trailing_position.clear();
    if (last.empty())
      impl->symbolic = cholmod_l_analyze(impl->upper, &common);
    else
      {
        // Constrained minimum degree: set 0 (everything else) first, set 1
        // (the unknowns asked for) last; no postordering, which could move
        // them.
        std::vector<SuiteSparse_long> member(n, 0), permutation(n);
        for (const auto i : last)
          member[i] = 1;
        if (!cholmod_l_camd(impl->upper,
                            nullptr,
                            0,
                            member.data(),
                            permutation.data(),
                            &common))
          fail("CHOLMOD constrained ordering failed", common);
        const int nmethods        = common.nmethods,
                  ordering        = common.method[0].ordering;
        const int postorder       = common.postorder;
        common.nmethods           = 1;
        common.method[0].ordering = CHOLMOD_GIVEN;
        common.postorder          = 0;
        impl->symbolic            = cholmod_l_analyze_p(
          impl->upper, permutation.data(), nullptr, 0, &common);
        common.nmethods           = nmethods;
        common.method[0].ordering = ordering;
        common.postorder          = postorder;
        if (impl->symbolic != nullptr)
          {
            const auto *perm
              = static_cast<const SuiteSparse_long *>(impl->symbolic->Perm);
            const std::size_t        first = n - last.size();
            std::vector<std::size_t> position(n);
            for (std::size_t k = first; k < n; ++k)
              {
                if (member[perm[k]] != 1)
                  throw std::runtime_error(
                    "CHOLMOD did not keep the constrained "
                    "ordering");
                position[perm[k]] = k - first;
              }
            for (const auto i : last)
              impl->trailing_position.push_back(position[i]);
          }
      }
    if (impl->symbolic == nullptr)
      fail("CHOLMOD symbolic analysis failed", common);
  }



  std::unique_ptr<SparseCholesky::Factor>
  SparseCholesky::factorize(const SparseMatrix<double> &matrix)
  {
    Assert(impl->symbolic != nullptr, ExcMessage("call analyze() first"));
    AssertDimension(matrix.m(), impl->upper->nrow);
    cholmod_common &common = impl->common;
    impl->fill_values(matrix);
    std::unique_ptr<Factor> factor(
      new Factor(cholmod_l_copy_factor(impl->symbolic, &common), &common));
    if (factor->L == nullptr
        || !cholmod_l_factorize(impl->upper, factor->L, &common))
      fail("CHOLMOD factorization failed", common);
    if (common.status == CHOLMOD_NOT_POSDEF)
      throw std::runtime_error(
        "the stiffness matrix is numerically singular (CHOLMOD: not positive "
        "definite at column "
        + std::to_string(factor->L->minor) + " of " + std::to_string(matrix.m())
        + "); the geometry or mesh is too extreme for double precision");
    return factor;
  }



  void
  SparseCholesky::solve(const Factor &factor, Vector<double> &rhs) const
  {
    cholmod_common &common = impl->common;
    cholmod_dense  *b      = cholmod_l_allocate_dense(
      rhs.size(), 1, rhs.size(), CHOLMOD_REAL, &common);
    std::copy(rhs.begin(), rhs.end(), static_cast<double *>(b->x));
    cholmod_dense *x = cholmod_l_solve(CHOLMOD_A, factor.L, b, &common);
    if (x == nullptr)
      fail("CHOLMOD solve failed", common);
    const double *values = static_cast<const double *>(x->x);
    std::copy(values, values + rhs.size(), rhs.begin());
    cholmod_l_free_dense(&x, &common);
    cholmod_l_free_dense(&b, &common);
  }



  void
  SparseCholesky::trailing_inverse(const Factor       &factor,
                                   FullMatrix<double> &inverse) const
  {
    const cholmod_factor *L = factor.L;
    Assert(L->is_super && L->is_ll, ExcInternalError());
    const std::vector<std::size_t> &p = impl->trailing_position;
    Assert(!p.empty(), ExcMessage("analyze() was given no unknowns"));
    const types::blas_int n     = p.size();
    const std::size_t     first = L->n - n;

    // L_SS, column major, from the supernodes holding columns first..n-1:
    // supernode s has columns super[s]..super[s+1]-1, row indices
    // Ls[pi[s]..pi[s+1]-1] and values Lx[px[s]..] (nsrow x nscol, column
    // major).
    std::vector<double> block(static_cast<std::size_t>(n) * n, 0.);
    const auto         *super = static_cast<const SuiteSparse_long *>(L->super);
    const auto         *pi    = static_cast<const SuiteSparse_long *>(L->pi);
    const auto         *px    = static_cast<const SuiteSparse_long *>(L->px);
    const auto         *Ls    = static_cast<const SuiteSparse_long *>(L->s);
    const auto         *Lx    = static_cast<const double *>(L->x);
    for (std::size_t s = 0; s < L->nsuper; ++s)
      {
        const std::size_t k1 = super[s], k2 = super[s + 1];
        if (k2 <= first)
          continue;
        const std::size_t nsrow = pi[s + 1] - pi[s];
        for (std::size_t j = std::max(k1, first); j < k2; ++j)
          for (std::size_t r = 0; r < nsrow; ++r)
            {
              const std::size_t row = Ls[pi[s] + r];
              if (row >= j)
                block[(row - first) + (j - first) * n]
                  = Lx[px[s] + (j - k1) * nsrow + r];
            }
      }
    types::blas_int info  = 0;
    const char      lower = 'L';
    potri(&lower, &n, block.data(), &n, &info);
    if (info != 0)
      throw std::runtime_error("LAPACK dpotri failed (info "
                               + std::to_string(info)
                               + ") inverting the interface Schur complement");

    // Back to the caller's numbering of the unknowns.
    inverse.reinit(n, n);
    for (types::blas_int a = 0; a < n; ++a)
      for (types::blas_int b = 0; b < n; ++b)
        inverse(a, b) = block[std::max(p[a], p[b]) + std::min(p[a], p[b]) * n];
  }
} // namespace coaxfit
