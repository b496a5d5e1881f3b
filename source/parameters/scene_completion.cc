#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/material_library.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/parameter_reading.h>
#include <coaxfit/parameters/parameters.h>

#include <cmath>
#include <tuple>

namespace coaxfit
{
  namespace
  {
    /**
     * Every case a run computes must stay in the linear (small strain)
     * range; a clearance (U_w <= 0) is a state like any other.
     */
    void
    check_effective_interference(const Parameters &p)
    {
      const double               D = p.drawing.joint_diameter;
      const std::vector<FitCase> cases
        = p.fit.fit_case == FitCase::all ?
            std::vector<FitCase>{FitCase::min, FitCase::mean, FitCase::max} :
            std::vector<FitCase>{p.fit_limits.fit_case};
      for (const FitCase c : cases)
        {
          const double U   = p.fit_limits.interference(c);
          const double U_w = U - p.fit_limits.smoothing_loss;
          if (U_w >= -0.1 * D && U_w <= 0.1 * D
              && (U_w == 0. || std::abs(U_w) >= 1e-9 * D))
            continue;
          const std::string what
            = p.sections && p.sections->conical() ?
                "parameter Fit/Push-on distance = "
                  + number(p.fit.push_on_distance)
                  + " mm (U = a C = " + number(U) + " mm)" :
              p.fit.iso_fit.empty() ?
                "parameter Fit/Diametral interference = " + number(U) + " mm" :
                "parameter Fit/ISO fit = " + p.fit_limits.iso_fit + " (case "
                  + to_string(c) + ": U = " + number(U) + " mm)";
          throw InputError(
            what
            + " gives the effective interference U_w = U - 0.8 "
              "(Rz_shaft + Rz_hub) = "
            + number(U_w)
            + " mm: allowed is 0 or 1e-9 D_F <= |U_w| <= 0.1 D_F (D_F = "
            + number(D) + " mm; negative: a clearance)");
        }
    }
  } // namespace



  FitLimits
  fit_limits_of(const FitParameters &fit, const double joint_diameter)
  {
    FitLimits limits;
    limits.smoothing_loss = fit.smoothing_loss();
    limits.fit_case
      = fit.fit_case == FitCase::all ? FitCase::mean : fit.fit_case;
    if (fit.iso_fit.empty())
      {
        if (fit.fit_case != FitCase::mean)
          throw InputError("parameter Fit/Case = " + to_string(fit.fit_case)
                           + " needs Fit/ISO fit: with Fit/Diametral "
                             "interference alone there is one "
                             "interference (allowed: mean)");
        limits.U_min = limits.U_max = fit.diametral_interference;
        return limits;
      }
    const IsoFit iso   = iso_fit(fit.iso_fit, joint_diameter);
    limits.source      = "Fit/ISO fit " + iso.name;
    limits.iso_fit     = iso.name;
    limits.hole_upper  = 1e-3 * iso.hole_upper;
    limits.hole_lower  = 1e-3 * iso.hole_lower;
    limits.shaft_upper = 1e-3 * iso.shaft_upper;
    limits.shaft_lower = 1e-3 * iso.shaft_lower;
    limits.U_min       = 1e-3 * iso.min_interference();
    limits.U_max       = 1e-3 * iso.max_interference();
    return limits;
  }



