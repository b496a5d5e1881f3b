#ifndef coaxfit_fit_selection_h
#define coaxfit_fit_selection_h

#include <coaxfit/design/state_solver.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/parameters.h>

#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * `Design/Mode = select`: the band of measured (drawing) diametral
   * interferences [U_min, U_max] (mm, smoothing loss included) that carries
   * K_A times the required loads with Design/Slip safety in every state
   * and that shaft and hub bear with Design/Yield safety (a brittle hub:
   * Design/Fracture safety), and the ISO 286 fits whose whole band lies
   * inside it, ranked.
   *
   * The states: assembly (room temperature, no speed, no pressures) and,
   * with loads of operation, the state in service. While the contact zone
   * stays the same each state is linear in the interference: the contact
   * force and the stresses are a U + b (b = 0 at assembly, where the
   * unilateral problem is even positively homogeneous in U_w). Each state
   * is solved at two interferences (DIN 7190's U_min_din and U_max_din,
   * or the run's interference and 1.5 times it), and each criterion
   * (slip, yield of the shaft, yield of the hub, fracture of a brittle hub)
   * gives its interference from that straight line: the safety against
   * slip is linear in the normal force, the equivalent stress over the
   * strength nearly so (the von Mises norm of affine stresses is not
   * affine where b is not 0). The governing criterion of each end is then
   * solved again at the interference found (aiming at the required safety
   * plus 0.01 %); unless its safety is then the required one to 0.1 % and
   * not below it (the contact zone changed, the joint opened, or the
   * norm's curvature), secant steps on the last two solves correct it (at
   * most six, bisection where a secant step leaves the bracket). Each end is
   * finally solved in every state, which checks the other criteria and the
   * contact zone there (notes say where the joint is open or the contact is
   * lost).
   *
   * DIN 7190's values come from the same criteria on Lame's rings
   * (Din7190, plane stress): the pressure is affine in U_w, so the slip end
   * is exact; the yield end is the root of the equivalent stress at the
   * check points, found by bisection of the closed form.
   *
   * A shrink fit (Design/Joining) must also be joinable(): the fits inside
   * the band that cannot be joined by temperature are left out (counted in
   * `unjoinable`, named in a note), since another joining method would
   * change the friction and with it U_min.
   *
   * Ranking of the fits: the preferred fits of ISO 286-1 first, then the
   * widest tolerances (IT of hole plus IT of shaft, the interference band
   * es - ei + ES - EI), then the band best centred in [U_min, U_max]. Each fit
   * is also marked whether its band lies inside DIN 7190's [U_min_din,
   * U_max_din]: the finite elements may accept a fit the plain-cylinder
   * formulas do not.
   *
   * A hub that may yield (Material/Hub/Plasticity = von Mises) with
   * Design/Plastic utilisation P > 0: the hub's yield is no criterion;
   * U_max is where its plastic utilisation (D_p - D_F) / (D_aA - D_F) on
   * the elastic-plastic load path reaches P, and where the hub yields at
   * U_min the slip safety comes from that path (a yielding hub carries
   * less pressure than the elastic model gives). DIN 7190's column takes
   * the thick-walled cylinder of elastic_plastic_hub_pressure() for both.
   *
   * A taper fit (sections that meet on a cone, taper C) has no ISO fit: its
   * interference is U = a C of the push-on distance a. The band found the
   * same way is one of push-on distances [a_min, a_max] = [U_min, U_max] /
   * C (push_on()), the largest interference the model takes being the
   * smaller of 0.1 D_F and l_F C / 10 (the push small against the joint,
   * as a run of the taper requires); where no stress criterion ends the
   * band before that limit, the limit ends it. found() then means a_min <=
   * a_max.
   */
  class FitSelection
  {
  public:
    static constexpr double infinite = std::numeric_limits<double>::infinity();

    /** Solves the state of a Parameters (same scene and meshes). */
    using Solve = std::function<SolvedState(const Parameters &)>;

    /** One end of the band: its interference and what governs it. */
    struct End
    {
      double       U = 0.;     ///< measured diametral interference (mm)
      std::string  state;      ///< "at assembly" or "in service"
      std::string  criterion;  ///< "slip", "yield of the hub", ...
      double       safety = 0; ///< the governing safety at U (FE)
      unsigned int solves = 0; ///< FE solves of its correction

      /** "criterion state", or the one given ("" if neither). */
      std::string
      governed_by() const
      {
        return state.empty() || criterion.empty() ? criterion + state :
                                                    criterion + " " + state;
      }
    };

    /** The figures of a state at one end (FE, solved at that end). */
    struct Check
    {
      std::string end;   ///< "U_min" or "U_max"
      std::string state; ///< "at assembly" or "in service"
      double      U           = 0.;
      double      safety_slip = 0., safety_yield_hub = 0.;
      double      safety_yield_shaft = 0., safety_fracture_hub = 0.;
      double      separated_length = 0.; ///< mm of the half joint
      bool        contact_lost     = false;
      bool        converged        = true;
    };

    /**
     * The elastic-plastic state of a fit along its load path (joining, and
     * operation when Operation has loads), as a selection with
     * Design/Plastic utilisation > 0 takes it.
     */
    struct PlasticState
    {
      bool        completed = false;       ///< every stage was solved
      std::string failure;                 ///< why not
      double      elastic_fraction = 0.;   ///< of U_w at the first yield
      double      utilisation      = 0.;   ///< the hub's, largest of the stages
      double      plastic_diameter = 0.;   ///< the hub's D_p there (mm)
      std::string utilisation_stage;       ///< the stage that reached it
      double      least_normal_force = 0.; ///< N, the least of the stages
      std::string least_stage;             ///< the stage of least force
      double      joined_pressure = 0.;    ///< mean, after joining (MPa)
    };

    /**
     * Load path/Stages of the selection's load paths: joining, and with
     * loads of operation also operation and unloading (the fit must hold
     * after its first cycle in service too: a hub that yielded further in
     * operation keeps less pressure when cooled or stopped).
     */
    static std::string
    load_path_stages(const Parameters &parameters)
    {
      return parameters.operation.has_loads() ?
               "joining, operation, unloading" :
               "joining";
    }

    /** A stage of a load path as a state: "after joining", "in operation". */
    static std::string
    stage_words(const std::string &stage)
    {
      return stage == "operation" ? "in operation" : "after " + stage;
    }

    /** Follows the load path of a Parameters (same scene). */
    using PlasticSolve = std::function<PlasticState(const Parameters &)>;

    /** An end of the band on the elastic-plastic load path. */
    struct PlasticCheck
    {
      std::string  end; ///< "U_min" or "U_max"
      double       U = 0.;
      PlasticState state;
      double       safety_slip = 0.; ///< of the least normal force
    };

    /**
     * Select for the run of @p parameters (Design/Mode = select); @p solve
     * solves a state of the same scene at another interference or loads,
     * elastically. With Design/Plastic utilisation > 0 (a hub that may
     * yield) @p plastic follows the load path of an interference: the
     * hub's criterion is then its plastic utilisation on that path
     * (compute_plastic()), no longer its elastic yield.
     */
    FitSelection(const Parameters   &parameters,
                 const Solve        &solve,
                 const PlasticSolve &plastic = PlasticSolve());

    End                      least, largest;         ///< FE: U_min, U_max
    End                      least_din, largest_din; ///< DIN 7190
    std::vector<IsoFit>      fits;          ///< ranked, inside the band
    std::vector<IsoFit>      unjoinable;    ///< inside, but not joinable()
    std::vector<Check>       checks;        ///< each end, each state
    std::vector<std::string> notes;         ///< contact zone, corrections
    unsigned int             n_solves = 0;  ///< FE solves in all
    double                   diameter = 0.; ///< D_F (mm)
    DesignParameters         design;        ///< the loads and safeties
    bool                     brittle_hub = false; ///< fracture, not yield
    double taper = 0.; ///< C of a taper fit; 0: a cylindrical joint
    /** Design/Plastic utilisation; 0: the selection is elastic. */
    double                    allowed_utilisation = 0.;
    std::vector<PlasticCheck> plastic_checks;       ///< each end
    unsigned int              n_plastic_solves = 0; ///< load paths followed
    double U_limit = 0.; ///< the largest interference the model takes (mm)

    /** The safety against slip of the normal force @p N (N). */
    double
    slip_safety_of(double N) const;

    /** Whether the joint is a cone: a band of push-on distances. */
    bool
    taper_fit() const
    {
      return taper > 0.;
    }

    /** The push-on distance (mm) of the interference @p U of a taper fit. */
    double
    push_on(const double U) const
    {
      return U / taper;
    }

    /**
     * The diametral opening (mm) that joining by temperature reaches with
     * Design/Joining = shrink: the hub heated to its temperature limit
     * and the shaft cooled to -196 C (liquid nitrogen) together; infinite
     * where a part has no limit or the joint is not shrunk (pressure oil,
     * press: not assessed here).
     */
    double joining_opening   = infinite;
    double joining_clearance = 0.; ///< mm, Operation/Joining clearance

    /**
     * Whether @p fit can be joined by temperature: its largest
     * interference plus the joining clearance within joining_opening.
     */
    bool
    joinable(const IsoFit &fit) const
    {
      return 1e-3 * fit.max_interference() + joining_clearance
             <= joining_opening;
    }

    /** Whether the band of @p fit lies inside DIN 7190's [U_min, U_max]. */
    bool
    inside_din_band(const IsoFit &fit) const
    {
      return 1e-3 * fit.min_interference() >= least_din.U
             && 1e-3 * fit.max_interference() <= largest_din.U;
    }

    /** Whether some fit satisfies the design. */
    bool
    found() const
    {
      return taper_fit() ? std::isfinite(least.U) && least.U <= largest.U :
                           !fits.empty();
    }

    /** Empty if a fit was found, else why none: the conflict. */
    std::string
    conflict() const;

    /** The console table (up to @p max_fits fits). */
    void
    print(std::ostream &out, unsigned int max_fits = 10) const;

    /** The "## Fit selection" section of report.md. */
    void
    print_markdown(std::ostream &out) const;

    /**
     * @p parameters with the measured diametral interference @p U (mm)
     * given directly (no ISO fit, case mean; the smoothing loss kept; a
     * taper fit's push-on distance U / C).
     */
    static Parameters
    at_interference(const Parameters &parameters, double U);

  private:
    /** A line of the band's table: FE and DIN 7190, what governs each. */
    struct BandRow
    {
      std::string label;
      double      fe, din;
      std::string fe_by, din_by;
    };

    /** The band's lines: U_min, U_max, and for a taper a_min, a_max. */
    std::vector<BandRow>
    band_rows() const;

    void
    compute_din(const Parameters &parameters);

    void
    compute_fe(const Parameters &parameters, const Solve &solve);

    /**
     * With a hub that may yield: U_max where the hub's plastic utilisation
     * on the load path reaches the allowed one, and U_min again from the
     * load path where the hub yields at the elastic U_min (each found by
     * secant steps in a bracket, the load path followed at each
     * interference from the unloaded state).
     */
    void
    compute_plastic(const Parameters &parameters, const PlasticSolve &solve);

    /**
     * DIN 7190's ends for a hub that may yield (the thick-walled cylinder
     * of elastic_plastic_hub_pressure(), at assembly).
     */
    void
    compute_din_plastic(const Parameters &parameters);


    void
    compute_joining(const Parameters &parameters);

    void
    rank_fits();

    void
    note_fits();
  };
} // namespace coaxfit

#endif
