#ifndef coaxfit_condensed_body_h
#define coaxfit_condensed_body_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/factorization_cache.h>
#include <coaxfit/solvers/interface_operator.h>

namespace coaxfit
{
  /**
   * Interface condensation: the compliance C of a body on S (the paper's
   * K_i, nodal force -> u_r at the interface points, C_ij = u_r,i for a unit
   * force at j) formed once by BodySolver::interface_compliance(): the
   * inverse of the Schur complement on S. A step then costs O(n^2) for n
   * interface points: u = C F; with prescribed points P and free points Q,
   * C_PP F_P = u_P - C_PQ F_Q (one LU of C_PP per set of prescribed points,
   * kept in a FactorizationCache). Only the final state needs a full solve
   * of the body.
   */
  class CondensedBody : public InterfaceOperator
  {
  public:
    /** Form the compliance of the body that @p solver solves. */
    explicit CondensedBody(BodySolver &solver);

    /**
     * The operator of a given compliance @p compliance (symmetric positive
     * definite): the body's own seen from other points, M C M^T for a
     * mortar side.
     */
    explicit CondensedBody(const FullMatrix<double> &compliance);

    void
    solve(const std::vector<bool> &prescribed,
          const Vector<double>    &displacement,
          const Vector<double>    &force,
          Vector<double>          &u_r,
          Vector<double>          &force_out) override;

    unsigned int
    n_factorizations() const override
    {
      return factorizations.n_factorizations();
    }

    /** The compliance C: C(i, j) = u_r,i for a unit force at j. */
    const FullMatrix<double> &
    get_compliance() const
    {
      return compliance;
    }

  private:
    FullMatrix<double>                           compliance;
    FactorizationCache<LAPACKFullMatrix<double>> factorizations;
  };
} // namespace coaxfit

#endif
