#include <coaxfit/fe/section_scene.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

namespace coaxfit
{
  namespace
  {
    using Json = nlohmann::ordered_json;

    Json
    geometry_and_mesh(const RunResults &results)
    {
      const Parameters &p = results.parameters;
      const auto       &g = p.geometry;
      Json              j;
      j["geometry"] = {
        {"R0", g.R0},
        {"R1", g.R1},
        {"R2", g.R2},
        {"L1", g.L1},
        {"L2", g.L2},
        {"d", g.d},
        {"contact_length", g.contact_length()},
        {"units",
         "mm; R0, R1, R2 radii, L1, L2 half lengths, d radial effective interference of the model"}};
      j["geometry"].update({{"joint_diameter", 2. * g.R1},
                            {"shaft_bore_diameter", 2. * g.R0},
                            {"hub_outer_diameter", 2. * g.R2},
                            {"hub_length", 2. * g.L2},
                            {"shaft_length", 2. * g.L1},
                            {"joint_length", 2. * g.contact_length()}});
      if (p.sections)
        j["geometry"]["sections"]
          = {{"shaft", p.drawing.shaft_section},
             {"hub", p.drawing.hub_section},
             {"model", g.whole ? "whole" : "half"},
             {"joint_start", g.whole ? g.joint_start() : -g.contact_length()},
             {"joint_end", g.whole ? g.joint_end() : g.contact_length()},
             {"drawing_offset", p.sections->drawing_offset()},
             {"units",
              "outlines z, D in mm (drawing); model half: the half z >= 0 "
              "of the model, drawing z = model z + drawing_offset; "
              "joint_start, joint_end: model z of the joint's ends (mm)"}};
      if (p.sections && p.sections->shoulder_face())
        {
          const auto &face = *p.sections->shoulder_face();
          j["geometry"]["sections"]["shoulder_face"]
            = {{"z", face.z},
               {"diameter_inner", face.diameter_inner},
               {"diameter_outer", face.diameter_outer},
               {"modelled",
                "free: no axial load, so the face carries no force; both "
                "bodies held axially at the joint's end beside it"}};
        }
      j["paper"]         = {{"beta1", g.R0 / g.R1},
                            {"beta2", g.R2 / g.R1},
                            {"l1", g.L1 / g.R1},
                            {"l2", g.L2 / g.R1},
                            {"delta", g.d / g.R1}};
      const FitLimits &f = p.fit_limits;
      j["fit"]           = {{"source", f.source},
                            {"iso_fit", f.iso_fit},
                            {"case", to_string(f.fit_case)},
                            {"U_min", f.U_min},
                            {"U_max", f.U_max},
                            {"U_used", f.used()},
                            {"smoothing_loss", f.smoothing_loss},
                            {"U_effective", 2. * g.d},
                            {"deviations_mm",
                             {{"hole_upper", f.hole_upper},
                              {"hole_lower", f.hole_lower},
                              {"shaft_upper", f.shaft_upper},
                              {"shaft_lower", f.shaft_lower}}},
                            {"units", "mm, diametral"}};
      Json materials;
      for (const auto &[name, m] :
           {std::pair<std::string, const Material *>{"shaft", &p.shaft},
            {"hub", &p.hub}})
        materials[name] = {{"name", m->name},
                           {"E", m->E},
                           {"nu", m->nu},
                           {"yield_strength", m->yield_strength},
                           {"density", m->density},
                           {"thermal_expansion", m->thermal_expansion},
                           {"tensile_strength", m->tensile_strength},
                           {"cooling_expansion", m->cooling_expansion},
                           {"temperature_limit", m->temperature_limit},
                           {"kind", to_string(m->kind)}};
      j["material"] = materials;
      Json cells, dofs;
      for (const Body &body : results.scene.bodies)
        {
          cells[body.key()] = body.discretization->n_cells();
          dofs[body.key()]  = body.discretization->n_dofs();
        }
      j["mesh"] = {{"degree", p.mesh.degree},
                   {"global_refinements", p.mesh.global_refinements},
                   {"cells", cells},
                   {"dofs", dofs},
                   {"interface_points", results.interface.n_points()}};
      // How the joint's sides of sections are coupled: the same nodes, or
      // the mortar projection from the finer side onto the other's points.
      const Scene &scene = results.scene;
      if (p.sections) // plain cylinders always share their nodes
        j["mesh"]["joint_coupling"]
          = scene.has_transfer() ?
              "mortar: " + scene.bodies[scene.mortar_body()].key() + " onto "
                + scene.bodies[scene.point_body()].key() + " points" :
              std::string("matching nodes");
      return j;
    }