  namespace
  {
    /**
     * The scene of `Geometry/Shaft section` and `Hub section`: both given,
     * the plain entries left out (derived from the sections), the mesh
     * and loads this version models with sections.
     */
    void
    complete_sections(Parameters &p, std::set<std::string> &missing)
    {
      const std::string shaft = "Geometry/Shaft section",
                        hub   = "Geometry/Hub section";
      if (p.drawing.shaft_section.empty() || p.drawing.hub_section.empty())
        throw InputError(
          "parameter " + (p.drawing.shaft_section.empty() ? shaft : hub)
          + " is empty while " + (p.drawing.shaft_section.empty() ? hub : shaft)
          + " is given: give both sections (a plain cylinder "
            "as its outline), or neither");
      for (const std::string name : {"Joint diameter",
                                     "Shaft bore diameter",
                                     "Hub outer diameter",
                                     "Hub length",
                                     "Shaft length"})
        if (missing.erase("Geometry." + name) == 0)
          throw InputError("parameter Geometry/" + name + " is given with "
                           + shaft + " and " + hub
                           + ": the sections decide it; leave it out");
      const auto scene
        = std::make_shared<const SectionScene>(p.drawing.shaft_section,
                                               p.drawing.hub_section);
      p.drawing.joint_diameter      = 2. * scene->joint_radius();
      p.drawing.shaft_bore_diameter = scene->shaft_bore_diameter();
      p.drawing.hub_outer_diameter  = scene->hub_outer_diameter();
      p.drawing.hub_length          = scene->joint_length();
      p.drawing.shaft_length        = scene->shaft_length();
      p.sections                    = scene;
      const double l_F              = scene->joint_length();
      require(p.mesh.cell_size == 0.
                || (p.mesh.cell_size >= 1e-3 * l_F
                    && p.mesh.cell_size <= 0.25 * l_F),
              "Mesh/Cell size",
              p.mesh.cell_size,
              "0 (l_F / 100) or l_F / 1000 to l_F / 4 (l_F = " + number(l_F)
                + " mm, the joint length of the sections)");
      require(p.mesh.hub_cell_size == 0.
                || (p.mesh.hub_cell_size >= 1e-3 * l_F
                    && p.mesh.hub_cell_size <= 0.25 * l_F),
              "Mesh/Hub cell size",
              p.mesh.hub_cell_size,
              "0 (Mesh/Cell size) or l_F / 1000 to l_F / 4 (l_F = "
                + number(l_F) + " mm)");
      // A gmsh file's mesh is used as it is: the model whole, its joint
      // nodes its own (documented with the entries; no note).
      if (scene->has_file())
        p.mesh.shared_joint_nodes = false;
      // A rounded edge at the joint: the fillet's nodes lie on its arc,
      // the other body's under it on a straight line; they are coupled by
      // the projection of meshes of their own.
      if (!scene->rounded_ends().empty())
        p.mesh.shared_joint_nodes = false;
      if (!p.mesh.shared_joint_nodes)
        {
          if (p.solver.linear_solver == LinearSolverType::amg
              || p.coupling.interface_operator == InterfaceOperatorType::full)
            throw InputError("parameters Solver/Linear solver = amg and "
                             "Coupling/Interface operator = full are not "
                             "allowed with Mesh/Joint nodes = own (the "
                             "projection works on the condensed operator)");
        }
      require(p.mesh.grading_ratio <= 3.,
              "Mesh/Grading ratio",
              p.mesh.grading_ratio,
              "1 to 3 for sections (the cells grow by it from the joint's "
              "ends and corners)");
      // The cells far from the joint are at most 8 cell sizes: refuse
      // what would take gmsh minutes (its quadrilateral pairing is
      // superlinear).
      const double h = (p.mesh.cell_size > 0. ? p.mesh.cell_size : 0.01 * l_F);
      for (const bool shaft : {true, false})
        {
          const SectionOutline &s = scene->drawn(shaft);
          if (!scene->from_file(shaft) && s.area() / (64. * h * h) > 50000.)
            throw InputError(
              "parameter Mesh/Cell size = " + number(h) + " mm would mesh "
              + s.entry() + " (area " + number(s.area())
              + " mm^2) into more than 50000 cells; use at least "
              + number(std::sqrt(s.area() / (64. * 50000.)), 3) + " mm");
        }
      // Named faces: each name on a face of a gmsh file's section.
      std::set<std::string> names;
      for (const bool shaft : {true, false})
        for (const auto &[name, id] : scene->face_names(shaft))
          if (name != "joint" && name != "axis")
            names.insert(name);
      // A pressure must find its faces, never vanish silently.
      for (const auto &[name, value] : p.operation.face_pressures())
        if (names.count(name) != 0 && !scene->has_free_named_face(true, name)
            && !scene->has_free_named_face(false, name))
          throw InputError(
            "parameter Operation/Face pressures names the face '" + name
            + "', which lies on the joint (contact may spread over it, as "
              "over a fillet at the joint's end); allowed: faces off the "
              "joint");
      for (const auto &[entry, value, shaft] :
           {std::make_tuple("Operation/Hub outer pressure",
                            p.operation.hub_outer_pressure,
                            false),
            std::make_tuple("Operation/Shaft bore pressure",
                            p.operation.shaft_bore_pressure,
                            true)})
        if (value > 0. && !scene->has_pressure_surface(shaft))
          throw InputError(
            "parameter " + std::string(entry) + " = " + number(value)
            + " MPa: the " + (shaft ? "shaft" : "hub")
            + "'s section has no face at its " + (shaft ? "bore" : "largest")
            + " diameter to carry it"
            + (scene->from_file(shaft) ?
                 " that is not named in its gmsh file (a named face takes "
                 "Operation/Face pressures)" :
                 " (a straight edge of constant diameter)")
            + "; allowed: 0, or name the faces with Operation/Face "
              "pressures");
      for (const auto &[name, value] : p.operation.face_pressures())
        if (name == "joint" || name == "axis")
          throw InputError(
            "parameter Operation/Face pressures names the face '" + name
            + "', which carries "
            + (name == "joint" ? "the contact" : "the axis")
            + " and takes no pressure of operation; allowed: the other named "
              "faces of a section's gmsh file");
        else if (names.count(name) == 0)
          {
            std::string list;
            for (const std::string &n : names)
              list += (list.empty() ? "" : ", ") + n;
            throw InputError(
              "parameter Operation/Face pressures names the face '" + name
              + "', which no section's gmsh file has; allowed: "
              + (list.empty() ? std::string("none (no named faces besides "
                                            "joint and axis)") :
                                list));
          }
      // A face where the sections touch beside the joint is modelled
      // free: a pressure there would act where the other body is.
      for (const auto &[name, value] : p.operation.face_pressures())
        for (const bool shaft : {true, false})
          if (scene->named_face_on_shoulder(shaft, name))
            throw InputError(
              "parameter Operation/Face pressures names the face '" + name
              + "', part of which lies on the other section at the face "
                "where they touch (z = "
              + number(scene->shoulder_face()->z, 6)
              + "); allowed: faces where the section is free");
      // Nothing holds a body along a frictionless cylinder: the face
      // pressures on each body must have no axial resultant (a taper's
      // held faces would hold it, but loads are refused on a cone).
      for (const bool shaft : {true, false})
        {
          double       scale = 0.;
          const double force
            = scene->axial_face_force(shaft,
                                      p.operation.face_pressures(),
                                      scale);
          // Pressures rounded by a user balance to about 1e-7 of their
          // load; what is left is held by the axial pin, below 1e-6.
          if (std::abs(force) > 1e-6 * scale)
            throw InputError(
              "parameter Operation/Face pressures: the pressures on the "
              + std::string(shaft ? "shaft" : "hub") + "'s faces push it "
              + (force > 0. ? "towards +z" : "towards -z") + " with "
              + number(std::abs(force), 6)
              + " N, and nothing holds it along the axis (a frictionless "
                "cylindrical joint carries no axial force"
              + (scene->shoulder_face() ?
                   "; the face on which the sections also touch is modelled "
                   "without contact" :
                   "")
              + "); allowed: pressures with no axial resultant on each body "
                "(the same pressure on faces of equal projected area on "
                "both sides, or faces along the axis)");
        }
      const MeshParameters plain;
      if (p.mesh.axial_cells != plain.axial_cells
          || p.mesh.radial_cells != plain.radial_cells)
        p.read_notes.push_back("Mesh/Axial cells and Mesh/Radial cells are not "
                               "used: the sections are meshed by Mesh/Cell "
                               "size");
    }

