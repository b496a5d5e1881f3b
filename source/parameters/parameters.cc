#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_file.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/parameters/material_library.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/parameter_file.h>
#include <coaxfit/parameters/parameter_reading.h>
#include <coaxfit/parameters/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace coaxfit
{


  namespace
  {
    template <typename Enum>
    using Names = std::vector<std::pair<std::string, Enum>>;

    /** The names of the enumerators as written in a parameter file. */
    const Names<SolverMethod> &
    names(SolverMethod)
    {
      static const Names<SolverMethod> n{{"staggered", SolverMethod::staggered},
                                         {"monolithic",
                                          SolverMethod::monolithic}};
      return n;
    }

    const Names<AlphaControllerPreset> &
    names(AlphaControllerPreset)
    {
      static const Names<AlphaControllerPreset> n{
        {"fixed", AlphaControllerPreset::fixed},
        {"winkler", AlphaControllerPreset::winkler},
        {"pointwise", AlphaControllerPreset::pointwise},
        {"aitken", AlphaControllerPreset::aitken},
        {"iqn-ils", AlphaControllerPreset::iqn_ils},
        {"ibqn", AlphaControllerPreset::ibqn},
        {"auto", AlphaControllerPreset::automatic}};
      return n;
    }

    const Names<AlphaRuleType> &
    names(AlphaRuleType)
    {
      static const Names<AlphaRuleType> n{{"auto", AlphaRuleType::automatic},
                                          {"fixed", AlphaRuleType::fixed},
                                          {"winkler", AlphaRuleType::winkler},
                                          {"pointwise",
                                           AlphaRuleType::pointwise}};
      return n;
    }

    const Names<AcceleratorType> &
    names(AcceleratorType)
    {
      static const Names<AcceleratorType> n{
        {"auto", AcceleratorType::automatic},
        {"none", AcceleratorType::none},
        {"aitken", AcceleratorType::aitken},
        {"iqn-ils", AcceleratorType::iqn_ils},
        {"ibqn", AcceleratorType::ibqn}};
      return n;
    }

    const Names<InterfaceOperatorType> &
    names(InterfaceOperatorType)
    {
      static const Names<InterfaceOperatorType> n{
        {"auto", InterfaceOperatorType::automatic},
        {"full", InterfaceOperatorType::full},
        {"condensed", InterfaceOperatorType::condensed}};
      return n;
    }

    const Names<HistoryOnChange> &
    names(HistoryOnChange)
    {
      static const Names<HistoryOnChange> n{{"restart",
                                             HistoryOnChange::restart},
                                            {"keep", HistoryOnChange::keep},
                                            {"filter", HistoryOnChange::filter},
                                            {"model", HistoryOnChange::model}};
      return n;
    }

    const Names<ActiveSetUpdateType> &
    names(ActiveSetUpdateType)
    {
      static const Names<ActiveSetUpdateType> n{
        {"auto", ActiveSetUpdateType::automatic},
        {"every step", ActiveSetUpdateType::every_step},
        {"when converged", ActiveSetUpdateType::when_converged}};
      return n;
    }

    const Names<LinearSolverType> &
    names(LinearSolverType)
    {
      static const Names<LinearSolverType> n{
        {"auto", LinearSolverType::automatic},
        {"direct", LinearSolverType::direct},
        {"amg", LinearSolverType::amg}};
      return n;
    }

    const Names<SweepFiles> &
    names(SweepFiles)
    {
      static const Names<SweepFiles> n{{"figures", SweepFiles::figures},
                                       {"complete", SweepFiles::complete}};
      return n;
    }

    const Names<VolumetricIntegration> &
    names(VolumetricIntegration)
    {
      static const Names<VolumetricIntegration> n{
        {"full", VolumetricIntegration::full},
        {"reduced", VolumetricIntegration::reduced}};
      return n;
    }

    template <typename Enum>
    std::string
    name_of(const Enum value)
    {
      for (const auto &[name, e] : names(value))
        if (e == value)
          return name;
      Assert(false, ExcInternalError());
      return "";
    }

    /**
     * Declare a selection entry bound to an enum member: the pattern lists
     * the names of names(Enum), the default is the member's value.
     */
    template <typename Enum>
    void
    add_selection(ParameterHandler  &prm,
                  const std::string &entry,
                  Enum              &member,
                  const std::string &documentation)
    {
      std::string options;
      for (const auto &[name, e] : names(member))
        options += (options.empty() ? "" : "|") + name;
      prm.declare_entry(entry,
                        name_of(member),
                        Patterns::Selection(options),
                        documentation);
      prm.add_action(entry, [&member](const std::string &value) {
        for (const auto &[name, e] : names(member))
          if (name == value)
            member = e;
      });
    }

    /**
     * The value of an entry that is auto (returned as 0) or a number
     * 0 < x < 1 called @p symbol in messages; throws an InputError naming
     * @p entry otherwise.
     */
    double
    auto_or_fraction(const std::string &entry,
                     const std::string &symbol,
                     const std::string &text)
    {
      if (text == "auto")
        return 0.;
      const std::string allowed
        = ": allowed is auto or 0 < " + symbol + " < 1.";
      std::istringstream in(text);
      double             value = 0.;
      if (!(in >> value) || !(in >> std::ws).eof())
        throw InputError("parameter " + entry + " = " + text
                         + " is not a number" + allowed);
      if (!(value > 0. && value < 1.))
        throw InputError("parameter " + entry + " = " + text
                         + " is out of range" + allowed);
      return value;
    }



    std::string
    base_name(const std::string &filename)
    {
      std::string name  = filename;
      const auto  slash = name.find_last_of('/');
      if (slash != std::string::npos)
        name = name.substr(slash + 1);
      for (const std::string extension : {".prm", ".json", ".xml"})
        if (name.size() > extension.size()
            && name.compare(name.size() - extension.size(),
                            extension.size(),
                            extension)
                 == 0)
          name.resize(name.size() - extension.size());
      return name.empty() ? std::string("default") : name;
    }

  } // namespace



  std::string
  to_string(const SolverMethod value)
  {
    return name_of(value);
  }



  std::string
  to_string(const LinearSolverType value)
  {
    return name_of(value);
  }

  std::string
  to_string(const AlphaControllerPreset value)
  {
    return name_of(value);
  }

  std::string
  to_string(const AlphaRuleType value)
  {
    return name_of(value);
  }

  std::string
  to_string(const AcceleratorType value)
  {
    return name_of(value);
  }

  std::string
  to_string(const InterfaceOperatorType value)
  {
    return name_of(value);
  }

  std::string
  to_string(const ActiveSetUpdateType value)
  {
    return name_of(value);
  }

  std::string
  to_string(const VolumetricIntegration value)
  {
    return name_of(value);
  }



  void
  GeometryParameters::validate() const
  {
    require(R1 > R0,
            "Geometry/R1",
            R1,
            "R0 < R1 < R2 (R0 = " + number(R0) + ")");
    require(R2 > R1, "Geometry/R2", R2, "R2 > R1 (R1 = " + number(R1) + ")");
    // Proportions a mesh of 2D cells can represent in double precision.
    require(R2 <= 1e4 * R1, "Geometry/R2", R2, "R1 < R2 <= 1e4 R1");
    // Thinner walls make the stiffness numerically singular (the bound
    // itself allowed despite round-off in R1 - R0).
    const double min_wall = 1e-3 * R1 * (1. - 1e-9);
    require(R1 - R0 >= min_wall,
            "Geometry/R0",
            R0,
            "a shaft wall R1 - R0 of at least 1e-3 R1 (R1 = " + number(R1)
              + ")");
    require(R2 - R1 >= min_wall,
            "Geometry/R2",
            R2,
            "a hub wall R2 - R1 of at least 1e-3 R1 (R1 = " + number(R1) + ")");
    require(L1 > 0. && L1 >= 1e-4 * R1 && L1 <= 1e4 * R1,
            "Geometry/L1",
            L1,
            "1e-4 R1 <= L1 <= 1e4 R1");
    require(L2 > 0. && L2 >= 1e-4 * R1 && L2 <= 1e4 * R1,
            "Geometry/L2",
            L2,
            "1e-4 R1 <= L2 <= 1e4 R1");
    require(d >= -0.1 * R1 && d <= 0.1 * R1,
            "Geometry/d",
            d,
            "-0.1 R1 <= d <= 0.1 R1 (R1 = " + number(R1) + ")");
  }



  void
  Material::declare_parameters(ParameterHandler  &prm,
                               const std::string &body_label)
  {
    const bool required = true;
    prm.add_parameter("Name",
                      name,
                      "Material of the " + body_label
                        + " from the library: " + material_names(", ")
                        + " (doc/materials.md lists the values and their "
                          "sources), or custom. A name fills E, nu, Yield "
                          "strength, Tensile strength, Density, Thermal "
                          "expansion, Cooling expansion, Temperature limit "
                          "and Kind; entries given in the file override it.",
                      Patterns::Selection(material_names("|") + "|custom"));
    prm.add_parameter("E",
                      E,
                      "Young's modulus of the " + body_label
                        + " in MPa. Required unless Name gives it. Allowed: "
                          "1e-6 to 1e9 (foams to diamond are 1e-2 to "
                          "1.2e6).",
                      Patterns::Double(1e-6, 1e9),
                      required);
    prm.add_parameter("nu",
                      nu,
                      "Poisson's ratio of the " + body_label
                        + " (dimensionless). Required unless Name gives it. "
                          "Allowed: -1 < nu < 0.5.",
                      Patterns::Double(-1., 0.5),
                      required);
    prm.add_parameter("Yield strength",
                      yield_strength,
                      "Yield strength R_e (or R_p0.2) of the " + body_label
                        + " in MPa, for the safety against yield. 0: "
                          "unknown (from Name if given; no yield check "
                          "otherwise). Allowed: 0 to 1e5.",
                      Patterns::Double(0., 1e5));
    prm.add_parameter("Density",
                      density,
                      "Density of the " + body_label
                        + " in kg/m^3 (reported; for loads of operation). "
                          "0: unknown (from Name if given). Allowed: 0 to "
                          "1e5.",
                      Patterns::Double(0., 1e5));
    prm.add_parameter("Thermal expansion",
                      thermal_expansion,
                      "Linear thermal expansion coefficient of the "
                        + body_label
                        + " in 1/K (reported; for loads of operation and "
                          "for heating the part for joining). 0: unknown "
                          "(from Name if given). Allowed: 0 to 1e-3.",
                      Patterns::Double(0., 1e-3));
    prm.add_parameter("Tensile strength",
                      tensile_strength,
                      "Tensile strength R_m of the " + body_label
                        + " in MPa, for the safety against fracture of a "
                          "brittle material (Kind). 0: unknown (from Name if "
                          "given). Allowed: 0 to 1e5.",
                      Patterns::Double(0., 1e5));
    prm.add_parameter("Cooling expansion",
                      cooling_expansion,
                      "Mean linear expansion coefficient of the " + body_label
                        + " for undercooling, in 1/K, given positive (DIN "
                          "7190 lists it negative: steel -8.5e-6, cast iron "
                          "-8e-6, bronze -15e-6, aluminium alloys -18e-6); "
                          "for the temperature to which the shaft is cooled "
                          "for joining. Smaller than the heating "
                          "coefficient, as metals shrink less per kelvin "
                          "when cold. 0: not given (from Name if given; "
                          "otherwise the Thermal expansion is used, which "
                          "gives too warm a cooling temperature, and the "
                          "output says so). Allowed: 0 to 1e-3.",
                      Patterns::Double(0., 1e-3));
    prm.add_parameter("Temperature limit",
                      temperature_limit,
                      "Temperature of the " + body_label
                        + " in degrees C above which heating changes the "
                          "material (the tempering temperature of a "
                          "quenched and tempered or case-hardened steel, the "
                          "artificial ageing temperature of an aluminium "
                          "alloy): heating the hub above it for joining, or "
                          "operating a part above it, gives a warning. 0: "
                          "unknown (from Name if given; otherwise the hub "
                          "is compared with 350 C, the usual limit for "
                          "heating a steel hub). Allowed: 0 to 2000.",
                      Patterns::Double(0., 2000.));
    prm.add_parameter("Kind",
                      kind_text,
                      "How the " + body_label
                        + " is assessed: metal (a ductile metal: von "
                          "Mises against Yield strength), brittle (grey "
                          "cast iron: a brittle hub is assessed by DIN "
                          "7190's criterion for brittle materials, its "
                          "largest hoop stress against Tensile strength, "
                          "with the safety against fracture, instead of "
                          "yield; needs Tensile strength), polymer (as a "
                          "metal, but E below 1000 MPa is expected, no unit "
                          "warning), or auto: the kind of the library "
                          "material Name (EN-GJL-250 brittle, the others "
                          "metal), metal for custom.",
                      Patterns::Selection("auto|metal|brittle|polymer"));
    prm.add_parameter("Plasticity",
                      plasticity_text,
                      "Material model of the " + body_label
                        + ": none (linear elastic; above the yield "
                          "strength the run warns and its pressure is one "
                          "the part cannot carry) or von Mises (elastic-"
                          "plastic, small strains: the von Mises yield "
                          "surface of Yield strength with linear isotropic "
                          "hardening of Hardening modulus; the interference "
                          "is then applied in increments and the pressure "
                          "that remains is the one the yielded part "
                          "carries). Needs Yield strength > 0 (given or "
                          "from Name). Two bodies only in this version.",
                      Patterns::Selection("none|von Mises"));
    prm.add_parameter("Hardening modulus",
                      hardening_modulus,
                      "Plasticity = von Mises: slope H of the yield "
                      "stress over the equivalent plastic strain, in "
                      "MPa (linear isotropic hardening: sigma_y = "
                      "Yield strength + H eps_p); 0 is perfectly "
                      "plastic. Allowed: 0 <= H < E.",
                      Patterns::Double());
  }



  void
  Material::validate(const std::string &path) const
  {
    require(E >= 1e-6 && E <= 1e9, path + "/E", E, "1e-6 <= E <= 1e9");
    require(nu > -1. && nu < 0.5, path + "/nu", nu, "-1 < nu < 0.5");
    require(hardening_modulus >= 0. && hardening_modulus < E,
            path + "/Hardening modulus",
            hardening_modulus,
            "0 <= H < E (0: perfectly plastic)");
    if (plastic && !(yield_strength > 0.))
      throw InputError("parameter " + path
                       + "/Yield strength = 0 (unknown) but Plasticity = "
                         "von Mises: an elastic-plastic body needs its yield "
                         "strength, allowed is Yield strength > 0 in MPa (or "
                         "a Name that gives it)");
    if (plastic && kind == MaterialKind::brittle)
      throw InputError("parameter " + path
                       + "/Plasticity = von Mises but the material is "
                         "brittle (Kind): a brittle part does not yield, "
                         "allowed is Plasticity = none for it");
    if (kind == MaterialKind::brittle && !(tensile_strength > 0.))
      throw InputError("parameter " + path
                       + "/Tensile strength = 0 (unknown) but the material "
                         "is brittle (Kind): a brittle part is assessed "
                         "against its tensile strength R_m, allowed is R_m "
                         "> 0 in MPa (or a Name that gives it)");
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.add_parameter("Axial cells",
                      axial_cells,
                      "Number of cells along the contact length "
                      "0 <= z <= min(L1, L2) before global refinement "
                      "(the paper used 10-12). Cells shrink towards the "
                      "end of contact by the grading ratio; the part of "
                      "the longer body beyond the contact gets cells that "
                      "grow away from it. Allowed: 1 to 10000.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Radial cells",
                      radial_cells,
                      "Number of cells across each wall before global "
                      "refinement (the paper used 10), shrinking towards "
                      "the contact surface. Allowed: 1 to 10000.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Grading ratio",
                      grading_ratio,
                      "Ratio of the sizes of neighbouring cells "
                      "(geometric progression, the paper used 1.3-1.6); "
                      "1 gives a uniform mesh. Allowed: 1 to 10.",
                      Patterns::Double(1.0, 10.0));
    prm.add_parameter("Global refinements",
                      global_refinements,
                      "Number of uniform refinements applied to both "
                      "meshes; 0 is the paper's coarse mesh. Allowed: 0 to "
                      "10.",
                      Patterns::Integer(0, 10));
    prm.add_parameter("Cell size",
                      cell_size,
                      "Sections only (Geometry/Shaft section, Hub "
                      "section): the size of the cells at the ends of the "
                      "joint and at re-entrant corners in mm before global "
                      "refinement; away from them cells grow by Mesh/"
                      "Grading ratio per cell up to 8 times this size. "
                      "Both bodies get the same vertices on the joint. 0: "
                      "l_F / 100. Mesh/Axial cells and Radial cells apply "
                      "to plain cylinders only; Mesh/Grading ratio at most 3 "
                      "here. Allowed: 0, or l_F / 1000 to l_F / 4, and at "
                      "most about 50000 cells per section.",
                      Patterns::Double(0.));
    prm.add_parameter("Hub cell size",
                      hub_cell_size,
                      "Sections only: Mesh/Cell size for the hub (mm); 0: "
                      "Mesh/Cell size. With Mesh/Joint nodes = shared the "
                      "joint's vertices follow Mesh/Cell size in both "
                      "bodies. Allowed: as Mesh/Cell size.",
                      Patterns::Double(0.));
    prm.declare_entry("Joint nodes",
                      "shared",
                      Patterns::Selection("shared|own"),
                      "Sections only. shared: both bodies get the same "
                      "vertices on the joint, so their joint nodes coincide "
                      "and the coupling takes the exact index map. own: each "
                      "body is meshed on its own (the joint nodes need not "
                      "match); the finer side's displacements reach the "
                      "coarser side's points by the r-weighted L2 "
                      "projection M and the forces go back by M^T (total "
                      "force conserved), with the condensed operator of the "
                      "staggered method (Solver/Method = staggered, "
                      "Solver/Linear solver direct) and no coarse model. A "
                      "section from a gmsh file or a rounded edge at the "
                      "joint always takes own.");
    prm.add_action("Joint nodes", [this](const std::string &value) {
      shared_joint_nodes = value == "shared";
    });
    prm.add_parameter("Degree",
                      degree,
                      "Polynomial degree p of the FE_Q elements for both "
                      "displacement components. Allowed: 1 to 4.",
                      Patterns::Integer(1, 4));
    add_selection(prm,
                  "Volumetric integration",
                  volumetric_integration,
                  "full: the whole stiffness with the (p+1)-point "
                  "Gauss rule per direction. reduced: selective "
                  "reduced integration, the lambda (volumetric) part "
                  "with the p-point rule, the 2 mu part with p+1; it "
                  "removes volumetric locking of low degrees for nearly "
                  "incompressible materials (nu -> 0.5; see "
                  "benchmarks/stress). The contact pressure comes from "
                  "reactions; the VTU stresses take their volumetric "
                  "part from the reduced points (field "
                  "volumetric_stress), which is accurate for FE_Q(2) "
                  "and up; FE_Q(1) gives one value per cell, off by up "
                  "to a third of p next to the axis at nu = 0.4999.");
    prm.leave_subsection();
  }



  void
  LoadPathParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load path");
    prm.add_parameter("Increments",
                      increments,
                      "Bodies with Plasticity = von Mises only: the "
                      "interference is applied elastically up to the first "
                      "yield (one solve), then in this many equal "
                      "increments up to its full value; an increment whose "
                      "Newton solve or coupling fails is halved and "
                      "retried, and the increments after it grow back to "
                      "this size (doubling), so that the load path does "
                      "not depend on the coupling method. Allowed: 1 to "
                      "10000.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Max bisections",
                      max_bisections,
                      "The smallest increment is the nominal one halved "
                      "this often: an increment that fails at that size "
                      "stops the run as not converged (exit 2, naming the "
                      "stage, the body and the increment; near a limit "
                      "load the increments would otherwise creep towards "
                      "it without end). Allowed: 0 to 30.",
                      Patterns::Integer(0, 30));
    prm.add_parameter("Newton tolerance",
                      newton_tolerance,
                      "Relative residual at which a body's Newton solve "
                      "(radial return, consistent tangent) has converged: "
                      "the norm of the out-of-balance nodal forces over "
                      "the norm of the forces the body carries (a solve "
                      "whose last correction is below 1e-12 of the field "
                      "has converged too: round-off). Tighter than the "
                      "coupling's tolerance, so that the coupling sees "
                      "smooth maps. Allowed: 1e-12 to 1e-8.",
                      Patterns::Double(1e-12, 1e-8));
    prm.add_parameter("Max Newton iterations",
                      max_newton_iterations,
                      "Newton iterations of one body solve before the "
                      "increment counts as failed and is halved. Allowed: "
                      "2 to 200.",
                      Patterns::Integer(2, 200));
    prm.add_parameter(
      "Stages",
      stages_text,
      "Bodies with Plasticity = von Mises only: the stages of the load "
      "path, each from the state the one before left (a body that yielded "
      "keeps its plastic strain). joining: the interference applied (always "
      "first); operation: the loads of the subsection Operation applied "
      "(temperatures, speed, pressures) at the full interference; "
      "unloading: those loads removed again (the pressure that remains "
      "after operation); disassembly: the interference removed, the parts "
      "apart (the residual stresses and the permanent change of the hub's "
      "bore and the shaft's diameter; needs Contact/Unilateral = true). "
      "Each stage is applied in Increments equal increments. auto: joining, "
      "and operation when Operation has loads. Allowed: auto or a "
      "comma-separated list in this order, e.g. 'joining, operation, "
      "unloading, disassembly' (operation only with loads, unloading only "
      "after operation).",
      Patterns::Anything());
    prm.leave_subsection();
  }



  std::string
  to_string(const LoadPathParameters::Stage stage)
  {
    switch (stage)
      {
        case LoadPathParameters::Stage::joining:
          return "joining";
        case LoadPathParameters::Stage::operation:
          return "operation";
        case LoadPathParameters::Stage::unloading:
          return "unloading";
        case LoadPathParameters::Stage::disassembly:
          return "disassembly";
      }
    return "";
  }



  std::vector<LoadPathParameters::Stage>
  LoadPathParameters::stages(const bool has_loads, const bool unilateral) const
  {
    const std::string entry
      = "parameter Load path/Stages = '" + stages_text + "': ";
    std::vector<Stage> list;
    if (Utilities::trim(stages_text) == "auto")
      {
        list.push_back(Stage::joining);
        if (has_loads)
          list.push_back(Stage::operation);
        return list;
      }
    const Stage              all[4] = {Stage::joining,
                                       Stage::operation,
                                       Stage::unloading,
                                       Stage::disassembly};
    std::vector<std::string> items;
    {
      std::istringstream text(stages_text);
      std::string        item;
      while (std::getline(text, item, ','))
        items.push_back(item);
      if (!stages_text.empty() && stages_text.back() == ',')
        items.emplace_back();
    }
    for (const std::string &item : items)
      {
        const std::string name = Utilities::trim(item);
        if (name.empty())
          throw InputError(entry
                           + "an empty item; allowed is auto or a list "
                             "such as 'joining, operation, unloading, "
                             "disassembly'");
        bool known = false;
        for (const Stage s : all)
          if (name == to_string(s))
            {
              known = true;
              if (!list.empty()
                  && static_cast<int>(s) <= static_cast<int>(list.back()))
                throw InputError(entry + "'" + name
                                 + "' repeated or out of order; allowed is "
                                   "auto or a list in the order joining, "
                                   "operation, unloading, disassembly");
              list.push_back(s);
            }
        if (!known)
          throw InputError(entry + "unknown stage '" + name
                           + "'; allowed are joining, operation, "
                             "unloading, disassembly (or auto)");
      }
    if (list.empty() || list.front() != Stage::joining)
      throw InputError(entry + "the list starts with joining");
    const auto has = [&](const Stage s) {
      return std::find(list.begin(), list.end(), s) != list.end();
    };
    if (has(Stage::operation) && !has_loads)
      throw InputError(entry
                       + "operation needs loads of operation (Operation/"
                         "Speed, temperatures or pressures); the "
                         "subsection Operation has none");
    if (has(Stage::unloading) && !has(Stage::operation))
      throw InputError(entry + "unloading follows operation; list both");
    if (has(Stage::disassembly) && !unilateral)
      throw InputError(entry
                       + "disassembly lets the joint open and needs "
                         "Contact/Unilateral = true");
    return list;
  }



  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    add_selection(prm,
                  "Method",
                  method,
                  "staggered: the principle of alternating continuity "
                  "(each body solved on its own, Dirichlet and "
                  "Neumann steps alternating). monolithic: the "
                  "reference, both bodies in one system with the "
                  "contact points tied and a primal-dual active set "
                  "for separation; the Coupling settings are not "
                  "used.");
    add_selection(prm,
                  "Linear solver",
                  linear_solver,
                  "How each body's systems are solved. direct: sparse "
                  "Cholesky (CHOLMOD), factorized once per set of "
                  "prescribed points; the interface compliance is the "
                  "inverse of the factor's trailing block. amg: conjugate "
                  "gradients preconditioned by Trilinos' algebraic "
                  "multigrid (ML), the preconditioner built once per set "
                  "of prescribed points and reused across coupling steps; "
                  "needs less memory on large meshes (the coupling then "
                  "solves both bodies at every step, Coupling/Interface "
                  "operator = full; staggered method only; MPI is "
                  "initialized for Trilinos, about 0.5 s). auto: direct "
                  "while its estimated memory fits the available memory, "
                  "amg beyond (benchmarks/README.md has the measured "
                  "crossover).");
    prm.leave_subsection();
  }



  void
  CouplingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    prm.add_parameter("Alpha",
                      alpha,
                      "Relaxation weight alpha (project convention): the "
                      "Neumann step applies p = p1 + alpha (p2 - p1) and "
                      "the Dirichlet step u = u1 + (1 - alpha) (u2 - d - "
                      "u1), with index 1 the shaft and 2 the hub. A stiff "
                      "solid shaft wants alpha near 1, a thin tube near 0. "
                      "The fixed rule uses it throughout, from the "
                      "paper's zero force; ibqn does not use it. The "
                      "adaptive rules (winkler, "
                      "pointwise, and so aitken and iqn-ils) do not use "
                      "it: their first Neumann step applies a uniform "
                      "pressure (scaled afterwards to the one that closes "
                      "the gap best) whose compliances give the Winkler "
                      "alpha k2/(k1 + k2) (with clearance everywhere the "
                      "first Dirichlet step measures them; the step is "
                      "rescaled, no extra solve). Allowed: 0 < alpha < 1.",
                      Patterns::Double(0., 1.));
    add_selection(prm,
                  "Alpha controller",
                  controller,
                  "How the staggered process is steered: a preset of an "
                  "alpha rule and an accelerator (each can be chosen "
                  "on its own with Alpha rule and Accelerator). fixed: "
                  "the constant Coupling/Alpha, no acceleration (the "
                  "paper's process). winkler: one alpha = k2/(k1 + k2) "
                  "from the bodies' current compliances, formulas "
                  "(4.20)-(4.21), re-estimated after every Neumann step. "
                  "pointwise: an alpha per interface point by (4.22) "
                  "with Coupling/Beta. aitken: the Winkler alpha plus "
                  "dynamic (Aitken) relaxation of the traction iterate. "
                  "iqn-ils: the Winkler alpha plus interface "
                  "quasi-Newton (inverse least squares) acceleration. "
                  "ibqn: interface block quasi-Newton, no alpha: each "
                  "body's interface compliance is modelled from every "
                  "solve of that body (Neumann and Dirichlet, whatever "
                  "the contact zone was), starting from the coarse "
                  "model's compliance; the next Neumann force and "
                  "Dirichlet displacement solve the contact problem of "
                  "these models (contact flags included), so a change "
                  "of the contact zone costs no history. auto: ibqn "
                  "where Coupling/Coarse model applies (Mesh/Global "
                  "refinements >= 1, direct linear solver), iqn-ils "
                  "elsewhere. Measured: benchmarks/README.md.");
    add_selection(prm,
                  "Alpha rule",
                  rule,
                  "How alpha is chosen: fixed, winkler or pointwise (see "
                  "Alpha controller). auto: the rule of the Alpha "
                  "controller preset (winkler for aitken and iqn-ils). "
                  "With an accelerator the adaptive rules estimate alpha "
                  "once, from the first loaded Neumann step, so that "
                  "the accelerated map stays the same.");
    add_selection(prm,
                  "Accelerator",
                  acceleration,
                  "Acceleration of the traction fixed point x -> G(x) "
                  "(one Neumann and one Dirichlet step): none, aitken "
                  "(dynamic relaxation) or iqn-ils (interface "
                  "quasi-Newton); or ibqn, which replaces the fixed "
                  "point by models of the two bodies (see Alpha "
                  "controller; alpha is then not used). auto: the "
                  "accelerator of the Alpha controller preset (none for "
                  "fixed, winkler and pointwise).");
    declare_iteration_parameters(prm);
    prm.leave_subsection();
  }



  void
  CouplingParameters::declare_iteration_parameters(ParameterHandler &prm)
  {
    add_selection(prm,
                  "Interface operator",
                  interface_operator,
                  "full: every step solves both bodies (two triangular "
                  "solves each with the cached factorizations, one "
                  "more factorization per body for every new set of "
                  "points in contact). condensed: each body's "
                  "compliance on S is formed once (the inverse of the "
                  "trailing block of the free body's Cholesky factor, "
                  "interface points ordered last), the iteration runs "
                  "on the interface only with dense algebra, and one "
                  "full solve per body gives the final fields. auto: "
                  "condensed up to 2000 interface points (dense "
                  "compliance up to 32 MB per body), full above. "
                  "Measured speeds: benchmarks/README.md.");
    add_selection(prm,
                  "Active set change",
                  history_on_change,
                  "What the accelerator keeps of its history when points "
                  "enter or leave contact (the fixed-point map changes "
                  "at those points). restart: forget it (each change "
                  "starts the quasi-Newton model anew). keep: keep every "
                  "column. filter: keep the columns with the rows of the "
                  "changed points removed. model: start a new history, "
                  "but keep the inverse Jacobian that the old one "
                  "built (without the changed points' rows and "
                  "columns) as the prior of the new model (multi-vector "
                  "quasi-Newton, IQN-IMVJ; n^2 numbers for n interface "
                  "points), so the first step after the "
                  "change is already a quasi-Newton step. Measured on the "
                  "separating variants: benchmarks/README.md.");
    prm.declare_entry(
      "Coarse model",
      "auto",
      Patterns::Selection("auto|none"),
      "Prior of the quasi-Newton model. For ibqn: each body's compliance on "
      "the coarse mesh (its answer to the coarse nodal forces of the fine "
      "ones, interpolated), plus a half-space or shell compliance for the "
      "waves that mesh cannot represent; for iqn-ils: the inverse Jacobian of "
      "the process on the same case meshed one refinement coarser, formed "
      "with that mesh's condensed interface operators for the run's alpha "
      "and contact points (again after every change of the contact "
      "points), so that the first accelerated step already corrects the "
      "long waves of the interface and the history only has to learn what "
      "the coarse mesh cannot represent (multi-level acceleration). auto: "
      "used when there is such a mesh (Mesh/Global refinements >= 1), the "
      "linear solver is direct and the coarse interface has at most 2000 "
      "points (2000 fine points for ibqn's dense models); the run also "
      "starts from the coarse case's solution. none: plain IQN-ILS (and "
      "ibqn with Winkler compliances measured in its first step). "
      "Measured: benchmarks/README.md.");
    prm.add_action("Coarse model", [this](const std::string &value) {
      coarse_model = value == "auto";
    });
    prm.declare_entry("Beta",
                      "auto",
                      Patterns::Anything(),
                      "beta of the pointwise rule, formula (4.22): "
                      "alpha_i = beta u2/((1 - beta) u1 + beta u2); 0.5 "
                      "gives (4.21). auto: chosen from the contraction of "
                      "the first steps' residuals among 0.5, 0.3 and 0.15 "
                      "or 0.7. Allowed: auto or 0 < beta < 1.");
    prm.add_action("Beta", [this](const std::string &text) {
      beta = auto_or_fraction("Coupling/Beta", "beta", text);
    });
    prm.add_parameter("Aitken initial omega",
                      aitken_omega,
                      "Relaxation factor of the first Aitken step (1: "
                      "the plain process). Allowed: 0 < omega <= 2.",
                      Patterns::Double(0., 2.));
    prm.add_parameter("IQN-ILS columns",
                      iqn_columns,
                      "Largest number of previous iterations the IQN-ILS "
                      "model keeps; for ibqn, the largest number of "
                      "solves kept per body. Allowed: 1 to 1000.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("IQN-ILS filter",
                      iqn_filter,
                      "QR filter of IQN-ILS (and of ibqn's samples): a "
                      "column whose part orthogonal to the newer columns "
                      "is below this fraction of its norm is dropped. "
                      "Allowed: 0 <= filter < 1.",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Tolerance",
                      tolerance,
                      "The iteration stops when both the relative "
                      "displacement mismatch max|u2 - u1 - d|/d (after a "
                      "Neumann step) and the relative traction mismatch "
                      "max|p2 - p1|/max|p| (after a Dirichlet step) are "
                      "below this value. Allowed: 1e-12 <= tol < 1 (the "
                      "traction mismatch is a difference of nodal "
                      "reactions and reaches its round-off level near "
                      "1e-13: 3e-14 on variant 5's mesh, more with thin "
                      "walls, so a smaller tolerance cannot be met).",
                      Patterns::Double(1e-12, 1.));
    prm.add_parameter("Max steps",
                      max_steps,
                      "Largest number of coupling steps (each Neumann or "
                      "Dirichlet solve of both bodies is one step). A run "
                      "that reaches it without converging exits with a "
                      "non-zero code. Allowed: 1 to 100000.",
                      Patterns::Integer(1, 100000));
  }



  void
  CouplingParameters::validate() const
  {
    require(alpha > 0. && alpha < 1., "Coupling/Alpha", alpha, "0 < alpha < 1");
    require(aitken_omega > 0.,
            "Coupling/Aitken initial omega",
            aitken_omega,
            "0 < omega <= 2");
    require(iqn_filter < 1.,
            "Coupling/IQN-ILS filter",
            iqn_filter,
            "0 <= filter < 1");
    require(tolerance < 1.,
            "Coupling/Tolerance",
            tolerance,
            "1e-12 <= tol < 1");
  }



  AlphaRuleType
  CouplingParameters::alpha_rule() const
  {
    if (rule != AlphaRuleType::automatic)
      return rule;
    switch (controller)
      {
        case AlphaControllerPreset::fixed:
          return AlphaRuleType::fixed;
        case AlphaControllerPreset::pointwise:
          return AlphaRuleType::pointwise;
        default:
          return AlphaRuleType::winkler;
      }
  }



  AcceleratorType
  CouplingParameters::accelerator(const bool coarse_model_available) const
  {
    if (acceleration != AcceleratorType::automatic)
      return acceleration;
    switch (controller)
      {
        case AlphaControllerPreset::ibqn:
          return AcceleratorType::ibqn;
        case AlphaControllerPreset::automatic:
          return coarse_model_available ? AcceleratorType::ibqn :
                                          AcceleratorType::iqn_ils;
        case AlphaControllerPreset::aitken:
          return AcceleratorType::aitken;
        case AlphaControllerPreset::iqn_ils:
          return AcceleratorType::iqn_ils;
        default:
          return AcceleratorType::none;
      }
  }



  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.add_parameter("Unilateral",
                      unilateral,
                      "true: the contact is unilateral as in the paper "
                      "(1.2)-(1.3): tensile contact forces are set to zero "
                      "and points with a gap >= 0 and no force separate. "
                      "false: bilateral (the surfaces are held together, "
                      "the pressure may become tensile).");
    add_selection(prm,
                  "Active set update",
                  active_set_update,
                  "When the contact / separated flags change. every "
                  "step: the paper's process, tensile forces are set "
                  "to zero in every force step and the flags are set "
                  "after every Neumann step. when converged: the flags "
                  "stay fixed while the coupling converges to the "
                  "Active set tolerance, then tensile contact points "
                  "separate and penetrating separated points close "
                  "(primal-dual active set); accelerators (aitken, "
                  "iqn-ils) need this. auto: every step without an "
                  "accelerator and with the fixed rule, when converged "
                  "otherwise.");
    prm.declare_entry(
      "Active set tolerance",
      "auto",
      Patterns::Anything(),
      "In the when-converged mode the flags are updated once both "
      "relative mismatches are below this value (or Coupling/Tolerance if "
      "larger). Not used by ibqn, whose model sets the flags after every "
      "step. Each update restarts the accelerator, so from a uniform "
      "start a rough first guess of the zone is cheaper than an accurate "
      "one (0.1 halves the steps of the separating variants against "
      "1e-4), while flags predicted by the coarser mesh (Coupling/Coarse "
      "model) are worth keeping a little longer (0.1 lost them for variant "
      "18: 94 steps). auto: 1e-2 when the run starts from the coarser "
      "mesh's solution, 0.1 otherwise (measured on several meshes: "
      "benchmarks/README.md). If an update returns to flags seen before (a cycle), the "
      "value is divided by 100 for the rest of the run. The final flags "
      "are always checked at Coupling/Tolerance. Allowed: auto or "
      "0 < tol < 1.");
    prm.add_action("Active set tolerance", [this](const std::string &text) {
      active_set_tolerance
        = auto_or_fraction("Contact/Active set tolerance", "tol", text);
    });
    prm.leave_subsection();
  }



  void
  ContactParameters::validate() const
  {
    require(active_set_tolerance >= 0. && active_set_tolerance < 1.,
            "Contact/Active set tolerance",
            active_set_tolerance,
            "auto or 0 < tol < 1");
  }



  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.add_parameter("Directory",
                      directory,
                      "Directory for the results (created if missing). "
                      "Empty: output/<base name of the parameter file>, "
                      "relative to the working directory.",
                      Patterns::Anything());
    prm.add_parameter("Write vtu",
                      write_vtu,
                      "Write one VTU file per body for the final state, "
                      "interface.vtp and a .pvd grouping them (for "
                      "ParaView).");
    prm.add_parameter("Write plots",
                      write_plots,
                      "Draw contact_pressure.png, surface_stresses.png and "
                      "convergence.png with gnuplot (skipped with a note "
                      "when gnuplot is not installed).");
    prm.add_parameter("Write report",
                      write_report,
                      "Write report.md: inputs, the design table (FE next "
                      "to DIN 7190), warnings and plots.");
    prm.add_parameter("Print timing",
                      print_timing,
                      "Print the wall times of the phases at the end of "
                      "the run (they are always in summary.json). Tests "
                      "switch this off to keep their output reproducible.");
    add_selection(prm,
                  "Sweep files",
                  sweep_files,
                  "What each value of a --sweep writes into its "
                  "subdirectory. figures: summary.json, "
                  "contact_pressure.csv, convergence.csv, the surface "
                  "stresses and parameters.prm (run that file for the "
                  "value's VTU, plots and report). complete: everything "
                  "that Write vtu, Write plots and Write report ask for, "
                  "as a single run (about 5x the time of a sweep of "
                  "figures at the default mesh). Single runs and several "
                  "files ignore this entry.");
    prm.leave_subsection();
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    drawing.declare_parameters(prm);
    fit.declare_parameters(prm);
    prm.enter_subsection("Material");
    for (const auto &[name, material, label] :
         {std::tuple<std::string, Material *, std::string>{"Shaft",
                                                           &shaft,
                                                           "shaft D1"},
          {"Hub", &hub, "hub D2"}})
      {
        prm.enter_subsection(name);
        material->declare_parameters(prm, label);
        prm.leave_subsection();
      }
    prm.leave_subsection();
    design.declare_parameters(prm);
    operation.declare_parameters(prm);
    mesh.declare_parameters(prm);
    solver.declare_parameters(prm);
    load_path.declare_parameters(prm);
    coupling.declare_parameters(prm);
    contact.declare_parameters(prm);
    output.declare_parameters(prm);
  }



  void
  MeshParameters::validate() const
  {
    // The smallest cell of a graded direction is ratio^-(cells - 1) of the
    // largest: beyond 1e6 the mesh cannot be represented sensibly.
    const unsigned int cells = std::max(axial_cells, radial_cells);
    require(std::pow(grading_ratio, cells - 1.) <= 1e6,
            "Mesh/Grading ratio",
            grading_ratio,
            "Grading ratio^(cells - 1) <= 1e6 with Mesh/Axial cells = "
              + std::to_string(axial_cells)
              + " and Mesh/Radial cells = " + std::to_string(radial_cells));
  }



  void
  Parameters::validate() const
  {
    geometry.validate();
    design.validate();
    require(design.edge_distance < geometry.contact_length(),
            "Design/Edge distance",
            design.edge_distance,
            "0 <= distance < l_F / 2 = " + number(geometry.contact_length())
              + " mm (half the joint length: the maxima are taken between "
                "the mid-plane and the band at the end of the joint)");
    // Axial and radial cells are those of the plain cylinders.
    if (!drawing.has_sections())
      mesh.validate();
    if (solver.method == SolverMethod::monolithic
        && solver.linear_solver == LinearSolverType::amg)
      throw InputError("parameter Solver/Linear solver = amg: allowed with "
                       "Solver/Method = staggered only (the monolithic "
                       "reference factorizes its coupled system: give "
                       "direct or auto)");
    if (solver.linear_solver == LinearSolverType::amg
        && coupling.interface_operator == InterfaceOperatorType::condensed)
      throw InputError("parameter Coupling/Interface operator = condensed "
                       "needs the factors of Solver/Linear solver = direct "
                       "(with amg: full or auto)");
    shaft.validate("Material/Shaft");
    hub.validate("Material/Hub");
    operation.validate(2. * geometry.R1, geometry.R0 == 0.);
    // Loads of operation need the material data that turn them into
    // forces; 0 means unknown there.
    for (const auto &[material, path] :
         {std::pair<const Material *, std::string>{&shaft, "Material/Shaft"},
          {&hub, "Material/Hub"}})
      {
        const double T = material == &shaft ? operation.shaft_temperature() :
                                              operation.hub_temperature();
        if (T != operation.assembly_temperature
            && material->thermal_expansion == 0.)
          throw InputError("parameter " + path
                           + "/Thermal expansion = 0 (unknown) but the "
                             "operating temperature differs from "
                             "Operation/Assembly temperature: allowed is a "
                             "coefficient > 0 in 1/K (or a Name that "
                             "gives it).");
        if (operation.speed > 0. && material->density == 0.)
          throw InputError("parameter " + path
                           + "/Density = 0 (unknown) but Operation/Speed = "
                           + number(operation.speed)
                           + " 1/min: allowed is a density > 0 in kg/m^3 "
                             "(or a Name that gives it).");
      }
    coupling.validate();
    contact.validate();
    // A selection that may let the hub yield needs a hub that can; in check
    // mode an elastic hub leaves the entry unused (input_warnings()).
    if (design.plastic_utilisation > 0. && !hub.plastic
        && design.mode == DesignMode::select)
      throw InputError("parameter Design/Plastic utilisation = "
                       + number(design.plastic_utilisation)
                       + ": a selection that lets the hub yield needs "
                         "Material/Hub/Plasticity = von Mises (with its "
                         "Yield strength); allowed without it is 0");
    if (shaft.plastic || hub.plastic)
      load_path.stages(operation.has_loads(), contact.unilateral);
    else if (Utilities::trim(load_path.stages_text) != "auto")
      throw InputError("parameter Load path/Stages = '" + load_path.stages_text
                       + "': the stages of a load path are computed for "
                         "bodies with Plasticity = von Mises (an elastic "
                         "fit's states follow from its loads: the state of "
                         "operation is reported next to the state of "
                         "assembly); allowed is auto");
  }



  void
  Parameters::derive_model()
  {
    geometry.R0    = 0.5 * drawing.shaft_bore_diameter;
    geometry.R1    = 0.5 * drawing.joint_diameter;
    geometry.R2    = 0.5 * drawing.hub_outer_diameter;
    geometry.L1    = 0.5 * drawing.shaft_length;
    geometry.L2    = 0.5 * drawing.hub_length;
    geometry.d     = 0.5 * fit_limits.effective();
    geometry.whole = sections && !sections->half_model();
    if (geometry.whole)
      {
        geometry.z_joint_start = sections->joint_start();
        geometry.z_joint_end   = sections->joint_end();
      }
  }



  std::string
  replace_prm_line(const std::string &text,
                   const std::string &entry,
                   const std::string &value)
  {
    std::istringstream lines(text);
    std::string        line, result;
    while (std::getline(lines, line))
      {
        const auto first = line.find_first_not_of(' ');
        if (first != std::string::npos
            && line.compare(first, 4 + entry.size(), "set " + entry) == 0
            && line.find_first_not_of(' ', first + 4 + entry.size())
                 == line.find('=', first))
          {
            if (value.empty())
              continue;
            line = line.substr(0, line.find('=') + 1) + " " + value;
          }
        result += line + '\n';
      }
    return result;
  }



  Parameters
  Parameters::for_fit_case(const FitCase c) const
  {
    Assert(c != FitCase::all, ExcInternalError());
    Parameters p          = *this;
    p.fit_limits.fit_case = c;
    p.geometry.d          = 0.5 * p.fit_limits.effective();
    if (fit.fit_case == FitCase::all)
      {
        p.output.directory = output_directory() + "/" + to_string(c);
        p.case_name        = case_name + "_" + to_string(c);
        // Its parameters.prm repeats this case alone, into its directory.
        p.used_prm = replace_prm_line(p.used_prm, "Case", to_string(c));
        p.used_prm
          = replace_prm_line(p.used_prm, "Directory", p.output.directory);
        // A taper's cases are push-on distances (one interference each).
        if (sections && sections->conical())
          {
            p.fit.push_on_distance = p.fit_limits.used() / sections->taper();
            p.used_prm = replace_prm_line(p.used_prm, "Case", "mean");
            p.used_prm = replace_prm_line(p.used_prm,
                                          "Push-on distance",
                                          number(p.fit.push_on_distance, 17));
          }
      }
    return p;
  }



  std::vector<std::string>
  Parameters::input_warnings() const
  {
    std::vector<std::string> list = read_notes;
    if (design.plastic_utilisation > 0. && !hub.plastic)
      list.push_back("Design/Plastic utilisation = "
                     + number(design.plastic_utilisation)
                     + " is not used: the hub is elastic "
                       "(Material/Hub/Plasticity = none)");
    const double U_w = 2. * geometry.d;
    const double D_F = 2. * geometry.R1;
    if (U_w > 3e-3 * D_F)
      list.push_back("the effective interference " + number(U_w) + " mm is "
                     + number(std::round(1e4 * U_w / D_F) / 100.)
                     + " % of the joint diameter (above 0.3 %: a unit slip, "
                       "or beyond the elastic range of most metals)");
    // E typed in GPa (210 for steel): below any metal's 1000 MPa unless
    // the part is declared a polymer; a named metal's E far from its own.
    std::string low_E, far_E;
    for (const auto &[name, m] :
         {std::pair<std::string, const Material *>{"Shaft", &shaft},
          {"Hub", &hub}})
      {
        const MaterialData *data = find_material(m->name);
        if (m->E < 1000. && m->kind != MaterialKind::polymer)
          low_E += std::string(low_E.empty() ? "" : ", ") + "Material/" + name
                   + "/E = " + number(m->E);
        else if (data != nullptr && m->E_given
                 && std::max(m->E / data->E, data->E / m->E) > 2.)
          far_E += std::string(far_E.empty() ? "" : "; ") + "Material/" + name
                   + "/E = " + number(m->E) + " MPa for " + m->name
                   + ", whose E is " + number(data->E) + " MPa (a factor "
                   + number(std::max(m->E / data->E, data->E / m->E)) + ")";
      }
    if (!low_E.empty())
      list.push_back(
        low_E
        + " MPa is below 1000 MPa, less than any metal (steel 210000 MPa): "
          "E typed in GPa? E is in MPa; for a plastic part set "
          "Material/<body>/Kind = polymer");
    if (!far_E.empty())
      list.push_back(far_E
                     + ": more than a factor 2 from the library value (a "
                       "unit slip: GPa or kPa for MPa?)");
    if (shaft.kind == MaterialKind::brittle)
      list.push_back(
        "the shaft is brittle (Material/Shaft/Kind): DIN 7190's criterion "
        "for brittle materials (hoop stress against R_m) is applied to the "
        "hub only; the shaft, compressed at the joint, is checked against "
        "its Yield strength as a metal");
    const double ratio = std::max(shaft.E / hub.E, hub.E / shaft.E);
    if (ratio > 1e3)
      list.push_back("Young's moduli of shaft (" + number(shaft.E)
                     + " MPa) and hub (" + number(hub.E)
                     + " MPa) differ by a factor " + number(ratio)
                     + " (a unit slip: GPa or kPa for MPa?)");
    // Volumetric locking of full integration (benchmarks/stress: the
    // pressure of prm/lame.prm 22 % low at nu = 0.4999999 with FE_Q(1)).
    if (!mesh.reduced_volumetric_integration())
      {
        const double limit = mesh.degree == 1 ? 0.49 : 0.499;
        for (const auto &[name, nu] :
             {std::pair<std::string, double>{"Shaft", shaft.nu},
              {"Hub", hub.nu}})
          if (nu > limit)
            list.push_back(
              "Material/" + name + "/nu = " + number(nu) + " is above "
              + number(limit)
              + ": with Mesh/Degree = " + std::to_string(mesh.degree)
              + " and full integration the nearly incompressible body "
                "locks (stiff, pressures too low); set Mesh/Volumetric "
                "integration = reduced");
      }
    return list;
  }



  void
  Parameters::set(const std::string &path, const std::string &value)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    set_entry(prm, path, value);
  }



  bool
  is_declared_entry(const std::string &path)
  {
    ParameterHandler prm;
    Parameters().declare_parameters(prm);
    return declares_entry(prm, path);
  }



  std::string
  Parameters::output_directory() const
  {
    return output.directory.empty() ? "output/" + case_name : output.directory;
  }



  Parameters
  read_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot open parameter file '" + filename + "'");
      // A directory opens as a stream on Linux but cannot be read.
      in.peek();
      if (in.bad())
        throw InputError("cannot read parameter file '" + filename + "'");
    }

    const std::vector<std::string> files_read = check_parameter_file(filename);
    Parameters                     parameters;
    parameters.files_read = files_read;
    ParameterHandler prm;
    parameters.declare_parameters(prm);
    parse_parameter_file(prm, filename);

    for (const auto &[path, value] : overrides)
      set_entry(prm, path, value);

    // A section from a gmsh file: its path relative to the parameter
    // file, written absolute so that the run's parameters.prm repeats it
    // from anywhere.
    for (const auto &[entry, text] :
         {std::pair<std::string, std::string *>{
            "Shaft section", &parameters.drawing.shaft_section},
          {"Hub section", &parameters.drawing.hub_section}})
      if (is_section_file_name(*text))
        {
          const std::string resolved
            = resolved_section_file(*text, filename, "Geometry/" + entry);
          prm.enter_subsection("Geometry");
          prm.set(entry, resolved);
          prm.leave_subsection();
          *text = resolved;
        }

    // The scene has no silent defaults: name every entry that is missing.
    // deal.II joins the path with '.' and writes other characters than
    // letters and digits as _XX (hexadecimal): back to the names of the file.
    std::set<std::string> missing = entries_not_set(prm);
    complete_scene(parameters, missing);
    if (!missing.empty())
      {
        throw InputError("parameter file '" + filename
                         + "' does not give the scene entries "
                         + entry_list(missing)
                         + " (the geometry, interference and materials have "
                           "no defaults: set them in the file or with "
                           "--set; a Material Name gives E and nu, a Fit/ISO "
                           "fit the interference)");
      }

    parameters.case_name = base_name(filename);
    parameters.validate();

    // The written parameters must repeat the run: the values a material
    // Name filled in are written as given.
    set_material_entries(prm, "Shaft", parameters.shaft);
    set_material_entries(prm, "Hub", parameters.hub);

    std::ostringstream prm_text, json_text;
    prm.print_parameters(prm_text, ParameterHandler::ShortPRM);
    prm.print_parameters(json_text,
                         ParameterHandler::OutputStyle(
                           ParameterHandler::JSON | ParameterHandler::Short));
    // The file name goes into a comment line: no control characters.
    std::string printable = filename;
    for (char &c : printable)
      if (std::iscntrl(static_cast<unsigned char>(c)))
        c = '?';
    std::string prm_lines = prm_text.str();
    // With an ISO fit the interference is the fit's: the entry would only
    // be reported as not used when the file is run again.
    if (!parameters.fit.iso_fit.empty()
        || (parameters.sections && parameters.sections->conical()))
      prm_lines = replace_prm_line(prm_lines, "Diametral interference", "");
    // With sections the plain geometry entries are derived, and the file
    // would be refused if it gave them.
    if (parameters.drawing.has_sections())
      for (const std::string name : {"Joint diameter",
                                     "Shaft bore diameter",
                                     "Hub outer diameter",
                                     "Hub length",
                                     "Shaft length"})
        prm_lines = replace_prm_line(prm_lines, name, "");
    parameters.used_prm = "# coaxfit: the parameters of this run (file '"
                          + printable + "' with the --set overrides)\n"
                          + prm_lines;
    parameters.used_json = json_text.str();
    return parameters;
  }



  void
  print_parameters(std::ostream &out)
  {
    Parameters       parameters;
    ParameterHandler prm;
    parameters.declare_parameters(prm);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::Text);
    // A template, not a scene: the entries of the scene that a file must
    // give are written commented out, so that a copy refuses to run (and
    // names them) until they are filled in; the values shown are examples.
    const std::set<std::string> required = entries_not_set(prm);
    std::istringstream          lines(text.str());
    std::vector<std::string>    path;
    std::string                 line;
    out << "# coaxfit parameter template. Entries marked 'required' are "
           "commented out:\n# give each its value (the one shown is an "
           "example) and remove the '#'.\n";
    while (std::getline(lines, line))
      {
        const std::size_t first = line.find_first_not_of(' ');
        const std::string body
          = first == std::string::npos ? "" : line.substr(first);
        if (body.rfind("subsection ", 0) == 0)
          path.push_back(body.substr(11));
        else if (body == "end" && !path.empty())
          path.pop_back();
        else if (body.rfind("set ", 0) == 0)
          {
            std::string name = body.substr(4, body.find('=') - 4);
            name.erase(name.find_last_not_of(' ') + 1);
            std::string full;
            for (const std::string &s : path)
              full += s + '.';
            if (required.count(full + name) > 0)
              {
                out << line.substr(0, first) << "# " << body
                    << "   # required\n";
                continue;
              }
          }
        out << line << '\n';
      }
    out.flush();
  }
} // namespace coaxfit
