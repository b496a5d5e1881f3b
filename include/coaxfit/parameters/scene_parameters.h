#ifndef coaxfit_scene_parameters_h
#define coaxfit_scene_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <coaxfit/parameters/friction.h>

#include <limits>
#include <string>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Subsection `Geometry`: the joint as a drawing gives it, in DIN 7190's
   * terms: diameters and full lengths in mm, the hub centred on the shaft.
   * Parameters::derive_model() turns it into the half section the finite
   * element model uses (GeometryParameters: radii and half lengths).
   */
  struct DrawingGeometry
  {
    double joint_diameter      = 200.; ///< D_F
    double shaft_bore_diameter = 0.;   ///< D_iI (0: solid shaft)
    double hub_outer_diameter  = 400.; ///< D_aA
    double hub_length          = 200.; ///< full length of the hub
    double shaft_length        = 400.; ///< full length of the shaft
    /**
     * `Shaft section`, `Hub section`: outlines `z, D; z, D, R; ...` as
     * given; both empty: the plain cylinders of the entries above.
     */
    std::string shaft_section, hub_section;

    /** Whether the bodies are drawn as sections. */
    bool
    has_sections() const
    {
      return !shaft_section.empty() || !hub_section.empty();
    }

    void
    declare_parameters(ParameterHandler &prm);

    /** Relations between the entries; InputError names the entry. */
    void
    validate() const;
  };

  /** Which interference of a toleranced fit a run uses (`Fit/Case`). */
  enum class FitCase
  {
    mean,
    min,
    max,
    all ///< the three in one run
  };

  /** Subsection `Fit`: the interference, given or from an ISO 286 fit. */
  struct FitParameters
  {
    double      diametral_interference = 0.5; ///< U (mm)
    std::string iso_fit;                      ///< e.g. "H7/s6"; empty: none
    FitCase     fit_case         = FitCase::mean;
    double      shaft_roughness  = 0.; ///< Rz of the shaft (micrometres)
    double      hub_roughness    = 0.; ///< Rz of the hub bore (micrometres)
    double      push_on_distance = 0.; ///< a (mm) of a taper fit; 0: none

    void
    declare_parameters(ParameterHandler &prm);

    /** DIN 7190's smoothing loss 0.8 (Rz_shaft + Rz_hub) in mm. */
    double
    smoothing_loss() const
    {
      return 0.8e-3 * (shaft_roughness + hub_roughness);
    }
  };

  /**
   * The interference a run uses, with where it came from: the limits of a
   * toleranced fit (ISO 286 deviations in mm), the case chosen and the
   * smoothing loss. All lengths in mm; deviations NaN without an ISO fit.
   */
  struct FitLimits
  {
    std::string source = "Fit/Diametral interference";
    std::string iso_fit; ///< normalized, e.g. "H7/s6"; empty: none
    double      hole_upper  = std::numeric_limits<double>::quiet_NaN();
    double      hole_lower  = std::numeric_limits<double>::quiet_NaN();
    double      shaft_upper = std::numeric_limits<double>::quiet_NaN();
    double      shaft_lower = std::numeric_limits<double>::quiet_NaN();
    double      U_min = 0.5, U_max = 0.5;
    double      smoothing_loss = 0.;
    FitCase     fit_case       = FitCase::mean;

    /** The interference of @p c (mean, min or max) before smoothing. */
    double
    interference(FitCase c) const
    {
      return c == FitCase::min ? U_min :
             c == FitCase::max ? U_max :
                                 0.5 * U_min + 0.5 * U_max; // no overflow
    }

    /** The interference of the case in use, before smoothing. */
    double
    used() const
    {
      return interference(fit_case);
    }

    /** The effective interference U_w = U - smoothing loss. */
    double
    effective() const
    {
      return used() - smoothing_loss;
    }
  };

  /**
   * What a run does with the design (`Design/Mode`): check the fit given
   * in Fit, or select the ISO 286 fits that carry the required loads and
   * that the parts bear.
   */
  enum class DesignMode
  {
    check,
    select
  };

  /** Subsection `Design`: what the joint must carry and how it slips. */
  struct DesignParameters
  {
    DesignMode mode               = DesignMode::check;
    double     application_factor = 1.; ///< K_A, on the loads
    /** `Friction coefficient` as given: auto or a number. */
    std::string   friction_text        = "auto";
    std::string   joining_text         = "shrink"; ///< `Joining` as given
    JoiningMethod joining              = JoiningMethod::shrink;
    double        friction_coefficient = 0.15; ///< in use, after resolve
    std::string   friction_source;             ///< where it comes from
    bool   friction_from_table = true; ///< auto: DIN 7190's, after resolve
    double press_in_friction_coefficient = 0.08;
    double required_torque               = 0.; ///< N m; 0: none
    double required_axial_force          = 0.; ///< N; 0: none
    double slip_safety     = 1.; ///< required against slip (verdict)
    double yield_safety    = 1.; ///< required against yield (verdict)
    double fracture_safety = 2.; ///< required of a brittle hub (verdict)
    /**
     * The hub's plastic utilisation (D_p - D_F) / (D_aA - D_F) a selection
     * allows at U_max (a hub with Plasticity = von Mises); 0: elastic.
     */
    double plastic_utilisation = 0.;
    double edge_distance       = 0.;   ///< mm; 0: 5 % of l_F
    bool   corner_trend        = true; ///< solve once more, one level coarser

    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Relations between the entries (select mode needs a load to carry);
     * InputError names the entry.
     */
    void
    validate() const;

    /**
     * Decide the coefficient of friction in use: the number given, or for
     * auto DIN 7190-1's for the pairing of @p shaft and @p hub and the
     * Joining; InputError names the entry.
     */
    void
    resolve_friction(MaterialFamily shaft, MaterialFamily hub);

    /** The edge distance in use for a joint of length @p joint_length. */
    double
    edge_distance_for(const double joint_length) const
    {
      return edge_distance > 0. ? edge_distance : 0.05 * joint_length;
    }
  };

  /**
   * Subsection `Operation`: the state in service next to the state of
   * assembly. Each body carries its own loads: a uniform temperature change
   * from the assembly temperature (thermal eigenstrain), the centrifugal
   * body force of the speed, and pressures on its free cylindrical
   * surfaces. Temperatures in degrees C, speed in 1/min, pressures in MPa,
   * the joining clearance in mm (diametral).
   */
  struct OperationParameters
  {
    double      assembly_temperature = 20.;
    std::string shaft_temperature_text;   ///< empty: the assembly temperature
    std::string hub_temperature_text;     ///< empty: the assembly temperature
    double      speed               = 0.; ///< 1/min
    double      shaft_bore_pressure = 0.; ///< MPa, on the shaft's bore
    double      hub_outer_pressure  = 0.; ///< MPa, on the hub's outer surface
    std::string joining_clearance_text = "auto"; ///< mm or auto
    /** "name: p; name: p": MPa on the named faces of gmsh file sections. */
    std::string face_pressures_text;

    /**
     * The pressures (MPa) on named faces, in the order given; throws
     * InputError naming Operation/Face pressures if the text is not
     * "name: p; ..." with 0 <= p <= 1e4 and each name once.
     */
    std::vector<std::pair<std::string, double>>
    face_pressures() const;

    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Parse the entries given as text and check the ranges; InputError
     * names the entry. @p joint_diameter (mm) scales the automatic joining
     * clearance, @p solid_shaft refuses a bore pressure without a bore.
     */
    void
    validate(double joint_diameter, bool solid_shaft) const;

    /** Operating temperature of the shaft (degrees C). */
    double
    shaft_temperature() const;

    /** Operating temperature of the hub (degrees C). */
    double
    hub_temperature() const;

    /** Angular velocity omega = 2 pi n / 60 (rad/s). */
    double
    omega() const;

    /**
     * The diametral joining clearance (mm): the entry, or with auto DIN
     * 7190's guide value 0.001 D_F for the joint diameter @p joint_diameter.
     */
    double
    joining_clearance(double joint_diameter) const;

    /** Whether any load of operation differs from the assembly state. */
    bool
    has_loads() const;
  };

  /** The name of a fit case as written in a parameter file. */
  std::string
  to_string(FitCase value);
} // namespace coaxfit

#endif