    Json
    contact(const RunResults &results)
    {
      const UnilateralActiveSet &set    = results.solver.get_active_set();
      const GeometryParameters  &g      = results.parameters.geometry;
      const double               length = g.modelled_joint_length();
      const auto zones     = set.separated_zones(results.interface.z(),
                                             g.joint_start(),
                                             g.joint_end());
      double     separated = 0.;
      Json       zone_list = Json::array();
      for (const auto &zone : zones)
        {
          separated += zone.second - zone.first;
          zone_list.push_back({zone.first, zone.second});
        }
      // lost: every point separated; touching: in contact without
      // pressure (U = 0); tension: bilateral contact pulling everywhere.
      const bool  lost = set.n_separated() == results.interface.n_points();
      const char *state
        = lost ? "lost" :
          !(results.pressure.max > 0.) ?
                 (results.pressure.min < 0. ? "tension" : "touching") :
          separated > 0. ? "partial" :
                           "full";
      return {{"state", state},
              {"unilateral", set.enabled()},
              {"active_set_update",
               set.update_mode() == UnilateralActiveSet::Update::every_step ?
                 "every step" :
                 "when converged"},
              {"contact_length", length - separated},
              {"separated_length", separated},
              {"separated_points", set.n_separated()},
              {"separated_zones", zone_list}};
    }

    Json
    coupling_and_solver(const RunResults &results)
    {
      const InterfaceSolver  &solver     = results.solver;
      const SolverStatistics &statistics = results.statistics;
      const auto             &c          = results.parameters.coupling;
      Json                    alpha      = Json::array();
      // Empty where the method has no alpha (ibqn).
      for (const CouplingStep &s : solver.history())
        if (std::isfinite(s.alpha))
          alpha.push_back(s.alpha);
      Json j;
      j["coupling"]
        = {{"controller",
            statistics.method == "monolithic" ? std::string("monolithic") :
                                                to_string(c.controller)},
           {"alpha_rule", statistics.alpha_rule},
           {"accelerator", statistics.accelerator},
           {"coarse_model_points", statistics.coarse_model_points},
           {"coarse_priors", statistics.coarse_priors},
           {"coarse_start_steps", statistics.coarse_start_steps},
           {"tolerance", c.tolerance},
           {"max_steps", c.max_steps},
           {"alpha_history", alpha}};
      j["residuals"]
        = {{"displacement_relative", solver.displacement_residual()},
           {"traction_relative", solver.traction_residual()}};
      j["solver"] = {{"method", statistics.method},
                     {"linear_solver", statistics.linear_solver},
                     {"factorizations", statistics.factorizations},
                     {"solves", statistics.solves}};
      return j;
    }

    /**
     * A taper fit: the cone, the push-on distance and the interference it
     * makes, the push-on force and whether the joint is self-locking.
     */
    Json
    taper(const RunResults &results)
    {
      const Parameters   &p  = results.parameters;
      const FitDesign    &d  = results.design;
      const SectionScene &s  = *p.sections;
      const double        C  = s.taper();
      const double        mu = p.design.friction_coefficient;
      return {{"units", "mm, N, degrees"},
              {"taper", C},
              {"half_angle", std::atan(0.5 * C) * 180. / M_PI},
              {"diameter_small",
               2.
                 * s.joint_radius_at(s.push_direction() > 0. ? s.joint_start() :
                                                               s.joint_end())},
              {"diameter_large",
               2.
                 * s.joint_radius_at(
                   s.push_direction() > 0. ? s.joint_end() : s.joint_start())},
              {"push_on_distance", p.fit.push_on_distance},
              {"push_direction", s.push_direction()},
              {"diametral_interference", p.fit.push_on_distance * C},
              {"push_on_force_frictionless", d.push_on_force},
              {"push_on_force_frictionless_estimate", d.push_on_force_din},
              {"self_locking", mu > 0.5 * C},
              {"friction_coefficient", mu}};
    }



