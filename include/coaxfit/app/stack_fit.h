#ifndef coaxfit_stack_fit_h
#define coaxfit_stack_fit_h

#include <coaxfit/coupling/stack_coupling.h>
#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/design/stack_fit_selection.h>
#include <coaxfit/design/verdict.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/parameters/stack_parameters.h>
#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/condensed_body.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * The figures of one joint of a stack after joining: its pressure in the
   * assembly and alone (its two bodies with the others removed), the
   * plane-stress compound-cylinder estimates of both, and what a designer
   * asks of it.
   */
  struct JointFigures
  {
    std::string name;
    double      diameter;                    ///< mm
    double      diametral_interference;      ///< mm, nominal
    double      smoothing_loss;              ///< mm, 0.8 (Rz_i + Rz_o)
    double      effective_interference;      ///< mm, U_w (solved with)
    double      p_mid, p_mean, p_min, p_max; ///< MPa, in the assembly
    double      mid_plane_z;                 ///< drawing z of p_mid (mm)
    /**
     * A joint of several pieces (seats beside a relief groove): each
     * piece's drawing z from and to (mm) and its mean pressure (MPa);
     * empty for one piece.
     */
    std::vector<std::array<double, 3>> pieces;
    /**
     * The reliefs of the joint (StackSections::joint_reliefs(): grooves
     * between its pieces, end reliefs beyond its ends), each with the
     * least radial gap left across it in this state and the drawing z of
     * that gap (mm). The gap is the drawn clearance less the joint's whole
     * radial interference (as if the relief's surface carried it) plus
     * the outer body's radial displacement less the inner one's, where the
     * relief is judged; no more than 0 would touch, which is not modelled
     * (StackFit::postprocess() refuses it).
     */
    struct ReliefGap
    {
      JointRelief relief;
      double      gap, z;
    };
    std::vector<ReliefGap> reliefs;
    bool                   closed;         ///< every point in contact
    double                 contact_length; ///< mm, full length in contact
    unsigned int           separated_points;
    /**
     * The diametral gap 2 (u_outer - u_inner - d) left where the joint is
     * open, smallest and largest over its points (mm; 0 where closed): a
     * running clearance after pressing.
     */
    double       gap_min, gap_max;
    double       alone_p_mid, alone_p_mean; ///< MPa, the joint alone
    unsigned int alone_steps;          ///< staggered steps of the joint alone
    double       lame_p, lame_alone_p; ///< plane-stress estimates (MPa)
    double       friction_coefficient; ///< 0: not given
    double       torque_capacity;      ///< N m (friction given)
    double       axial_force_capacity; ///< N, nu p_mean pi D l
    double       slip_safety;          ///< over Design/Required torque; 0: none
    bool         slip_judged = false;  ///< a required torque judges its slip
    /**
     * @name Joining (DIN 7190): the outer part of the joint heated, or the
     * inner one cooled (the parts of Assembly/Order), until the largest
     * interference plus the joining clearance is gone, with the
     * coefficient of the joint's own body.
     */
    /** @{ */
    double joining_interference = 0.; ///< mm, the largest U
    /**
     * mm, what the parts joined before add to it (diametral, the largest
     * over the points): the inner part's outside grown, the outer part's
     * bore closed (Assembly/Order).
     */
    double joining_growth    = 0.;
    double joining_clearance = 0.; ///< mm
    double heat_outer_to     = 0.; ///< C; NaN: no thermal expansion known
    double cool_inner_to     = 0.; ///< C; NaN: no expansion coefficient known
    /** The inner body's heating coefficient was used (no Cooling expansion). */
    bool cooling_from_heating = false;
    /** The outer part's lowest Temperature limit (C; infinite: none). */
    double heat_limit = std::numeric_limits<double>::infinity();
    /** The body of the outer part with that limit. */
    std::string heat_limit_body;
    /** The outer part's temperature would exceed heat_limit. */
    bool heat_above_limit = false;
    /**
     * C: where neither heating to heat_limit nor cooling to -196 C opens
     * the joint alone, the temperature the inner part is cooled to while
     * the outer part is heated to heat_limit (NaN: not needed, or not
     * known).
     */
    double both_cool_inner_to = std::numeric_limits<double>::quiet_NaN();
    /** The cooling temperature is not below -196 C (liquid nitrogen). */
    bool cool_reachable = true;
    /** @} */
    /**
     * @name Pressing (Assembly/Order): the joint made by pressing its inner
     * part (the bodies already joined to its inner body) into its outer
     * part, at the assembly temperature.
     */
    /** @{ */
    unsigned int             press_order = 0; ///< 1: made first
    std::vector<std::string> press_inner_part, press_outer_part;
    double                   press_in_friction_coefficient = 0.; ///< nu_e
    double                   press_p_mean   = 0.; ///< MPa, in the part-assembly
    double                   press_in_force = 0.; ///< N, nu_e p_mean pi D l
    /** N, from the plane-stress compound cylinders of the part-assembly. */
    double press_in_force_estimate = 0.;
    /**
     * N, with every joint of the part-assembly at its largest interference
     * (an ISO fit's U_max less the smoothing loss): what the press must
     * give.
     */
    double press_in_force_largest = 0.;
    /** @} */
    /**
     * With a speed of operation: the speed (1/min) from which the joint
     * is open over its whole length, the other loads as in operation (0:
     * open at rest); infinite if it holds up to loosening_limit(), NaN if
     * not computed (no speed, bilateral joints).
     */
    double loosening_speed = std::numeric_limits<double>::quiet_NaN();
  };


  /**
   * The strength figures of one body of a stack after joining: the largest
   * von Mises stress on its surfaces at the mid-plane (the plane state
   * DIN 7190's check refers to) and over its surfaces, and the safety
   * against yield R_e / sigma_vM at the mid-plane.
   */
  struct BodyFigures
  {
    std::string name;
    double      von_mises_mid_plane; ///< MPa
    double      von_mises_max;       ///< MPa, over the body's surfaces
    /**
     * A section: where on its surfaces von_mises_max is (the drawing's z
     * and D, mm); NaN for a ring.
     */
    double von_mises_max_z = std::numeric_limits<double>::quiet_NaN();
    double von_mises_max_d = std::numeric_limits<double>::quiet_NaN();
    double yield_strength;   ///< MPa; 0: unknown
    double yield_safety;     ///< 0: unknown yield strength
    bool   brittle;          ///< Material/<body>/Kind brittle
    double tensile_strength; ///< R_m, MPa; 0: unknown
    /** The largest hoop stress on its surfaces at the mid-plane (MPa). */
    double hoop_mid_plane;
    /**
     * R_m over the hoop tension (a brittle body with R_m; infinite
     * without tension); 0: not judged.
     */
    double fracture_safety;
  };

  /**
   * The radial displacement of a reported surface (Assembly/Report
   * surfaces) after joining, over its nodes along the axis.
   */
  struct SurfaceFigures
  {
    std::string name;                 ///< `<body> bore` or `<body> outer`
    double      radius;               ///< mm, of the drawing
    double      u_mean, u_min, u_max; ///< mm (mean weighted by length)
  };

  /**
   * An assembly of several coaxial plain rings (Assembly/Bodies): one
   * Triangulation<2> and axisymmetric elasticity operator per body, each
   * joint's points shared by the meshes of its two bodies, every body
   * condensed onto its joint points (a body in the middle onto both of
   * its surfaces: its 2 x 2 block compliance couples its joints). The
   * joints' contact is solved all at once, by the staggered process
   * (StackCoupling) or monolithically (solve_stack_contact()); then every
   * body's field, each joint alone, the plane-stress estimates and the
   * results (summary.json, contact_pressure_<joint>.csv, a VTU per body
   * and solution.pvd, convergence.csv, parameters.prm), written
   * atomically.
   */
  class StackFit
  {
  public:
    explicit StackFit(const StackParameters &parameters);

    /** Mesh, assemble and factorize every body; condense each. */
    void
    setup_system();

    /**
     * Solve the contact of all joints (Solver/Method); progress lines to
     * @p progress if not null. Returns whether it converged.
     */
    bool
    solve(std::ostream *progress);

    /** Each body's field and the figures of every joint and surface. */
    void
    postprocess();

    /**
     * Write the results into @p directory (a staging directory). Returns
     * what became of the plots: drawn (the files), skipped (why), or empty
     * (Output/Write plots = false).
     */
    std::string
    output_results(const std::string &directory) const;

    /**
     * The whole run for the command line: set up, solve, print the joint
     * table to @p out, write the results atomically (or, with @p into,
     * into that existing directory: a case of a study staged as a whole).
     * Returns the exit code (0, or 2 if the process did not converge; a
     * diverged process writes nothing).
     */
    int
    run(std::ostream &out, bool progress, const std::string &into = "");

    const std::vector<JointFigures> &
    joint_figures() const
    {
      return joints_out;
    }

    const std::vector<BodyFigures> &
    body_figures() const
    {
      return bodies_out;
    }

    /**
     * The verdict of the assembly after postprocess(): each joint with an
     * interference touches, each joint's safety against slip reaches
     * Design/Slip safety (with a required torque), each body's safety
     * against yield (brittle: fracture) reaches Design/Yield safety
     * (Design/Fracture safety).
     */
    const Verdict &
    get_verdict() const
    {
      return verdict;
    }

    /** Whether the stack carries loads of operation (Operation). */
    bool
    has_loads() const
    {
      return parameters.operation.has_loads();
    }

    /**
     * The joints in the state of assembly (no loads of operation), with
     * loads; empty without (joint_figures() is then that state). Only the
     * pressures, contact, gap, torque capacity and slip safety are set.
     */
    const std::vector<JointFigures> &
    assembly_joint_figures() const
    {
      return joints_assembly;
    }

    /** The bodies' strength in the state of assembly, with loads. */
    const std::vector<BodyFigures> &
    assembly_body_figures() const
    {
      return bodies_assembly;
    }

    /** The state of assembly (no loads), with loads; empty without. */
    const StackState &
    assembly_state() const
    {
      return assembly_solution;
    }

    const std::vector<SurfaceFigures> &
    surface_figures() const
    {
      return surfaces_out;
    }

    const StackState &
    state() const
    {
      return solution;
    }

    const std::vector<StackJoint> &
    joints() const
    {
      return stack_joints;
    }

    /** The condensed compliance of body @p b on its joint points. */
    const FullMatrix<double> &
    compliance(unsigned int b) const
    {
      return condensed[b]->get_compliance();
    }

    unsigned int
    n_steps() const
    {
      return steps;
    }

    /**
     * The stack at the measured diametral interferences @p U (mm, one per
     * joint; each less its smoothing loss), solved monolithically on the
     * condensed compliances (after setup_system()): the state of assembly
     * and, with loads of operation, the state in service, each with what
     * a fit selection judges (StackFitSelection).
     */
    std::vector<StackStateFigures>
    evaluate(const std::vector<double> &U);

    /**
     * Design/Mode = select: choose the fits (StackFitSelection, printed
     * to @p out) and, if found, put them into the parameters and joints.
     */
    void
    select_fits(std::ostream &out);

    /** The parameters run (with a selection's chosen fits). */
    const StackParameters &
    get_parameters() const
    {
      return parameters;
    }

    /** The selection of Design/Mode = select (null: check mode). */
    const StackFitSelection *
    get_selection() const
    {
      return selection.get();
    }

  private:
    /** The criteria of the verdict the figures fail (get_verdict()). */
    std::vector<std::string>
    failed_criteria() const;

    /**
     * interface_<joint>.vtp: the contact surface of joint @p k as a
     * polyline at the joint's radius (the outer side's displacement, the
     * inner side's as `<inner>_displacement_mm`, pressure, gap, status),
     * into @p directory.
     */
    void
    write_interface(const std::string &directory, unsigned int k) const;

    /**
     * plots.gp, contact_pressure.png (each joint in the assembly and
     * alone, and the plane-stress estimates) and convergence.png, drawn
     * by gnuplot in @p directory; what was written, or why the plots
     * were skipped.
     */
    std::string
    write_plots(const std::string &directory) const;

    /**
     * report.md: inputs, verdict, joints, bodies, surfaces, and the files
     * written (@p plots_note: what became of the plots).
     */
    void
    write_report(const std::string &directory,
                 const std::string &plots_note) const;

    /**
     * Each body's field for the joint forces of @p state, with its own
     * answer to its loads of operation added if @p loaded.
     */
    std::vector<Vector<double>>
    body_fields(const StackState &state, bool loaded) const;

    /**
     * The pressures, contact, gap, torque capacity and slip safety of
     * joint @p k in @p state with the bodies' fields @p state_fields.
     */
    JointFigures
    joint_state(unsigned int                       k,
                const StackState                  &state,
                const std::vector<Vector<double>> &state_fields) const;

    /**
     * The stresses of body @p b on its surfaces at the mid-plane, of its
     * stresses along its check radii @p along (stresses_along_radii()) (the points of the verdict's yield and fracture
     * figures): a ring's bore and outside, a section's joints and its
     * smallest and largest radius, at z = 0 of a half model or, whole, on
     * the plane through the middle of its bore joint (the innermost
     * body's: its joint).
     */
    std::vector<StressState>
    mid_plane_stresses(
      unsigned int                                 b,
      const std::vector<std::vector<StressState>> &along) const;

    /**
     * The stresses of body @p b with the field @p field along each of its
     * check_radii() (stresses_along_radius()), which mid_plane_stresses()
     * takes.
     */
    std::vector<std::vector<StressState>>
    stresses_along_radii(unsigned int b, const Vector<double> &field) const;

    /**
     * The diametral gap (mm) at each point of joint @p k that the bodies'
     * fields @p state_fields leave with the radial @p interference: 2
     * (u_outer - u_inner - interference); about 0 where in contact.
     */
    /**
     * The reliefs of joint @p k with the least radial gap the bodies'
     * fields @p state_fields leave across each (JointFigures::reliefs).
     */
    std::vector<JointFigures::ReliefGap>
    relief_gaps(unsigned int                       k,
                const std::vector<Vector<double>> &state_fields) const;

    /**
     * Each relief of joint @p k (StackSections::joint_reliefs()): its
     * radial gap (mm) at each plane where it is judged, (drawing z, gap),
     * that the fields @p state_fields leave with the radial
     * @p interference (mm).
     */
    std::vector<std::vector<std::pair<double, double>>>
    relief_plane_gaps(unsigned int                       k,
                      double                             interference,
                      const std::vector<Vector<double>> &state_fields) const;

    /**
     * Refuse (InputError naming Fit/<joint>) a relief that the bodies
     * close in the state of assembly or in operation: its least gap no
     * more than 0 (its bottom would touch, which is not modelled).
     */
    void
    check_reliefs() const;

    std::vector<double>
    joint_gaps(unsigned int                       k,
               double                             interference,
               const std::vector<Vector<double>> &state_fields) const;

    /**
     * The radii of body @p b's surfaces that its strength figures take
     * (solid bodies' axis left out).
     */
    std::vector<double>
    check_radii(unsigned int b) const;

    /**
     * Write the results of a selection that found no fits into
     * @p directory: summary.json (the selection, the verdict naming the
     * conflict), fit_selection.csv, report.md, parameters.prm.
     */
    void
    output_selection_only(const std::string &directory) const;

    /**
     * The strength figures of body @p b with the field @p field (its
     * stresses with the thermal strain of the body's current load).
     */
    BodyFigures
    body_strength(unsigned int b, const Vector<double> &field) const;

    /**
     * The plane-stress compound cylinders of bodies @p first to @p last
     * with their loads of operation (if the stack has them and
     * @p loaded), its joints unilateral if Contact/Unilateral or
     * @p unilateral says so: the
     * interferences less the free rings' growth apart, the pressures on
     * the free surfaces of the whole stack.
     */
    CompoundCylinders
    plane_stress(unsigned int first,
                 unsigned int last,
                 bool         loaded     = true,
                 bool         unilateral = false) const;

    /**
     * The contact of all joints at the speed whose omega^2 is
     * @p omega_squared ((rad/s)^2), the other loads as in operation
     * (monolithically on the bodies' condensed compliances @p C).
     */
    StackState
    state_at_speed(const std::vector<FullMatrix<double>> &C,
                   double                                 omega_squared) const;

    /**
     * Each joint's loosening speed (JointFigures::loosening_speed): the
     * speeds scanned upwards in steps of 10 % from 100 1/min to
     * loosening_limit(), the first at which a joint is open over its
     * whole length bisected to 1e-6.
     */
    void
    loosening_speeds();

    /**
     * The highest speed the loosening speeds are sought up to (1/min): 1e6,
     * or ten times the operating speed if that is more.
     */
    double
    loosening_limit() const
    {
      return std::max(1e6, 10. * parameters.operation.speed);
    }

    /** The joining figures of joint @p k into @p f (DIN 7190). */
    void
    joining(unsigned int k, JointFigures &f) const;

    /**
     * Each joint's radial effective interference (mm): the largest (an ISO
     * fit's U_max less the smoothing loss) if @p largest, else the one in
     * use.
     */
    std::vector<double>
    radial_interferences(bool largest) const;
    /**
     * Each joint's radial effective interference (mm) at the measured
     * diametral interferences @p U (mm): (U - smoothing loss) / 2.
     */
    std::vector<double>
    radial_interferences(const std::vector<double> &U) const;
    /**
     * The contact of the part-assembly of bodies @p first to @p last at
     * the assembly temperature (the others removed, the same meshes),
     * monolithically on the bodies' compliances on its joints' points,
     * unilateral (parts being pressed together cannot bond);
     * its joints at the radial interferences @p radial (mm, one per joint
     * of the stack); heated as a whole by @p heating kelvin (negative:
     * cooled, with the cooling coefficients if @p cooling).
     */
    StackState
    part_assembly(unsigned int               first,
                  unsigned int               last,
                  const std::vector<double> &radial,
                  double                     heating = 0.,
                  bool                       cooling = false) const;
    /**
     * What the parts joined before joint @p k (Assembly/Order) add to its
     * diametral interference at each of its points (mm), their joints at
     * the radial interferences @p radial: the inner part's outside grown,
     * the outer part's bore closed.
     */
    Vector<double>
    joining_growth(unsigned int k, const std::vector<double> &radial) const;
    /**
     * The radial displacement (mm) at the points of joint @p k of a part
     * of at least two bodies from @p first in @p state (part_assembly()):
     * the outer part's bore (first = k + 1) or the inner part's outside
     * (it ends at body k), u = C F of the part's joint next to it.
     */
    Vector<double>
    part_surface(unsigned int      k,
                 unsigned int      first,
                 const StackState &state) const;
    /**
     * How far joint @p k's parts as they are when it is made
     * (Assembly/Order) open it at most (mm, diametral): the outer part
     * heated to the lowest Temperature limit of its bodies and the inner
     * part cooled to -196 C (part_opening() of each, both at once), the
     * joints at the radial interferences @p radial (mm, one per joint);
     * infinite where the outer part has no limit (heating opens any
     * joint) or neither part's coefficients are known.
     */
    double
    joining_reach(unsigned int k, const std::vector<double> &radial) const;
    /**
     * The lowest Temperature limit (C; infinite: none) of the bodies of the
     * part that is heated to make joint @p k (Assembly/Order), and whose it
     * is.
     */
    std::pair<double, std::string>
    heating_limit(unsigned int k) const;
    /**
     * How far (mm, diametral, the least over its points) the part of
     * bodies @p first to @p last opens joint @p k when heated (the outer
     * part, its bore growing) or @p cooling (the inner part, its outside
     * shrinking) as a whole by @p dT kelvin: the joint's body's free
     * growth alpha D dT, and for a part of several bodies what its joints'
     * changed forces add (solved on the condensed compliances, unilateral:
     * a joint of the part may open), its joints at the radial
     * interferences @p radial (mm, one per joint of the stack). NaN if a
     * body of the part has no coefficient.
     */
    double
    part_opening(unsigned int               k,
                 unsigned int               first,
                 unsigned int               last,
                 bool                       cooling,
                 double                     dT,
                 const std::vector<double> &radial) const;
    /** Body @p b's coefficient of expansion for heating or @p cooling. */
    double
    expansion(unsigned int b, bool cooling) const;
    /**
     * The coefficient (1/K) by which the part of bodies @p first to @p last
     * opens joint @p k when heated (the outer part, its bore growing) or
     * @p cooling (the inner part, its outside shrinking) by the
     * temperature change that opens it by @p opening (mm, diametral):
     * the joint's body's own alpha for a part of one body (DIN 7190),
     * otherwise the part's (part_opening() over D dT, a few fixed-point
     * steps where a joint of the part opens). NaN if a body of the part
     * has no coefficient.
     */
    double
    part_expansion(unsigned int k,
                   unsigned int first,
                   unsigned int last,
                   bool         cooling,
                   double       opening) const;
    /**
     * The press-in figures of joint @p k into @p f: its pressure in the
     * part-assembly present when it is pressed (Assembly/Order).
     */
    void
    pressing(unsigned int k, JointFigures &f) const;
    /** The two bodies of joint @p k alone: their contact, and steps. */
    StackState
    joint_alone(unsigned int k, unsigned int &staggered_steps) const;

    /**
     * The cautions of the run: the parameters' (warnings()) and each
     * section body whose largest von Mises stress on its surfaces exceeds
     * its yield strength (local yield at a fillet or corner).
     */
    std::vector<std::string>
    cautions() const;
    /**
     * How the sections are meshed (Mesh/Cell size, 0: the shortest
     * joint's l_F / 100; Grading ratio; Global refinements).
     */
    SectionMeshSettings
    section_settings() const;
    /**
     * The radius of body @p b's bore (@p bore) or outside (mm): a ring's
     * diameters, a section's smallest and largest radius.
     */
    double
    surface_radius(unsigned int b, bool bore) const;

    /** The radius and nodal u_r along the surface @p name. */
    SurfaceFigures
    surface(const std::string &name) const;

    /** A copy: Design/Mode = select puts the chosen fits in. */
    StackParameters parameters;
    /** The selection of Design/Mode = select (null: check). */
    std::shared_ptr<const StackFitSelection>         selection;
    std::vector<std::unique_ptr<BodyDiscretization>> bodies;
    std::vector<std::unique_ptr<BodySolver>>         solvers;
    std::vector<std::unique_ptr<CondensedBody>>      condensed;
    std::vector<StackJoint>                          stack_joints;
    std::vector<double>                              alpha;
    StackState                                       solution;
    std::vector<Vector<double>>                      fields;
    /** Each body's answer to its loads of operation (empty: none). */
    std::vector<Vector<double>> load_fields;
    /**
     * With a speed: each joint's load shift per (rad/s)^2 of rotation
     * (StackJoint::load_shift is the rest plus omega^2 times this).
     */
    std::vector<Vector<double>> rotation_shift;
    /** With loads: the state of assembly and its figures. */
    StackState                  assembly_solution;
    std::vector<JointFigures>   joints_assembly;
    std::vector<BodyFigures>    bodies_assembly;
    std::vector<StackState>     alone;
    std::vector<JointFigures>   joints_out;
    std::vector<SurfaceFigures> surfaces_out;
    std::vector<BodyFigures>    bodies_out;
    Verdict                     verdict = Verdict(std::vector<std::string>());
    std::vector<std::pair<double, double>> history;
    bool                                   converged        = false;
    unsigned int                           steps            = 0;
    unsigned int                           body_solves      = 0;
    unsigned int                           active_set_steps = 0;
    std::map<std::string, double>          timing;
  };
} // namespace coaxfit

#endif
