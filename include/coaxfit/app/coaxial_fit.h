#ifndef coaxfit_coaxial_fit_h
#define coaxfit_coaxial_fit_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <coaxfit/coupling/coarse_interface_model.h>
#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/coupling/staggered_coupling.h>
#include <coaxfit/design/fit_design.h>
#include <coaxfit/design/pressure_summary.h>
#include <coaxfit/design/state_solver.h>
#include <coaxfit/design/verdict.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/condensed_body.h>

#include <array>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * One coaxfit run, in deal.II's tutorial structure: setup_system() builds
   * the bodies of its Scene (the shaft D1 and the hub D2) with matching
   * joint surfaces, their interface and factorizations; solve() runs the
   * selected solver (staggered coupling or monolithic reference);
   * output_results() writes the result files through the ResultWriters and
   * summary.json. run() does all three, with the files staged in a
   * ResultDirectory that replaces Output/Directory as a whole once every file
   * is complete.
   */
  class CoaxialFit : public StateSolver
  {
  public:
    /**
     * Progress (header, steps, files, timing) goes to @p out when
     * @p verbose; the final report always.
     */
    explicit CoaxialFit(const Parameters &parameters,
                        std::ostream     &out     = std::cout,
                        bool              verbose = true);

    /**
     * Run the case. Returns true if the coupling converged (false: the state
     * is written, marked not converged); throws SolverError if it diverged
     * and InputError if Output/Directory cannot be used (checked before any
     * work). A run that throws leaves the earlier results untouched.
     */
    bool
    run();

    /**
     * Run the case into the existing directory @p directory (no staging,
     * no commit): what run() does between its checks and its commit, for a
     * caller that stages several cases together (Fit/Case = all).
     */
    bool
    run_in(const std::string &directory);

    /** Meshes, DoFs, matrices, the contact interface, factorizations. */
    void
    setup_system();

    /**
     * Whether a case that differs from this one only in the entry
     * @p entry (Section/Name) can reuse its meshes, matrices and
     * factorizations: entries of Fit, Operation, Coupling, Contact, Design
     * and Output change the interference, the loads or the settings of the
     * coupling, never a body's matrix.
     */
    static bool
    reusable_across(const std::string &entry);

    /**
     * Make this case, set up, the case of @p other, which differs from it
     * only in entries for which reusable_across() holds: its parameters,
     * interference and loads of operation are taken, the meshes, matrices
     * and factorizations kept. run_in() then runs it without a new setup.
     */
    void
    reuse_for(const Parameters &other);

    /**
     * Set up the case one refinement coarser that the corner trend of the
     * report solves (if Design/Corner trend asks for it) and the coarse
     * model of the coupling uses (Coupling/Coarse model; its condensed
     * operators formed too), so that cases made from this one by
     * reuse_for() reuse its setup.
     */
    void
    prepare_corner_trend();

    /** The coupling iteration; one line per step to @p progress if given. */
    bool
    solve(std::ostream *progress);

    /** Print the report and write the result files into @p directory. */
    void
    output_results(const std::string &directory);

    /** The coupling (after solve()). */
    const InterfaceSolver &
    get_coupling() const
    {
      return *coupling;
    }

    /** The contact interface (after setup_system()). */
    const ContactInterface &
    get_interface() const override
    {
      return *interface;
    }

    /** Pressures, design figures and how the solve ended (after solve()). */
    SolvedState
    solved_state() const override;

    /**
     * The state of @p other (the loads of operation of this case changed),
     * solved by a case of its own, quietly.
     */
    SolvedState
    solve_state(const Parameters &other) override;

    /** The design figures (after output_results()). */
    const FitDesign &
    get_design() const
    {
      return *design;
    }

    /** The verdict (after output_results()). */
    const Verdict &
    get_verdict() const
    {
      return *verdict;
    }

    /** Pressures of the current state (after solve()). */
    PressureSummary
    pressure_summary() const;

    /** The design figures of the current state (after solve()). */
    FitDesign
    state_design() const;

    /**
     * The nodal contact force of the two bodies (after setup_system()) for
     * the pointwise radial interference @p interference (mm) and no loads
     * (unilateral or bilateral contact), by the run's own method; throws
     * SolverError if it does not converge. The problem is linear in the
     * interference while the contact zone is fixed.
     */
    Vector<double>
    contact_force_for(const Vector<double> &interference,
                      bool                  unilateral) override;

    /**
     * How the loads @p loads of the free bodies (one per body of the
     * scene) change the interference at each point of the joint: u_r of
     * its inner side minus u_r of its outer side (mm).
     */
    Vector<double>
    interference_change(const std::vector<BodyLoad> &loads) override;

    /** Largest interface for which Interface operator = auto condenses. */
    static constexpr unsigned int max_condensed_points = 2000;

  private:
    /**
     * The drawing's gap at each interface point over a rounded edge
     * (ContactInterface::set_shape_gap()).
     */
    Vector<double>
    rounded_edge_gap() const;

    /**
     * The active set a solve of @p contact starts from: every point in
     * contact but those a rounded edge leaves open by its shape.
     */
    static UnilateralActiveSet
    initial_active_set(const ContactInterface     &contact,
                       bool                        unilateral,
                       UnilateralActiveSet::Update mode);

    /**
     * Each body's field under its loads of operation (free contact
     * surface) and the contact interface with the interference they leave.
     */
    void
    setup_loads();

    /** Whether Coupling/Interface operator (auto: by size) condenses. */
    bool
    use_condensed_operator() const;

    /** Form the bodies' condensed operators if not yet formed. */
    void
    condense();
    /** The active set update mode (auto resolved). */
    UnilateralActiveSet::Update
    active_set_mode() const;

    /**
     * The solver of Solver/Method for the interface @p contact: the
     * staggered coupling with full or condensed operators (made once), or
     * the monolithic reference.
     */
    std::unique_ptr<InterfaceSolver>
    make_solver(const ContactInterface &contact,
                bool                    unilateral,
                bool                    start_from_coarse = false);
    /**
     * Solve the case one refinement coarser and start @p staggered from its
     * contact force and flags, transferred by @p model (nested
     * iteration); the corner trend then
     * reuses that solution. Without a coarse solution the start stays the
     * uniform pressure.
     */
    void
    start_from_coarse_solution(StaggeredCoupling          &staggered,
                               const CoarseInterfaceModel &model);

    /**
     * The von Mises stresses at the end of the joint (hub bore, shaft
     * surface) of the same case solved one refinement coarser; empty if
     * that solve diverged.
     */
    std::vector<double>
    coarser_corner_values();

    /**
     * Whether the coupling takes the prior of its quasi-Newton model from
     * the case one refinement coarser (Coupling/Coarse model).
     */
    bool
    wants_coarse_model() const;
    /** The short-wave interface compliances of the joint's two sides. */
    std::array<ShortWaveCompliance, 2>
    short_wave_compliances() const;
    /**
     * The coarse model for the interface @p contact of this case (the
     * coarser case set up, its condensed operators formed); null if the
     * coarser interface is too large to condense.
     */
    std::unique_ptr<CoarseInterfaceModel>
    make_coarse_model(const ContactInterface &contact);
    /** Set up coarse_twin (this case one refinement coarser) if not yet. */
    void
    set_up_coarse_twin();
    /** This case one refinement coarser, without its own corner trend. */
    Parameters
    coarser_parameters() const;

    /** Warnings about the final state with @p pressure, one line each. */
    std::vector<std::string>
    warnings(const PressureSummary &pressure) const;

    /** The report of the final state, printed always. */
    void
    print_report(const PressureSummary          &pressure,
                 const Complementarity          &complementarity,
                 const std::vector<std::string> &warnings) const;

    Parameters parameters;
    bool       is_set_up  = false;
    bool       amg_solver = false; ///< Solver/Linear solver, see use_amg()
    /** The coarser case of the corner trend, kept for reuse_for(). */
    std::unique_ptr<CoaxialFit> coarse_twin;
    /** Whether coarse_twin holds the solution of this case's parameters. */
    enum class TwinState
    {
      stale,  ///< not solved for the current parameters
      solved, ///< solved (converged or not)
      failed  ///< its coupling threw a SolverError
    } twin_state
      = TwinState::stale;
    std::ostream                     &out;
    ConditionalOStream                pcout;
    Scene                             scene;
    std::unique_ptr<ContactInterface> interface;
    std::unique_ptr<InterfaceSolver>  coupling;
    std::unique_ptr<FitDesign>        design;
    std::unique_ptr<Verdict>          verdict;
    /** Each body's field: the contact answer plus its loads' answer. */
    std::vector<Vector<double>> fields;
    SolverStatistics            statistics; ///< after solve()
    TimerOutput                 timer;
  };
} // namespace coaxfit

#endif
