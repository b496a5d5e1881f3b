#ifndef coaxfit_monolithic_solver_h
#define coaxfit_monolithic_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/solvers/sparse_cholesky.h>

namespace coaxfit
{
  /**
   * The reference for the staggered method: both bodies in one linear
   * system. Shaft and hub DoFs are numbered one after the other; at every
   * interface point in contact the hub's u_r is tied to the shaft's,
   * u2 = u1 + d, an inhomogeneous AffineConstraints line that condenses
   * the hub's DoF there away, so the system is solved for both bodies at once
   * by one sparse Cholesky factorization (CHOLMOD). The sparsity pattern is
   * built once with every point tied (a superset of the pattern of any active
   * set) and analyzed once; each active set then costs one numeric
   * factorization.
   *
   * Joints whose nodes do not match (`Mesh/Joint nodes = own`): the
   * interface points are those of one body P (Scene::point_body()), the
   * other body A reaches them through the mortar projection M; the tie is
   * then u_P = M u_A +- d at each point of P in contact, a line with the
   * entries of M on A's joint DoFs, and A's contact forces are M^T F.
   *
   * Unilateral contact is handled by a primal-dual active set loop (as in
   * deal.II's step-41): after each solve, a tied point whose contact force
   * is tensile is released, a released point that penetrates is tied again;
   * the loop ends when the set does not change. Each loop step is one row
   * of the history (kind "Neumann" is not meaningful here; steps are
   * monolithic solves).
   */
  class MonolithicSolver : public InterfaceSolver
  {
  public:
    /**
     * The solver of the joint of @p scene (set up and assembled) on its
     * interface @p interface, with the flags @p active_set and at most
     * @p max_steps active set steps.
     */
    MonolithicSolver(const Scene               &scene,
                     const ContactInterface    &interface,
                     const UnilateralActiveSet &active_set,
                     unsigned int               max_steps);

    bool
    run(std::ostream *progress) override;

    /** The fields of the last coupled solve. */
    std::pair<Vector<double>, Vector<double>>
    solve_fields() override;

    SolverStatistics
    statistics() const override;

  private:
    /** Solve the coupled system with the current set of tied points. */
    void
    solve_tied();

    /** The pattern of the coupled matrix with every point tied, analyzed. */
    void
    setup_pattern();

    /**
     * The tie of the coupled numbering (shaft DoFs, then hub DoFs): at every
     * tied point the hub's interface DoF is constrained to the shaft's plus
     * the interference, u2 = u1 + d.
     */
    AffineConstraints<double>
    tie_constraints(const std::vector<bool> &tied) const;

    const BodyDiscretization &shaft;
    const BodyDiscretization &hub;
    /** Non-matching joint: the transfer from A to P, M (n_P x n_A). */
    const Scene       *scene = nullptr;
    FullMatrix<double> transfer_matrix;
    bool               hub_is_point_side = true;
    /** The bodies' stiffness in the joint's frame (a cone). */
    SparseMatrix<double>    shaft_rotated, hub_rotated;
    Vector<double>          shaft_field, hub_field;
    const ContactInterface &interface;
    const unsigned int      max_steps;
    unsigned int            factorizations = 0;
    SparsityPattern         pattern;
    SparseCholesky          cholesky;
  };
} // namespace coaxfit

#endif