    Json
    design(const RunResults &results)
    {
      const FitDesign &d = results.design;
      Json             checks, maxima;
      for (const FitDesign::CheckPoint &c : d.check_points)
        checks[c.name] = {{"fe",
                           {{"radial", c.fe.radial()},
                            {"hoop", c.fe.hoop()},
                            {"axial", c.fe.sigma[1]},
                            {"shear_rz", c.fe.sigma[3]},
                            {"von_mises", c.fe.von_mises()}}},
                          {"din",
                           {{"radial", c.din.radial},
                            {"hoop", c.din.hoop},
                            {"equivalent", c.din.equivalent()}}}};
      for (const FitDesign::SurfaceMaximum &m : d.surface_maxima)
        maxima[m.name]
          = {{"von_mises", m.von_mises},
             {"z", m.z},
             {"von_mises_middle_half", m.interior},
             {"z_middle_half", m.interior_z},
             {"at_joint_end_singular", m.corner},
             {"at_joint_end_one_refinement_coarser", m.corner_coarser}};
      const DesignParameters &p = results.parameters.design;
      return {{"units", "MPa, N, N m, mm"},
              {"friction_coefficient", p.friction_coefficient},
              {"friction_source", p.friction_source},
              {"joining", to_string(p.joining)},
              {"press_in_friction_coefficient",
               p.press_in_friction_coefficient},
              {"required_torque", p.required_torque},
              {"required_axial_force", p.required_axial_force},
              {"normal_force", d.normal_force},
              {"pressure_mean_fe", d.mean_pressure},
              {"pressure_din", d.pressure_din},
              {"torque_capacity", d.torque_capacity},
              {"torque_capacity_din", d.torque_capacity_din},
              {"axial_force_capacity", d.axial_force_capacity},
              {"axial_force_capacity_din", d.axial_force_capacity_din},
              {"press_in_force", d.press_in_force},
              {"press_in_force_din", d.press_in_force_din},
              {"safety_slip", d.safety_slip},
              {"safety_slip_din", d.safety_slip_din},
              {"safety_yield_shaft", d.safety_yield_shaft},
              {"safety_yield_shaft_din", d.safety_yield_shaft_din},
              {"safety_yield_hub", d.safety_yield_hub},
              {"safety_yield_hub_din", d.safety_yield_hub_din},
              {"strength_stress_shaft", d.strength_stress_shaft},
              {"strength_stress_hub", d.strength_stress_hub},
              {"safety_yield_shaft_edge", d.safety_yield_shaft_edge},
              {"safety_yield_hub_edge", d.safety_yield_hub_edge},
              {"safety_yield_shaft_assembly", d.safety_yield_shaft_assembly},
              {"safety_yield_hub_assembly", d.safety_yield_hub_assembly},
              {"edge_distance", d.edge_distance},
              {"check_points_mid_plane", checks},
              {"surface_maxima", maxima},
              {"hoop_stress_max_hub", d.hoop_stress_max_hub},
              {"hoop_stress_max_hub_din", d.hoop_stress_max_hub_din},
              {"safety_fracture_hub", d.safety_fracture_hub},
              {"safety_fracture_hub_din", d.safety_fracture_hub_din}};
    }

    Json
    state(const OperationAnalysis::State &s)
    {
      return {{"pressure_at_mid_plane", s.pressure_mid_plane},
              {"pressure_mean", s.pressure_mean},
              {"pressure_max", s.pressure_max},
              {"pressure_din", s.pressure_din},
              {"torque_capacity", s.torque_capacity},
              {"torque_capacity_din", s.torque_capacity_din},
              {"axial_force_capacity", s.axial_force_capacity},
              {"axial_force_capacity_din", s.axial_force_capacity_din},
              {"safety_slip", s.safety_slip},
              {"safety_slip_din", s.safety_slip_din},
              {"safety_yield_shaft", s.safety_yield_shaft},
              {"safety_yield_hub", s.safety_yield_hub},
              {"separated_length", s.separated_length},
              {"contact_lost", s.contact_lost},
              {"converged", s.converged},
              {"iterations", s.iterations},
              {"safety_fracture_hub", s.safety_fracture_hub}};
    }

