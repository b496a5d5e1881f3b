#ifndef coaxfit_interface_pressure_h
#define coaxfit_interface_pressure_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/interface_side.h>

namespace coaxfit
{
  /**
   * @name Nodal forces and pressures on one side of a joint
   *
   * A nodal force F_i (N per radian, compression positive along the side's
   * inward normal) and a nodal pressure p_i (MPa) are related by the lumped
   * weights of the side, F_i = p_i w_i with w_i = int_S N_i r ds, as
   * ContactInterface does for matching sides. A uniform pressure p gives
   * F_i = p w_i, which is also its consistent load int_S p N_i r ds, and
   * comes back as p at every node.
   */
  /** @{ */

  /**
   * The nodal pressures p_i = F_i / w_i (MPa) of the nodal forces @p force.
   * Where w_i = 0 (a degree-2 end node on the axis) the pressure is not
   * defined and is returned as NaN.
   */
  Vector<double>
  nodal_pressure(const InterfaceSide &side, const Vector<double> &force);

  /** The nodal forces F_i = p_i w_i of the nodal pressures @p pressure. */
  Vector<double>
  nodal_force(const InterfaceSide &side, const Vector<double> &pressure);

  /** The nodal forces F_i = p w_i of a uniform pressure @p pressure. */
  Vector<double>
  uniform_pressure_force(const InterfaceSide &side, double pressure);

  /**
   * The mean pressure (MPa): the total force sum_i F_i over the r-weighted
   * size int_S r ds of the side.
   */
  double
  mean_pressure(const InterfaceSide &side, const Vector<double> &force);

  /** @} */
} // namespace coaxfit

#endif
