#include <coaxfit/app/stack_fit.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

namespace coaxfit
{
  namespace
  {
    using Json = nlohmann::ordered_json;

    /** @p x, or null if it is not finite (JSON has no NaN). */
    Json
    number_or_null(const double x)
    {
      return std::isfinite(x) ? Json(x) : Json(nullptr);
    }

    /** The pressures of a joint (MPa). */
    Json
    pressure_json(const JointFigures &f)
    {
      return {{"at_mid_plane", number_or_null(f.p_mid)},
              {"mean", number_or_null(f.p_mean)},
              {"min", number_or_null(f.p_min)},
              {"max", number_or_null(f.p_max)}};
    }

    /** The contact of a joint: closed, length, open points, gaps (mm). */
    Json
    contact_json(const JointFigures &f)
    {
      return {{"closed", f.closed},
              {"length", f.contact_length},
              {"separated_points", f.separated_points},
              {"gap_min", f.gap_min},
              {"gap_max", f.gap_max}};
    }

    /**
     * The reliefs of a joint's figures @p f: each one's kind (groove, end),
     * drawing z from and to, its drawn clearance and the least radial gap
     * left (mm).
     */
    Json
    reliefs_json(const JointFigures &f)
    {
      Json reliefs = Json::array();
      for (const JointFigures::ReliefGap &g : f.reliefs)
        reliefs.push_back({{"kind", g.relief.groove ? "groove" : "end"},
                           {"z_from", g.relief.from},
                           {"z_to", g.relief.to},
                           {"clearance", g.relief.clearance},
                           {"least_gap", number_or_null(g.gap)},
                           {"least_gap_z", g.z}});
      return reliefs;
    }



    /**
     * The figures of a joint; its safety against slip with @p slip (a
     * required torque given).
     */
    Json
    joint_json(const JointFigures &f, const bool slip)
    {
      Json j;
      j["name"]                    = f.name;
      j["diameter"]                = f.diameter;
      j["diametral_interference"]  = f.diametral_interference;
      j["smoothing_loss"]          = f.smoothing_loss;
      j["effective_interference"]  = f.effective_interference;
      j["pressure"]                = pressure_json(f);
      j["pressure"]["mid_plane_z"] = f.mid_plane_z;
      if (!f.pieces.empty())
        {
          j["pieces"] = Json::array();
          for (const auto &[from, to, mean] : f.pieces)
            j["pieces"].push_back({{"z_from", from},
                                   {"z_to", to},
                                   {"length", to - from},
                                   {"mean_pressure", number_or_null(mean)}});
        }
      if (!f.reliefs.empty())
        j["reliefs"] = reliefs_json(f);
      j["contact"] = contact_json(f);
      j["alone"]   = {{"pressure",
                       {{"at_mid_plane", number_or_null(f.alone_p_mid)},
                        {"mean", number_or_null(f.alone_p_mean)}}},
                      {"staggered_steps", f.alone_steps}};
      j["joining"]
        = {{"interference_max", f.joining_interference},
           {"interference_from_parts", f.joining_growth},
           {"clearance", f.joining_clearance},
           {"heat_outer_to", number_or_null(f.heat_outer_to)},
           {"heat_above_limit", f.heat_above_limit},
           {"heat_limit", number_or_null(f.heat_limit)},
           {"both_cool_inner_to", number_or_null(f.both_cool_inner_to)},
           {"cool_inner_to", number_or_null(f.cool_inner_to)}};
      // Without the inner body's expansion nothing is known of cooling.
      j["joining"]["cool_reachable"]
        = std::isnan(f.cool_inner_to) ? Json(nullptr) : Json(f.cool_reachable);
      j["joining"]["cooling_from_heating"] = std::isnan(f.cool_inner_to) ?
                                               Json(nullptr) :
                                               Json(f.cooling_from_heating);
      j["press_in"]
        = {{"order", f.press_order},
           {"inner_part", f.press_inner_part},
           {"outer_part", f.press_outer_part},
           {"friction_coefficient", f.press_in_friction_coefficient},
           {"pressure_mean", f.press_p_mean},
           {"force", f.press_in_force},
           {"force_plane_stress", f.press_in_force_estimate},
           {"force_largest", f.press_in_force_largest}};
      if (!std::isnan(f.loosening_speed))
        j["loosening_speed"] = number_or_null(f.loosening_speed);
      j["plane_stress_estimate"]
        = {{"pressure", f.lame_p}, {"pressure_alone", f.lame_alone_p}};
      if (f.friction_coefficient > 0.)
        {
          // mu p_mean pi D l, N: the axial force capacity.
          j["design"] = {{"friction_coefficient", f.friction_coefficient},
                         {"torque_capacity", number_or_null(f.torque_capacity)},
                         {"axial_force_capacity",
                          number_or_null(f.axial_force_capacity)}};
          if (slip)
            j["design"]["slip_safety"] = f.slip_safety;
        }
      return j;
    }

