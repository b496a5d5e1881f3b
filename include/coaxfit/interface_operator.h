#ifndef coaxfit_interface_operator_h
#define coaxfit_interface_operator_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <map>
#include <memory>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  class Body;

  /**
   * What the staggered process needs from one body: given at each interface
   * point either the radial displacement (prescribed) or the nodal contact
   * force, return both at every point. A Body answers by a full solve; a
   * CondensedBody by dense algebra with the body's interface compliance.
   */
  class InterfaceOperator
  {
  public:
    virtual ~InterfaceOperator() = default;

    virtual void
    solve(const std::vector<bool>   &prescribed,
          const std::vector<double> &displacement,
          const std::vector<double> &force,
          std::vector<double>       &u_r,
          std::vector<double>       &force_out)
      = 0;

    /** Neumann step: nodal contact forces on all of S give u_r on S. */
    void
    solve_neumann(const std::vector<double> &force, std::vector<double> &u_r);

    /** Dirichlet step: u_r on all of S gives the nodal reactions on S. */
    void
    solve_dirichlet(const std::vector<double> &u_r, std::vector<double> &force);
  };

  /**
   * Interface condensation: the compliance C of a body on S (the paper's
   * K_i, nodal force -> u_r at the interface points, C_ij = u_r,i for a unit
   * force at j) formed once by Body::interface_compliance(): the inverse of
   * the trailing block of the free body's Cholesky factor (interface points
   * are eliminated last), i.e. of the Schur complement on S. A step then
   * costs O(n^2) for n
   * interface points: u = C F; with prescribed points P and free points Q,
   * C_PP F_P = u_P - C_PQ F_Q (one LU of C_PP per set of prescribed points,
   * cached). Only the final state needs a full solve of the body.
   */
  class CondensedBody : public InterfaceOperator
  {
  public:
    /** Form the compliance of @p body (set up and assembled). */
    explicit CondensedBody(Body &body);

    void
    solve(const std::vector<bool>   &prescribed,
          const std::vector<double> &displacement,
          const std::vector<double> &force,
          std::vector<double>       &u_r,
          std::vector<double>       &force_out) override;

    /** The compliance C: C(i, j) = u_r,i for a unit force at j. */
    const FullMatrix<double> &
    get_compliance() const
    {
      return compliance;
    }

    /** Number of LU factorizations of C_PP. */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

  private:
    FullMatrix<double> compliance; ///< C
    std::map<std::vector<bool>, std::unique_ptr<LAPACKFullMatrix<double>>>
                 factorizations;
    unsigned int factorization_count = 0;
  };
} // namespace coaxfit

#endif
