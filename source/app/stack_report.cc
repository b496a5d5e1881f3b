#include <coaxfit/app/stack_fit.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/io/result_writers.h>
#include <coaxfit/parameters/operation_entries.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace coaxfit
{
  namespace
  {
    /** @p x in MPa, or `not given` for 0. */
    std::string
    strength(const double x)
    {
      return x > 0. ? design_figure(x) + " MPa" : std::string("not given");
    }

    /** A safety: `-` where not judged, `infinite` without stress. */
    std::string
    safety(const double x)
    {
      return x == 0.       ? std::string("-") :
             std::isinf(x) ? std::string("infinite") :
                             design_figure(x);
    }

    /**
     * A joint's torque capacity and safety against slip as two cells of a
     * table (`-` without a friction coefficient or a required load,
     * @p judged).
     */
    std::string
    slip_cells(const JointFigures &f, const bool judged)
    {
      return (f.friction_coefficient > 0. ? design_figure(f.torque_capacity) :
                                            std::string("-"))
             + " | " + (judged ? safety(f.slip_safety) : std::string("-"));
    }
  } // namespace



  void
  StackFit::write_report(const std::string &directory,
                         const std::string &plots_note) const
  {
    const StackParameters &p    = parameters;
    const std::string      name = directory + "/report.md";
    std::ofstream          md   = open_result_file(name);
    md << "# coaxfit: " << p.case_name << "\n\nAn assembly of "
       << p.bodies.size() << " coaxial bodies (listed inside out) and its "
       << p.n_joints() << (p.n_joints() == 1 ? " joint" : " joints")
       << ", all solved at once.\n\n";
    if (verdict.ok())
      md << "Verdict: OK\n\n";
    else
      {
        md << "Verdict: FAILED\n\n";
        for (const std::string &f : verdict.failed)
          md << "- " << f << '\n';
        md << '\n';
      }
    for (const std::string &caution : cautions())
      md << "Caution: " << caution << ".\n\n";
    md << "The criteria: each joint with an interference touches; with a "
          "required torque or axial force each joint's safety against slip "
          "reaches "
       << design_figure(p.slip_safety)
       << " (Design/Slip safety); each body's safety against yield "
          "reaches "
       << design_figure(p.yield_safety)
       << " (Design/Yield safety), a brittle body's against fracture "
       << design_figure(p.fracture_safety)
       << " (Design/Fracture safety); a body without its strength is not "
          "judged.\n\n";
    if (selection)
      selection->print_markdown(md);

    if (has_loads())
      {
        md << "## Loads of operation\n\n"
           << p.operation.describe(p.bodies)
           << ". The tables below are of the service state; the state of "
              "assembly (no loads, at the assembly temperature "
           << design_figure(p.operation.assembly_temperature)
           << " C) is here, and the verdict judges both.\n\n"
              "| joint | p(0) MPa | mean MPa | min MPa | max MPa | contact | "
              "torque capacity N m | safety against slip |\n"
              "|---|---|---|---|---|---|---|---|\n";
        for (const JointFigures &f : joints_assembly)
          md << "| " << f.name << " | " << design_figure(f.p_mid) << " | "
             << design_figure(f.p_mean) << " | " << design_figure(f.p_min)
             << " | " << design_figure(f.p_max) << " | "
             << (f.closed ? std::string("closed") :
                            std::to_string(f.separated_points) + " points open")
             << " | " << slip_cells(f, p.slip_judged(&f - &joints_assembly[0]))
             << " |\n";
        for (const JointFigures &f : joints_out)
          if (!std::isnan(f.loosening_speed))
            md << "\nLoosening speed of " << f.name << ": "
               << (std::isinf(f.loosening_speed) ?
                     "it holds up to " + design_figure(loosening_limit())
                       + " 1/min" :
                     "open over its whole length from "
                       + design_figure(f.loosening_speed) + " 1/min")
               << " (the other loads as in operation).\n";
        md << "\n| body | von Mises, mid-plane MPa | hoop, mid-plane MPa | "
              "safety against yield | safety against fracture |\n"
              "|---|---|---|---|---|\n";
        for (const BodyFigures &f : bodies_assembly)
          md << "| " << f.name << " | " << design_figure(f.von_mises_mid_plane)
             << " | " << design_figure(f.hoop_mid_plane) << " | "
             << (f.brittle ? std::string("- (brittle)") :
                             safety(f.yield_safety))
             << " | " << safety(f.fracture_safety) << " |\n";
        md << '\n';
      }

    md << "## Bodies\n\n| body | bore D_i mm | outer D_a mm | length mm | "
          "material | E MPa | nu | R_e | R_m | kind |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (unsigned int b = 0; b < p.bodies.size(); ++b)
      {
        const Material &m = p.materials[b];
        md << "| " << p.bodies[b] << (p.drawn_as_section(b) ? " (section)" : "")
           << " | "
           << (p.rings[b].inner_diameter > 0. ?
                 design_figure(p.rings[b].inner_diameter) :
                 std::string("solid"))
           << " | " << design_figure(p.rings[b].outer_diameter) << " | "
           << design_figure(p.rings[b].length) << " | " << m.name << " | "
           << design_figure(m.E) << " | " << m.nu << " | "
           << strength(m.yield_strength) << " | "
           << strength(m.tensile_strength) << " | " << to_string(m.kind)
           << " |\n";
      }
    if (p.sections)
      {
        md << "\nA body drawn as a section (Geometry/<body> section) is "
              "given as the plain ring of the plane-stress estimate: from "
              "the joint inside it (the innermost body: its smallest "
              "diameter) to the joint outside it (the outermost body: its "
              "outer diameter averaged over its joint), its section's "
              "axial extent. Its sections:\n\n";
        for (unsigned int b = 0; b < p.bodies.size(); ++b)
          if (p.drawn_as_section(b))
            md << "- " << p.bodies[b] << ": `" << p.section_text[b] << "`\n";
        for (unsigned int k = 0; k + 1 < p.bodies.size(); ++k)
          if (const auto &face = p.sections->shoulder_face(k))
            md << "\n"
               << p.joint_name(k)
               << ": the sections also touch on the face across the axis at "
                  "z = "
               << number(face->z, 6) << " (D "
               << number(face->diameter_inner, 6) << " to "
               << number(face->diameter_outer, 6)
               << " mm). The joint is frictionless and nothing loads the "
                  "bodies along the axis, so the face carries no force: it "
                  "is modelled free, both bodies held axially at the "
                  "joint's end beside it.\n";
      }

    md << "\n## Joints" << (has_loads() ? " in operation" : "")
       << "\n\nPressures in MPa: in the stack (at the "
          "mid-plane, mean over the joint, least and largest nodal value), "
          "alone (the joint's two bodies with the others removed, the same "
          "meshes) and the plane-stress compound-cylinder estimates "
          "(exact for bodies of equal length with free ends; under rotation an "
          "estimate"
       << (p.sections ? "; a section is estimated as its equivalent ring "
                        "(Bodies), which its web or flanges make stiffer or "
                        "softer than it is" :
                        "")
       << ").\n\n"
          "U is the nominal diametral interference, U_w what is left "
          "after the smoothing loss 0.8 (Rz_inner + Rz_outer) of DIN "
          "7190-1, the interference the joint is solved with.\n\n"
          "| joint | D mm | U mm | from | U_w mm | p(0) | mean | min | max "
          "| contact | alone: mean | estimate | estimate alone |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (unsigned int k = 0; k < joints_out.size(); ++k)
      {
        const JointFigures &f = joints_out[k];
        md << "| " << f.name << " | " << design_figure(f.diameter) << " | "
           << f.diametral_interference << " | " << p.fits[k].source << " | "
           << f.effective_interference << " | " << design_figure(f.p_mid)
           << " | " << design_figure(f.p_mean) << " | "
           << design_figure(f.p_min) << " | " << design_figure(f.p_max) << " | "
           << (f.closed ?
                 std::string("closed") :
                 std::to_string(f.separated_points) + " of "
                   + std::to_string(stack_joints[k].n_points())
                   + " points open, diametral gap " + design_figure(f.gap_min)
                   + " to " + design_figure(f.gap_max) + " mm")
           << " | " << design_figure(f.alone_p_mean) << " | "
           << design_figure(f.lame_p) << " | " << design_figure(f.lame_alone_p)
           << " |\n";
      }
    // A joint of several pieces: where it bears and where p(0) is.
    for (unsigned int k = 0; k < joints_out.size(); ++k)
      if (!joints_out[k].pieces.empty())
        {
          const JointFigures &f = joints_out[k];
          md << "\n"
             << f.name << " bears on " << f.pieces.size()
             << " pieces of one diameter, l_F "
             << design_figure(stack_joints[k].length()) << " mm:";
          for (const auto &[from, to, mean] : f.pieces)
            md << (&from == &f.pieces[0][0] ? " z " : "; z ")
               << design_figure(from) << " to " << design_figure(to)
               << ", mean " << design_figure(mean) << " MPa";
          // The bodies whose mid-plane is this joint's: the outer one (its
          // bore joint), and the innermost for the first joint.
          md << ". Its p(0) and the mid-plane figures of "
             << (k == 0 ? p.bodies[0] + " and " : std::string())
             << p.bodies[k + 1] << " are taken at z "
             << design_figure(f.mid_plane_z) << ".\n";
        }
    // Each relief: open, by how much.
    for (unsigned int k = 0; k < joints_out.size(); ++k)
      for (unsigned int r = 0; r < joints_out[k].reliefs.size(); ++r)
        {
          const JointFigures::ReliefGap &g = joints_out[k].reliefs[r];
          md << "\n"
             << joints_out[k].name << ": the " << g.relief.name() << " from z "
             << design_figure(g.relief.from) << " to "
             << design_figure(g.relief.to) << " (drawn clearance "
             << design_figure(g.relief.clearance)
             << " mm) stays open: its least radial gap is "
             << design_figure(g.gap) << " mm at z " << design_figure(g.z);
          if (!joints_assembly.empty())
            md << " in operation, "
               << design_figure(joints_assembly[k].reliefs[r].gap)
               << " mm at z " << design_figure(joints_assembly[k].reliefs[r].z)
               << " when assembled";
          md << ".\n";
        }
    bool friction = false;
    for (const JointFigures &f : joints_out)
      friction = friction || f.friction_coefficient > 0.;
    if (friction)
      {
        md << "\n| joint | friction coefficient | axial force capacity N | "
              "torque capacity N m | safety against slip |\n"
              "|---|---|---|---|---|\n";
        for (const JointFigures &f : joints_out)
          md << "| " << f.name << " | "
             << (f.friction_coefficient > 0. ?
                   design_figure(f.friction_coefficient) + " | "
                     + number(f.axial_force_capacity, 6) :
                   std::string("not given | -"))
             << " | " << slip_cells(f, p.slip_judged(&f - &joints_out[0]))
             << " |\n";
        for (unsigned int k = 0; k < joints_out.size(); ++k)
          if (p.fits[k].friction_text == "auto")
            md << "\n"
               << p.joint_name(k) << ": friction coefficient from "
               << p.fits[k].friction_source << ".\n";
        if (p.slip_judged())
          md << "\nThe loads " << p.required_loads_text()
             << " pass through every joint (Design/Required torque, "
                "Required axial force, Application factor); a joint's "
                "safety against slip is its friction force mu p pi D l over "
                "DIN 7190's resultant of the axial and the circumferential "
                "force 2 M / D, times K_A.\n";
      }

    md << "\n## Joining (DIN 7190)\n\nEach joint's outer part heated, or "
          "its inner part cooled (the parts as in Pressing below), until "
          "the largest interference and the joining clearance "
          "(Operation/Joining clearance) are gone: a part of one body by DIN "
          "7190's alpha D, a part of several bodies at its own rate per "
          "kelvin (each body's free growth and what its joints' forces "
          "change where the bodies expand differently); from the assembly "
          "temperature "
       << design_figure(p.operation.assembly_temperature)
       << " C. Cooling below -196 C (liquid nitrogen) is not reachable.\n\n"
          "The parts joined before add to the interference: the inner "
          "part's outside has grown and the outer part's bore has closed "
          "under the joints made before (largest over the joint, at the "
          "largest interferences).\n\n"
          "| joint | U_max mm | from the parts mm | clearance mm | heat the "
          "outer part to C | or cool the inner part to C |\n"
          "|---|---|---|---|---|---|\n";
    for (const JointFigures &f : joints_out)
      md << "| " << f.name << " | " << design_figure(f.joining_interference)
         << " | " << design_figure(f.joining_growth) << " | "
         << design_figure(f.joining_clearance) << " | "
         << (std::isnan(f.heat_outer_to) ?
               std::string("no thermal expansion") :
               design_figure(f.heat_outer_to)
                 + (f.heat_above_limit ?
                      " (above " + f.heat_limit_body + "'s limit "
                        + design_figure(f.heat_limit) + ")" :
                      ""))
         << " | "
         << (std::isnan(f.cool_inner_to) ?
               std::string("no thermal expansion") :
               design_figure(f.cool_inner_to)
                 + (f.cool_inner_to <= absolute_zero ?
                      " (not reachable: below absolute zero)" :
                    !f.cool_reachable ?
                      " (not reachable)" :
                    f.cooling_from_heating ?
                      " (heating coefficient: colder in fact)" :
                      ""))
         << " |\n";
    // Neither alone: both at once.
    for (const JointFigures &f : joints_out)
      if (!std::isnan(f.both_cool_inner_to))
        md << "\n"
           << f.name
           << ": neither alone; both at once: " << part_text(f.press_outer_part)
           << " at its limit " << design_figure(f.heat_limit) << " C and "
           << part_text(f.press_inner_part) << " cooled to "
           << design_figure(f.both_cool_inner_to) << " C"
           << (f.both_cool_inner_to < OperationAnalysis::coldest_coolant ?
                 " (not reachable)" :
                 "")
           << ".\n";

    md << "\n## Pressing (Assembly/Order: " << p.order_text
       << ")\n\nEach joint pressed lengthwise at the assembly temperature: "
          "its inner part (the bodies already joined to its inner body) "
          "into its outer part. The press-in force is F = nu_e p_mean pi D "
          "l, p_mean the joint's mean pressure in the part-assembly present "
          "then (the other bodies removed, the same meshes), at the "
          "interference in use (Fit/Case "
       << p.fit_case
       << "); the estimate takes the plane-stress compound cylinders of the "
          "same part-assembly. The last column has every joint of the "
          "part-assembly at its largest interference (an ISO fit's U_max "
          "less the smoothing loss): the force the press must give.\n\n"
          "| joint | made | pressed | into | p_mean MPa | nu_e | force N | "
          "estimate N | at the largest interferences N |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (const JointFigures &f : joints_out)
      {
        md << "| " << f.name << " | " << f.press_order << " | "
           << part_text(f.press_inner_part) << " | "
           << part_text(f.press_outer_part) << " | "
           << design_figure(f.press_p_mean) << " | "
           << design_figure(f.press_in_friction_coefficient) << " | "
           << design_figure(f.press_in_force) << " | "
           << design_figure(f.press_in_force_estimate) << " | "
           << design_figure(f.press_in_force_largest) << " |\n";
      }

    md << "\n## Strength of the bodies\n\nOn the bodies' joint and free "
          "surfaces, MPa; the safeties at the mid-plane.\n\n"
          "| body | von Mises, mid-plane | von Mises, largest | hoop, "
          "mid-plane | safety against yield | safety against fracture "
          "|\n|---|---|---|---|---|---|\n";
    for (const BodyFigures &f : bodies_out)
      md << "| " << f.name << " | " << design_figure(f.von_mises_mid_plane)
         << " | " << design_figure(f.von_mises_max) << " | "
         << design_figure(f.hoop_mid_plane) << " | "
         << (f.brittle ? std::string("- (brittle)") : safety(f.yield_safety))
         << " | " << safety(f.fracture_safety) << " |\n";

    if (!surfaces_out.empty())
      {
        md << "\n## Reported surfaces\n\n| surface | D mm | u_r mean mm | "
              "min | max | change of diameter mm |\n"
              "|---|---|---|---|---|---|\n";
        for (const SurfaceFigures &s : surfaces_out)
          md << "| " << s.name << " | " << design_figure(2. * s.radius) << " | "
             << design_figure(s.u_mean) << " | " << design_figure(s.u_min)
             << " | " << design_figure(s.u_max) << " | "
             << design_figure(2. * s.u_mean) << " |\n";
      }

    md << "\n## Solution\n\n";
    unsigned int dofs = 0;
    for (const auto &b : bodies)
      dofs += b->get_dof_handler().n_dofs();
    md << dofs << " degrees of freedom in " << bodies.size() << " bodies (FE_Q("
       << p.mesh.degree << ")); ";
    if (p.method == SolverMethod::monolithic)
      md << "the contact of all joints solved monolithically on the "
            "bodies' full operators (one system, the joints' points tied), "
         << active_set_steps << " active set step(s).\n";
    else
      md << "the staggered Dirichlet-Neumann process over all joints ("
         << (p.ordering == StackOrdering::jacobi ? "Jacobi" : "Gauss-Seidel")
         << "), " << (converged ? "converged in " : "NOT converged in ")
         << steps << (converged ? " steps" : " steps (Coupling/Max steps)")
         << " (" << body_solves << " body solves), tolerance " << p.tolerance
         << ".\n";
    // The files as written (without VTU files, plots or the convergence
    // plot of a monolithic run, the list is shorter).
    std::set<std::string> files = {"report.md"};
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      files.insert(entry.path().filename().string());
    md << "\nFiles: ";
    for (const std::string &file : files)
      md << (file == *files.begin() ? "" : ", ") << file;
    md << " (summary.json holds every figure"
       << (files.count("solution.pvd") > 0 ?
             ", solution.pvd opens every body and joint in ParaView" :
             "")
       << (plots_note.rfind("plots skipped", 0) == 0 ?
             ", " + plots_note :
           files.count("plots.gp") > 0 ?
             std::string(", plots.gp redraws the plots") :
             std::string())
       << ", parameters.prm repeats the run).\n";
    close_result_file(md, name);
  }
} // namespace coaxfit