    /** What the verdict and a selection judge against. */
    Json
    requirements_json(const StackParameters &p)
    {
      return {{"required_torque", p.required_torque},
              {"required_axial_force", p.required_axial_force},
              {"application_factor", p.application_factor},
              {"slip_safety", p.slip_safety},
              {"yield_safety", p.yield_safety},
              {"fracture_safety", p.fracture_safety},
              {"running_clearance", p.running_clearance}};
    }
  } // namespace



  void
  StackFit::output_selection_only(const std::string &directory) const
  {
    {
      const std::string name = directory + "/parameters.prm";
      std::ofstream     out  = open_result_file(name);
      out << parameters.used_prm;
      close_result_file(out, name);
    }
    {
      const std::string name = directory + "/fit_selection.csv";
      std::ofstream     out  = open_result_file(name);
      selection->write_csv(out);
      close_result_file(out, name);
    }
    if (parameters.write_report)
      {
        const std::string name = directory + "/report.md";
        std::ofstream     out  = open_result_file(name);
        out << "# coaxfit: " << parameters.case_name
            << "\n\nVerdict: FAILED\n\n";
        for (const std::string &f : verdict.failed)
          out << "- " << f << '\n';
        out << '\n';
        selection->print_markdown(out);
        close_result_file(out, name);
      }
    Json j;
    j["case"]              = parameters.case_name;
    j["assembly"]          = {{"bodies", parameters.bodies}};
    j["design_mode"]       = parameters.design_mode;
    j["requirements"]      = requirements_json(parameters);
    j["verdict"]           = {{"ok", verdict.ok()}, {"failed", verdict.failed}};
    j["warnings"]          = cautions();
    j["selection"]         = Json::parse(selection->json());
    const std::string name = directory + "/summary.json";
    std::ofstream     out  = open_result_file(name);
    out << j.dump(2) << '\n';
    close_result_file(out, name);
  }



