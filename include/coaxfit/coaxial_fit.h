#ifndef coaxfit_coaxial_fit_h
#define coaxfit_coaxial_fit_h

#include <coaxfit/body.h>
#include <coaxfit/parameters.h>
#include <ostream>

namespace coaxfit
{
  /**
   * One coaxfit run: builds the shaft D1 and the hub D2 with matching
   * contact surfaces, runs the staggered coupling and writes the results
   * (contact_pressure.csv, convergence.csv, summary.json, VTU + PVD) to the
   * output directory. Progress goes to the stream given to run().
   */
  class CoaxialFit
  {
  public:
    explicit CoaxialFit(const Parameters &parameters);

    /**
     * Run the case. Returns true if the coupling converged; throws
     * SolverError if it diverged (then no result file is written).
     */
    bool
    run(std::ostream &out);

    /** Geometry of the shaft D1 as meshed for these parameters. */
    static BodyGeometry
    shaft_geometry(const Parameters &parameters);

    /** Geometry of the hub D2 as meshed for these parameters. */
    static BodyGeometry
    hub_geometry(const Parameters &parameters);

  private:
    const Parameters parameters;
    Body             shaft;
    Body             hub;
  };
} // namespace coaxfit

#endif
