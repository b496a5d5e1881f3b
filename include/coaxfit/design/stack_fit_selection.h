#ifndef coaxfit_stack_fit_selection_h
#define coaxfit_stack_fit_selection_h

#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * What the selection of a stack's fits takes from one state of the stack
   * (at assembly, or in service) at given interferences: each joint's
   * torque capacity and mean pressure (it touches where positive), and the
   * stresses of each body at its mid-plane check points (the points of
   * the verdict's yield and fracture figures).
   */
  struct StackStateFigures
  {
    std::string                                     state;  ///< "at assembly"
    std::vector<double>                             torque; ///< N m, per joint
    std::vector<double>                             p_mean; ///< MPa, per joint
    std::vector<std::vector<Axisymmetric::Vector4>> stress; ///< per body
    /**
     * Per joint, at each point: the diametral gap the bodies leave (mm;
     * about 0 where in contact), for Design/Running clearance.
     */
    std::vector<std::vector<double>> gap;
    /**
     * Per joint: its reliefs' radial gaps at their planes over their drawn
     * clearances (StackFit::relief_plane_gaps()); below 0 the relief
     * closes, which is not modelled.
     */
    std::vector<std::vector<double>> relief_gap;
    /**
     * Per joint, at each point: what the parts joined before it add to its
     * diametral interference (mm; StackFit::joining_growth()), in the
     * state of assembly only (empty in service).
     */
    std::vector<std::vector<double>> joining_growth;
  };

  /**
   * `Design/Mode = select` for a stack (Assembly/Bodies): the ISO 286 fits
   * of the selected joints (Design/Selected joints) that together carry
   * Design/Required torque through every joint with Design/Slip safety and
   * that every body bears with Design/Yield safety (a brittle body:
   * Design/Fracture safety), in the state of assembly and, with loads of
   * operation, in service; each selected joint touches everywhere in its
   * band.
   *
   * The joints interact (a hub's fit squeezes the sleeve onto the shaft),
   * so the fits are chosen together. While the contact zones stay, every
   * state is affine in the joints' interferences: the torque capacities
   * and the stresses are q(U) = q_0 + G (U - U_0). G comes from one FE
   * solve of each state at U_0 (each selected joint at 0.001 D plus its
   * smoothing loss) and one more per selected joint. Over a box of
   * interferences (each joint's fit band) an affine quantity has its
   * extremes at the box's corners, and so has the von Mises stress (a
   * norm of affine stresses, convex): each combination of candidate fits
   * is judged exactly for the linear model at the 2^J corners of its box.
   *
   * The combinations (each joint's candidate_fits() whose smallest
   * interference exceeds its smoothing loss) are ranked: fewest fits that
   * cannot be joined by temperature with the parts joined before
   * (joinable() at the combination's largest interferences; such a fit
   * must be pressed in), then as the two-body selection ranks fits: fewest fits
   * that are not preferred ones of ISO 286-1, then the widest tolerances
   * (the sum of the bands), then the largest least margin (the smallest ratio
   * of a safety to its requirement over the criteria and corners). The first is
   * checked by FE at every corner (up to 16; for more joints at each
   * criterion's worst corner) in every state; where a criterion fails there (a
   * contact zone that changed), the next is checked (at most
   * max_checks()). Before the search, prune() leaves out the candidates
   * no combination can use; where there are still more combinations than
   * max_combinations(), each joint's list is cut to its best-ranked
   * candidates (a note says so).
   *
   * Beside the choice, each selected joint's allowed band with the other
   * joints anywhere in their chosen fits (the linear model): the interval
   * of its measured interference where every criterion holds, and which
   * criterion ends it on either side.
   */
  class StackFitSelection
  {
  public:
    /**
     * Evaluates the stack at measured diametral interferences (mm, one per
     * joint, the smoothing loss still to be taken off): the state of
     * assembly first, then the state in service if there are loads.
     */
    using Evaluate = std::function<std::vector<StackStateFigures>(
      const std::vector<double> &)>;

    /** The largest number of combinations judged on the linear model. */
    static constexpr unsigned int
    max_combinations()
    {
      return 2000000;
    }

    /** The largest number of combinations checked by FE. */
    static constexpr unsigned int
    max_checks()
    {
      return 5;
    }

    /**
     * How far joint k's parts open it at most for joining (mm, diametral;
     * infinite where not judged) at measured diametral interferences (mm,
     * one per joint): StackFit::joining_reach().
     */
    using Reach
      = std::function<double(unsigned int, const std::vector<double> &)>;

    /**
     * Select for @p parameters, the stack evaluated by @p evaluate, the
     * joints' joining reach by @p reach.
     */
    StackFitSelection(const StackParameters &parameters,
                      const Evaluate        &evaluate,
                      const Reach           &reach);

    /** A combination: a candidate index per selected joint. */
    struct Combination
    {
      std::vector<unsigned int> choice;            ///< per selected joint
      unsigned int              unjoinable    = 0; ///< joints, joinable()
      unsigned int              not_preferred = 0;
      double                    width         = 0.; ///< um, sum of bands
      double                    margin        = 0.; ///< least, linear model
      std::string               governed_by; ///< the criterion of the margin
    };

    /** An FE check of the chosen fits at one corner in one state. */
    struct Check
    {
      std::vector<double> U; ///< measured, mm, per joint
      std::string         state;
      double              margin = 0.;    ///< FE, least ratio
      double              linear = 0.;    ///< the linear model's there
      std::string         governed_by;    ///< FE
      bool                touches = true; ///< every selected joint
    };

    /** A selected joint's band with the others in their chosen fits. */
    struct Band
    {
      double      low = 0., high = 0.; ///< mm, measured
      std::string low_by, high_by;     ///< the criteria ending it
    };

    /**
     * The joints of the box, inside out: the selected ones and those that
     * keep an ISO fit (kept; one candidate, their band).
     */
    std::vector<unsigned int>        selected;
    std::vector<bool>                kept;       ///< per entry of selected
    std::vector<std::vector<IsoFit>> candidates; ///< per selected joint
    std::vector<unsigned int>        n_fits;     ///< candidates before any cut
    std::vector<Combination>         ranked; ///< feasible, best first (<= 10)
    unsigned long                    n_combinations = 0; ///< judged
    double       n_all_combinations = 0.; ///< of all candidates, before pruning
    unsigned int n_pruned = 0; ///< candidates that cannot be part of any
    unsigned long            n_feasible = 0;
    std::vector<IsoFit>      chosen; ///< per selected joint; empty: none
    std::vector<Check>       checks; ///< of the chosen fits
    std::vector<Band>        bands;  ///< per selected joint
    std::vector<std::string> notes;
    unsigned int             n_solves = 0; ///< FE states solved
    std::string              conflict;     ///< why none, if none

    /**
     * Whether joint @p k can be joined by temperature (DIN 7190) with the
     * joints at the measured interferences @p U (mm, a combination's
     * largest): its parts as they are when it is made (Assembly/Order),
     * the outer heated to the lowest temperature limit of its bodies and
     * the inner cooled to -196 C (liquid nitrogen), together open more
     * than its interference, plus what the parts joined before add to it
     * (joining_growth()), plus Operation/Joining clearance. True where
     * neither part's coefficients and limit are known, and for joints
     * made by pressure oil or pressed in (Design/Joining).
     */
    bool
    joinable(unsigned int k, const std::vector<double> &U) const;

    /**
     * The joints with an interference (selected or kept) that cannot be
     * joined by temperature at the measured interferences @p U (mm):
     * joinable() false.
     */
    std::vector<unsigned int>
    unjoinable_joints(const std::vector<double> &U) const;

    /**
     * Joint @p k's reach (Reach) at the measured interferences @p U, kept
     * for the interferences of the joints of its parts (all it depends
     * on).
     */
    double
    reach_of(unsigned int k, const std::vector<double> &U) const;

    /**
     * The linear model's largest growth over joint @p k's points of its
     * diametral interference by the parts joined before it, at the
     * measured interferences @p U (mm).
     */
    double
    joining_growth(unsigned int k, const std::vector<double> &U) const;

    /** Whether fits were found and passed their FE check. */
    bool
    found() const
    {
      return !chosen.empty();
    }

    /** The FE check of least margin (null if none). */
    const Check *
    least_check() const
    {
      const Check *least = nullptr;
      for (const Check &c : checks)
        if (!least || c.margin < least->margin)
          least = &c;
      return least;
    }

    /** The console table. */
    void
    print(std::ostream &out) const;

    /** The "## Fit selection" section of report.md. */
    void
    print_markdown(std::ostream &out) const;

    /** fit_selection.csv: the ranked combinations. */
    void
    write_csv(std::ostream &out) const;

    /** The object `selection` of summary.json, as JSON text. */
    std::string
    json() const;

  private:
    /** The joints' joining reach at measured interferences. */
    Reach reach_at;
    /** reach_of()'s: per joint and its parts' interferences. */
    mutable std::map<std::pair<unsigned int, std::vector<double>>, double>
      reached;
    /**
     * Per joint, at each point: the linear model of joining_growth() at
     * U_0, and its slope per selected joint (mm per mm).
     */
    std::vector<std::vector<double>>              growth0;
    std::vector<std::vector<std::vector<double>>> growth_slope;

    /** The least ratio of a safety to its requirement, and where. */
    struct Judgement
    {
      double       margin  = 0.;
      unsigned int which   = 0;    ///< index into criterion_names
      bool         touches = true; ///< every selected joint
    };

    /** The states' figures as one vector (the layout of base). */
    std::vector<double>
    flatten(const std::vector<StackStateFigures> &states) const;

    /** Judge the flat figures @p q (flatten()); see Judgement. */
    Judgement
    judge(const std::vector<double> &q) const;

    /** The linear model's flat figures at @p U (measured, mm, all joints). */
    std::vector<double>
    linear(const std::vector<double> &U) const;

    /** Combination @p c's corner @p corner (a bit per selected joint). */
    std::vector<double>
    corner_of(const Combination &c, unsigned int corner) const;

    /**
     * Leave out the candidates that no combination can use: where an
     * affine criterion (a joint's torque capacity, a chosen joint's mean
     * pressure) fails at an end of the candidate's band even with the
     * other joints anywhere in their candidates' envelope (the largest
     * value an affine function takes over a box, at its corner). Repeated
     * while the envelopes shrink. Exact: no feasible combination is lost.
     */
    void
    prune();

    /** Judge every combination on the linear model; keep the best. */
    void
    search();

    /** Check the best combinations by FE; set chosen and checks. */
    void
    check(const Evaluate &evaluate);

    /** Each selected joint's band with the others in the chosen fits. */
    void
    compute_bands();

    /**
     * The torque joint @p k must carry in place of both required loads
     * (StackParameters::required_torque_at() at its diameter, N m).
     */
    double
    required_torque(const unsigned int k) const
    {
      return parameters.required_torque_at(parameters.joint_diameter(k));
    }

    const StackParameters    &parameters;
    std::string               last_pruned; ///< what pruned last
    unsigned int              n_states = 0;
    std::vector<std::string>  state_names;
    std::vector<unsigned int> n_points; ///< stress points per body
    /** Joints given a clearance that keep Design/Running clearance. */
    std::vector<unsigned int> running;
    std::vector<unsigned int> n_gap_points; ///< per entry of running
    /** The joints with reliefs, and their points in relief_gap. */
    std::vector<unsigned int>        relieved, n_relief_points;
    std::vector<std::string>         criterion_names;
    std::vector<double>              U0;    ///< mm, all joints
    std::vector<double>              q0;    ///< flat figures at U0
    std::vector<std::vector<double>> slope; ///< per selected joint, per mm
  };
} // namespace coaxfit

#endif