  std::string
  StackFit::output_results(const std::string &directory) const
  {
    const unsigned int N = bodies.size();

    // parameters.prm: repeats the run.
    {
      const std::string name = directory + "/parameters.prm";
      std::ofstream     out  = open_result_file(name);
      out << parameters.used_prm;
      close_result_file(out, name);
    }
    if (selection)
      {
        const std::string name = directory + "/fit_selection.csv";
        std::ofstream     out  = open_result_file(name);
        selection->write_csv(out);
        close_result_file(out, name);
      }

    // contact_pressure_<joint>.csv: the lumped pressure at each point.
    for (unsigned int k = 0; k < stack_joints.size(); ++k)
      {
        const StackJoint    &joint = stack_joints[k];
        const Vector<double> p     = solution.pressure(stack_joints, k);
        const Vector<double> pa    = alone[k].pressure({joint}, 0);
        check_values_for_output(p, "contact_pressure_" + joint.name + ".csv");
        const std::string name
          = directory + "/contact_pressure_" + joint.name + ".csv";
        // With loads of operation the state of assembly follows (the
        // other columns are the service state).
        const Vector<double> p_assembly
          = has_loads() ? assembly_solution.pressure(stack_joints, k) :
                          Vector<double>();
        std::ofstream out = open_result_file(name);
        out << "z_mm,pressure_MPa,contact,pressure_alone_MPa"
            << (has_loads() ? ",pressure_assembly_MPa,contact_assembly" : "")
            << (parameters.sections ? ",z_drawing_mm" : "") << '\n';
        for (unsigned int i = 0; i < joint.n_points(); ++i)
          {
            out << joint.z[i] << ',' << p[i] << ','
                << (solution.contact[k][i] ? 1 : 0) << ',' << pa[i];
            if (has_loads())
              out << ',' << p_assembly[i] << ','
                  << (assembly_solution.contact[k][i] ? 1 : 0);
            // Sections: z of the drawing too (a half model's z is from
            // its plane of symmetry).
            if (parameters.sections)
              out << ',' << joint.z[i] + parameters.sections->drawing_offset();
            out << '\n';
          }
        close_result_file(out, name);
      }

    // convergence.csv: the residuals of every staggered step.
    {
      const std::string name = directory + "/convergence.csv";
      std::ofstream     out  = open_result_file(name);
      out << "step,displacement_residual,traction_residual\n";
      for (unsigned int s = 0; s < history.size(); ++s)
        out << s + 1 << ',' << history[s].first << ',' << history[s].second
            << '\n';
      close_result_file(out, name);
    }

    // A VTU per body and solution.pvd grouping them.
    if (parameters.write_vtu)
      {
        for (unsigned int b = 0; b < N; ++b)
          {
            const std::string file
              = Body::key_of(parameters.bodies[b]) + ".vtu";
            check_values_for_output(fields[b], file);
            // The assembled drawing: each ring larger at its outer joint
            // by that joint's interference (zero at its bore if it has a
            // joint there), so that warped bodies meet where they touch.
            double oversize = 0., offset = 0.;
            if (b + 1 < N)
              {
                const double d     = stack_joints[b].interference;
                const double r_in  = parameters.rings[b].inner_diameter / 2.;
                const double r_out = parameters.rings[b].outer_diameter / 2.;
                oversize           = b == 0 ? d / r_out : d / (r_out - r_in);
                offset             = b == 0 ? 0. : -oversize * r_in;
              }
            write_result_file(directory + "/" + file, [&](std::ostream &out) {
              bodies[b]->output_results(fields[b], out, b, oversize, offset);
            });
          }
        for (unsigned int k = 0; k + 1 < N; ++k)
          write_interface(directory, k);
        // Named blocks: a body each, then each joint's contact surface
        // (`contact_<inner>_<outer>`, lower case as the bodies' files).
        const std::string name = directory + "/solution.pvd";
        std::ofstream     out  = open_result_file(name);
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
        for (unsigned int b = 0; b < N; ++b)
          out << "<DataSet timestep=\"0\" group=\"\" part=\"" << b
              << "\" name=\"" << Body::key_of(parameters.bodies[b])
              << "\" file=\"" << Body::key_of(parameters.bodies[b])
              << ".vtu\"/>\n";
        // ParaView's block selectors take letters, digits and _ only: a
        // name that two joints (or a body) would share gets the joint's
        // number (bodies A_B, C and A, B_C).
        std::set<std::string> used;
        for (unsigned int b = 0; b < N; ++b)
          used.insert(Body::key_of(parameters.bodies[b]));
        for (unsigned int k = 0; k + 1 < N; ++k)
          {
            std::string block = "contact_" + Body::key_of(parameters.bodies[k])
                                + '_' + Body::key_of(parameters.bodies[k + 1]);
            for (unsigned int n = k + 1; used.count(block) > 0; n += N)
              block += '_' + std::to_string(n);
            used.insert(block);
            out << "<DataSet timestep=\"0\" group=\"\" part=\"" << N + k
                << "\" name=\"" << block << "\" file=\"interface_"
                << stack_joints[k].name << ".vtp\"/>\n";
          }
        out << "</Collection>\n</VTKFile>\n";
        close_result_file(out, name);
      }

    const std::string plots_note
      = parameters.write_plots ? write_plots(directory) : "";

    // summary.json, last.
    Json j;
    j["case"]         = parameters.case_name;
    j["assembly"]     = {{"bodies", parameters.bodies}};
    j["converged"]    = converged;
    j["verdict"]      = {{"ok", verdict.ok()}, {"failed", verdict.failed}};
    j["warnings"]     = cautions();
    j["design_mode"]  = parameters.design_mode;
    j["requirements"] = requirements_json(parameters);
    if (selection)
      j["selection"] = Json::parse(selection->json());
    Json method;
    method["method"] = parameters.method == SolverMethod::monolithic ?
                         "monolithic" :
                         "staggered";
    if (parameters.method == SolverMethod::staggered)
      {
        method["ordering"] = parameters.ordering == StackOrdering::jacobi ?
                               "jacobi" :
                               "gauss-seidel";
        method["accelerator"]
          = parameters.accelerator == StackAccelerator::none   ? "none" :
            parameters.accelerator == StackAccelerator::aitken ? "aitken" :
                                                                 "iqn-ils";
        method["steps"]       = steps;
        method["body_solves"] = body_solves;
        method["alpha"]       = alpha;
      }
    else
      {
        method["operators"]        = "full";
        method["active_set_steps"] = active_set_steps;
      }
    j["coupling"] = method;
    // The loads of operation: the joints' and bodies' figures are of the
    // service state, each with its state of assembly under "assembly".
    const StackOperation &o = parameters.operation;
    Json                  temperatures;
    for (unsigned int b = 0; b < N; ++b)
      temperatures[parameters.bodies[b]] = o.temperature_of(b);
    j["operation"]   = {{"loads", has_loads()},
                        {"conditions", o.describe(parameters.bodies)},
                        {"assembly_temperature", o.assembly_temperature},
                        {"temperature", temperatures},
                        {"speed", o.speed},
                        {"bore_pressure", o.bore_pressure},
                        {"outer_pressure", o.outer_pressure}};
    Json joints_json = Json::array();
    for (const JointFigures &f : joints_out)
      {
        const unsigned int k = &f - &joints_out[0];
        joints_json.push_back(joint_json(f, parameters.slip_judged(k)));
        joints_json.back()["fit"] = parameters.fits[k].source;
        if (f.friction_coefficient > 0.)
          joints_json.back()["design"]["friction_source"]
            = parameters.fits[k].friction_source;
        if (has_loads())
          {
            const JointFigures &a = joints_assembly[k];
            Json                assembly;
            assembly["pressure"] = pressure_json(a);
            assembly["contact"]  = contact_json(a);
            if (!a.reliefs.empty())
              assembly["reliefs"] = reliefs_json(a);
            if (a.friction_coefficient > 0.)
              {
                assembly["torque_capacity"] = number_or_null(a.torque_capacity);
                if (parameters.slip_judged(k))
                  assembly["slip_safety"] = a.slip_safety;
              }
            joints_json.back()["assembly"] = assembly;
          }
      }
    j["joints"] = joints_json;
    // Assembly/Order: the joints in the order they are made.
    Json order = Json::array();
    for (const unsigned int k : parameters.joining_order)
      order.push_back(parameters.joint_name(k));
    j["joining_order"] = order;
    Json bodies_json   = Json::array();
    for (const BodyFigures &f : bodies_out)
      {
        Json b = {{"name", f.name},
                  {"von_mises_mid_plane", f.von_mises_mid_plane},
                  {"von_mises_max", f.von_mises_max}};
        if (!std::isnan(f.von_mises_max_z))
          b["von_mises_max_at"]
            = {{"z", f.von_mises_max_z}, {"diameter", f.von_mises_max_d}};
        if (f.yield_strength > 0. && !f.brittle)
          {
            b["yield_strength"] = f.yield_strength;
            // null for a body without stress (infinite safety).
            b["yield_safety"] = number_or_null(f.yield_safety);
          }
        b["hoop_mid_plane"] = number_or_null(f.hoop_mid_plane);
        if (f.brittle && f.tensile_strength > 0.)
          {
            b["tensile_strength"] = f.tensile_strength;
            b["fracture_safety"]  = number_or_null(f.fracture_safety);
          }
        if (has_loads())
          {
            const BodyFigures &a = bodies_assembly[&f - &bodies_out[0]];
            b["assembly"]
              = {{"von_mises_mid_plane", a.von_mises_mid_plane},
                 {"von_mises_max", a.von_mises_max},
                 {"hoop_mid_plane", number_or_null(a.hoop_mid_plane)}};
            if (a.yield_strength > 0. && !a.brittle)
              b["assembly"]["yield_safety"] = number_or_null(a.yield_safety);
            if (a.brittle && a.tensile_strength > 0.)
              b["assembly"]["fracture_safety"]
                = number_or_null(a.fracture_safety);
          }
        bodies_json.push_back(b);
      }
    j["bodies"] = bodies_json;
    if (!surfaces_out.empty())
      {
        Json surfaces = Json::array();
        for (const SurfaceFigures &s : surfaces_out)
          surfaces.push_back(
            {{"name", s.name},
             {"diameter", 2. * s.radius},
             {"u_r", {{"mean", s.u_mean}, {"min", s.u_min}, {"max", s.u_max}}},
             {"diameter_change", 2. * s.u_mean}});
        j["surfaces"] = surfaces;
      }
    Json dofs;
    for (unsigned int b = 0; b < N; ++b)
      dofs[Body::key_of(parameters.bodies[b])]
        = bodies[b]->get_dof_handler().n_dofs();
    j["mesh"] = {{"n_dofs", dofs}, {"degree", parameters.mesh.degree}};
    // Sections: the half model (z from the plane of symmetry) or whole,
    // and what was drawn.
    if (parameters.sections)
      {
        const std::string model
          = parameters.sections->half_model() ? "half" : "whole";
        j["mesh"]["model"]   = model;
        nlohmann::json drawn = nlohmann::json::object();
        for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
          if (parameters.drawn_as_section(b))
            drawn[parameters.bodies[b]] = parameters.section_text[b];
        j["sections"]        = {{"model", model},
                                {"drawing_z_of_model_z0_mm",
                                 parameters.sections->drawing_offset()},
                                {"drawn", drawn}};
        nlohmann::json faces = nlohmann::json::array();
        for (unsigned int k = 0; k + 1 < parameters.bodies.size(); ++k)
          if (const auto &face = parameters.sections->shoulder_face(k))
            faces.push_back({{"joint", parameters.joint_name(k)},
                             {"z", face->z},
                             {"diameter_inner", face->diameter_inner},
                             {"diameter_outer", face->diameter_outer}});
        j["sections"]["shoulder_faces"] = faces;
      }
    j["timing"]            = timing;
    const std::string name = directory + "/summary.json";
    std::ofstream     out  = open_result_file(name);
    out << j.dump(2) << '\n';
    close_result_file(out, name);
    // The report last: it lists the files written.
    if (parameters.write_report)
      write_report(directory, plots_note);
    return plots_note;
  }
} // namespace coaxfit
