#ifndef coaxfit_plastic_fit_h
#define coaxfit_plastic_fit_h

#include <coaxfit/coupling/plastic_coupling.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/design/radial_plastic_fit.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/solvers/plastic_body.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The run of a fit whose shaft or hub may yield (Material/<body>/
   * Plasticity = von Mises), in deal.II's tutorial structure:
   * setup_system() builds the two plain cylinders and their PlasticBody
   * solvers; elastic_limit_fraction() finds the elastic limit (one linear
   * solve: the fraction of the interference at which the first point
   * reaches its yield strength); solve() follows the stages of the load
   * path (Load path/Stages: joining, operation, unloading, disassembly),
   * each in increments, each increment a coupled solve of the contact
   * (PlasticCoupling, staggered or monolithic by Solver/Method) from the
   * committed plastic states, halved when a Newton solve or the coupling
   * fails; the state at the end of each stage is kept (figures, contact
   * pressure, VTU) and output_results() writes them all.
   *
   * A fit that stays elastic along its stages (joining and operation) is
   * handed to the elastic code unchanged (CoaxialFit, with all its
   * results): run() says so and returns its exit code.
   */
  class PlasticFit
  {
  public:
    PlasticFit(const Parameters &parameters, std::ostream &out, bool verbose);

    /**
     * Run the case; the exit code (0 converged, 2 a load increment that
     * could not be solved: the last converged state is written, marked not
     * converged). Throws InputError for what this version does not
     * compute (checked before any work).
     */
    int
    run();

    /**
     * What run() does into the existing directory @p directory (no
     * staging, no commit): the check of a fit a selection chose. The exit
     * code as run()'s.
     */
    int
    run_in(const std::string &directory);

    /**
     * For a fit selection: set up and follow the stages (joining, and
     * operation as Load path/Stages gives it) without output; whether all
     * were completed. The states: stage_results(); a fit that stays
     * elastic is followed by the plastic code all the same (its joining
     * is the one elastic solve).
     */
    bool
    compute();

    /**
     * The fraction of the interference at which the first point yields
     * (after setup_system(); > 1: joining stays elastic).
     */
    double
    elastic_limit() const
    {
      return elastic_fraction;
    }

    /** Why the load path stopped (empty if it was completed). */
    const std::string &
    failure_text() const
    {
      return failure;
    }

    /** Meshes, DoFs, the plastic bodies and the coupling. */
    void
    setup_system();

    /**
     * The elastic solve at the full interference: the fraction of it at
     * which the first point yields (> 1: the fit stays elastic).
     */
    double
    elastic_limit_fraction();

    /**
     * The stages of the load path from the elastic limit on (the state at
     * the end of each kept); whether all were completed.
     */
    bool
    solve();

    /** The estimates of the state after joining (radial model, formulas). */
    void
    postprocess();

    /** The names of every file an elastic-plastic run may write. */
    static std::set<std::string>
    file_names();

    /** Print the report and write the result files into @p directory. */
    void
    output_results(const std::string &directory) const;

    /** One increment of the load path, as it was solved. */
    struct Increment
    {
      unsigned int stage;          ///< index into the stages
      double       fraction;       ///< of the full interference
      double       load_factor;    ///< of the loads of operation
      unsigned int steps;          ///< coupling (or Newton) steps
      unsigned int max_iterations; ///< of one body's Newton solve
      unsigned int halvings;       ///< before it converged
      double       mean_pressure;  ///< MPa
    };

    /** The plastic figures of one body. */
    struct BodyFigures
    {
      std::string name;
      bool        plastic_model = false; ///< Plasticity = von Mises
      bool        yields        = false;
      bool        fully_plastic = false; ///< the whole wall at one section
      /**
       * mm, at the mid-plane: the border of the plastic zone that grew from
       * the joint (for a hub D_p of the thick-walled cylinder); for a zone
       * apart from the joint (a shaft yielding about its axis) its border
       * towards the joint.
       */
      double plastic_diameter_mid = 0.;
      /**
       * At the mid-plane: (D_p - D_F) / (D_aA - D_F) for a zone grown from
       * the joint (0 elastic, 1 through the wall), else the share of the
       * wall's quadrature points that yield.
       */
      double utilisation = 0.;
      double r_min = 0., r_max = 0., z_max = 0.; ///< plastic zone, mm
      double max_equivalent_plastic_strain = 0.;
      double max_von_mises                 = 0.; ///< MPa
    };

    /** The state at the end of one stage of the load path. */
    struct StageResult
    {
      LoadPathParameters::Stage kind      = LoadPathParameters::Stage::joining;
      bool                      completed = false;
      double                    fraction  = 0.;   ///< of the interference
      double                    load_factor = 0.; ///< of the operation loads
      Vector<double>            pressure;         ///< F_i / w_i, MPa
      double       p_mid = 0., p_mean = 0., p_min = 0., p_max = 0.; ///< MPa
      double       z_of_max         = 0.;
      unsigned int separated_points = 0;
      std::vector<BodyFigures> figures;
      double torque_capacity = 0., slip_safety = 0.; ///< N m, -
      double normal_force = 0.;                      ///< N, p_mean pi D_F l_F
      /**
       * The change of the hub's bore diameter and of the shaft's outer
       * diameter at the mid-plane of the joint (mm): after disassembly the
       * permanent change of the parts.
       */
      double      hub_bore_change = 0., shaft_diameter_change = 0.;
      std::string contact_csv; ///< contact_pressure.csv's text
      std::string vtu[2];      ///< the shaft's and the hub's VTU
    };

    /** The state at the end of each stage reached (after solve()). */
    const std::vector<StageResult> &
    stage_results() const
    {
      return stages;
    }

  private:
    /**
     * After setup_system(): whether nothing yields along joining and
     * operation and no unloading or disassembly is asked (the elastic
     * code's answer is the answer; a line says so).
     */
    bool
    stays_elastic();

    /** The line on the path about to be followed. */
    void
    print_path() const;

    /** The line on a path that stopped (to the error stream). */
    void
    report_failure() const;

    /** The elastic code's run of this fit into @p directory ("": its own). */
    int
    run_elastic(const std::string &directory);

    /** Refuse what this version does not compute (before any work). */
    void
    check_scope() const;

    /** The pointwise radial interference for @p fraction of the full. */
    Vector<double>
    interference(double fraction) const;

    /** The mean pressure of the current contact force (MPa). */
    double
    mean_pressure() const;

    /**
     * Follow one stage from its progress @p t (0..1; > 0 for joining from
     * the elastic limit): interference and load factor linear in t between
     * the stage's start and end; whether it was completed.
     */
    bool
    follow(StageResult &stage,
           double       fraction_start,
           double       load_start,
           double       t);

    /**
     * The stage whose torque capacity is least (disassembly aside; the
     * first of equals).
     */
    const StageResult &
    least_torque_stage() const;

    /**
     * The safety against slip of @p stage: its normal force with the
     * coefficient of friction over K_A times the required loads (NaN
     * without a required load).
     */
    double
    slip_safety(const StageResult &stage) const;

    /**
     * What the fit fails, one line each (empty: Verdict OK): the load path
     * not completed; the surfaces apart in a stage it is used in (not
     * disassembly); the slip safety of the least normal force of those
     * stages below Design/Slip safety; the hub's plastic utilisation above
     * Design/Plastic utilisation; a shaft that yields.
     */
    std::vector<std::string>
    verdict_failures() const;

    /** report.md into @p directory, with the verdict's @p failed lines. */
    void
    write_report(const std::string              &directory,
                 const std::vector<std::string> &failed) const;

    /** The hub's plastic utilisation, the largest of the stages reached. */
    double
    largest_hub_utilisation() const
    {
      double used = 0.;
      for (const StageResult &stage : stages)
        used = std::max(used, stage.figures[1].utilisation);
      return used;
    }

    /** Keep the committed state's figures and files in @p stage. */
    void
    capture(StageResult &stage) const;

    /**
     * The largest von Mises stress over the yield strength of the elastic
     * state at the full interference and @p load_factor times the loads of
     * operation (committed); @p what names the solve in an error.
     */
    double
    elastic_yield_ratio(double load_factor, const std::string &what);

    /** elastic_yield_ratio() of the state of operation. */
    double
    operation_yield_ratio();

    /** The figures of body @p b from its committed state. */
    BodyFigures
    body_figures(unsigned int b) const;

    Parameters                                parameters;
    std::ostream                             &out;
    const bool                                verbose;
    Scene                                     scene;
    std::vector<std::unique_ptr<PlasticBody>> bodies; ///< shaft, hub
    std::unique_ptr<PlasticCoupling>          coupling;

    std::vector<LoadPathParameters::Stage> stage_list;
    double                                 elastic_fraction = 0.;
    double                                 reached          = 0.;
    bool                                   completed        = false;
    bool        checks_a_selection = false; ///< run_in(): a selection's case
    std::string failure;
    std::vector<Increment>   increments;
    std::vector<StageResult> stages; ///< those reached
    unsigned int             total_steps = 0, body_solves = 0;
    unsigned int total_halvings = 0; ///< failed increments, all stages
    unsigned int elastic_steps  = 0; ///< of the elastic solve of joining

    // After postprocess():
    double                   din_estimate = 0., din_limit = 0.;
    RadialPlasticFit::Result radial;
    bool                     radial_valid = false;
    /** A line on the method chosen, printed by run() (or empty). */
    std::string method_note;
    double      elastic_lame = 0.;
    double      time_setup = 0., time_solve = 0.;
  };
} // namespace coaxfit

#endif
