#ifndef coaxfit_results_h
#define coaxfit_results_h

#include <coaxfit/contact_interface.h>
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
    double coupling      = 0.;
    double output        = 0.;
    double total         = 0.;
  };

  /**
   * The contact pressure along S and the figures derived from it: at the
   * mid-plane, the mean over S, extremes and where they are, and the Lame
   * pressure of the same radii and materials. The pressure at the hub-end
   * corner is singular: max grows with mesh refinement, so compare meshes or
   * methods by the mid-plane and mean values.
   */
  struct PressureSummary
  {
    std::vector<double> pressure; ///< consistent pressure at each point (MPa)
    double              at_mid_plane;
    double              mean;
    double              min, z_of_min;
    double              max, z_of_max;
    double              lame;

    PressureSummary(const Parameters          &parameters,
                    const ContactInterface    &interface,
                    const std::vector<double> &force);
  };

  /** contact_pressure.csv: z, pressure, u_r of both bodies, gap, status. */
  void
  write_contact_pressure(const std::string       &filename,
                         const ContactInterface  &interface,
                         const PressureSummary   &pressure,
                         const StaggeredCoupling &coupling);

  /** convergence.csv: one row per coupling step. */
  void
  write_convergence(const std::string       &filename,
                    const StaggeredCoupling &coupling);

  /** Everything a script needs to know about a run, as JSON. */
  struct SummaryData
  {
    const Parameters        &parameters;
    const Body              &shaft;
    const Body              &hub;
    const ContactInterface  &interface;
    const StaggeredCoupling &coupling;
    const PressureSummary   &pressure;
    const Timing            &timing;
    const std::string       &controller;
    std::vector<std::string> warnings;
  };

  /** summary.json. */
  void
  write_summary(const std::string &filename, const SummaryData &data);
} // namespace coaxfit

#endif
