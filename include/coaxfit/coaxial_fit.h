#ifndef coaxfit_coaxial_fit_h
#define coaxfit_coaxial_fit_h

#include <coaxfit/alpha_controller.h>
#include <coaxfit/body.h>
#include <coaxfit/contact_interface.h>
#include <coaxfit/monolithic_solver.h>
#include <coaxfit/parameters.h>
#include <coaxfit/results.h>
#include <coaxfit/staggered_coupling.h>

#include <memory>
#include <ostream>

namespace coaxfit
{
  /**
   * One coaxfit run, in deal.II's tutorial structure: setup_system() builds
   * the shaft D1 and the hub D2 with matching contact surfaces, their
   * interface and factorizations; solve() runs the staggered coupling;
   * output_results() writes contact_pressure.csv, convergence.csv,
   * summary.json and VTU + PVD to the output directory. run() does all
   * three.
   */
  class CoaxialFit
  {
  public:
    explicit CoaxialFit(const Parameters &parameters);

    /**
     * Run the case, printing progress to @p out. Returns true if the
     * coupling converged; throws SolverError if it diverged (then no result
     * file is written).
     */
    bool
    run(std::ostream &out);

    /** Meshes, DoFs, matrices, the contact interface, factorizations. */
    void
    setup_system();

    /** The coupling iteration; one line per step to @p progress if given. */
    bool
    solve(std::ostream *progress);

    /** Write the result files and print a short report to @p out. */
    void
    output_results(std::ostream &out);

    /** The coupling (after solve()). */
    const InterfaceSolver &
    get_coupling() const
    {
      return *coupling;
    }

    /** The contact interface (after setup_system()). */
    const ContactInterface &
    get_interface() const
    {
      return *interface;
    }

    /** Pressures of the current state (after solve()). */
    PressureSummary
    pressure_summary() const;

    /** Geometry of the shaft D1 as meshed for these parameters. */
    static BodyGeometry
    shaft_geometry(const Parameters &parameters);

    /** Geometry of the hub D2 as meshed for these parameters. */
    static BodyGeometry
    hub_geometry(const Parameters &parameters);

    /** Largest interface for which Interface operator = auto condenses. */
    static constexpr unsigned int max_condensed_points = 2000;

  private:
    /** Whether Coupling/Interface operator (auto: by size) condenses. */
    bool
    use_condensed_operator() const;

    /** The active set update mode selected by Contact/Active set update. */
    UnilateralActiveSet::Update
    active_set_mode() const;

    const Parameters                  parameters;
    Body                              shaft;
    Body                              hub;
    std::unique_ptr<ContactInterface> interface;
    std::unique_ptr<AlphaController>  controller;
    std::unique_ptr<InterfaceSolver>  coupling;
    std::unique_ptr<CondensedBody>    condensed_shaft, condensed_hub;
    Timing                            timing;
  };
} // namespace coaxfit

#endif
