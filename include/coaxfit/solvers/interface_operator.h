#ifndef coaxfit_interface_operator_h
#define coaxfit_interface_operator_h

#include <deal.II/lac/vector.h>

#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * What the staggered process needs from one body: given at each interface
   * point either the radial displacement (prescribed) or the nodal contact
   * force, return both at every point. A BodySolver answers by a full
   * solve; a CondensedBody by dense algebra with the body's interface
   * compliance.
   *
   * Nodal contact forces are compression positive and in the axisymmetric
   * "per radian" form F_i = int_S p N_i r dz.
   */
  class InterfaceOperator
  {
  public:
    virtual ~InterfaceOperator() = default;

    /**
     * Point i gets the radial displacement @p displacement[i] if
     * @p prescribed[i], otherwise the nodal contact force @p force[i]. On
     * return @p u_r holds the radial displacement and @p force_out the
     * contact force at every point (the reaction where prescribed, the given
     * force elsewhere).
     */
    virtual void
    solve(const std::vector<bool> &prescribed,
          const Vector<double>    &displacement,
          const Vector<double>    &force,
          Vector<double>          &u_r,
          Vector<double>          &force_out)
      = 0;

    /** Number of factorizations made so far. */
    virtual unsigned int
    n_factorizations() const = 0;

    /** Neumann step: nodal contact forces on all of S give u_r on S. */
    void
    solve_neumann(const Vector<double> &force, Vector<double> &u_r);
  };
} // namespace coaxfit

#endif
