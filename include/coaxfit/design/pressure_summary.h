#ifndef coaxfit_pressure_summary_h
#define coaxfit_pressure_summary_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/parameters/parameters.h>

namespace coaxfit
{
  /**
   * The contact pressure along S, as nodal pressure p_i = F_i / w_i
   * (nodal contact force over the point's lumped weight: exact for a
   * uniform pressure, zero exactly where the surfaces separate, and closer
   * to the independent CalculiX reference than the L2-projected pressure
   * M^-1 F, which oscillates next to the corner and at separated points),
   * and the figures derived from it: at the mid-plane, the mean over S,
   * extremes and where they are, and the Lame pressure of the same radii
   * and materials. The pressure at the hub-end corner is singular: max
   * grows with mesh refinement, so compare meshes or methods by the
   * mid-plane and mean values.
   */
  struct PressureSummary
  {
    /** Nodal pressure F_i / w_i at each interface point (MPa). */
    Vector<double> pressure;
    double         at_mid_plane;
    double         mean;
    double         min, z_of_min;
    double         max, z_of_max;
    /**
     * Lame's pressure for the same radii (plane stress, equal lengths),
     * with the loads of operation (Din7190; 0 where the joint opens).
     */
    double lame;

    PressureSummary(const Parameters       &parameters,
                    const ContactInterface &interface,
                    const Vector<double>   &force);
  };

  /**
   * How well the final state satisfies the unilateral contact conditions
   * (1.2)-(1.3), from nodal pressures p_i = F_i/w_i and gaps g_i: the
   * largest tensile pressure and the largest |p_i g_i| relative to the
   * largest pressure (times d), and the largest penetration relative to d.
   */
  struct Complementarity
  {
    double max_tension_relative;
    double max_penetration_relative;
    double max_pressure_gap_relative;

    Complementarity(const ContactInterface &interface,
                    const InterfaceSolver  &coupling);
  };
} // namespace coaxfit

#endif
