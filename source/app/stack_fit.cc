#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/app/stack_fit.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/coupling/stack_monolithic_solver.h>
#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/design/din7190.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/fe/body_stress.h>
#include <coaxfit/fe/stack_mesh.h>
#include <coaxfit/fe/stack_sections.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/parameters/operation_entries.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

namespace coaxfit
{
  namespace
  {
    /** A safety for the console: `infinite` without stress. */
    std::string
    safety_text(const double x)
    {
      std::ostringstream s;
      s.precision(6);
      if (std::isinf(x))
        s << "infinite";
      else
        s << x;
      return s.str();
    }

    /**
     * The joining figures of a joint in words: `joining (U_max ... +
     * clearance ... mm, DIN 7190): heat <outer> to ... or cool <inner> to
     * ...`.
     */
    std::string
    joining_text(const JointFigures &f)
    {
      // The parts as they are when the joint is made (Assembly/Order).
      const std::string inner = part_text(f.press_inner_part),
                        outer = part_text(f.press_outer_part);
      std::ostringstream s;
      s << std::setprecision(6) << "joining (U_max " << f.joining_interference
        << " mm";
      if (f.joining_growth != 0.)
        s << (f.joining_growth > 0. ? " + " : " - ")
          << std::abs(f.joining_growth) << " mm from the parts joined before";
      s << " + clearance " << f.joining_clearance << " mm, DIN 7190): ";
      if (!std::isnan(f.heat_outer_to))
        s << "heat " << outer << " to " << celsius(f.heat_outer_to)
          << (f.heat_above_limit ?
                " (above " + f.heat_limit_body + "'s temperature limit "
                  + celsius(f.heat_limit) + ")" :
                "");
      if (!std::isnan(f.heat_outer_to) && !std::isnan(f.cool_inner_to))
        s << " or ";
      if (!std::isnan(f.cool_inner_to))
        s << "cool " << inner << " to " << celsius(f.cool_inner_to)
          << (f.cool_inner_to <= absolute_zero ?
                " (not reachable: below absolute zero)" :
              !f.cool_reachable ? " (not reachable: below -196 C)" :
              f.cooling_from_heating ?
                                  " (with its heating coefficient: no "
                                  "Cooling expansion given, colder in fact)" :
                                  "");
      if (!std::isnan(f.both_cool_inner_to))
        s << "; or both: " << outer << " at " << celsius(f.heat_limit)
          << " and " << inner << " cooled to " << celsius(f.both_cool_inner_to)
          << (f.both_cool_inner_to < OperationAnalysis::coldest_coolant ?
                " (not reachable: below -196 C)" :
                "");
      return s.str();
    }

    /**
     * The press-in figures of a joint in words: `press-in force ... N
     * (made 2nd: Shaft + Sleeve into Hub, p_mean ... MPa, nu_e ...; plane
     * stress ... N)`.
     */
    std::string
    press_text(const JointFigures &f)
    {
      std::ostringstream s;
      s << std::setprecision(6) << "press-in force " << f.press_in_force
        << " N (made " << f.press_order
        << (f.press_order == 1 ? "st" :
            f.press_order == 2 ? "nd" :
            f.press_order == 3 ? "rd" :
                                 "th")
        << ": " << part_text(f.press_inner_part) << " into "
        << part_text(f.press_outer_part) << ", p_mean " << f.press_p_mean
        << " MPa, nu_e " << f.press_in_friction_coefficient << "; plane stress "
        << f.press_in_force_estimate << " N)";
      if (std::abs(f.press_in_force_largest - f.press_in_force)
          > 1e-9 * f.press_in_force_largest)
        s << ", " << f.press_in_force_largest
          << " N at the largest interferences";
      return s.str();
    }

