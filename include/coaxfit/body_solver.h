#ifndef coaxfit_body_solver_h
#define coaxfit_body_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/body_discretization.h>
#include <coaxfit/factorization_cache.h>
#include <coaxfit/interface_operator.h>
#include <coaxfit/sparse_cholesky.h>

#include <vector>

namespace coaxfit
{
  /**
   * Solves one body (a BodyDiscretization, set up and assembled) with mixed
   * data on its contact surface S: the radial displacement at prescribed
   * interface points (Dirichlet, shear-free), the nodal contact force at
   * the others (Neumann). Reactions are rows of K u - f, not differentiated
   * stresses.
   *
   * Each set of prescribed points gives a different matrix (the same
   * pattern, the prescribed rows and columns zeroed); its sparse Cholesky
   * factorization (CHOLMOD) is made when first needed and kept in a
   * FactorizationCache. The symbolic analysis, with the interface points
   * ordered last, is shared by all sets, so the compliance on S is the
   * inverse of the trailing block of the free body's factor.
   */
  class BodySolver : public InterfaceOperator
  {
  public:
    explicit BodySolver(const BodyDiscretization &body);

    void
    solve(const std::vector<bool> &prescribed,
          const Vector<double>    &displacement,
          const Vector<double>    &force,
          Vector<double>          &u_r,
          Vector<double>          &force_out) override;

    /**
     * The whole displacement field for the same data as solve(): used for
     * the output of a final state.
     */
    Vector<double>
    solve_field(const std::vector<bool> &prescribed,
                const Vector<double>    &displacement,
                const Vector<double>    &force);

    /**
     * The field of the body under the load vector @p load alone, with a
     * free contact surface (no contact force): the body's own answer to its
     * loads of operation.
     */
    Vector<double>
    solve_load_field(const Vector<double> &load);

    /**
     * Make (or find in the cache) the factorization for the set of
     * prescribed points @p prescribed, so that later solves only
     * substitute.
     */
    void
    factorize(const std::vector<bool> &prescribed);

    /**
     * The interface compliance of the free body (no point prescribed):
     * C(i, j) = radial displacement at point i for a unit nodal contact force
     * at point j.
     */
    void
    interface_compliance(FullMatrix<double> &compliance);

    unsigned int
    n_factorizations() const override
    {
      return factorizations.n_factorizations();
    }

    /** Number of solves (each a forward and backward substitution). */
    unsigned int
    n_solves() const
    {
      return solve_count;
    }

  private:
    /** The factorization for a set of prescribed points, made if needed. */
    const SparseCholesky::Factor &
    factorization(const std::vector<bool> &prescribed);

    const BodyDiscretization                  &body;
    SparseCholesky                             cholesky;
    bool                                       analyzed = false;
    FactorizationCache<SparseCholesky::Factor> factorizations;
    unsigned int                               solve_count = 0;
  };
} // namespace coaxfit

#endif