    Json
    operation(const RunResults &results)
    {
      const OperationAnalysis   &a = results.operation;
      const OperationParameters &o = results.parameters.operation;
      // Infinite speeds (rotation never opens the joint) are null with a
      // flag, as JSON has no infinity.
      const auto speed = [](const double n) {
        return std::isinf(n) ? Json(nullptr) : Json(n);
      };
      Json j = {
        {"units", "MPa, N, N m, mm, degrees C, 1/min"},
        {"loads",
         {{"assembly_temperature", o.assembly_temperature},
          {"shaft_temperature", o.shaft_temperature()},
          {"hub_temperature", o.hub_temperature()},
          {"speed", o.speed},
          {"shaft_bore_pressure", o.shaft_bore_pressure},
          {"hub_outer_pressure", o.hub_outer_pressure},
          {"any", a.has_loads}}},
        {"assembly", state(a.assembly)},
        {"operating", state(a.operation)},
        {"loosening_speed", speed(a.loosening_speed_whole)},
        {"loosening_speed_first_point", speed(a.loosening_speed_first)},
        {"loosening_speed_din", speed(a.loosening_speed_din)},
        {"loosening_never",
         std::isinf(a.loosening_speed_whole)
           || std::isinf(a.loosening_speed_first)},
        {"loosening_check",
         {{"min_pressure_at_first_point_speed", a.min_pressure_at_first},
          {"separated_points_1_percent_below_first", a.separated_below_first},
          {"separated_points_1_percent_above_first", a.separated_above_first},
          {"max_pressure_at_whole_joint_speed", a.max_pressure_at_whole}}},
        {"loosening_note", a.loosening_note},
        {"joining",
         {{"interference_max", a.joining_interference},
          {"clearance", a.joining_clearance},
          {"hub_temperature", a.joining_temperature_hub},
          {"shaft_temperature", a.joining_temperature_shaft},
          {"shaft_cooling_expansion", a.joining_cooling_expansion},
          {"shaft_cooling_expansion_from_heating",
           std::isnan(a.joining_temperature_shaft) ?
             Json(nullptr) :
             Json(a.joining_cooling_from_heating)},
          {"shaft_cooling_reachable",
           std::isnan(a.joining_temperature_shaft) ?
             Json(nullptr) :
             Json(a.joining_cooling_reachable)},
          {"coldest_coolant", OperationAnalysis::coldest_coolant},
          {"hub_temperature_limit", a.hub_temperature_limit},
          {"hub_above_temperature_limit", a.joining_hub_above_limit}}},
        {"holds", a.holds},
        {"verdict", a.verdict}};
      // Named faces (sections from gmsh files) only when given: the keys
      // of every other run stay as they are.
      for (const auto &[name, p] : o.face_pressures())
        j["loads"]["face_pressures"][name] = p;
      return j;
    }
  } // namespace



  std::string
  SummaryWriter::write(const RunResults  &results,
                       const std::string &directory) const
  {
    const PressureSummary &ps = results.pressure;
    Json                   j;
    j["case"]       = results.parameters.case_name;
    j["converged"]  = results.solver.converged();
    j["iterations"] = results.solver.n_steps();
    j["iterations_to_paper_criterion"]
      = results.solver.steps_to_displacement_mismatch(1e-2);
    j.update(geometry_and_mesh(results));
    j.update(coupling_and_solver(results));
    j["pressure"] = {{"units", "MPa, compression positive"},
                     {"at_mid_plane", ps.at_mid_plane},
                     {"mean", ps.mean},
                     {"min", ps.min},
                     {"z_of_min", ps.z_of_min},
                     {"max", ps.max},
                     {"z_of_max", ps.z_of_max},
                     {"lame", ps.lame},
                     {"tensile", ps.min < 0.}};
    j["contact"]  = contact(results);
    // The joints, as a stack of several bodies lists them (here one).
    {
      const auto  &bodies = results.scene.bodies;
      const auto  &joint  = results.scene.joints.front();
      const Json  &c      = j["contact"];
      const double D      = 2. * results.parameters.geometry.R1;
      j["joints"]         = Json::array(
        {{{"name",
                   bodies[joint.inner].name() + "-" + bodies[joint.outer].name()},
                  {"diameter", D},
                  {"diametral_interference", 2. * results.parameters.geometry.d},
                  {"pressure",
                   {{"at_mid_plane", ps.at_mid_plane},
                    {"mean", ps.mean},
                    {"min", ps.min},
                    {"max", ps.max}}},
                  {"contact",
                   {{"closed", c["separated_points"] == 0},
                    {"length",
                     c["contact_length"].get<double>()
                       * results.parameters.geometry.mirror_factor()},
                    {"separated_points", c["separated_points"]}}},
                  {"fit", results.parameters.fit_limits.source}}});
    }
    j["design"] = design(results);
    if (results.parameters.sections && results.parameters.sections->conical())
      j["taper"] = taper(results);
    j["operation"] = operation(results);
    j["active_set"]
      = {{"changes", results.solver.get_active_set().n_changes()}};
    j["complementarity"]
      = {{"max_tension_relative", results.complementarity.max_tension_relative},
         {"max_penetration_relative",
          results.complementarity.max_penetration_relative},
         {"max_pressure_gap_relative",
          results.complementarity.max_pressure_gap_relative}};
    j["warnings"] = results.warnings;
    j["verdict"]
      = {{"ok", results.verdict.ok()}, {"failed", results.verdict.failed}};
    Json timing(results.timing);
    timing["units"] = "s";
    j["timing"]     = timing;

    const std::string name = file_names()[0];
    std::ofstream     out  = open_result_file(directory + "/" + name);
    // Non-finite numbers become null; bytes that are not UTF-8 (a file
    // name) are replaced, so the file is always valid JSON.
    out << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
    close_result_file(out, directory + "/" + name);
    return name + ": the figures of this run";
  }


  std::vector<std::string>
  SummaryWriter::file_names() const
  {
    return {"summary.json"};
  }
} // namespace coaxfit
