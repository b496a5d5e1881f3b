#ifndef coaxfit_parameters_h
#define coaxfit_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <coaxfit/parameters/material_library.h>
#include <coaxfit/parameters/scene_parameters.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  class SectionScene;

  using namespace dealii;

  /**
   * Isotropic linear elastic material: Young's modulus in MPa and Poisson's
   * ratio, with the Lame constants derived from them, and the strength and
   * physical data of the design figures. Subsection `Material/Shaft` or
   * `Material/Hub`; a `Name` from the material library fills what the file
   * does not give (read_parameters()).
   */
  struct Material
  {
    double      E                 = 2.0e5;
    double      nu                = 0.33;
    std::string name              = "custom";
    double      yield_strength    = 0.; ///< MPa; 0: unknown
    double      density           = 0.; ///< kg/m^3; 0: unknown
    double      thermal_expansion = 0.; ///< 1/K
    double      tensile_strength  = 0.; ///< R_m, MPa; 0: unknown
    /** 1/K, for undercooling (DIN 7190), positive; 0: not given. */
    double cooling_expansion = 0.;
    /** Degrees C above which heating changes the material; 0: unknown. */
    double      temperature_limit = 0.;
    std::string temperature_limit_reason; ///< from the library, or empty
    std::string kind_text = "auto";       ///< the entry Kind as given
    /** The kind in use: Kind, or for auto the library's (metal if none). */
    MaterialKind kind = MaterialKind::metal;
    /** The library's group of the Name, for the friction coefficient. */
    MaterialFamily family = MaterialFamily::unknown;
    /** Whether E was given in the file (not filled in from the Name). */
    bool E_given = true;
    /** The entry Plasticity as given: none or von Mises. */
    std::string plasticity_text = "none";
    /**
     * Whether the body may yield (Plasticity = von Mises): then its
     * stresses are bounded by the von Mises yield surface of
     * Yield strength, hardening linearly with Hardening modulus.
     */
    bool plastic = false;
    /** Linear isotropic hardening modulus H (MPa); 0: perfectly plastic. */
    double hardening_modulus = 0.;

    /**
     * Declare `Name`, `E`, `nu`, `Yield strength`, `Tensile strength`,
     * `Density`, `Thermal expansion`, `Cooling expansion`, `Temperature
     * limit` and `Kind`, bound to the members, for the body named
     * @p body_label in the documentation. E and nu define the scene: they
     * must be given, directly or by a Name.
     */
    void
    declare_parameters(ParameterHandler &prm, const std::string &body_label);

    /** Strict bounds that a pattern cannot state; @p path names the
     * subsection in messages. */
    void
    validate(const std::string &path) const;

    /**
     * The expansion coefficient (1/K) for cooling the part for joining:
     * Cooling expansion, or the heating coefficient if it is not given.
     */
    double
    joining_cooling_expansion() const
    {
      return cooling_expansion > 0. ? cooling_expansion : thermal_expansion;
    }

    /** First Lame constant lambda (MPa). */
    double
    lambda() const
    {
      return E * nu / ((1. + nu) * (1. - 2. * nu));
    }

    /** Shear modulus mu (MPa). */
    double
    mu() const
    {
      return E / (2. * (1. + nu));
    }

    /**
     * The same mu without lambda (nu = 0): the deviatoric-like part of a
     * selective reduced integration, whose lambda part is added separately.
     */
    Material
    without_lambda() const
    {
      Material m = *this;
      m.E        = 2. * mu();
      m.nu       = 0.;
      return m;
    }
  };

  /**
   * The half section the finite element model uses (mm), derived from the
   * drawing (`Geometry`) and the fit (`Fit`) by Parameters::derive_model(),
   * in the paper's terms: radii, *half* lengths measured from the common
   * mid-plane z = 0 (only z >= 0 is modelled) and the radial effective
   * interference d = U_w / 2. Not a parameter of the file.
   */
  struct GeometryParameters
  {
    double R0 = 0.;   ///< inner radius of the shaft (0: solid shaft)
    double R1 = 100.; ///< nominal contact radius
    double R2 = 200.; ///< outer radius of the hub
    double L1 = 200.; ///< half length of the shaft
    double L2 = 100.; ///< half length of the hub
    double d  = 0.25; ///< radial interference

    /** Relations between the radii and lengths (an internal check). */
    void
    validate() const;

    /**
     * Whether the whole joint is modelled (sections without a plane of
     * symmetry): the joint runs from z_joint_start to z_joint_end in the
     * drawing's coordinates; otherwise the half z >= 0 from the
     * mid-plane z = 0 to contact_length().
     */
    bool   whole         = false;
    double z_joint_start = 0.; ///< whole model: drawing z of one joint end
    double z_joint_end   = 0.; ///< whole model: drawing z of the other

    /** Contact length min(L1, L2) in mm: half the joint length. */
    double
    contact_length() const
    {
      return std::min(L1, L2);
    }

    /** Model z (mm) where the modelled joint starts: 0 for the half. */
    double
    joint_start() const
    {
      return whole ? z_joint_start : 0.;
    }

    /** Model z (mm) where the modelled joint ends. */
    double
    joint_end() const
    {
      return whole ? z_joint_end : contact_length();
    }

    /** Model z (mm) of the middle of the joint: 0 for the half. */
    double
    joint_middle() const
    {
      return whole ? 0.5 * (z_joint_start + z_joint_end) : 0.;
    }

    /** Length of the joint the model holds (mm): half or whole. */
    double
    modelled_joint_length() const
    {
      return joint_end() - joint_start();
    }

    /** The factor from the model's joint to the whole: 2 for the half. */
    double
    mirror_factor() const
    {
      return whole ? 1. : 2.;
    }
  };

  /** Integration of the volumetric (lambda) part of the stiffness. */
  enum class VolumetricIntegration
  {
    full,
    reduced
  };

  /** Subsection `Mesh`: the graded meshes of both bodies. */
  struct MeshParameters
  {
    unsigned int          axial_cells            = 12;
    unsigned int          radial_cells           = 10;
    double                grading_ratio          = 1.4;
    unsigned int          global_refinements     = 0;
    unsigned int          degree                 = 2;
    VolumetricIntegration volumetric_integration = VolumetricIntegration::full;
    /** mm at the ends of a section's joint; 0: l_F / 100 (sections only). */
    double cell_size = 0.;
    /** mm, the hub's cell size; 0: cell_size (sections only). */
    double hub_cell_size = 0.;
    /**
     * Sections only: whether both bodies get the same vertices on the
     * joint (`shared`), or each is meshed on its own (`own`: the joint
     * nodes need not match, and the displacements and forces cross the
     * joint by a mortar projection).
     */
    bool shared_joint_nodes = true;

    /** The grading must leave cells of representable size. */
    void
    validate() const;

    void
    declare_parameters(ParameterHandler &prm);

    /** Selective reduced integration of the volumetric part. */
    bool
    reduced_volumetric_integration() const
    {
      return volumetric_integration == VolumetricIntegration::reduced;
    }
  };

  /** Subsection `Solver`. */
  enum class SolverMethod
  {
    staggered,
    monolithic
  };

  /** How each body's linear systems are solved (`Solver/Linear solver`). */
  enum class LinearSolverType
  {
    automatic, ///< direct while its estimated memory fits, amg beyond
    direct,    ///< CHOLMOD supernodal Cholesky
    amg        ///< CG with Trilinos' algebraic multigrid (ML)
  };

  /**
   * `Load path`: how the interference is applied to bodies that may yield
   * (Material/<body>/Plasticity = von Mises): in increments, each solved
   * by Newton's method per body within the coupling.
   */
  struct LoadPathParameters
  {
    /** Equal increments from the first yield to the full interference. */
    unsigned int increments = 8;
    /** Halvings of a failed increment before the run gives up. */
    unsigned int max_bisections = 10;
    /** Relative residual of a body's Newton solve. */
    double newton_tolerance = 1e-10;
    /** Newton iterations of one body solve before the increment is cut. */
    unsigned int max_newton_iterations = 25;
    /**
     * `Stages`: "auto" or a list from joining, operation, unloading,
     * disassembly (stages()).
     */
    std::string stages_text = "auto";

    /** The stages of the load path after joining, in order. */
    enum class Stage
    {
      joining,
      operation,  ///< the loads of operation applied
      unloading,  ///< the loads of operation removed again
      disassembly ///< the interference removed: the parts apart
    };

    /**
     * The stages in order, joining first: "auto" is joining, then
     * operation if @p has_loads. InputError names Load path/Stages for an
     * unknown or repeated name, a wrong order, operation without loads,
     * unloading without operation, disassembly with @p unilateral false.
     */
    std::vector<Stage>
    stages(bool has_loads, bool unilateral) const;

    void
    declare_parameters(ParameterHandler &prm);
  };

  /** The name of a stage of the load path as a parameter file writes it. */
  std::string
  to_string(LoadPathParameters::Stage stage);

  struct SolverParameters
  {
    SolverMethod     method        = SolverMethod::staggered;
    LinearSolverType linear_solver = LinearSolverType::automatic;

    void
    declare_parameters(ParameterHandler &prm);
  };

  /**
   * The controller presets of `Coupling/Alpha controller`: each is an alpha
   * rule with an accelerator (see CouplingParameters::alpha_rule() and
   * CouplingParameters::accelerator()).
   */
  enum class AlphaControllerPreset
  {
    fixed,
    winkler,
    pointwise,
    aitken,
    iqn_ils,
    ibqn,     ///< interface block quasi-Newton (no alpha)
    automatic ///< ibqn where a coarse model exists, iqn-ils elsewhere
  };

  /** How alpha is chosen (`Coupling/Alpha rule`). */
  enum class AlphaRuleType
  {
    automatic, ///< as the Alpha controller preset says
    fixed,
    winkler,
    pointwise
  };

  /** Acceleration of the traction fixed point (`Coupling/Accelerator`). */
  enum class AcceleratorType
  {
    automatic, ///< as the Alpha controller preset says
    none,
    aitken,
    iqn_ils,
    ibqn ///< interface block quasi-Newton with the contact inside
  };

  /** Which operator of a body the coupling iterates with. */
  enum class InterfaceOperatorType
  {
    automatic,
    full,
    condensed
  };

  /**
   * What the accelerator keeps of its history when the set of contact
   * points changes (the fixed-point map changes at those points).
   */
  enum class HistoryOnChange
  {
    restart, ///< forget everything
    keep,    ///< keep every column as it is
    filter,  ///< keep the columns, with the changed points' rows removed
    model    ///< keep the model built so far as the prior of the new one
  };

  /** Subsection `Coupling`: the staggered process. */
  struct CouplingParameters
  {
    double                alpha              = 0.8;
    AlphaControllerPreset controller         = AlphaControllerPreset::automatic;
    AlphaRuleType         rule               = AlphaRuleType::automatic;
    AcceleratorType       acceleration       = AcceleratorType::automatic;
    double                tolerance          = 1e-8;
    unsigned int          max_steps          = 200;
    double                beta               = 0.; ///< (4.22); 0: automatic
    double                aitken_omega       = 1.0;
    unsigned int          iqn_columns        = 50;
    double                iqn_filter         = 1e-10;
    InterfaceOperatorType interface_operator = InterfaceOperatorType::automatic;
    HistoryOnChange       history_on_change  = HistoryOnChange::restart;
    /** Coupling/Coarse model: true for auto, false for none. */
    bool coarse_model = true;

    void
    declare_parameters(ParameterHandler &prm);

    /**
     * The entries of the iteration itself (interface operator, Beta,
     * accelerator settings, tolerance, step limit), in the current
     * subsection.
     */
    void
    declare_iteration_parameters(ParameterHandler &prm);

    /** Strict bounds that a pattern cannot state. */
    void
    validate() const;

    /** The alpha rule in use: Alpha rule, or the preset's if automatic. */
    AlphaRuleType
    alpha_rule() const;

    /**
     * The accelerator in use: Accelerator, or the preset's if automatic.
     * @p coarse_model tells whether the coarse model of Coupling/Coarse
     * model is available: the auto preset takes ibqn with it and iqn-ils
     * without (ibqn's prior of the bodies' compliances comes from it).
     */
    AcceleratorType
    accelerator(bool coarse_model = true) const;
  };

  /** When the contact / separated flags change. */
  enum class ActiveSetUpdateType
  {
    automatic,
    every_step,
    when_converged
  };

  /** Subsection `Contact`: the unilateral pass. */
  struct ContactParameters
  {
    bool                unilateral        = true;
    ActiveSetUpdateType active_set_update = ActiveSetUpdateType::automatic;
    /** 0: auto (1e-2 from a coarse start, 0.1 otherwise). */
    double active_set_tolerance = 0.;

    void
    declare_parameters(ParameterHandler &prm);

    void
    validate() const;
  };

  /** Subsection `Output`. */
  /** What each value of a `--sweep` writes (`Output/Sweep files`). */
  enum class SweepFiles
  {
    figures, ///< summary.json, the CSV files and parameters
    complete ///< also VTU, plots and report, as Write vtu/plots/report say
  };

  struct OutputParameters
  {
    /** As given; Parameters::output_directory() resolves an empty one. */
    std::string directory;
    bool        write_vtu    = true;
    bool        write_plots  = true;
    bool        write_report = true;
    bool        print_timing = true;
    SweepFiles  sweep_files  = SweepFiles::figures;

    void
    declare_parameters(ParameterHandler &prm);
  };

  /**
   * Every knob of a coaxfit run, one small struct per subsection of the
   * `.prm` file. Each entry is declared once, with its documentation, unit
   * and allowed range, by ParameterHandler::add_parameter() bound to its
   * member; reading a file or a `--set Section/Name=value` override sets
   * the member. Bounds live in the patterns; validate() checks only strict
   * bounds and relations between entries.
   *
   * The entries that define the scene (geometry, interference, materials)
   * have no silent default: a file must give them (or `--set`), see
   * read_parameters(). The member defaults below are the paper's variant 5
   * for programs that build a Parameters object directly (the tests).
   */
  struct Parameters
  {
    DrawingGeometry    drawing;    ///< `Geometry`: diameters, full lengths
    FitParameters      fit;        ///< `Fit`
    FitLimits          fit_limits; ///< the interference in use (derived)
    GeometryParameters geometry;   ///< the model's half section (derived)
    /**
     * The sections of `Geometry/Shaft section` and `Hub section`, checked
     * and placed (derived); null for plain cylinders.
     */
    std::shared_ptr<const SectionScene> sections;
    Material            shaft; ///< material of D1 (shaft or tube)
    Material            hub;   ///< material of D2 (hub)
    DesignParameters    design;
    OperationParameters operation; ///< `Operation`: loads in service
    MeshParameters      mesh;
    SolverParameters    solver;
    LoadPathParameters  load_path; ///< `Load path`: plastic bodies
    CouplingParameters  coupling;
    ContactParameters   contact;
    OutputParameters    output;

    /** Name of the case: the parameter file's base name. */
    std::string case_name = "default";

    /**
     * The parameters exactly as read (file and `--set` overrides), as a
     * `.prm` file and as JSON: written to the output directory so that the
     * run can be repeated. Empty for objects not made by read_parameters().
     */
    std::string used_prm, used_json;

    /** Notes of read_parameters() about the input (an ignored entry). */
    std::vector<std::string> read_notes;

    /**
     * Every file read for these parameters (canonical paths: the parameter
     * file and the files it includes); no output may overwrite one.
     */
    std::vector<std::string> files_read;

    /** Declare every entry in @p prm, bound to the members of this object. */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Check what the patterns cannot: strict bounds and relations between
     * entries. Throws InputError with a one-line message naming the
     * parameter, its value and the allowed range.
     */
    void
    validate() const;

    /**
     * Set the entry @p path (`Section/Name`) to @p value, as `--set` does:
     * checked against the entry's pattern, InputError if it does not match.
     * Does not validate() the whole.
     */
    void
    set(const std::string &path, const std::string &value);

    /**
     * Set geometry (the model's half section) from drawing and fit_limits:
     * R = D/2, L = length/2, d = U_w/2.
     */
    void
    derive_model();

    /**
     * This object for the fit case @p c (mean, min or max): fit_limits and
     * the model's interference follow, the case name gets the suffix
     * `_min`, `_mean` or `_max` when Fit/Case is all.
     */
    Parameters
    for_fit_case(FitCase c) const;

    /**
     * Warnings about legal input that is probably a mistake (interference
     * above 0.3 % of D_F, Young's moduli differing by more than 1e3), one
     * line each.
     */
    std::vector<std::string>
    input_warnings() const;

    /** The output directory: Output/Directory or output/<case name>. */
    std::string
    output_directory() const;
  };

  /**
   * Read @p filename, apply the command line @p overrides (pairs of a
   * `Section/Subsection/Name` path and a value), check that every entry of
   * the scene was given, and validate. Every problem is reported as an
   * InputError with a one-line message.
   */
  Parameters
  read_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides);

  /**
   * Complete the scene of @p p as read: fill the materials from their Name
   * (E and nu leave @p missing), drop `Fit/Diametral interference` from
   * @p missing when an ISO fit decides, and, if nothing is missing, check
   * the drawing, compute Parameters::fit_limits and derive the model's half
   * section. InputError names the entry at fault.
   */
  void
  complete_scene(Parameters &p, std::set<std::string> &missing);

  /**
   * The limits of the interference of @p fit at the joint diameter
   * @p joint_diameter (mm): from its ISO fit, or its Diametral
   * interference; InputError names the entry at fault.
   */
  FitLimits
  fit_limits_of(const FitParameters &fit, double joint_diameter);

  /**
   * @p text (a parameter file as ParameterHandler prints it) with the value
   * of every `set @p entry = ...` line replaced by @p value, or the line
   * removed if @p value is empty.
   */
  std::string
  replace_prm_line(const std::string &text,
                   const std::string &entry,
                   const std::string &value);

  /** Whether `Section/Name` @p path is an entry of coaxfit's parameters. */
  bool
  is_declared_entry(const std::string &path);

  /** Print every parameter with its default, pattern and documentation. */
  void
  print_parameters(std::ostream &out);

  /** The name of an enumerator as written in a parameter file. */
  std::string
  to_string(SolverMethod value);
  std::string
  to_string(LinearSolverType value);
  std::string
  to_string(AlphaControllerPreset value);
  std::string
  to_string(AlphaRuleType value);
  std::string
  to_string(AcceleratorType value);
  std::string
  to_string(InterfaceOperatorType value);
  std::string
  to_string(ActiveSetUpdateType value);
  std::string
  to_string(VolumetricIntegration value);
} // namespace coaxfit

#endif
