#ifndef coaxfit_operation_analysis_h
#define coaxfit_operation_analysis_h

#include <coaxfit/design/state_solver.h>
#include <coaxfit/parameters/parameters.h>

#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{

  /**
   * The fit in service next to the fit as assembled (`Operation`): the
   * design figures of both states, the loosening speed and the joining
   * temperatures.
   *
   * - **Two states.** The run's own solve is the operating state (its loads
   *   of operation). With loads, the state of assembly (no loads) is solved
   *   by the run's StateSolver.
   * - **Loosening speed.** While the contact zone is fixed the problem is
   *   linear in the interference, and each body's answer to rotation is
   *   linear in omega^2: the interference at point i is
   *   d_i(omega^2) = d_i^S + omega^2 r_i (d^S: at rest under the other
   *   loads; r: the change per (rad/s)^2, both from free-body solves). The
   *   whole joint is open (no force anywhere is a solution of the unilateral
   *   problem, which is unique) exactly when d_i <= 0 at every point:
   *   omega_whole^2 = max_i d_i^S / (-r_i). The first point opens where the
   *   bilateral contact force F^S + omega^2 F^R (two solves with the run's
   *   own method) first reaches zero. Each speed is then confirmed by a
   *   unilateral solve at that speed. DIN 7190's (plane stress) speed is
   *   given next to them.
   * - **Joining temperatures** (DIN 7190): the hub heated, or the shaft
   *   cooled, until the largest interference plus the joining clearance is
   *   gone.
   *
   * Figures that cannot be given (no density, no thermal expansion, a speed
   * that never loosens the joint) are NaN or infinite, written as null.
   */
  class OperationAnalysis
  {
  public:
    static constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

    /** The figures of one state. */
    struct State
    {
      std::string  name; ///< "assembly" or "operation"
      double       pressure_mid_plane = unknown, pressure_mean = unknown;
      double       pressure_max = unknown, pressure_din = unknown; ///< MPa
      double       torque_capacity = unknown, torque_capacity_din = unknown;
      double       axial_force_capacity     = unknown; ///< N
      double       axial_force_capacity_din = unknown; ///< N
      double       safety_slip = unknown, safety_slip_din = unknown;
      double       press_in_force = unknown, press_in_force_din = unknown;
      double       safety_yield_shaft = unknown, safety_yield_hub = unknown;
      double       safety_fracture_hub = unknown; ///< brittle hub only
      double       separated_length    = 0.;      ///< mm of the half joint
      bool         contact_lost        = false;
      bool         converged           = true;
      unsigned int iterations          = 0;
    };

    /**
     * Analyse the run of @p parameters that @p fit has solved.
     */
    OperationAnalysis(const Parameters &parameters, StateSolver &fit);

    /** Whether the scene has loads of operation. */
    bool has_loads;

    State assembly, operation;

    /** @name Loosening speed (1/min) */
    /** @{ */
    double loosening_speed_first = unknown; ///< the first point opens
    double loosening_speed_whole = unknown; ///< the whole joint is open
    double loosening_speed_din   = unknown; ///< plane stress, DIN 7190
    /** Confirmation: smallest pressure of a solve at the first speed. */
    double min_pressure_at_first = unknown;
    /** Confirmation: separated points 1 % below and above that speed. */
    unsigned int separated_below_first = 0, separated_above_first = 0;
    /** Confirmation: largest pressure of a solve at the whole-joint speed. */
    double max_pressure_at_whole = unknown;
    /** Why no loosening speed was computed; empty if it was. */
    std::string loosening_note;
    /**
     * The operating conditions in words: the assembly state's temperature
     * and the service state's temperatures, speed and pressures.
     */
    std::string conditions;
    /** @} */

    /** @name Joining (DIN 7190) */
    /** @{ */
    double joining_interference      = unknown; ///< largest U (mm)
    double joining_clearance         = unknown; ///< mm
    double joining_temperature_hub   = unknown; ///< degrees C, hub heated
    double joining_temperature_shaft = unknown; ///< degrees C, shaft cooled
    /** The coefficient (1/K) the shaft's cooling temperature used. */
    double joining_cooling_expansion = unknown;
    /**
     * Whether that was the heating coefficient, as Material/Shaft/Cooling
     * expansion was not given (the temperature is then too warm).
     */
    bool joining_cooling_from_heating = false;
    /**
     * Whether the shaft can be cooled to its joining temperature: not below
     * -196 C, liquid nitrogen, the coldest coolant used for joining (and
     * the range of DIN 7190's undercooling coefficients).
     */
    bool joining_cooling_reachable = true;
    /** The hub's temperature limit (degrees C; NaN: not known). */
    double hub_temperature_limit = unknown;
    /** Whether the hub's joining temperature is above that limit. */
    bool joining_hub_above_limit = false;
    /**
     * When neither way alone is reachable: the hub at its temperature
     * limit and the shaft at -196 C together open joining_by_both (mm)
     * of the joining_needed (mm: U_max and the clearance); NaN otherwise.
     */
    double joining_by_both = unknown, joining_needed = unknown;
    /** @} */

    /** The coldest coolant used for joining: liquid nitrogen (C). */
    static constexpr double coldest_coolant = -196.;

    /**
     * Cautions of the joining temperatures and of the operating
     * temperatures against the materials' temperature limits (one line
     * each).
     */
    std::vector<std::string>
    warnings(const Parameters &parameters) const;

    /**
     * Whether the fit holds in operation: the surfaces still touch and the
     * required loads (if any) are carried (safety against slip >= 1).
     */
    bool        holds = true;
    std::string verdict; ///< one line: why it holds or not
    /** "half joint" (a half model) or "joint" (a whole one). */
    std::string joint_name = "half joint";
    /** Where at_mid_plane is: "z = 0", or the middle of a whole joint. */
    std::string middle_name = "z = 0";

    /**
     * The console table of the two states and the figures above (without
     * loads only the joining temperatures).
     */
    void
    print(std::ostream &out) const;

    /** The same as a Markdown table and lines, for report.md. */
    void
    print_markdown(std::ostream &out) const;

  private:
    /** The line of the joining temperatures. */
    void
    print_joining(std::ostream &out) const;

    void
    compute_loosening_speed(const Parameters &parameters, StateSolver &fit);

    void
    compute_joining(const Parameters &parameters);
  };

  /** A temperature @p T in degrees C with one decimal: "226.2 C". */
  std::string
  celsius(double T);

  /** The figures of the solved state @p state, called @p name. */
  OperationAnalysis::State
  state_figures(const std::string &name, const SolvedState &state);

  /**
   * @p parameters in the state of assembly: no load of operation (room
   * temperature, at rest, no pressures) and no corner trend solve.
   */
  Parameters
  at_assembly(const Parameters &parameters);
} // namespace coaxfit

#endif
