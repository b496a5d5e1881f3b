#ifndef coaxfit_body_solver_h
#define coaxfit_body_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/solvers/factorization_cache.h>
#include <coaxfit/solvers/interface_operator.h>
#include <coaxfit/solvers/sparse_cholesky.h>

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
   *
   * With @p amg (Solver/Linear solver = amg) each set of prescribed points
   * gets instead its matrix in Trilinos' format and an algebraic multigrid
   * preconditioner (ML, with the translations as near-null space), built
   * once and kept the same way; each solve is then conjugate gradients to
   * a relative residual of 1e-12. No compliance is available then (the
   * coupling solves both bodies at every step); MPI must be initialized
   * (ensure_mpi_initialized()).
   */
  class BodySolver : public InterfaceOperator
  {
  public:
    explicit BodySolver(const BodyDiscretization &body, bool amg = false);

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
      return amg ? amg_systems.n_factorizations() :
                   factorizations.n_factorizations();
    }

    /** Conjugate gradient iterations of all solves so far (amg). */
    unsigned int
    n_cg_iterations() const
    {
      return cg_iterations;
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

    /** A matrix and its AMG preconditioner (Solver/Linear solver = amg). */
    struct AmgSystem
    {
      TrilinosWrappers::SparseMatrix    matrix;
      TrilinosWrappers::PreconditionAMG preconditioner;
    };

    /** The AMG system of @p prescribed (built when first asked for). */
    const AmgSystem &
    amg_system(const std::vector<bool> &prescribed);

    /**
     * The body's stiffness in the frame its solves use: K, or for a
     * joint on a cone K in the joint's frame (made when first asked for).
     */
    const SparseMatrix<double> &
    stiffness();

    /** K with the prescribed points' rows and columns eliminated. */
    SparseMatrix<double>
    eliminated_matrix(const std::vector<bool> &prescribed);

    /** Overwrite @p rhs with the solution of the system of @p prescribed. */
    void
    solve_system(const std::vector<bool> &prescribed, Vector<double> &rhs);

    const BodyDiscretization                  &body;
    SparseCholesky                             cholesky;
    bool                                       analyzed = false;
    FactorizationCache<SparseCholesky::Factor> factorizations;
    unsigned int                               solve_count = 0;
    const bool                                 amg;
    FactorizationCache<AmgSystem>              amg_systems;
    unsigned int                               cg_iterations = 0;
    SparseMatrix<double>                       rotated_stiffness;
  };
} // namespace coaxfit

#endif