    /**
     * A taper fit: the interference comes from Fit/Push-on distance
     * (U = a C), not from Fit/Diametral interference or an ISO fit.
     */
    void
    complete_taper(Parameters &p, const bool interference_given)
    {
      const std::string why
        = " with sections that meet on a cone (a taper fit, C = "
          + number(p.sections->taper(), 6)
          + "): Fit/Push-on distance sets the interference (U = a C)";
      if (interference_given)
        throw InputError("parameter Fit/Diametral interference is given" + why
                         + "; leave it out");
      if (!p.fit.iso_fit.empty())
        throw InputError("parameter Fit/ISO fit = " + p.fit.iso_fit
                         + " is given" + why + "; leave it out");
      if (p.fit.fit_case != FitCase::mean
          && p.design.mode != DesignMode::select)
        throw InputError("parameter Fit/Case = " + to_string(p.fit.fit_case)
                         + " is not allowed" + why
                         + " (one interference: allowed is mean)");
      const OperationParameters &o = p.operation;
      if (o.has_loads())
        throw InputError(
          "parameters Operation/Speed, Shaft temperature, Hub temperature "
          "and the pressures give loads of operation"
          + why
          + "; a taper fit is modelled as pushed on and held at its faces, "
            "which would also hold it against the axial strains of "
            "operation: allowed is the assembled state only (Speed 0, the "
            "temperatures those of assembly, no Shaft bore pressure, Hub "
            "outer pressure or Face pressures)");
      const double D     = 2. * p.sections->joint_radius();
      const double C     = p.sections->taper();
      const double l     = p.sections->joint_length();
      const double a_max = std::min(0.1 * D / C, 0.1 * l);
      // A selection chooses the push-on distance: one given only starts its
      // solves (none: one per mille of D_F in U).
      if (p.design.mode == DesignMode::select && p.fit.push_on_distance == 0.)
        p.fit.push_on_distance = std::min(1e-3 * D / C, 0.5 * a_max);
      // The sections are drawn where they touch and the model stays there:
      // the push must be small against the joint (and U in the linear
      // range).
      require(p.fit.push_on_distance > 0. && p.fit.push_on_distance <= a_max,
              "Fit/Push-on distance",
              p.fit.push_on_distance,
              "0 < a <= " + number(a_max)
                + " mm (a C <= 0.1 D_F for the taper C = " + number(C, 6)
                + " on D_F = " + number(D)
                + " mm, and a <= l_F / 10, the model staying where the "
                  "sections touch, l_F = "
                + number(l) + " mm)");
      p.fit.diametral_interference = p.fit.push_on_distance * C;
    }
  } // namespace



