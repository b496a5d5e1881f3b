#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/scene_parameters.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  std::string
  to_string(const FitCase value)
  {
    switch (value)
      {
        case FitCase::min:
          return "min";
        case FitCase::max:
          return "max";
        case FitCase::all:
          return "all";
        default:
          return "mean";
      }
  }



  void
  DrawingGeometry::declare_parameters(ParameterHandler &prm)
  {
    const Patterns::Double non_negative(0.);
    const bool             required = true;
    prm.enter_subsection("Geometry");
    prm.add_parameter("Joint diameter",
                      joint_diameter,
                      "Joint diameter D_F in mm: the nominal DIAMETER of "
                      "the shaft's seat and the hub's bore (both bodies "
                      "are meshed at it; small strain). Required. "
                      "Allowed: Shaft bore diameter < D_F < Hub outer "
                      "diameter, 1e-3 to 1e5 mm.",
                      non_negative,
                      required);
    prm.add_parameter("Shaft bore diameter",
                      shaft_bore_diameter,
                      "Bore DIAMETER D_iI of a hollow shaft in mm; 0 for a "
                      "solid shaft. Required. Allowed: 0, or 1e-3 mm <= D_iI "
                      "< D_F with a wall (D_F - D_iI)/2 of at least 5e-4 "
                      "D_F.",
                      non_negative,
                      required);
    prm.add_parameter("Hub outer diameter",
                      hub_outer_diameter,
                      "Outer DIAMETER D_aA of the hub in mm. Required. "
                      "Allowed: 1.001 D_F <= D_aA <= 1e4 D_F (a wall of at "
                      "least 5e-4 D_F), at most 1e5 mm.",
                      non_negative,
                      required);
    prm.add_parameter("Hub length",
                      hub_length,
                      "FULL length of the hub in mm (the joint length l_F "
                      "when the shaft is longer). The hub is centred on "
                      "the shaft. Required. Allowed: 1e-4 D_F to 1e4 D_F, "
                      "and 1e-3 to 1e5 mm.",
                      non_negative,
                      required);
    prm.add_parameter("Shaft length",
                      shaft_length,
                      "FULL length of the shaft in mm, centred on the hub. "
                      "Required. Allowed: 1e-4 D_F to 1e4 D_F, and 1e-3 to "
                      "1e5 mm.",
                      non_negative,
                      required);
    const std::string outline_rules
      = "Closed polygon 'z, D; z, D; ...' (axial position and DIAMETER in "
        "mm, drawing coordinates; the last point repeats the first; a "
        "third number R rounds that corner with a fillet of radius R). "
        "Both sections or neither: with them, the plain entries above are "
        "left out (the sections decide them: D_F and l_F from the joint, "
        "D_aA the hub's outer diameter averaged over the joint) and "
        "Mesh/Cell size decides the meshes. The joint is one cylinder or "
        "one cone (a taper fit: Fit/Push-on distance); a scene symmetric "
        "about a plane z = const is modelled as its half, any other whole "
        "(doc/real_parts.md). Or a gmsh file, '.geo' or '.msh', its path "
        "relative to the parameter file (x = r, y = z in mm; the physical "
        "curve 'joint' is the surface that meets the other body; only "
        "quadrilaterals): its mesh is used as it is, the scene modelled "
        "whole with Mesh/Joint nodes = own. Empty: the plain cylinders.";
    prm.add_parameter("Shaft section",
                      shaft_section,
                      "Section of the shaft, the inner body. " + outline_rules,
                      Patterns::Anything());
    prm.add_parameter("Hub section",
                      hub_section,
                      "Section of the hub, the outer body. " + outline_rules,
                      Patterns::Anything());
    prm.leave_subsection();
  }



  void
  DrawingGeometry::validate() const
  {
    // Absolute sizes from 1 micrometre to 100 m: every press fit, and
    // coordinates, displacements and stresses far inside the range of the
    // single-precision arrays of the VTU files (1e38).
    for (const auto &[name, size] :
         {std::pair<std::string, double>{"Geometry/Joint diameter",
                                         joint_diameter},
          {"Geometry/Hub outer diameter", hub_outer_diameter},
          {"Geometry/Hub length", hub_length},
          {"Geometry/Shaft length", shaft_length}})
      require(size >= 1e-3 && size <= 1e5, name, size, "1e-3 to 1e5 mm");
    require(shaft_bore_diameter == 0.
              || (shaft_bore_diameter >= 1e-3 && shaft_bore_diameter <= 1e5),
            "Geometry/Shaft bore diameter",
            shaft_bore_diameter,
            "0 (solid) or 1e-3 to 1e5 mm");
    const double D = joint_diameter;
    require(D > 0. && D > shaft_bore_diameter,
            "Geometry/Joint diameter",
            D,
            "Shaft bore diameter < D_F < Hub outer diameter (bore "
              + number(shaft_bore_diameter) + " mm)");
    require(hub_outer_diameter > D,
            "Geometry/Hub outer diameter",
            hub_outer_diameter,
            "D_aA > D_F (D_F = " + number(D) + " mm)");
    // Proportions a mesh of 2D cells can represent in double precision.
    require(hub_outer_diameter <= 1e4 * D,
            "Geometry/Hub outer diameter",
            hub_outer_diameter,
            "D_F < D_aA <= 1e4 D_F");
    // Thinner walls make the stiffness numerically singular (the bound
    // itself allowed despite round-off in the difference).
    const double min_wall = 5e-4 * D * (1. - 1e-9);
    require((D - shaft_bore_diameter) / 2. >= min_wall,
            "Geometry/Shaft bore diameter",
            shaft_bore_diameter,
            "a shaft wall (D_F - D_iI)/2 of at least 5e-4 D_F (D_F = "
              + number(D) + " mm)");
    require((hub_outer_diameter - D) / 2. >= min_wall,
            "Geometry/Hub outer diameter",
            hub_outer_diameter,
            "a hub wall (D_aA - D_F)/2 of at least 5e-4 D_F (D_F = " + number(D)
              + " mm)");
    for (const auto &[name, length] :
         {std::pair<std::string, double>{"Geometry/Hub length", hub_length},
          {"Geometry/Shaft length", shaft_length}})
      require(length > 0. && length >= 1e-4 * D && length <= 1e4 * D,
              name,
              length,
              "1e-4 D_F <= length <= 1e4 D_F (D_F = " + number(D) + " mm)");
  }



  void
  FitParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fit");
    prm.add_parameter("Diametral interference",
                      diametral_interference,
                      "Diametral interference U in mm: the shaft's "
                      "DIAMETER exceeds the bore's by U (the radial "
                      "interference is U/2). The model is linear (small "
                      "strain), so U/D_F should stay well below 0.01. "
                      "Required unless ISO fit is given. Zero or negative: a "
                      "clearance (the parts touch only if loads of "
                      "Operation close it). Allowed: after the smoothing "
                      "loss, 0 or 1e-9 D_F <= |U_w| <= 0.1 D_F.",
                      Patterns::Double(),
                      true);
    prm.add_parameter("ISO fit",
                      iso_fit,
                      "An interference or transition fit of ISO 286: hole "
                      "basis such as H7/s6 (holes H5 to H11 with shafts js, "
                      "k to zc in grades 5 to 11) or shaft basis such as "
                      "S7/h6 (shafts h5 to h11 with holes JS5 to JS11, K5 "
                      "to K8, M5 to M8, N5 to N11, P to ZC 5 to 11); joint "
                      "diameters over 1 up to 500 mm. When given it "
                      "decides the interference: U_min = ei - ES, U_max = "
                      "es - EI at the joint diameter, and Case chooses "
                      "which. Empty: Diametral interference is used.",
                      Patterns::Anything());
    prm.declare_entry("Case",
                      "mean",
                      Patterns::Selection("mean|min|max|all"),
                      "Which interference of the ISO fit a run uses: the "
                      "mean, the smallest (slip: the capacity to rely on) "
                      "or the largest (strength, press-in force); all: the "
                      "three in one run, each in its own subdirectory "
                      "min, mean, max of the output directory with one "
                      "table fit_cases.csv. Needs ISO fit unless mean.");
    prm.add_action("Case", [this](const std::string &value) {
      fit_case = value == "min" ? FitCase::min :
                 value == "max" ? FitCase::max :
                 value == "all" ? FitCase::all :
                                  FitCase::mean;
    });
    prm.add_parameter("Shaft roughness Rz",
                      shaft_roughness,
                      "Mean roughness depth Rz of the shaft's seat in "
                      "micrometres. DIN 7190 subtracts the smoothing loss "
                      "0.8 (Rz_shaft + Rz_hub) from the interference. "
                      "Allowed: 0 to 1000.",
                      Patterns::Double(0., 1000.));
    prm.add_parameter("Hub roughness Rz",
                      hub_roughness,
                      "Mean roughness depth Rz of the hub's bore in "
                      "micrometres (see Shaft roughness Rz). Allowed: 0 to "
                      "1000.",
                      Patterns::Double(0., 1000.));
    prm.add_parameter("Push-on distance",
                      push_on_distance,
                      "For a taper fit only (Geometry/Shaft section and Hub "
                      "section meeting on a cone): how far in mm the hub is "
                      "pushed along the axis, towards the cone's larger "
                      "diameter, from where the drawn sections touch. It "
                      "sets the interference: U = a C (C the taper, 0.1 "
                      "for 1:10); Diametral interference and ISO fit are "
                      "then left out. 0: not a taper fit. Allowed with a "
                      "cone: a > 0 with a C <= 0.1 D_F and a <= l_F / 10. "
                      "With Design/Mode = select it only starts the "
                      "selection's solves (0: a C = D_F / 1000).",
                      Patterns::Double(0.));
    prm.leave_subsection();
  }



  void
  DesignParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Design");
    prm.declare_entry("Mode",
                      "check",
                      Patterns::Selection("check|select"),
                      "check: compute the fit of the Fit section (its ISO "
                      "fit or interference). select: choose the fit; from "
                      "Required torque and Required axial force (times "
                      "Application factor), Slip safety, Yield safety and "
                      "Fracture safety, the finite element model of this "
                      "geometry gives the least and the largest measured "
                      "diametral interference (smoothing loss included) "
                      "at assembly and in service, DIN 7190's beside them, "
                      "and the ISO 286 fits inside that band, ranked; the "
                      "first is then computed as with Fit/Case = all. "
                      "select needs Required torque or Required axial "
                      "force > 0; Fit/ISO fit and Fit/Case are not used. "
                      "A taper fit (sections meeting on a cone) has no ISO "
                      "fit: select gives its band of push-on distances "
                      "(a = U / C) and computes its ends and middle as the "
                      "cases min, mean, max. A hub with Plasticity = von "
                      "Mises is held elastic by the selection unless "
                      "Plastic utilisation > 0 lets it yield.");
    prm.add_action("Mode", [this](const std::string &value) {
      mode = value == "select" ? DesignMode::select : DesignMode::check;
    });
    prm.add_parameter("Application factor",
                      application_factor,
                      "Application (service) factor K_A of the loads: the "
                      "joint must carry K_A times Required torque and "
                      "Required axial force (the safety against slip is "
                      "taken against those). 1: the loads as given; "
                      "shocks ask more (DIN 3990: 1.25 to 2.25). "
                      "Dimensionless. Allowed: 1 to 10.",
                      Patterns::Double(1., 10.));
    prm.add_parameter("Friction coefficient",
                      friction_text,
                      "Coefficient of static friction of the joint against "
                      "slip (DIN 7190's nu_r), for the transmissible torque "
                      "and axial force. auto: DIN 7190-1's value for the "
                      "pairing of the Material Names and the Joining: "
                      "steel on steel 0.14 shrunk (degreased 0.20), 0.12 "
                      "by pressure oil (degreased 0.18); steel on cast iron "
                      "0.10 (degreased 0.16); steel on light alloys 0.10; "
                      "steel on copper alloys 0.17 (the lower ends of the "
                      "standard's ranges); a material without a Name is "
                      "taken as steel; the report names the value's "
                      "source. A number overrides it (the value of your "
                      "tests). Allowed: auto or 1e-6 <= mu <= 1.",
                      Patterns::Anything());
    prm.add_parameter("Joining",
                      joining_text,
                      "How the joint is made, for the automatic Friction "
                      "coefficient: shrink (the hub heated or the shaft "
                      "cooled, surfaces as machined), shrink degreased, "
                      "pressure oil (widened by oil injection, joined with "
                      "mineral oil), pressure oil degreased (joined with "
                      "glycerine), press (pressed in lengthwise; DIN "
                      "7190-1's oiled pressure oil value). The joining "
                      "temperatures are printed for every method; only a "
                      "shrink fit is judged by them (the verdict, and in "
                      "select mode the fits that cannot be joined by "
                      "heating the hub to its Temperature limit and "
                      "cooling the shaft to -196 C are left out).",
                      Patterns::Selection(joining_method_names()));
    prm.add_action("Joining", [this](const std::string &value) {
      joining = joining_method(value);
    });
    prm.add_parameter("Press-in friction coefficient",
                      press_in_friction_coefficient,
                      "Coefficient of sliding friction while the shaft is "
                      "pressed in (DIN 7190's nu_e), for the press-in "
                      "force of the interference in use (the largest with "
                      "Case = max). Allowed: 1e-6 <= "
                      "mu <= 1.",
                      Patterns::Double(1e-6, 1.));
    prm.add_parameter("Required torque",
                      required_torque,
                      "Torque the joint must transmit, in N m; with "
                      "Required axial force it gives the safety against "
                      "slip. 0: none. Allowed: 0 to 1e12.",
                      Patterns::Double(0., 1e12));
    prm.add_parameter("Required axial force",
                      required_axial_force,
                      "Axial force the joint must transmit, in N. 0: none. "
                      "Allowed: 0 to 1e12.",
                      Patterns::Double(0., 1e12));
    prm.add_parameter("Slip safety",
                      slip_safety,
                      "The safety against slip the joint must have, for "
                      "the verdict: it fails where the transmissible torque "
                      "and axial force over the required ones (Required "
                      "torque, Required axial force) fall below this, at "
                      "assembly or in service. 1: the joint must not slip; "
                      "designs commonly ask more (1.5 and above): set the "
                      "value your rules require. Allowed: 1 to 100.",
                      Patterns::Double(1., 100.));
    prm.add_parameter("Yield safety",
                      yield_safety,
                      "The safety against yield (yield strength over the "
                      "von Mises stress away from the ends of the joint) "
                      "that shaft and hub must have, for the verdict, at "
                      "assembly and in service. 1: they must not yield. "
                      "Allowed: 1 to 100.",
                      Patterns::Double(1., 100.));
    prm.add_parameter("Fracture safety",
                      fracture_safety,
                      "The safety against fracture (tensile strength over "
                      "the largest hoop stress at the bore) that a brittle "
                      "hub (Material/Hub/Kind) must have, for the verdict. "
                      "Allowed: 1 to 100.",
                      Patterns::Double(1., 100.));
    prm.add_parameter(
      "Plastic utilisation",
      plastic_utilisation,
      "The plastic utilisation of the hub that Mode = select allows at "
      "U_max: (D_p - D_F) / (D_aA - D_F) at the mid-plane, D_p the "
      "diameter of the hub's plastic zone (0: elastic, 1: plastic through "
      "the wall). 0: the selection stays elastic (U_max from Yield "
      "safety, the hub must not yield). Above 0, with Material/Hub/"
      "Plasticity = von Mises: the hub may yield; U_max is the "
      "interference whose elastic-plastic load path (joining, and "
      "operation when Operation has loads) reaches this utilisation, and "
      "where the hub yields at U_min its pressure comes from that path "
      "too (a yielding hub carries less than the elastic formulas say). "
      "Yield safety then applies to the shaft only. In check mode an "
      "elastic-plastic run reports its hub's utilisation against it "
      "and its verdict fails a hub that yields beyond it (0: a hub that "
      "yields at all). "
      "Allowed: 0 to 0.9 (near 1 the pressure no longer grows with the "
      "interference and the hub's elastic ring is all that holds it).",
      Patterns::Double(0., 0.9));
    prm.add_parameter("Edge distance",
                      edge_distance,
                      "Distance in mm from the hub's edge (where the "
                      "stresses are singular) within which the maxima of "
                      "the stresses along the hub bore and the shaft "
                      "surface are not taken. 0: 5 % of the joint length "
                      "l_F (the shorter of hub and shaft). Allowed: 0 <= "
                      "distance < l_F / 2.",
                      Patterns::Double(0., 1e9));
    prm.add_parameter("Corner trend",
                      corner_trend,
                      "With Mesh/Global refinements >= 1: solve the case "
                      "once more on the mesh one refinement coarser, to "
                      "show how the stresses at the end of the joint (a "
                      "singular corner) grow with refinement. Reported "
                      "next to the corner values, never a design figure.");
    prm.leave_subsection();
  }



  void
  DesignParameters::resolve_friction(const MaterialFamily shaft,
                                     const MaterialFamily hub)
  {
    const std::string text = trimmed(friction_text);
    if (text == "auto")
      {
        const FrictionValue value = din7190_friction(shaft, hub, joining);
        friction_coefficient      = value.coefficient;
        friction_source           = value.source;
        friction_from_table       = true;
        return;
      }
    const double mu = plain_number(text);
    if (!(mu >= 1e-6 && mu <= 1.))
      throw InputError("parameter Design/Friction coefficient = '"
                       + friction_text
                       + "' is not allowed: allowed is auto or a number "
                         "from 1e-6 to 1");
    friction_coefficient = mu;
    friction_source      = "Design/Friction coefficient";
    friction_from_table  = false;
  }



  void
  DesignParameters::validate() const
  {
    if (mode == DesignMode::select && !(required_torque > 0.)
        && !(required_axial_force > 0.))
      throw InputError("parameter Design/Mode = select needs a load to "
                       "carry: allowed is Design/Required torque > 0 or "
                       "Design/Required axial force > 0 (both are 0)");
  }
} // namespace coaxfit
