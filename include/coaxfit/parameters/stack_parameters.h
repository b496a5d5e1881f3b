#ifndef coaxfit_stack_parameters_h
#define coaxfit_stack_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <coaxfit/fe/stack_sections.h>
#include <coaxfit/parameters/friction.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/parameters.h>

#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * One plain ring of a stack, `Geometry/<body>`: a cylinder or tube of the
   * drawing (diameters and full length in mm), centred on the common
   * mid-plane.
   */
  struct RingDrawing
  {
    double inner_diameter = 0.; ///< 0: solid (the innermost body only)
    double outer_diameter = 0.;
    double length         = 0.;

    /** Declare the entries of `Geometry/<body>` for the body @p name. */
    void
    declare_parameters(ParameterHandler &prm, const std::string &name);
  };

  /**
   * The fit of one joint of a stack, `Fit/<inner>-<outer>` (or the
   * entries given directly in `Fit`, which every joint without its own
   * takes).
   */
  struct JointFit
  {
    /**
     * mm; negative: a clearance. After read_stack_parameters() the
     * effective interference U_w the joint is solved with: the nominal
     * one less the smoothing loss.
     */
    double diametral_interference = 0.;
    double inner_roughness        = 0.; ///< Rz of the inner body's seat, um
    double outer_roughness        = 0.; ///< Rz of the outer body's bore, um
    double nominal_interference   = 0.; ///< U as given (derived), mm
    /** The largest interference (mm, derived): an ISO fit's, else U. */
    double largest_interference = 0.;
    double smoothing_loss       = 0.; ///< 0.8 (Rz_i + Rz_o), mm
    /**
     * nu_r against slip (derived from friction_text): 0: not given (no
     * torque figures).
     */
    double friction_coefficient = 0.;
    /**
     * `Friction coefficient` as written: a number, `auto` (DIN 7190-1's
     * value of the pairing and Design/Joining) or 0 (a joint's own: Fit's
     * value; Fit's: not given).
     */
    std::string friction_text = "0";
    /** Where friction_coefficient comes from, for the report (derived). */
    std::string friction_source;
    /**
     * DIN 7190's nu_e while the joint is pressed lengthwise, for its
     * press-in force; 0 in a joint's own entries: Fit's.
     */
    double      press_in_friction_coefficient = 0.;
    std::string iso_fit; ///< `H7/s6`; empty: none
    std::string source;  ///< where the interference comes from (derived)

    /** Declare the entries of a `Fit` subsection (@p what: for whom). */
    void
    declare_parameters(ParameterHandler &prm, const std::string &what);
  };

  /**
   * The loads of operation of a stack (`Operation`): a uniform temperature
   * per body (its thermal strain alpha (T - T_assembly)), the speed of
   * rotation of the whole stack (rho omega^2 r in every body), a pressure
   * on the bore of a hollow innermost body and on the outer surface of
   * the outermost. Without loads the run solves the state of assembly
   * only; with loads it solves both states and the verdict judges both.
   */
  struct StackOperation
  {
    double assembly_temperature = 20.; ///< degrees C
    /** `Operation/<body> temperature` as given; empty: assembly's. */
    std::vector<std::string> temperature_text;
    /** Each body's temperature in operation (degrees C, derived). */
    std::vector<double> temperature;
    double              speed          = 0.; ///< 1/min
    double              bore_pressure  = 0.; ///< MPa, innermost body's bore
    double              outer_pressure = 0.; ///< MPa, outermost body's outside
    /** `Operation/Joining clearance`: `auto` (0.001 D) or mm. */
    std::string joining_clearance_text = "auto";

    /** Body @p b's temperature (the assembly's if none is set). */
    double
    temperature_of(const unsigned int b) const
    {
      return b < temperature.size() ? temperature[b] : assembly_temperature;
    }

    /** Whether any load of operation is given. */
    bool
    has_loads() const;

    /**
     * The loads in words, e.g. `Shaft 40 C, Hub 80 C (assembly 20 C),
     * 3000 1/min, Hub outer pressure 5 MPa`, for the bodies @p bodies.
     */
    std::string
    describe(const std::vector<std::string> &bodies) const;

    /** omega^2 in (rad/s)^2. */
    double
    omega_squared() const
    {
      const double omega = speed * 2. * 3.14159265358979323846 / 60.;
      return omega * omega;
    }
  };

  /** How the staggered process of a stack visits its joints. */
  enum class StackOrdering
  {
    gauss_seidel, ///< joint by joint, inside out, each with the newest data
    jacobi        ///< every body at once from the same data
  };

  /** The accelerator of a stack's fixed point over all joints. */
  enum class StackAccelerator
  {
    none,
    aitken,
    iqn_ils
  };

  /**
   * The parameters of an assembly of several coaxial plain rings (a
   * compound cylinder, a sleeve between shaft and hub, a bushing in a
   * housing), named inside out in `Assembly/Bodies`. The file is read in
   * two passes: the body list first (assembly_bodies()), then the
   * subsections the list implies (read_stack_parameters()).
   */
  struct StackParameters
  {
    /** `Assembly/Bodies`, inside out. */
    std::vector<std::string> bodies;
    /**
     * `Geometry/<body>` of each body; for a body drawn as a section the
     * plain ring DIN 7190's estimate puts in its place (derived:
     * StackSections::equivalent_inner_diameter()).
     */
    std::vector<RingDrawing> rings;
    /** `Geometry/<body> section` of each body; empty: a plain ring. */
    std::vector<std::string> section_text;
    /**
     * The sections of a stack in which any body is drawn as a section
     * (derived; its rings as their rectangles); null: all plain rings.
     */
    std::shared_ptr<const StackSections> sections;
    /** `Material/<body>` of each body. */
    std::vector<Material> materials;
    /** The fit given directly in `Fit`. */
    JointFit default_fit;
    /** `Fit/<inner>-<outer>` of each joint as declared. */
    std::vector<JointFit> joint_entries;
    /** The fit each joint uses (its own entries, else default_fit's). */
    std::vector<JointFit> fits;
    /**
     * Design/Required torque (N m): every joint passes it (shaft to hub);
     * 0: none (no safety against slip).
     */
    double required_torque = 0.;
    /**
     * Design/Required axial force (N): every joint passes it as it passes
     * the torque (a helical gear's thrust); 0: none.
     */
    double required_axial_force = 0.;
    /** Design/Application factor K_A of both loads. */
    double application_factor = 1.;
    /**
     * Design/Joining: how the joints are made, for the friction
     * coefficients given as `auto`.
     */
    JoiningMethod joining      = JoiningMethod::shrink;
    std::string   joining_text = "shrink"; ///< as written

    /** Whether slip is judged: a Required torque or axial force. */
    bool
    slip_judged() const
    {
      return required_torque > 0. || required_axial_force > 0.;
    }

    /**
     * Whether joint @p k is a running fit: given a clearance (not chosen
     * by a selection), such as a pressed bushing's shaft. It passes no
     * torque or axial force: its slip is not judged.
     */
    bool
    running_fit(const unsigned int k) const
    {
      return !selected[k] && fits[k].nominal_interference < 0.;
    }

    /** Whether joint @p k's slip is judged (not a running fit). */
    bool
    slip_judged(const unsigned int k) const
    {
      return slip_judged() && !running_fit(k);
    }

    /**
     * The torque (N m) a joint of diameter @p diameter (mm) must carry in
     * place of both loads: DIN 7190's resultant of the circumferential
     * force 2 M / D and the axial force, times K_A, times D / 2. A joint's
     * safety against slip is its torque capacity over this one (its axial
     * force capacity over the resultant force).
     */
    double
    required_torque_at(const double diameter) const
    {
      return application_factor
             * std::hypot(required_torque,
                          required_axial_force * diameter / 2000.);
    }
    /**
     * The required loads in words: "1000 N m", "1000 N m and 5000 N
     * axially", with ", times K_A 1.5" where the factor is not 1.
     */
    std::string
    required_loads_text() const;

    /** Design/Slip safety: each joint's least safety against slip. */
    double slip_safety = 1.;
    /** Design/Yield safety: each ductile body's least safety. */
    double yield_safety = 1.;
    /** Design/Fracture safety: each brittle body's least safety. */
    double fracture_safety = 2.;
    /**
     * Design/Mode: `check` the fits given, or `select` the ISO 286 fits of
     * the joints of Design/Selected joints (StackFitSelection).
     */
    std::string design_mode = "check";
    /**
     * Design/Running clearance (mm, diametral): what every joint given a
     * clearance must keep at each point, in every state; 0: not judged.
     */
    double running_clearance = 0.;
    /** Design/Selected joints as given: `all`, or joint names. */
    std::string selected_text = "all";
    /** Per joint: chosen by the selection (Design/Mode = select). */
    std::vector<bool> selected;

    /**
     * Joint @p k takes the ISO fit @p fit (the selection's choice) at
     * Fit/Case, its roughness's smoothing loss taken off.
     */
    void
    use_iso_fit(unsigned int k, const IsoFit &fit);

    /** Whether the run selects fits (Design/Mode = select). */
    bool
    select_mode() const
    {
      return design_mode == "select";
    }
    /**
     * Fit/Case: which interference of the joints' ISO fits (every joint
     * the same): min, mean or max; all: the study of the bands' corners
     * (StackCaseStudy).
     */
    std::string fit_case = "mean";
    /**
     * `Fit/<inner>-<outer>/Case` of each joint: min, mean or max of its own
     * ISO fit; empty: Fit/Case's (a Fit/Case = all study sets the corners
     * of the bands so).
     */
    std::vector<std::string> joint_cases;

    /** The case of joint @p k's ISO fit: its own, else Fit/Case. */
    const std::string &
    case_of(const unsigned int k) const
    {
      return joint_cases[k].empty() ? fit_case : joint_cases[k];
    }
    /**
     * `Assembly/Order` as given: `inside out`, `outside in` or the joints
     * in the order they are made.
     */
    std::string order_text = "inside out";
    /** The joints in the order they are made (derived from order_text). */
    std::vector<unsigned int> joining_order;
    /** Surfaces whose radial displacement is reported (`<body> bore`). */
    std::vector<std::string> report_surfaces;
    /** The loads of operation (`Operation`). */
    StackOperation operation;

    MeshParameters   mesh;
    SolverMethod     method      = SolverMethod::staggered;
    StackOrdering    ordering    = StackOrdering::gauss_seidel;
    StackAccelerator accelerator = StackAccelerator::iqn_ils;
    double           alpha       = 0.; ///< 0: each joint's Winkler alpha
    double           tolerance   = 1e-8;
    unsigned int     max_steps   = 200;
    bool             unilateral  = true;
    std::string      directory;
    bool             write_vtu    = true;
    bool             write_plots  = true;
    bool             write_report = true;
    bool             print_timing = true;

    std::string case_name = "default";
    std::string used_prm; ///< the parameters as read, for parameters.prm

    /** The number of joints (bodies - 1). */
    unsigned int
    n_joints() const
    {
      return bodies.size() - 1;
    }

    /** Whether body @p b is drawn as a section (`Geometry/<body> section`). */
    bool
    drawn_as_section(const unsigned int b) const
    {
      return b < section_text.size() && !section_text[b].empty();
    }

    /** The name of joint @p k: `<inner>-<outer>`. */
    std::string
    joint_name(unsigned int k) const
    {
      return bodies[k] + "-" + bodies[k + 1];
    }

    /** The joint's diameter: the outer diameter of its inner body (mm). */
    double
    joint_diameter(unsigned int k) const
    {
      return sections ? 2. * sections->joint_radius(k) :
                        rings[k].outer_diameter;
    }

    /**
     * The part-assemblies joint @p k joins when it is made (Assembly/Order):
     * the bodies first to k already joined to its inner body and k + 1 to
     * last to its outer one.
     */
    std::pair<unsigned int, unsigned int>
    joined_parts(unsigned int k) const;
    /**
     * Whether `Section/Name` @p path is an entry of a stack of these
     * bodies (what --sweep may vary).
     */
    bool
    declares(const std::string &path) const;
    /** Declare every entry for the bodies in @p bodies (sized first). */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Check the scene: the rings meet (each inner diameter is the previous
     * outer one) and the ranges; an InputError naming the
     * entry otherwise.
     */
    void
    validate() const;

    /**
     * Cautions of the loads, one line each: a body held in operation above
     * its material's temperature limit (its strength figures do not hold
     * there).
     */
    std::vector<std::string>
    warnings() const;

    /** Output/Directory, or output/<case name>. */
    std::string
    output_directory() const
    {
      return directory.empty() ? "output/" + case_name : directory;
    }
  };

  /**
   * The body list `Assembly/Bodies` of the parameter file @p filename with
   * the overrides @p overrides (the first pass: every other entry skipped);
   * empty if the file gives none (a file of today's Shaft and Hub).
   * Refuses unknown or repeated names and fewer than two bodies.
   */
  /**
   * Names joined by ` + `: the bodies of a part-assembly (`Shaft + Sleeve`),
   * a combination of fits (`H7/s6 + H7/u6`).
   */
  std::string
  part_text(const std::vector<std::string> &part);

  std::vector<std::string>
  assembly_bodies(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides);

  /**
   * Print every entry of a stack of the bodies of @p filename
   * (Assembly/Bodies) with its default, pattern and documentation.
   */
  void
  print_stack_parameters(std::ostream &out, const std::string &filename);

  /** The second pass: every entry of the stack of @p filename. */
  StackParameters
  read_stack_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides);
} // namespace coaxfit

#endif