    /** Seconds since @p start. */
    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                           - start)
        .count();
    }

    /**
     * The rings of @p parameters as their meshes are built: one axial grid
     * for all (stack_axial_spacing()), cut at each ring's half length, the
     * radial cells graded towards the joint of the innermost and the
     * outermost ring, equal in a ring with two joints.
     */
    std::vector<StackRing>
    stack_rings(const StackParameters &parameters)
    {
      const unsigned int  N = parameters.bodies.size();
      std::vector<double> half_lengths, ends;
      for (unsigned int b = 0; b < N; ++b)
        half_lengths.push_back(parameters.rings[b].length / 2.);
      for (unsigned int k = 0; k + 1 < N; ++k)
        ends.push_back(std::min(half_lengths[k], half_lengths[k + 1]));
      const std::vector<double> axial
        = stack_axial_spacing(half_lengths,
                              ends,
                              parameters.mesh.axial_cells,
                              parameters.mesh.grading_ratio);
      std::vector<StackRing> rings;
      for (unsigned int b = 0; b < N; ++b)
        {
          StackRing ring;
          ring.r_inner     = parameters.rings[b].inner_diameter / 2.;
          ring.r_outer     = parameters.rings[b].outer_diameter / 2.;
          ring.half_length = half_lengths[b];
          double z         = 0.;
          for (unsigned int i = 0;
               i < axial.size() && z < half_lengths[b] * (1. - 1e-9);
               ++i)
            {
              ring.axial.push_back(axial[i]);
              z += axial[i];
            }
          const bool two_joints = b > 0 && b + 1 < N;
          ring.radial
            = graded_spacing(ring.r_outer - ring.r_inner,
                             parameters.mesh.radial_cells,
                             two_joints ? 1. : parameters.mesh.grading_ratio,
                             b + 1 < N);
          ring.inner_contact      = b > 0 ? ends[b - 1] : 0.;
          ring.outer_contact      = b + 1 < N ? ends[b] : 0.;
          ring.global_refinements = parameters.mesh.global_refinements;
          rings.push_back(ring);
        }
      return rings;
    }

    /**
     * Refuse a stack whose matrices, factors and dense compliances would
     * not fit into the available memory, before any mesh is built.
     */
    void
    check_stack_memory(const StackParameters &parameters)
    {
      double       needed = 0., points = 0.;
      const double refined = std::pow(2., parameters.mesh.global_refinements);
      const unsigned int p = parameters.mesh.degree;
      if (parameters.sections)
        {
          // Graded cells of about 4 times the cell size on average; the
          // joints' points at the finest size (both estimates generous).
          const StackSections &sections = *parameters.sections;
          double               h        = parameters.mesh.cell_size;
          if (h == 0.)
            {
              h = std::numeric_limits<double>::infinity();
              for (unsigned int k = 0; k < parameters.n_joints(); ++k)
                h = std::min(h, sections.joint_half_length(k) / 50.);
            }
          for (unsigned int b = 0; b < sections.n_bodies(); ++b)
            {
              // A gmsh file's own cells, refined alike (and once more if
              // the outlines' cells are split: counted).
              const double cells
                = sections.from_file(b) ?
                    4. * sections.file_cells(b) * refined * refined :
                    sections.modelled(b).area() / (16. * h * h) * refined
                      * refined;
              double n_points = 0.;
              for (const unsigned int k : {b - 1, b})
                if (k < parameters.n_joints())
                  n_points += p * (sections.half_model() ? 1. : 2.)
                                * sections.joint_half_length(k) / h * refined
                              + 1.;
              needed += estimated_memory(static_cast<std::size_t>(
                                           std::min(2. * p * p * cells, 1e15)),
                                         p)
                        + 3. * 8. * n_points * n_points;
              points += n_points;
            }
        }
      else
        for (const StackRing &ring : stack_rings(parameters))
          {
            const double n_r = p * ring.radial.size() * refined + 1.;
            const double n_z = p * ring.axial.size() * refined + 1.;
            const double n_points
              = n_z * ((ring.inner_contact > 0.) + (ring.outer_contact > 0.));
            needed += estimated_memory(static_cast<std::size_t>(
                                         std::min(2. * n_r * n_z, 1e15)),
                                       p)
                      + 3. * 8. * n_points * n_points;
            points += n_points;
          }
      needed += 2. * 8. * points * points; // the monolithic matrix
      const double available = available_memory();
      if (needed > available)
        throw InputError("parameter Mesh/Global refinements = "
                         + std::to_string(parameters.mesh.global_refinements)
                         + ": the " + std::to_string(parameters.bodies.size())
                         + " bodies need about "
                         + std::to_string(static_cast<long>(needed / 1e9 + 0.5))
                         + " GB of memory, more than the "
                         + std::to_string(static_cast<long>(available / 1e9))
                         + " GB available; use fewer Global refinements or "
                         + (parameters.sections ? "a larger Mesh/Cell size" :
                                                  "Axial/Radial cells"));
    }
  } // namespace



  StackFit::StackFit(const StackParameters &parameters)
    : parameters(parameters)
  {}



  void
  StackFit::setup_system()
  {
    const auto                   start = std::chrono::steady_clock::now();
    const unsigned int           N     = parameters.bodies.size();
    const std::vector<StackRing> rings = stack_rings(parameters);
    // Sections: every body meshed by gmsh at once (the two bodies of a
    // joint with its vertices), each body's mesh copied from its own.
    std::vector<std::shared_ptr<Triangulation<2>>> section_meshes;
    if (parameters.sections)
      section_meshes = parameters.sections->make_meshes(section_settings());
    for (unsigned int b = 0; b < N; ++b)
      {
        const StackRing ring = rings[b];
        BodyGeometry    g;
        g.r_inner                 = ring.r_inner;
        g.r_outer                 = ring.r_outer;
        g.length                  = ring.half_length;
        g.contact_at_outer_radius = b + 1 < N;
        g.inner_joint             = b > 0 && b + 1 < N;
        // The loads of operation: the body's thermal strain, the rotation,
        // the pressure on the free bore of the innermost body and on the
        // outside of the outermost.
        const StackOperation &o = parameters.operation;
        BodyLoad              load;
        load.thermal_strain = parameters.materials[b].thermal_expansion
                              * (o.temperature_of(b) - o.assembly_temperature);
        load.omega_squared  = o.omega_squared();
        load.inner_pressure = b == 0 ? o.bore_pressure : 0.;
        load.outer_pressure = b + 1 == N ? o.outer_pressure : 0.;
        bodies.push_back(
          std::make_unique<BodyDiscretization>(parameters.bodies[b],
                                               g,
                                               parameters.materials[b],
                                               parameters.mesh.degree,
                                               false,
                                               load));
        if (parameters.sections)
          {
            bodies.back()->set_mesh_builder(
              [mesh = section_meshes[b]](Triangulation<2> &t) {
                t.copy_triangulation(*mesh);
              });
            // A body beside a shoulder face is held axially at its joint's
            // end there (the reaction is zero either way), so that the
            // face's two sides stay together in the output.
            if (const std::optional<double> z
                = parameters.sections->axial_pin_z(b))
              bodies.back()->set_axial_pin_z(*z);
          }
        else
          bodies.back()->set_mesh_builder(
            [ring](Triangulation<2> &t) { make_stack_ring_mesh(t, ring); });
        bodies.back()->setup_system();
        bodies.back()->assemble_system();
        solvers.push_back(std::make_unique<BodySolver>(*bodies.back()));
        condensed.push_back(std::make_unique<CondensedBody>(*solvers.back()));
      }

    // Each joint's points: the inner body's outer surface, which must be
    // the outer body's bore point by point (one axial grid for all).
    stack_joints.clear();
    for (unsigned int k = 0; k + 1 < N; ++k)
      {
        const BodyDiscretization &in = *bodies[k], &out = *bodies[k + 1];
        StackJoint                joint;
        joint.name         = parameters.joint_name(k);
        joint.interference = parameters.fits[k].diametral_interference / 2.;
        joint.whole = parameters.sections && !parameters.sections->half_model();
        if (parameters.sections)
          joint.pieces = parameters.sections->joint_pieces(k);
        const unsigned int n      = out.n_inner_interface_points() > 0 ?
                                      out.n_inner_interface_points() :
                                      out.n_interface_points();
        const unsigned int at_in  = in.n_inner_interface_points();
        const unsigned int at_out = 0;
        if (in.n_interface_points() - at_in != n)
          throw std::logic_error("the meshes of " + joint.name
                                 + " do not share their joint points");
        joint.weights.reinit(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double z_in  = in.interface_z()[at_in + i];
            const double z_out = out.interface_z()[at_out + i];
            if (std::abs(z_in - z_out) > 1e-9 * parameters.rings[0].length)
              throw std::logic_error("the meshes of " + joint.name
                                     + " do not share their joint points");
            joint.z.push_back(z_in);
            joint.weights[i] = in.interface_weights()[at_in + i];
          }
        stack_joints.push_back(joint);
      }

    // Each body's own answer to its loads, and how far it moves the sides
    // of each joint apart.
    load_fields.clear();
    if (has_loads())
      {
        const StackLayout           layout(stack_joints);
        std::vector<Vector<double>> u_load;
        for (unsigned int b = 0; b < N; ++b)
          {
            load_fields.push_back(solvers[b]->solve_load_field(
              bodies[b]->assemble_load_vector(bodies[b]->load())));
            u_load.push_back(
              bodies[b]->interface_radial_values(load_fields.back()));
          }
        for (unsigned int k = 0; k + 1 < N; ++k)
          {
            StackJoint &joint = stack_joints[k];
            joint.load_shift.reinit(joint.n_points());
            for (unsigned int i = 0; i < joint.n_points(); ++i)
              joint.load_shift[i] = u_load[k + 1][layout.offset(k + 1, k) + i]
                                    - u_load[k][layout.offset(k, k) + i];
          }
        // With a speed, the part of the shift that rotation causes per
        // (rad/s)^2, for the loosening speeds.
        rotation_shift.clear();
        if (parameters.operation.speed > 0.)
          {
            std::vector<Vector<double>> u_unit;
            for (unsigned int b = 0; b < N; ++b)
              {
                BodyLoad unit;
                unit.omega_squared = 1.;
                u_unit.push_back(bodies[b]->interface_radial_values(
                  solvers[b]->solve_load_field(
                    bodies[b]->assemble_load_vector(unit))));
              }
            for (unsigned int k = 0; k + 1 < N; ++k)
              {
                rotation_shift.emplace_back(stack_joints[k].n_points());
                for (unsigned int i = 0; i < stack_joints[k].n_points(); ++i)
                  rotation_shift[k][i]
                    = u_unit[k + 1][layout.offset(k + 1, k) + i]
                      - u_unit[k][layout.offset(k, k) + i];
              }
          }
      }

    // Each joint's Winkler alpha k_o / (k_i + k_o) from the mean diagonal
    // compliances of its sides (the outer side's traction weight).
    alpha.clear();
    for (unsigned int k = 0; k + 1 < N; ++k)
      {
        if (parameters.alpha > 0.)
          {
            alpha.push_back(parameters.alpha);
            continue;
          }
        const FullMatrix<double> &C_in  = compliance(k),
                                 &C_out = compliance(k + 1);
        const unsigned int at_in        = bodies[k]->n_inner_interface_points();
        double             k_in = 0., k_out = 0.;
        for (unsigned int i = 0; i < stack_joints[k].n_points(); ++i)
          {
            k_in += std::abs(C_in(at_in + i, at_in + i));
            k_out += std::abs(C_out(i, i));
          }
        alpha.push_back(k_out / (k_in + k_out));
      }
    timing["setup"] = seconds_since(start);
  }



  std::vector<std::string>
  StackFit::cautions() const
  {
    std::vector<std::string> list = parameters.warnings();
    // A section's largest stress on its surfaces (a fillet, a corner)
    // above its yield strength, in either state.
    for (const auto *state : {&bodies_out, &bodies_assembly})
      for (const BodyFigures &f : *state)
        if (!std::isnan(f.von_mises_max_z) && !f.brittle
            && f.yield_strength > 0. && f.von_mises_max > f.yield_strength)
          {
            std::ostringstream s;
            s << std::setprecision(4) << f.name << " yields locally"
              << (state == &bodies_assembly ? " in the state of assembly" : "")
              << ": von Mises " << f.von_mises_max << " MPa at z "
              << f.von_mises_max_z << ", D " << f.von_mises_max_d
              << " mm on its surfaces (a fillet or corner) exceeds R_e "
              << f.yield_strength
              << " MPa; the yield safety judges the mid-plane as DIN 7190 "
                 "does, and at a sharp corner the value grows under "
                 "refinement";
            list.push_back(s.str());
          }
    // A shrink fit whose outer part would be heated above its limit (as
    // for two bodies): what else joins it.
    const bool shrink
      = parameters.joining == JoiningMethod::shrink
        || parameters.joining == JoiningMethod::shrink_degreased;
    for (const JointFigures &f : joints_out)
      if (shrink && f.heat_above_limit)
        {
          const std::string inner = part_text(f.press_inner_part),
                            outer = part_text(f.press_outer_part);
          std::string alternative;
          if (std::isnan(f.cool_inner_to))
            alternative = "join by pressing or with a smaller interference";
          else if (f.cool_reachable)
            alternative = "cooling " + inner + " to " + celsius(f.cool_inner_to)
                          + " instead avoids it";
          else if (f.both_cool_inner_to >= OperationAnalysis::coldest_coolant)
            alternative = "cooling " + inner + " alone is not reachable ("
                          + celsius(f.cool_inner_to)
                          + "); both at once do: " + outer + " at "
                          + celsius(f.heat_limit) + " and " + inner
                          + " cooled to " + celsius(f.both_cool_inner_to);
          else
            alternative = "neither cooling " + inner
                          + " alone nor both at once reach it (below -196 C): "
                            "press the parts together or reduce the "
                            "interference";
          list.push_back("joining " + f.name + ": heating " + outer + " to "
                         + celsius(f.heat_outer_to) + " exceeds "
                         + f.heat_limit_body + "'s temperature limit "
                         + celsius(f.heat_limit) + "; " + alternative);
        }
    return list;
  }



  SectionMeshSettings
  StackFit::section_settings() const
  {
    SectionMeshSettings settings;
    double              l_min = std::numeric_limits<double>::infinity();
    for (unsigned int k = 0; k < parameters.n_joints(); ++k)
      l_min = std::min(l_min, 2. * parameters.sections->joint_half_length(k));
    settings.cell_size          = parameters.mesh.cell_size > 0. ?
                                    parameters.mesh.cell_size :
                                    l_min / 100.;
    settings.grading_ratio      = parameters.mesh.grading_ratio;
    settings.global_refinements = parameters.mesh.global_refinements;
    return settings;
  }



  double
  StackFit::surface_radius(const unsigned int b, const bool bore) const
  {
    if (!parameters.drawn_as_section(b))
      return (bore ? parameters.rings[b].inner_diameter :
                     parameters.rings[b].outer_diameter)
             / 2.;
    return bore ? parameters.sections->bore_radius(b) :
                  parameters.sections->outer_radius(b);
  }



  bool
  StackFit::solve(std::ostream *progress)
  {
    const auto start = std::chrono::steady_clock::now();
    if (parameters.method == SolverMethod::monolithic)
      {
        // The reference on the full operators, independent of the
        // condensation the staggered process works on.
        std::vector<const BodyDiscretization *> discretizations;
        for (const auto &b : bodies)
          discretizations.push_back(b.get());
        StackMonolithicSolver monolithic(discretizations,
                                         stack_joints,
                                         parameters.unilateral);
        solution  = monolithic.solve(active_set_steps);
        converged = true;
        steps     = 0;
        if (progress)
          *progress << "  monolithic on the full operators: "
                    << active_set_steps << " active set"
                    << (active_set_steps == 1 ? "" : "s")
                    << ", traction mismatch "
                    << number(monolithic.traction_mismatch(), 3) << '\n';
      }
    else
      {
        std::vector<InterfaceOperator *> ops;
        for (const auto &c : condensed)
          ops.push_back(c.get());
        StackCoupling coupling(ops, stack_joints, parameters, alpha);
        converged   = coupling.run(progress);
        solution    = coupling.state();
        steps       = coupling.n_steps();
        body_solves = coupling.n_body_solves();
        history     = coupling.history();
      }
    timing["coupling"] = seconds_since(start);
    return converged;
  }



  SurfaceFigures
  StackFit::surface(const std::string &name) const
  {
    unsigned int b = 0;
    while (name != parameters.bodies[b] + " bore"
           && name != parameters.bodies[b] + " outer")
      ++b;
    const bool                bore = name == parameters.bodies[b] + " bore";
    const double              R    = surface_radius(b, bore);
    const BodyDiscretization &body = *bodies[b];
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         body.get_dof_handler(),
                                         points);
    std::vector<std::pair<double, double>> by_z; // (z, u_r)
    const auto                            &fe = body.get_dof_handler().get_fe();
    std::vector<types::global_dof_index>   dofs(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>      seen;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (fe.system_to_component_index(i).first == 0
              && std::abs(points[dofs[i]][0] - R) < 1e-9 * R
              && seen.insert(dofs[i]).second)
            by_z.emplace_back(points[dofs[i]][1], fields[b][dofs[i]]);
      }
    std::sort(by_z.begin(), by_z.end());
    SurfaceFigures s;
    s.name   = name;
    s.radius = R;
    s.u_min = s.u_max = by_z.front().second;
    double integral   = 0.;
    for (unsigned int i = 0; i < by_z.size(); ++i)
      {
        s.u_min = std::min(s.u_min, by_z[i].second);
        s.u_max = std::max(s.u_max, by_z[i].second);
        if (i > 0)
          integral += 0.5 * (by_z[i].second + by_z[i - 1].second)
                      * (by_z[i].first - by_z[i - 1].first);
      }
    const double length = by_z.back().first - by_z.front().first;
    s.u_mean            = length > 0. ? integral / length : s.u_min;
    return s;
  }



  std::vector<Vector<double>>
  StackFit::body_fields(const StackState &state, const bool loaded) const
  {
    const StackLayout           layout(stack_joints);
    std::vector<Vector<double>> result;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const unsigned int n = layout.n_points(b);
        Vector<double>     force(n);
        for (const unsigned int k : {b - 1, b})
          if (k < stack_joints.size())
            for (unsigned int i = 0; i < stack_joints[k].n_points(); ++i)
              force[layout.offset(b, k) + i] = state.force[k][i];
        result.push_back(solvers[b]->solve_field(std::vector<bool>(n, false),
                                                 Vector<double>(n),
                                                 force));
        if (loaded && !load_fields.empty())
          result.back() += load_fields[b];
      }
    return result;
  }



  JointFigures
  StackFit::joint_state(const unsigned int                 k,
                        const StackState                  &state,
                        const std::vector<Vector<double>> &state_fields) const
  {
    const StackLayout layout(stack_joints);
    const StackJoint &joint = stack_joints[k];
    JointFigures      f{};
    f.name                   = joint.name;
    f.diameter               = parameters.joint_diameter(k);
    f.diametral_interference = parameters.fits[k].nominal_interference;
    f.smoothing_loss         = parameters.fits[k].smoothing_loss;
    f.effective_interference = parameters.fits[k].diametral_interference;
    const Vector<double> p   = state.pressure(stack_joints, k);
    f.p_mid                  = p[joint.middle()];
    f.p_min                  = *std::min_element(p.begin(), p.end());
    f.p_max                  = *std::max_element(p.begin(), p.end());
    f.p_mean = state.force[k].mean_value() * state.force[k].size()
               / (joint.weights.mean_value() * joint.weights.size());
    f.separated_points
      = std::count(state.contact[k].begin(), state.contact[k].end(), false);
    f.closed = f.separated_points == 0;
    // The length in contact: each stretch between neighbouring points
    // counts whole if both touch, half if one does (the whole joint's:
    // twice the half model's), a relief groove not.
    double in_contact = 0.;
    for (unsigned int i = 0; i + 1 < joint.n_points(); ++i)
      in_contact += joint.bearing(i) ?
                      0.5 * (state.contact[k][i] + state.contact[k][i + 1])
                        * (joint.z[i + 1] - joint.z[i]) :
                      0.;
    f.contact_length = (joint.whole ? 1. : 2.) * in_contact;
    const double offset
      = parameters.sections ? parameters.sections->drawing_offset() : 0.;
    f.mid_plane_z = joint.middle_z() + offset;
    // Each piece's mean: its points' forces over their weights (a half
    // model's piece before the plane its mirror's).
    if (parameters.sections
        && parameters.sections->joint_drawn_pieces(k).size() > 1)
      for (const auto &[lo, hi] : parameters.sections->joint_drawn_pieces(k))
        {
          double a = lo - offset, b = hi - offset;
          if (!joint.whole && b <= 0.)
            std::tie(a, b) = std::make_pair(-b, -a);
          const double tol   = 1e-9 * (b - a);
          double       force = 0., weight = 0.;
          for (unsigned int i = 0; i < joint.n_points(); ++i)
            if (joint.z[i] >= a - tol && joint.z[i] <= b + tol)
              {
                force += state.force[k][i];
                weight += joint.weights[i];
              }
          f.pieces.push_back({{lo, hi, force / weight}});
        }
    f.reliefs = relief_gaps(k, state_fields);
    // The gap of each point from the bodies' own displacements (the loads'
    // answers included).
    const std::vector<double> gaps
      = joint_gaps(k, joint.interference, state_fields);
    f.gap_min = std::numeric_limits<double>::max();
    f.gap_max = 0.;
    for (unsigned int i = 0; i < joint.n_points(); ++i)
      {
        const double gap = state.contact[k][i] ? 0. : gaps[i];
        f.gap_min        = std::min(f.gap_min, gap);
        f.gap_max        = std::max(f.gap_max, gap);
      }
    f.friction_coefficient = parameters.fits[k].friction_coefficient;
    // T = nu p_mean pi D^2 l / 2 (N mm) over the joint's length l, in N m.
    f.torque_capacity = f.friction_coefficient * f.p_mean * M_PI * f.diameter
                        * f.diameter * joint.length() / 2. / 1000.;
    f.axial_force_capacity = 2000. * f.torque_capacity / f.diameter;
    // Against DIN 7190's resultant of both loads (as a torque at D).
    f.slip_judged = parameters.slip_judged(k);
    f.slip_safety
      = parameters.slip_judged(k) ?
          f.torque_capacity / parameters.required_torque_at(f.diameter) :
          0.;
    return f;
  }



  std::vector<double>
  StackFit::check_radii(const unsigned int b) const
  {
    // A ring's bore and outside; a section's joints (its equivalent
    // ring's diameters) and its smallest and largest radius.
    std::set<double> radii = {parameters.rings[b].inner_diameter / 2.,
                              parameters.rings[b].outer_diameter / 2.};
    if (parameters.sections)
      radii.insert({surface_radius(b, true), surface_radius(b, false)});
    radii.erase(0.);
    return std::vector<double>(radii.begin(), radii.end());
  }



  std::vector<StressState>
  StackFit::mid_plane_stresses(
    const unsigned int                           b,
    const std::vector<std::vector<StressState>> &along) const
  {
    // The mid-plane: z = 0 of a half model; of a whole one, the plane
    // through the middle of the body's bore joint (the innermost body's:
    // its outer joint); of a joint of several pieces, through the middle
    // of its main seat (StackJoint::middle_z()); on each radius its
    // nearest nodes. A section's surface that does not run through that
    // plane (a groove there, or its corner on it) has no mid-plane value.
    const StackJoint         &own   = stack_joints[b > 0 ? b - 1 : 0];
    const double              z_mid = own.middle_z();
    const std::vector<double> radii = check_radii(b);
    std::vector<StressState>  result;
    for (unsigned int i = 0; i < along.size(); ++i)
      {
        const std::vector<StressState> &states = along[i];
        if (parameters.sections
            && !parameters.sections->surface_through(b, radii[i], z_mid))
          continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (const StressState &s : states)
          nearest = std::min(nearest, std::abs(s.z - z_mid));
        for (const StressState &s : states)
          if (std::abs(s.z - z_mid) <= nearest)
            result.push_back(s);
      }
    return result;
  }



  std::vector<std::vector<StressState>>
  StackFit::stresses_along_radii(const unsigned int    b,
                                 const Vector<double> &field) const
  {
    std::vector<std::vector<StressState>> along;
    for (const double r : check_radii(b))
      along.push_back(stresses_along_radius(*bodies[b], field, r));
    return along;
  }



  std::vector<std::vector<std::pair<double, double>>>
  StackFit::relief_plane_gaps(
    const unsigned int                 k,
    const double                       interference,
    const std::vector<Vector<double>> &state_fields) const
  {
    std::vector<std::vector<std::pair<double, double>>> result;
    if (!parameters.sections)
      return result;
    const StackSections &sections = *parameters.sections;
    const bool           whole    = stack_joints[k].whole;
    const double         offset   = sections.drawing_offset();
    for (const JointRelief &relief : sections.joint_reliefs(k))
      {
        result.emplace_back();
        // 41 planes where it is judged, as its drawn clearance.
        for (unsigned int s = 0; s <= 40; ++s)
          {
            const double z
              = relief.judged_from
                + s / 40. * (relief.judged_to - relief.judged_from);
            const auto [outside, bore] = sections.relief_radii(k, z);
            if (outside < 0. || !std::isfinite(bore))
              continue;
            // A half model holds the mirror image of z < 0.
            const double z_model = whole ? z - offset : std::abs(z - offset);
            result.back().emplace_back(
              z,
              bore - outside - interference
                + displacement_at(*bodies[k + 1],
                                  state_fields[k + 1],
                                  Point<2>(bore, z_model))[0]
                - displacement_at(*bodies[k],
                                  state_fields[k],
                                  Point<2>(outside, z_model))[0]);
          }
      }
    return result;
  }



  std::vector<JointFigures::ReliefGap>
  StackFit::relief_gaps(const unsigned int                 k,
                        const std::vector<Vector<double>> &state_fields) const
  {
    std::vector<JointFigures::ReliefGap> result;
    const auto                           planes
      = relief_plane_gaps(k, stack_joints[k].interference, state_fields);
    for (unsigned int r = 0; r < planes.size(); ++r)
      {
        // None of its planes has both surfaces (a sliver between the 201
        // planes of its clearance): nothing to judge.
        if (planes[r].empty())
          continue;
        const JointRelief &relief = parameters.sections->joint_reliefs(k)[r];
        JointFigures::ReliefGap g{relief,
                                  std::numeric_limits<double>::max(),
                                  relief.judged_from};
        for (const auto &[z, gap] : planes[r])
          if (gap < g.gap)
            {
              g.gap = gap;
              g.z   = z;
            }
        result.push_back(g);
      }
    return result;
  }



  std::vector<double>
  StackFit::joint_gaps(const unsigned int                 k,
                       const double                       interference,
                       const std::vector<Vector<double>> &state_fields) const
  {
    const StackLayout    layout(stack_joints);
    const Vector<double> u_in
      = bodies[k]->interface_radial_values(state_fields[k]);
    const Vector<double> u_out
      = bodies[k + 1]->interface_radial_values(state_fields[k + 1]);
    std::vector<double> gaps;
    for (unsigned int i = 0; i < stack_joints[k].n_points(); ++i)
      gaps.push_back(2.
                     * (u_out[layout.offset(k + 1, k) + i]
                        - u_in[layout.offset(k, k) + i] - interference));
    return gaps;
  }



  std::vector<StackStateFigures>
  StackFit::evaluate(const std::vector<double> &U)
  {
    std::vector<FullMatrix<double>> C;
    for (const auto &c : condensed)
      C.push_back(c->get_compliance());
    std::vector<StackStateFigures> result;
    const std::vector<double>      radial = radial_interferences(U);
    for (const bool loaded : {false, true})
      {
        if (loaded && !has_loads())
          break;
        std::vector<StackJoint> joints = stack_joints;
        for (unsigned int k = 0; k < joints.size(); ++k)
          {
            joints[k].interference = radial[k];
            if (!loaded)
              joints[k].load_shift.reinit(0);
          }
        unsigned int     set_steps = 0;
        const StackState state
          = solve_stack_contact(C, joints, parameters.unilateral, set_steps);
        for (const Vector<double> &force : state.force)
          for (const double f : force)
            if (!std::isfinite(f))
              throw std::runtime_error(
                "the fit selection's contact problem gave forces that are "
                "not finite");
        const std::vector<Vector<double>> field = body_fields(state, loaded);
        StackStateFigures                 figures;
        figures.state = loaded ? "in service" : "at assembly";
        for (unsigned int k = 0; k < joints.size(); ++k)
          {
            const JointFigures f = joint_state(k, state, field);
            figures.torque.push_back(parameters.fits[k].friction_coefficient
                                     * f.p_mean * M_PI * f.diameter * f.diameter
                                     * joints[k].length() / 2. / 1000.);
            figures.p_mean.push_back(f.p_mean);

            // The diametral gap at each point (about 0 in contact).
            figures.gap.push_back(joint_gaps(k, joints[k].interference, field));
            // What the parts joined before add to the joint's
            // interference (the state of assembly).
            if (!loaded)
              {
                const Vector<double> growth = joining_growth(k, radial);
                figures.joining_growth.emplace_back(growth.begin(),
                                                    growth.end());
              }
            // Each relief's gap over its drawn clearance at its planes.
            figures.relief_gap.emplace_back();
            const auto planes
              = relief_plane_gaps(k, joints[k].interference, field);
            for (unsigned int r = 0; r < planes.size(); ++r)
              for (const auto &plane : planes[r])
                figures.relief_gap.back().push_back(
                  plane.second
                  / parameters.sections->joint_reliefs(k)[r].clearance);
          }
        for (unsigned int b = 0; b < bodies.size(); ++b)
          {
            // The state of assembly without the bodies' thermal strain.
            const BodyLoad load = bodies[b]->load();
            if (!loaded)
              bodies[b]->set_load(BodyLoad());
            std::vector<Axisymmetric::Vector4> stress;
            for (const StressState &s :
                 mid_plane_stresses(b, stresses_along_radii(b, field[b])))
              stress.push_back(s.sigma);
            bodies[b]->set_load(load);
            figures.stress.push_back(stress);
          }
        result.push_back(figures);
      }
    return result;
  }



  void
  StackFit::select_fits(std::ostream &out)
  {
    // How far joint k's parts open it at the measured interferences U.
    const auto reach
      = [this](const unsigned int k, const std::vector<double> &U) {
          return joining_reach(k, radial_interferences(U));
        };
    auto chosen = std::make_shared<StackFitSelection>(
      parameters,
      [this](const std::vector<double> &U) { return evaluate(U); },
      reach);
    chosen->print(out);
    if (chosen->found())
      for (unsigned int j = 0; j < chosen->selected.size(); ++j)
        if (!chosen->kept[j])
          {
            const unsigned int k = chosen->selected[j];
            parameters.use_iso_fit(k, chosen->chosen[j]);
            stack_joints[k].interference
              = parameters.fits[k].diametral_interference / 2.;
          }
    selection = chosen;
  }



  BodyFigures
  StackFit::body_strength(const unsigned int    b,
                          const Vector<double> &field) const
  {
    BodyFigures f;
    f.name                = parameters.bodies[b];
    f.von_mises_mid_plane = f.von_mises_max = 0.;
    f.hoop_mid_plane = -std::numeric_limits<double>::infinity();
    const std::vector<std::vector<StressState>> along
      = stresses_along_radii(b, field);
    for (const std::vector<StressState> &states : along)
      for (const StressState &s : states)
        f.von_mises_max = std::max(f.von_mises_max, s.von_mises());
    for (const StressState &s : mid_plane_stresses(b, along))
      {
        f.von_mises_mid_plane = std::max(f.von_mises_mid_plane, s.von_mises());
        f.hoop_mid_plane      = std::max(f.hoop_mid_plane, s.hoop());
      }
    // A section's largest stress may lie anywhere on its surfaces (a
    // fillet of its web).
    if (parameters.drawn_as_section(b))
      for (const StressState &s :
           stresses_on_faces(*bodies[b],
                             field,
                             [](const DoFHandler<2>::active_cell_iterator &cell,
                                const unsigned int                         f) {
                               // Its surfaces: not the axis, not the
                               // plane of symmetry.
                               const auto face = cell->face(f);
                               return face->at_boundary()
                                      && face->boundary_id() != BoundaryId::axis
                                      && face->boundary_id()
                                           != BoundaryId::symmetry;
                             }))
        if (s.von_mises() >= f.von_mises_max)
          {
            f.von_mises_max = s.von_mises();
            // Drawing z, a vertex's round-off (1e-10 of a gmsh mesh) gone.
            const double z = s.z + parameters.sections->drawing_offset();
            f.von_mises_max_z
              = std::abs(z) < 1e-9 * parameters.sections->extent() ? 0. : z;
            f.von_mises_max_d = 2. * s.r;
          }
    f.brittle          = parameters.materials[b].kind == MaterialKind::brittle;
    f.tensile_strength = parameters.materials[b].tensile_strength;
    f.fracture_safety
      = !f.brittle || f.tensile_strength <= 0. ? 0. :
        f.hoop_mid_plane > 0. ? f.tensile_strength / f.hoop_mid_plane :
                                std::numeric_limits<double>::infinity();
    f.yield_strength = parameters.materials[b].yield_strength;
    // A body without stress never yields: its safety is infinite.
    f.yield_safety
      = f.yield_strength <= 0. || f.brittle ? 0. :
        f.von_mises_mid_plane > 0. ? f.yield_strength / f.von_mises_mid_plane :
                                     std::numeric_limits<double>::infinity();
    return f;
  }



  StackState
  StackFit::state_at_speed(const std::vector<FullMatrix<double>> &C,
                           const double omega_squared) const
  {
    const double omega_squared_operation = parameters.operation.omega_squared();
    std::vector<StackJoint> joints       = stack_joints;
    for (unsigned int k = 0; k < joints.size(); ++k)
      for (unsigned int i = 0; i < joints[k].n_points(); ++i)
        joints[k].load_shift[i]
          += (omega_squared - omega_squared_operation) * rotation_shift[k][i];
    unsigned int set_steps = 0;
    return solve_stack_contact(C, joints, parameters.unilateral, set_steps);
  }



  void
  StackFit::loosening_speeds()
  {
    if (rotation_shift.empty() || !parameters.unilateral)
      return;
    const auto omega_squared = [](const double n) {
      const double omega = n * 2. * M_PI / 60.;
      return omega * omega;
    };
    const auto open = [](const StackState &state, const unsigned int k) {
      return std::none_of(state.contact[k].begin(),
                          state.contact[k].end(),
                          [](const bool c) { return c; });
    };
    // The compliances once for all the solves below.
    std::vector<FullMatrix<double>> C;
    for (const auto &c : condensed)
      C.push_back(c->get_compliance());
    const unsigned int  n_joints = stack_joints.size();
    std::vector<double> closed_below(n_joints, 0.),
      open_at(n_joints, std::numeric_limits<double>::infinity());
    // The scan: the first speed at which each joint is wholly open.
    for (double n = 100.; n <= loosening_limit() * 1.0000001; n *= 1.1)
      {
        const StackState state = state_at_speed(C, omega_squared(n));
        bool             done  = true;
        for (unsigned int k = 0; k < n_joints; ++k)
          if (std::isinf(open_at[k]))
            {
              if (open(state, k))
                open_at[k] = n;
              else
                closed_below[k] = n;
              done = done && !std::isinf(open_at[k]);
            }
        if (done)
          break;
      }
    for (unsigned int k = 0; k < n_joints; ++k)
      {
        // Every joint, a clearance too: heat or pressure may close it.
        JointFigures &f = joints_out[k];
        if (std::isinf(open_at[k]))
          {
            f.loosening_speed = open_at[k];
            continue;
          }
        // Open already at the first speed scanned: from rest.
        double lo = closed_below[k], hi = open_at[k];
        if (lo == 0. && open(state_at_speed(C, 0.), k))
          hi = 0.;
        while (hi - lo > 1e-6 * hi)
          {
            const double mid = 0.5 * (lo + hi);
            (open(state_at_speed(C, omega_squared(mid)), k) ? hi : lo) = mid;
          }
        f.loosening_speed = hi;
      }
  }



  CompoundCylinders
  StackFit::plane_stress(const unsigned int first,
                         const unsigned int last,
                         const bool         loaded,
                         const bool         unilateral) const
  {
    const bool                           with_loads = loaded && has_loads();
    const StackOperation                &o          = parameters.operation;
    std::vector<CompoundCylinders::Ring> rings;
    for (unsigned int b = first; b <= last; ++b)
      rings.push_back({parameters.rings[b].inner_diameter,
                       parameters.rings[b].outer_diameter,
                       parameters.materials[b].E,
                       parameters.materials[b].nu});
    // The loads: each joint's interference less the free rings' growth
    // apart (rho in kg/m^3: rho omega^2 is 1e-12 rho omega^2 MPa/mm^2).
    const auto free_growth = [&](const unsigned int b, const double r) {
      return free_ring_displacement(
        rings[b - first],
        r,
        parameters.materials[b].thermal_expansion
          * (o.temperature_of(b) - o.assembly_temperature),
        1e-12 * parameters.materials[b].density * o.omega_squared());
    };
    std::vector<double> U;
    for (unsigned int k = first; k < last; ++k)
      {
        const double R = parameters.joint_diameter(k) / 2.;
        U.push_back(parameters.fits[k].diametral_interference
                    - (with_loads ?
                         2. * (free_growth(k + 1, R) - free_growth(k, R)) :
                         0.));
      }
    // With bilateral joints (Contact/Unilateral = false) every joint of
    // the closed form stays closed too.
    return CompoundCylinders(rings,
                             U,
                             with_loads && first == 0 ? o.bore_pressure : 0.,
                             with_loads && last + 1 == bodies.size() ?
                               o.outer_pressure :
                               0.,
                             parameters.unilateral || unilateral);
  }



  void
  StackFit::postprocess()
  {
    const auto         start = std::chrono::steady_clock::now();
    const unsigned int N     = bodies.size();

    // Each body's field under the forces of its joints and its loads.
    fields = body_fields(solution, true);

    // The plane-stress compound cylinders: the stack, and each joint alone.
    const CompoundCylinders lame = plane_stress(0, N - 1);

    alone.clear();
    joints_out.clear();
    for (unsigned int k = 0; k + 1 < N; ++k)
      {
        const StackJoint &joint = stack_joints[k];
        JointFigures      f     = joint_state(k, solution, fields);
        alone.push_back(joint_alone(k, f.alone_steps));
        const Vector<double> pa = alone.back().pressure({joint}, 0);
        f.alone_p_mid           = pa[joint.middle()];
        f.alone_p_mean          = alone.back().force[0].mean_value() * pa.size()
                         / (joint.weights.mean_value() * joint.weights.size());
        f.lame_p       = lame.pressure(k);
        f.lame_alone_p = plane_stress(k, k + 1).pressure(0);
        pressing(k, f);
        joining(k, f);
        joints_out.push_back(f);
      }
    loosening_speeds();
    // Each body's strength: von Mises on its surfaces.
    bodies_out.clear();
    for (unsigned int b = 0; b < N; ++b)
      bodies_out.push_back(body_strength(b, fields[b]));

    // With loads, the state of assembly as well: the contact of the
    // unloaded bodies (the same discrete problem, solved directly), each
    // body's stresses without its thermal strain.
    joints_assembly.clear();
    bodies_assembly.clear();
    assembly_solution = StackState();
    if (has_loads())
      {
        std::vector<StackJoint> unloaded = stack_joints;
        for (StackJoint &joint : unloaded)
          joint.load_shift.reinit(0);
        std::vector<FullMatrix<double>> C;
        for (const auto &c : condensed)
          C.push_back(c->get_compliance());
        unsigned int set_steps = 0;
        assembly_solution
          = solve_stack_contact(C, unloaded, parameters.unilateral, set_steps);
        const std::vector<Vector<double>> assembled
          = body_fields(assembly_solution, false);
        for (unsigned int k = 0; k + 1 < N; ++k)
          joints_assembly.push_back(
            joint_state(k, assembly_solution, assembled));
        for (unsigned int b = 0; b < N; ++b)
          {
            const BodyLoad load = bodies[b]->load();
            bodies[b]->set_load(BodyLoad());
            bodies_assembly.push_back(body_strength(b, assembled[b]));
            bodies[b]->set_load(load);
          }
      }

    check_reliefs();
    surfaces_out.clear();
    for (const std::string &name : parameters.report_surfaces)
      surfaces_out.push_back(surface(name));
    verdict               = Verdict(failed_criteria());
    timing["postprocess"] = seconds_since(start);
  }



  void
  StackFit::check_reliefs() const
  {
    for (const bool operation : {false, true})
      for (const JointFigures &f : operation ? joints_out : joints_assembly)
        for (const JointFigures::ReliefGap &g : f.reliefs)
          if (!(g.gap > 0.))
            throw InputError(
              "parameter Fit/" + f.name + ": the joint's " + g.relief.name()
              + " from z = " + number(g.relief.from, 6) + " to "
              + number(g.relief.to, 6) + " closes "
              + (operation && has_loads() ? "under the loads of Operation" :
                                            "in the state of assembly")
              + ": its least radial gap is " + number(g.gap, 4)
              + " mm at z = " + number(g.z, 6) + " (the drawn clearance "
              + number(g.relief.clearance, 6)
              + " mm less the radial interference "
              + number(f.effective_interference / 2., 6)
              + " mm and what the bodies' displacements take), so its bottom "
                "would touch, which is not modelled; allowed: a relief that "
                "stays open (deeper, or smaller interferences of the stack's "
                "joints, or other loads)");
  }



  int
  StackFit::run(std::ostream &out, const bool progress, const std::string &into)
  {
    if (parameters.fit_case == "all")
      throw InputError(
        "parameter Fit/Case = all: the study of the ISO fits' corners is a "
        "run of its own (one parameter file, no --sweep, not one case of "
        "several files); allowed here: min, mean or max");
    const auto start = std::chrono::steady_clock::now();
    out << "coaxfit: " << parameters.case_name << ", "
        << parameters.bodies.size() << " bodies (";
    for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
      out << (b > 0 ? ", " : "") << parameters.bodies[b];
    out << "), " << parameters.n_joints()
        << (parameters.n_joints() == 1 ? " joint\n" : " joints\n");
    // The directory is checked before any work.
    std::set<std::string> files = {"summary.json",
                                   "parameters.prm",
                                   "convergence.csv",
                                   "solution.pvd",
                                   "report.md",
                                   "plots.gp",
                                   "contact_pressure.png",
                                   "convergence.png",
                                   "fit_selection.csv"};
    for (unsigned int k = 0; k < parameters.n_joints(); ++k)
      {
        files.insert("contact_pressure_" + parameters.joint_name(k) + ".csv");
        files.insert("interface_" + parameters.joint_name(k) + ".vtp");
      }
    for (const std::string &b : parameters.bodies)
      files.insert(Body::key_of(b) + ".vtu");
    // An earlier result of two bodies in the same directory may be
    // replaced as well.
    for (const std::string &name : all_result_file_names())
      files.insert(name);
    check_stack_memory(parameters);
    // Its own directory, staged; or the existing one of a study.
    std::optional<ResultDirectory> directory;
    if (into.empty())
      directory.emplace(parameters.output_directory(), files);

    setup_system();
    unsigned int n_dofs = 0;
    for (const auto &b : bodies)
      n_dofs += b->get_dof_handler().n_dofs();
    out << "  " << n_dofs << " DoFs in " << bodies.size() << " bodies, "
        << (parameters.method == SolverMethod::monolithic ?
              "monolithic" :
              std::string("staggered, ")
                + (parameters.ordering == StackOrdering::jacobi ?
                     "jacobi" :
                     "gauss-seidel"))
        << '\n';
    if (parameters.sections)
      out << "  sections meshed by gmsh, "
          << (parameters.sections->half_model() ?
                "the half beside the plane of symmetry z = "
                  + number(parameters.sections->drawing_offset(), 6)
                  + " of the drawing" :
                "whole (no plane of symmetry through every joint's "
                "middle; z of the drawing)")
          << '\n';
    for (unsigned int k = 0; k + 1 < parameters.bodies.size(); ++k)
      if (parameters.sections)
        if (const auto &face = parameters.sections->shoulder_face(k))
          out << "  " << parameters.joint_name(k)
              << ": the sections also touch on the face at z = "
              << number(face->z, 6) << " (D " << number(face->diameter_inner, 6)
              << " to " << number(face->diameter_outer, 6)
              << "); nothing loads the bodies along the axis, so it carries "
                 "no force: modelled free, both held axially at the joint's "
                 "end there\n";
    if (parameters.select_mode())
      {
        const auto selecting = std::chrono::steady_clock::now();
        select_fits(out);
        timing["selection"] = seconds_since(selecting);
        if (!selection->found())
          {
            // No fits: the selection and a verdict naming the conflict;
            // a design question answered, no error.
            verdict = Verdict({"no ISO fits found: " + selection->conflict});
            out << "  " << verdict.line() << '\n';
            output_selection_only(directory ? directory->staging_path() : into);
            if (directory)
              {
                directory->commit(out);
                out << "  results in " << parameters.output_directory() << '\n';
              }
            return 0;
          }
        out << '\n';
      }
    for (unsigned int k = 0; k < parameters.n_joints(); ++k)
      out << "  " << parameters.joint_name(k) << ": D "
          << parameters.joint_diameter(k) << " mm, U "
          << parameters.fits[k].nominal_interference << " mm ("
          << parameters.fits[k].source << ")"
          << (parameters.fits[k].smoothing_loss > 0. ?
                ", smoothing loss " + number(parameters.fits[k].smoothing_loss)
                  + " mm, effective U_w "
                  + number(parameters.fits[k].diametral_interference) + " mm" :
                std::string())
          << '\n';
    if (has_loads())
      out << "  loads of operation: "
          << parameters.operation.describe(parameters.bodies) << '\n';
    const bool ok = solve(progress ? &out : nullptr);
    if (!ok)
      {
        // The last state is written (converged false) unless it diverged:
        // a non-finite force is never written out.
        bool finite = true;
        for (const Vector<double> &force : solution.force)
          for (const double f : force)
            finite = finite && std::isfinite(f);
        out << "  not converged in " << steps << " steps (Coupling/Max steps "
            << parameters.max_steps << ", Coupling/Tolerance "
            << parameters.tolerance << ")"
            << (finite ? "; the last state is written, converged false" :
                         "; diverged (forces not finite): nothing written, "
                         "the earlier results are untouched")
            << '\n';
        if (!finite)
          return 2;
      }
    else if (parameters.method == SolverMethod::monolithic)
      out << "  contact problem solved, " << active_set_steps
          << " active set step(s)\n";
    else
      out << "  converged in " << steps << " steps (" << body_solves
          << " body solves)\n";
    postprocess();

    // The joints: in the assembly, alone (the joint's two bodies with
    // the others removed), and the plane-stress estimates of both.
    std::size_t width = 5;
    for (const JointFigures &f : joints_out)
      width = std::max(width, f.name.size());
    if (has_loads())
      {
        // The state of assembly first, then the service state.
        out << "\n  in the state of assembly (no loads of operation)\n  "
            << std::left << std::setw(width) << "joint" << std::right
            << "   D mm   p(0) MPa  mean MPa   min MPa   max MPa  contact\n";
        for (const JointFigures &f : joints_assembly)
          out << "  " << std::left << std::setw(width) << f.name << std::right
              << std::fixed << std::setprecision(1) << std::setw(7)
              << f.diameter << std::setprecision(4) << std::setw(11) << f.p_mid
              << std::setw(10) << f.p_mean << std::setw(10) << f.p_min
              << std::setw(10) << f.p_max << "  "
              << (f.closed ? "closed" :
                             std::to_string(f.separated_points) + " open")
              << '\n'
              << std::defaultfloat;
        out << "\n  in operation (the loads above)";
      }
    out << "\n  " << std::left << std::setw(width) << "joint" << std::right
        << "   D mm   p(0) MPa  mean MPa   min MPa   max MPa  contact   | "
           "alone: mean | plane stress: stack   alone\n";
    for (const JointFigures &f : joints_out)
      out << "  " << std::left << std::setw(width) << f.name << std::right
          << std::fixed << std::setprecision(1) << std::setw(7) << f.diameter
          << std::setprecision(4) << std::setw(11) << f.p_mid << std::setw(10)
          << f.p_mean << std::setw(10) << f.p_min << std::setw(10) << f.p_max
          << "  " << std::left << std::setw(9)
          << (f.closed ? "closed" :
                         std::to_string(f.separated_points) + " open")
          << std::right << " |" << std::setw(12) << f.alone_p_mean << " |"
          << std::setw(20) << f.lame_p << std::setw(10) << f.lame_alone_p
          << '\n'
          << std::defaultfloat;
    // A joint of several pieces: where it bears, each piece's mean, and
    // where p(0) is taken.
    for (const JointFigures &f : joints_out)
      if (!f.pieces.empty())
        {
          const StackJoint &joint = stack_joints[&f - &joints_out[0]];
          out << "  " << f.name << ": " << f.pieces.size() << " pieces, l_F "
              << joint.length() << " mm:";
          for (const auto &[from, to, mean] : f.pieces)
            out << (&from == &f.pieces[0][0] ? " z " : ", z ") << from << " to "
                << to << " mean " << mean << " MPa";
          out << "; p(0) at z " << f.mid_plane_z
              << (joint.middle_z() != joint.centre() ?
                    ", the middle of its longest piece (the joint's middle "
                    "is not inside one)" :
                    ", the joint's middle")
              << '\n';
        }
    // Each relief's least gap (in both states with loads).
    for (const JointFigures &f : joints_out)
      for (unsigned int r = 0; r < f.reliefs.size(); ++r)
        {
          const JointFigures::ReliefGap &g = f.reliefs[r];
          out << "  " << f.name << ": " << g.relief.name() << " z "
              << g.relief.from << " to " << g.relief.to
              << " open, least radial gap " << g.gap << " mm at z " << g.z;
          if (has_loads())
            {
              const auto &a = joints_assembly[&f - &joints_out[0]].reliefs[r];
              out << " in operation, " << a.gap << " mm at z " << a.z
                  << " when assembled";
            }
          out << " (drawn clearance " << g.relief.clearance << " mm)\n";
        }
    for (const JointFigures &f : joints_out)
      if (!f.closed)
        out << "  " << f.name << ": open at " << f.separated_points << " of "
            << stack_joints[&f - &joints_out[0]].n_points()
            << " points, diametral gap left " << std::setprecision(6)
            << f.gap_min << " to " << f.gap_max << " mm\n";
    for (const JointFigures &f : joints_out)
      if (f.friction_coefficient > 0.)
        {
          const unsigned int k = &f - &joints_out[0];
          out << "  " << f.name << ": torque capacity " << std::setprecision(6)
              << f.torque_capacity << " N m (friction coefficient "
              << f.friction_coefficient;
          if (parameters.fits[k].friction_text == "auto")
            out << ", " << parameters.fits[k].friction_source;
          out << ")";
          out << ", axial force capacity " << f.axial_force_capacity << " N";
          if (parameters.slip_judged(k))
            out << ", safety against slip " << f.slip_safety << " at "
                << parameters.required_loads_text()
                << (f.slip_safety < 1. ? ": SLIPS" : "");
          else if (parameters.slip_judged())
            out << ", a running fit: passes no load, its slip not judged";
          if (has_loads())
            {
              const JointFigures &a = joints_assembly[k];
              out << "; in the state of assembly " << a.torque_capacity
                  << " N m";
              if (parameters.slip_judged(k))
                out << ", safety " << a.slip_safety
                    << (a.slip_safety < 1. ? ": SLIPS" : "");
            }
          out << '\n';
        }
    for (const JointFigures &f : joints_out)
      if (!std::isnan(f.loosening_speed))
        out << "  " << f.name << ": "
            << (std::isinf(f.loosening_speed) ?
                  "holds up to " + number(loosening_limit(), 6) + " 1/min" :
                  "open over its whole length from "
                    + number(f.loosening_speed, 6) + " 1/min")
            << " (loosening speed, the other loads as in operation; "
               "operating speed "
            << parameters.operation.speed << " 1/min)\n";
    for (const JointFigures &f : joints_out)
      if (!std::isnan(f.heat_outer_to) || !std::isnan(f.cool_inner_to))
        out << "  " << f.name << ": " << joining_text(f) << '\n';
    for (const JointFigures &f : joints_out)
      out << "  " << f.name << ": " << press_text(f) << '\n';
    for (const BodyFigures &f : bodies_out)
      {
        out << "  " << f.name << ": von Mises " << std::setprecision(6)
            << f.von_mises_mid_plane << " MPa at the mid-plane, "
            << f.von_mises_max << " MPa at most on its surfaces";
        if (!std::isnan(f.von_mises_max_z))
          out << " (at z " << f.von_mises_max_z << ", D " << f.von_mises_max_d
              << " mm)";
        // A brittle body is judged against fracture, not yield.
        if (f.yield_strength > 0. && !f.brittle)
          {
            out << "; safety against yield ";
            if (std::isinf(f.yield_safety))
              out << "infinite";
            else
              out << f.yield_safety;
          }
        if (f.yield_strength > 0. && !f.brittle)
          out << " (R_e " << f.yield_strength << " MPa)"
              << (std::isinf(f.yield_safety) ? " (no stress)" : "")
              << (f.yield_safety < 1. ? ": YIELDS, the elastic answer "
                                        "does not hold" :
                                        "");
        if (f.brittle && f.tensile_strength > 0.)
          {
            out << "; brittle: hoop " << f.hoop_mid_plane
                << " MPa at the mid-plane, safety against fracture ";
            if (std::isinf(f.fracture_safety))
              out << "infinite (no tension)";
            else
              out << f.fracture_safety;
            out << " (R_m " << f.tensile_strength << " MPa)";
          }
        if (has_loads())
          {
            const BodyFigures &a = bodies_assembly[&f - &bodies_out[0]];
            out << "; in the state of assembly " << a.von_mises_mid_plane
                << " MPa";
            if (a.yield_strength > 0. && !a.brittle)
              out << ", safety against yield " << safety_text(a.yield_safety)
                  << (a.yield_safety < 1. ? ": YIELDS" : "");
            if (a.brittle && a.tensile_strength > 0.)
              out << ", safety against fracture "
                  << safety_text(a.fracture_safety)
                  << (a.fracture_safety < 1. ? ": FRACTURES" : "");
          }
        out << '\n';
      }
    for (const SurfaceFigures &s : surfaces_out)
      out << "  " << s.name << " (D " << 2. * s.radius << " mm): u_r mean "
          << std::setprecision(6) << s.u_mean << " mm, min " << s.u_min
          << ", max " << s.u_max << "; diameter change " << 2. * s.u_mean
          << " mm\n";

    for (const std::string &caution : cautions())
      out << "  caution: " << caution << '\n';
    out << "  " << verdict.line() << '\n';

    timing["total"] = seconds_since(start);
    const std::string plots_note
      = output_results(directory ? directory->staging_path() : into);
    if (plots_note.rfind("plots skipped", 0) == 0)
      out << "  " << plots_note << '\n';
    if (directory)
      {
        directory->commit(out);
        out << "  results in " << parameters.output_directory() << '\n';
      }
    if (parameters.print_timing)
      out << "  wall time " << std::setprecision(3) << seconds_since(start)
          << " s\n";
    return converged ? 0 : 2;
  }
} // namespace coaxfit
