#ifndef coaxfit_stack_monolithic_solver_h
#define coaxfit_stack_monolithic_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/stack_coupling.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/solvers/sparse_cholesky.h>

#include <vector>

namespace coaxfit
{
  /**
   * The monolithic reference of a stack on the full operators: all N
   * bodies in one linear system (the two-body MonolithicSolver
   * generalised), independent of the condensation onto the joints that
   * the staggered process and solve_stack_contact() use.
   *
   * The bodies' DoFs are numbered one body after the other. At every point
   * i of joint k in contact the outer body's u_r is tied to the inner
   * body's, u_{k+1,i} = u_{k,i} + d_{k,i} (StackJoint::interference_at():
   * the loads of operation enter as the free bodies' growth apart, as in
   * the condensed problem), an inhomogeneous AffineConstraints line that
   * condenses the outer body's DoF away; the system is solved by one
   * sparse Cholesky factorization (CHOLMOD). The pattern is built with
   * every point tied (a superset of any active set's) and analysed once;
   * each active set costs one numeric factorization.
   *
   * The contact force of a point is the inner body's reaction there (its
   * row of K u); the outer body's reaction must be the same force (the
   * traction mismatch, traction_mismatch()). Unilateral contact: a primal-
   * dual active set as in deal.II's step-41, a tied point whose force is
   * tensile released, a released point that penetrates tied again, until
   * the set stays.
   */
  class StackMonolithicSolver
  {
  public:
    /**
     * The solver of the stack of @p bodies (set up and assembled, inside
     * out) with the joints @p joints (joint k between bodies k and k + 1,
     * its points shared by both meshes); @p unilateral: contact may be
     * lost.
     */
    StackMonolithicSolver(const std::vector<const BodyDiscretization *> &bodies,
                          const std::vector<StackJoint>                 &joints,
                          bool unilateral);

    /**
     * Solve the contact of all joints; @p active_set_steps is set to the
     * number of solves (active sets) it took.
     * @throws SolverError if the active set does not settle.
     */
    StackState
    solve(unsigned int &active_set_steps);

    /**
     * The largest difference of the inner and the outer body's reaction at
     * a joint point of the last solve, over the largest reaction (lumped
     * pressures): the round-off of the tie, about 1e-12.
     */
    double
    traction_mismatch() const
    {
      return mismatch;
    }

    /** The number of numeric factorizations made. */
    unsigned int
    n_factorizations() const
    {
      return factorizations;
    }

  private:
    /** The pattern of the coupled matrix with every point tied, analysed. */
    void
    setup_pattern();

    /** The ties of the points in contact @p tied (per joint). */
    AffineConstraints<double>
    tie_constraints(const std::vector<std::vector<bool>> &tied) const;

    /**
     * Solve the coupled system with the points @p tied; the forces and the
     * gaps (u_outer - u_inner - d, mm) at every joint point.
     */
    void
    solve_tied(const std::vector<std::vector<bool>> &tied,
               std::vector<Vector<double>>          &force,
               std::vector<Vector<double>>          &gap);

    /** The DoF of joint @p k's point @p i in body @p b (k or k + 1). */
    unsigned int
    joint_dof(unsigned int b, unsigned int k, unsigned int i) const;

    std::vector<const BodyDiscretization *> bodies;
    const std::vector<StackJoint>          &joints;
    const bool                              unilateral;
    std::vector<unsigned int>               offset;  ///< first DoF per body
    std::vector<SparseMatrix<double>>       rotated; ///< unused on cylinders
    SparsityPattern                         pattern;
    SparseCholesky                          cholesky;
    unsigned int                            factorizations = 0;
    double                                  mismatch       = 0.;
  };
} // namespace coaxfit

#endif