  void
  complete_scene(Parameters &p, std::set<std::string> &missing)
  {
    if (p.drawing.has_sections())
      complete_sections(p, missing);
    else if (!p.operation.face_pressures().empty())
      throw InputError("parameter Operation/Face pressures = '"
                       + p.operation.face_pressures_text
                       + "' names faces, which only sections from gmsh "
                         "files have; allowed: empty (plain cylinders take "
                         "Shaft bore pressure and Hub outer pressure)");
    fill_material(p.shaft, "Shaft", missing);
    fill_material(p.hub, "Hub", missing);
    // A selection chooses the interference itself.
    const bool interference_given
      = missing.count("Fit.Diametral interference") == 0;
    const bool taper = p.sections && p.sections->conical();
    if (taper)
      complete_taper(p, interference_given);
    else if (p.fit.push_on_distance != 0.)
      throw InputError("parameter Fit/Push-on distance = "
                       + number(p.fit.push_on_distance)
                       + " mm: allowed only for a taper fit (sections that "
                         "meet on a cone); give 0 or leave it out");
    if (taper)
      missing.erase("Fit.Diametral interference");
    else if (p.design.mode == DesignMode::select)
      missing.erase("Fit.Diametral interference");
    else if (!p.fit.iso_fit.empty())
      {
        missing.erase("Fit.Diametral interference");
        if (interference_given)
          p.read_notes.push_back("Fit/Diametral interference = "
                                 + number(p.fit.diametral_interference)
                                 + " mm is not used: Fit/ISO fit = "
                                 + p.fit.iso_fit + " decides the interference");
      }
    if (!missing.empty())
      return; // read_parameters() names what is missing
    p.design.resolve_friction(p.shaft.family, p.hub.family);
    // auto takes a material without a Name as steel: say so where its E
    // is not a steel's.
    if (p.design.friction_from_table)
      for (const auto &[m, path] :
           {std::make_pair(&p.shaft, "Shaft"), std::make_pair(&p.hub, "Hub")})
        if (m->family == MaterialFamily::unknown
            && !(m->E >= 180000. && m->E <= 240000.))
          p.read_notes.push_back(
            "Material/" + std::string(path)
            + " has no Name and E = " + number(m->E)
            + " MPa, not a steel's: Design/Friction coefficient = auto took "
              "it as steel ("
            + number(p.design.friction_coefficient)
            + "); give its Name or the coefficient");
    if (p.drawing.has_sections())
      {
        // The plain entries are derived: say which sections they come from.
        try
          {
            p.drawing.validate();
          }
        catch (const InputError &e)
          {
            throw InputError(
              "parameters Geometry/Shaft section and Geometry/Hub section "
              "give a scene outside the allowed range (as the plain "
              "cylinders of their joint: "
              + std::string(e.what()) + ")");
          }
      }
    else
      p.drawing.validate();
    // A selection chooses the fit: Fit/ISO fit and Fit/Case are not used
    // (the interference given only starts its solves when DIN 7190's ends
    // cannot).
    FitParameters fit = p.fit;
    if (p.design.mode == DesignMode::select)
      {
        fit.iso_fit.clear();
        fit.fit_case = FitCase::mean;
        // Only a start: without a usable interference (none given, or
        // more than the model allows, 0.1 D), one per mille of D.
        const double D = p.drawing.joint_diameter;
        if (!taper
            && (!interference_given
                || !(std::abs(fit.diametral_interference) <= 0.1 * D)))
          fit.diametral_interference = 1e-3 * D;
      }
    p.fit_limits = fit_limits_of(fit, p.drawing.joint_diameter);
    if (taper)
      p.fit_limits.source = "Fit/Push-on distance";
    if (p.design.mode == DesignMode::check)
      check_effective_interference(p);
    p.derive_model();
  }
} // namespace coaxfit
