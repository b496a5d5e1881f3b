#ifndef coaxfit_tied_pattern_h
#define coaxfit_tied_pattern_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Add to @p dsp the entries a body's stiffness matrix @p K, placed at
   * rows and columns from @p offset on in a monolithic system, can have
   * under the ties @p all_tied (every joint point tied): each row and
   * column kept and also moved to the DoFs its tie line names (one on
   * matching sides, a row of the mortar matrix on others). The union over
   * all active sets, which the monolithic solvers analyse once.
   */
  void
  add_tied_pattern(DynamicSparsityPattern          &dsp,
                   const SparseMatrix<double>      &K,
                   unsigned int                     offset,
                   const AffineConstraints<double> &all_tied);
} // namespace coaxfit

#endif
