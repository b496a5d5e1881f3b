#ifndef coaxfit_results_h
#define coaxfit_results_h

#include <coaxfit/contact_interface.h>
#include <coaxfit/interface_solver.h>
#include <coaxfit/parameters.h>
#include <coaxfit/staggered_coupling.h>

#include <string>
#include <vector>

namespace coaxfit
{
  /** Wall times of the phases of a run (s). */
  struct Timing
  {
    double setup         = 0.;
    double factorization = 0.;
    double condensation  = 0.;
    double coupling      = 0.;
    double output        = 0.;
    double total         = 0.;
  };

  /**
   * The contact pressure along S, as nodal pressure p_i = F_i / w_i
   * (nodal contact force over the point's lumped weight: exact for a
   * uniform pressure, zero exactly where the surfaces separate, and closer
   * to the independent CalculiX reference than the L2-projected pressure
   * M^-1 F, which oscillates next to the corner and at separated points),
   * and the figures derived from it: at the
   * mid-plane, the mean over S, extremes and where they are, and the Lame
   * pressure of the same radii and materials. The pressure at the hub-end
   * corner is singular: max grows with mesh refinement, so compare meshes or
   * methods by the mid-plane and mean values.
   */
  struct PressureSummary
  {
    /** Nodal pressure F_i / w_i at each interface point (MPa). */
    std::vector<double> pressure;
    double              at_mid_plane;
    double              mean;
    double              min, z_of_min;
    double              max, z_of_max;
    double              lame;

    PressureSummary(const Parameters          &parameters,
                    const ContactInterface    &interface,
                    const std::vector<double> &force);
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

  /** contact_pressure.csv: z, pressure, u_r of both bodies, gap, status. */
  void
  write_contact_pressure(const std::string      &filename,
                         const ContactInterface &interface,
                         const PressureSummary  &pressure,
                         const InterfaceSolver  &coupling);

  /** convergence.csv: one row per coupling step. */
  void
  write_convergence(const std::string     &filename,
                    const InterfaceSolver &coupling);

  /**
   * interface.vtp: the contact surface as a polyline in the (r, z) plane
   * with pressure, gap and status (1 contact, 0 separated), for ParaView.
   */
  void
  write_interface_vtp(const std::string      &filename,
                      const Parameters       &parameters,
                      const ContactInterface &interface,
                      const PressureSummary  &pressure,
                      const InterfaceSolver  &coupling);

  /** Everything a script needs to know about a run, as JSON. */
  struct SummaryData
  {
    const Parameters        &parameters;
    const Body              &shaft;
    const Body              &hub;
    const ContactInterface  &interface;
    const InterfaceSolver   &coupling;
    const PressureSummary   &pressure;
    const Timing            &timing;
    const Complementarity   &complementarity;
    const std::string        controller;
    std::vector<std::string> warnings;
  };

  /** summary.json. */
  void
  write_summary(const std::string &filename, const SummaryData &data);
} // namespace coaxfit

#endif
