#include <deal.II/base/multithread_info.h>

#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/base/blas_threads.h>
#include <coaxfit/base/concurrency.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/base/mpi_session.h>
#include <coaxfit/coupling/monolithic_solver.h>
#include <coaxfit/coupling/staggered_coupling.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>

#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

namespace coaxfit
{
  CoaxialFit::CoaxialFit(const Parameters &parameters,
                         std::ostream     &out,
                         const bool        verbose)
    : parameters(parameters)
    , out(out)
    , pcout(out, verbose)
    , scene(parameters)
    , timer(out, TimerOutput::never, TimerOutput::wall_times)
  {}



  void
  CoaxialFit::setup_system()
  {
    {
      TimerOutput::Scope scope(timer, "setup");
      for (Body &body : scene.bodies)
        body.discretization->setup_system();
      for (Body &body : scene.bodies)
        body.discretization->assemble_system();
      scene.connect_joint();
      amg_solver = use_amg(parameters);
      if (scene.has_transfer()
          && (amg_solver
              || scene.bodies[scene.point_body()]
                     .discretization->n_interface_points()
                   > max_condensed_points))
        throw InputError(
          "parameter Mesh/Joint nodes = own: the joint nodes do not match, "
          "and the projection between them needs the condensed operator "
          "(at most "
          + std::to_string(max_condensed_points)
          + " interface points, a direct linear solver); use "
            "Mesh/Joint nodes = shared or a coarser mesh");
      if (amg_solver)
        ensure_mpi_initialized();
      for (Body &body : scene.bodies)
        body.solver
          = std::make_unique<BodySolver>(*body.discretization, amg_solver);
    }

    // The free body's factorization is needed by every staggered run (the
    // Neumann answer, the compliance of the condensed operator, the final
    // fields), so both bodies make it now, concurrently. Factorizations
    // with prescribed points are made when the coupling first asks for
    // them (the condensed operator never does). The monolithic solver
    // factorizes its own system.
    if (parameters.solver.method != SolverMethod::monolithic)
      {
        set_blas_threads(1);
        TimerOutput::Scope scope(timer, "factorization");
        for_each_concurrently(scene.bodies, [](Body &body) {
          body.solver->factorize(
            std::vector<bool>(body.discretization->n_interface_points(),
                              false));
        });
      }
    setup_loads();
    if (parameters.solver.method == SolverMethod::monolithic)
      set_blas_threads(MultithreadInfo::n_threads());
    is_set_up = true;
  }



  void
  CoaxialFit::setup_loads()
  {
    // Each body's own answer to its loads of operation with a free contact
    // surface (one solve with the free body's factorization); the coupling
    // then sees the interference they leave at each point.
    bool any_load = false;
    for (Body &body : scene.bodies)
      {
        body.load_field.reinit(body.discretization->n_dofs());
        any_load = any_load || body.discretization->load().any();
      }
    if (any_load)
      {
        TimerOutput::Scope scope(timer, "loads");
        set_blas_threads(1);
        for_each_concurrently(scene.bodies, [](Body &body) {
          body.load_field = body.answer_to(body.discretization->load());
        });
      }
    const JointSides &joint = scene.joint();
    const Body       &inner = scene.inner(joint), &outer = scene.outer(joint);
    // On the points of one side if they do not match (the other side's
    // values arrive by the mortar transfer).
    const Vector<double> u1_load
      = scene.joint_values(joint.inner,
                           inner.discretization->interface_radial_values(
                             inner.load_field));
    const Vector<double> u2_load
      = scene.joint_values(joint.outer,
                           outer.discretization->interface_radial_values(
                             outer.load_field));
    interface = scene.has_transfer() ?
                  std::make_unique<ContactInterface>(
                    *scene.bodies[scene.point_body()].discretization,
                    joint.interference,
                    u1_load,
                    u2_load) :
                  std::make_unique<ContactInterface>(*inner.discretization,
                                                     *outer.discretization,
                                                     joint.interference,
                                                     u1_load,
                                                     u2_load);
    if (parameters.sections && !parameters.sections->rounded_ends().empty())
      interface->set_shape_gap(rounded_edge_gap());
  }



  UnilateralActiveSet
  CoaxialFit::initial_active_set(const ContactInterface           &contact,
                                 const bool                        unilateral,
                                 const UnilateralActiveSet::Update mode)
  {
    UnilateralActiveSet set(contact.n_points(), unilateral, mode);
    // Over a rounded edge only the joint itself starts in contact; the
    // pass closes the fillet where the deformation makes it touch.
    const Vector<double> &gap = contact.drawing_gap();
    if (gap.size() > 0)
      {
        std::vector<bool> flags(gap.size());
        for (unsigned int i = 0; i < gap.size(); ++i)
          flags[i] = gap[i] == 0.;
        set.assume(flags);
      }
    return set;
  }



  Vector<double>
  CoaxialFit::rounded_edge_gap() const
  {
    // The drawing's radial distance from the shaft's surface to the hub's
    // at each interface point: the other side's surface interpolated
    // linearly in z between its joint points (both sides end where the
    // fillet ends). Zero on the joint itself.
    const unsigned int        p          = scene.point_body();
    const BodyDiscretization &P          = *scene.bodies[p].discretization;
    const BodyDiscretization &A          = *scene.bodies[1 - p].discretization;
    const bool                hub_points = p == scene.joint().outer;
    const auto               &a          = A.interface_points();
    Vector<double>            gap(P.n_interface_points());
    const double              tol = 1e-9 * parameters.geometry.R1;
    for (unsigned int i = 0; i < gap.size(); ++i)
      {
        const Point<2> &x = P.interface_points()[i];
        double          r = a.back()[0];
        for (unsigned int k = 1; k < a.size(); ++k)
          if (a[k][1] >= x[1])
            {
              const double t = (x[1] - a[k - 1][1]) / (a[k][1] - a[k - 1][1]);
              r              = a[k - 1][0]
                  + std::max(0., std::min(1., t)) * (a[k][0] - a[k - 1][0]);
              break;
            }
        const double g = hub_points ? x[0] - r : r - x[0];
        gap[i]         = g > tol ? g : 0.;
      }
    return gap;
  }



  std::unique_ptr<InterfaceSolver>
  CoaxialFit::make_solver(const ContactInterface &contact,
                          const bool              unilateral,
                          const bool              start_from_coarse)
  {
    const JointSides &joint = scene.joint();
    Body &inner = scene.bodies[joint.inner], &outer = scene.bodies[joint.outer];
    if (parameters.solver.method == SolverMethod::monolithic)
      return std::make_unique<MonolithicSolver>(
        scene,
        contact,
        initial_active_set(contact,
                           unilateral,
                           UnilateralActiveSet::Update::when_converged),
        parameters.coupling.max_steps);

    InterfaceOperator *inner_operator = inner.solver.get();
    InterfaceOperator *outer_operator = outer.solver.get();
    if (use_condensed_operator())
      {
        condense();
        inner_operator = inner.condensed.get();
        outer_operator = outer.condensed.get();
      }
    // Timed on its own for the main solve only: the analysis of operation
    // times its solvers as a whole.
    std::optional<TimerOutput::Scope> scope;
    if (start_from_coarse && wants_coarse_model())
      scope.emplace(timer, "coarse_case");
    std::unique_ptr<CoarseInterfaceModel> model
      = wants_coarse_model() ? make_coarse_model(contact) : nullptr;
    // The auto controller: ibqn with a coarse model, iqn-ils without.
    CouplingParameters coupling = parameters.coupling;
    coupling.acceleration       = coupling.accelerator(model != nullptr);
    // ibqn's models are dense (n^2 numbers per body, O(n^3) per step).
    if (coupling.acceleration == AcceleratorType::ibqn
        && contact.n_points() > max_condensed_points)
      throw InputError(
        "Coupling/Alpha controller (or Coupling/Accelerator) = ibqn keeps "
        "dense models of the bodies' interface compliances and allows at "
        "most "
        + std::to_string(max_condensed_points)
        + " interface points; this mesh has "
        + std::to_string(contact.n_points())
        + ". Use auto (iqn-ils there) or iqn-ils.");
    auto staggered = std::make_unique<StaggeredCoupling>(
      *inner.solver,
      *outer.solver,
      *inner_operator,
      *outer_operator,
      contact,
      coupling,
      initial_active_set(contact, unilateral, active_set_mode()),
      parameters.contact.active_set_tolerance);
    if (model)
      {
        if (start_from_coarse)
          start_from_coarse_solution(*staggered, *model);
        staggered->use_coarse_model(std::move(model));
      }
    if (scene.has_transfer())
      staggered->set_force_transfer([this](const unsigned int    side,
                                           const Vector<double> &force) {
        const JointSides &joint = scene.joint();
        return scene.body_forces(side == 0 ? joint.inner : joint.outer, force);
      });
    return staggered;
  }



  void
  CoaxialFit::condense()
  {
    bool all_condensed = true;
    for (const Body &body : scene.bodies)
      all_condensed = all_condensed && body.condensed;
    if (all_condensed)
      return;
    TimerOutput::Scope scope(timer, "condensation");
    for_each_concurrently(scene.bodies, [](Body &body) {
      if (!body.condensed)
        body.condensed = std::make_unique<CondensedBody>(*body.solver);
    });
    // The mortar side seen from the interface points: M C M^T.
    if (scene.has_transfer())
      {
        Body                    &body = scene.bodies[scene.mortar_body()];
        const FullMatrix<double> M    = scene.joint_transfer().matrix();
        FullMatrix<double>       MC(M.m(), M.n()), compliance(M.m(), M.m());
        M.mmult(MC, body.condensed->get_compliance());
        MC.mTmult(compliance, M);
        body.condensed = std::make_unique<CondensedBody>(compliance);
      }
  }



  std::array<ShortWaveCompliance, 2>
  CoaxialFit::short_wave_compliances() const
  {
    // E, nu, the joint radius and the wall thickness (0: solid) of a side.
    const auto side = [&](const unsigned int body) {
      const BodyDiscretization &d = *scene.bodies[body].discretization;
      const BodyGeometry       &g = d.geometry();
      return ShortWaveCompliance{d.material().E,
                                 d.material().nu,
                                 g.contact_radius(),
                                 g.r_inner > 0. ? g.r_outer - g.r_inner : 0.};
    };
    return {{side(scene.joint().inner), side(scene.joint().outer)}};
  }



  void
  CoaxialFit::start_from_coarse_solution(StaggeredCoupling          &staggered,
                                         const CoarseInterfaceModel &model)
  {
    coarse_twin->reuse_for(coarser_parameters());
    twin_state = TwinState::failed;
    try
      {
        coarse_twin->solve(nullptr);
      }
    catch (const SolverError &)
      {
        return; // the fine run starts as without a coarse mesh
      }
    twin_state                    = TwinState::solved;
    const InterfaceSolver &coarse = *coarse_twin->coupling;
    if (!coarse.converged())
      return;
    staggered.start_from(model.prolongate(coarse.contact_force()),
                         model.prolongate(coarse.get_active_set().in_contact()),
                         coarse.history().size());
  }



  bool
  CoaxialFit::wants_coarse_model() const
  {
    return parameters.coupling.coarse_model
           && (parameters.coupling.accelerator() == AcceleratorType::iqn_ils
               || parameters.coupling.accelerator() == AcceleratorType::ibqn)
           && parameters.solver.method != SolverMethod::monolithic
           && parameters.mesh.global_refinements > 0 && !amg_solver
           && !scene.has_transfer();
  }



  std::unique_ptr<CoarseInterfaceModel>
  CoaxialFit::make_coarse_model(const ContactInterface &contact)
  {
    set_up_coarse_twin();
    // The prior is dense on the fine interface (n^2 numbers, O(n^2) per
    // step), and the coarse points must be fine points (not so for FE_Q(3)
    // and higher, whose refined support points do not nest).
    if (coarse_twin->interface->n_points() > max_condensed_points
        || contact.n_points() > max_condensed_points
        || !CoarseInterfaceModel::nested(*coarse_twin->interface, contact))
      return nullptr;
    coarse_twin->condense();
    const Scene &coarse = coarse_twin->scene;
    return std::make_unique<CoarseInterfaceModel>(
      *coarse.inner(coarse.joint()).condensed,
      *coarse.outer(coarse.joint()).condensed,
      *coarse_twin->interface,
      contact,
      short_wave_compliances(),
      parameters.mesh.degree);
  }



  bool
  CoaxialFit::solve(std::ostream *progress)
  {
    coupling = make_solver(*interface, parameters.contact.unilateral, true);
    TimerOutput::Scope scope(timer, "coupling");
    const bool         converged = coupling->run(progress);
    // The contact answer plus each body's answer to its own loads.
    const JointSides &joint = scene.joint();
    fields.resize(scene.bodies.size());
    std::tie(fields[joint.inner], fields[joint.outer])
      = coupling->solve_fields();
    for (unsigned int b = 0; b < scene.bodies.size(); ++b)
      fields[b] += scene.bodies[b].load_field;
    // The work of this state, before the analysis of operation adds more.
    statistics = coupling->statistics();
    if (amg_solver)
      {
        statistics.linear_solver = "amg";
        for (const Body &body : scene.bodies)
          statistics.solves[body.key() + "_cg_iterations"]
            = body.solver->n_cg_iterations();
      }
    return converged;
  }



  Vector<double>
  CoaxialFit::contact_force_for(const Vector<double> &interference,
                                const bool            unilateral)
  {
    const Vector<double>   zero(interference.size());
    const JointSides      &joint = scene.joint();
    const ContactInterface contact
      = scene.has_transfer() ?
          ContactInterface(*scene.bodies[scene.point_body()].discretization,
                           0.,
                           interference,
                           zero) :
          ContactInterface(*scene.inner(joint).discretization,
                           *scene.outer(joint).discretization,
                           0.,
                           interference,
                           zero);
    const auto solver = make_solver(contact, unilateral);
    if (!solver->run(nullptr))
      throw SolverError("a solve of the operating analysis did not converge "
                        "within Coupling/Max steps = "
                        + std::to_string(parameters.coupling.max_steps));
    return solver->contact_force();
  }



  Vector<double>
  CoaxialFit::interference_change(const std::vector<BodyLoad> &loads)
  {
    AssertDimension(loads.size(), scene.bodies.size());
    std::vector<Vector<double>> u_r(scene.bodies.size());
    for_each_concurrently(scene.bodies, [&](Body &body) {
      const unsigned int b = &body - scene.bodies.data();
      u_r[b]               = scene.joint_values(b,
                                  body.discretization->interface_radial_values(
                                    body.answer_to(loads[b])));
    });
    Vector<double> change(u_r[scene.joint().inner]);
    change -= u_r[scene.joint().outer];
    return change;
  }



  FitDesign
  CoaxialFit::state_design() const
  {
    const JointSides &joint = scene.joint();
    return FitDesign(parameters,
                     *scene.inner(joint).discretization,
                     fields[joint.inner],
                     *scene.outer(joint).discretization,
                     fields[joint.outer],
                     coupling->contact_force());
  }



  SolvedState
  CoaxialFit::solved_state() const
  {
    return {pressure_summary(),
            state_design(),
            coupling->converged(),
            coupling->n_steps(),
            coupling->get_active_set().separated_zones(
              interface->z(),
              parameters.geometry.joint_start(),
              parameters.geometry.joint_end())};
  }



  SolvedState
  CoaxialFit::solve_state(const Parameters &other)
  {
    std::ostringstream quiet;
    CoaxialFit         fit(other, quiet, false);
    fit.setup_system();
    fit.solve(nullptr);
    return fit.solved_state();
  }



  bool
  CoaxialFit::use_condensed_operator() const
  {
    const InterfaceOperatorType type = parameters.coupling.interface_operator;
    if (amg_solver) // no compliance without a factor
      return false;
    return type == InterfaceOperatorType::condensed
           || (type == InterfaceOperatorType::automatic
               && interface->n_points() <= max_condensed_points);
  }



  UnilateralActiveSet::Update
  CoaxialFit::active_set_mode() const
  {
    const ActiveSetUpdateType mode = parameters.contact.active_set_update;
    const bool                plain_fixed
      = parameters.coupling.alpha_rule() == AlphaRuleType::fixed
        && parameters.coupling.accelerator() == AcceleratorType::none;
    if (mode == ActiveSetUpdateType::every_step
        || (mode == ActiveSetUpdateType::automatic && plain_fixed))
      return UnilateralActiveSet::Update::every_step;
    return UnilateralActiveSet::Update::when_converged;
  }



  PressureSummary
  CoaxialFit::pressure_summary() const
  {
    return PressureSummary(parameters, *interface, coupling->contact_force());
  }



  std::vector<std::string>
  CoaxialFit::warnings(const PressureSummary &pressure) const
  {
    std::vector<std::string> list;
    if (!coupling->converged())
      {
        std::ostringstream w;
        w << "not converged within Coupling/Max steps = "
          << parameters.coupling.max_steps << " (|du|/d = " << std::scientific
          << std::setprecision(3) << coupling->displacement_residual()
          << ", |dp|/p = " << coupling->traction_residual() << ")";
        list.push_back(w.str());
      }
    // A joint that opens over part of its length: the pressure is zero
    // there, which the FE capacity counts and DIN 7190's uniform pressure
    // does not.
    const UnilateralActiveSet &set = coupling->get_active_set();
    if (set.enabled() && set.n_separated() > 0
        && set.n_separated() < interface->n_points())
      {
        const GeometryParameters &g      = parameters.geometry;
        const double              length = g.modelled_joint_length();
        const auto                zones
          = set.separated_zones(interface->z(), g.joint_start(), g.joint_end());
        double             open = 0.;
        std::ostringstream w;
        w << std::setprecision(4) << "the joint opens over ";
        std::ostringstream where;
        where << std::setprecision(4);
        for (const auto &zone : zones)
          {
            open += zone.second - zone.first;
            where << (where.tellp() > 0 ? ", " : "") << zone.first << " to "
                  << zone.second;
          }
        w << open << " mm of the " << length
          << (g.whole ? " mm joint (z = " : " mm half length (z = ")
          << where.str()
          << " mm): no contact pressure there; the FE capacity counts only "
             "the closed part, DIN 7190's uniform pressure assumes it closed";
        // Points open only on a rounded edge beyond the joint: no warning.
        if (open > 0.)
          list.push_back(w.str());
      }
    if (!parameters.contact.unilateral && pressure.min < 0.)
      {
        std::ostringstream w;
        w << std::setprecision(4)
          << "the bilateral contact pressure is tensile (min " << pressure.min
          << " MPa at z = " << pressure.z_of_min
          << " mm): the surfaces want to separate there, which "
          << "Contact/Unilateral = false does not allow";
        list.push_back(w.str());
      }
    return list;
  }



  void
  CoaxialFit::print_report(const PressureSummary          &pressure,
                           const Complementarity          &complementarity,
                           const std::vector<std::string> &warnings) const
  {
    std::ostringstream report;
    report << std::fixed << std::setprecision(4);
    if (coupling->converged())
      report << "  converged in " << coupling->n_steps() << " steps ("
             << coupling->steps_to_displacement_mismatch(1e-2)
             << " to the paper's criterion max|du|/d < 1e-2)\n";
    if (parameters.contact.unilateral)
      {
        const auto zones = coupling->get_active_set().separated_zones(
          interface->z(),
          parameters.geometry.joint_start(),
          parameters.geometry.joint_end());
        report << "  separated zones:";
        if (zones.empty())
          report << " none";
        for (const auto &zone : zones)
          report << " [" << std::setprecision(2) << zone.first << ", "
                 << zone.second << "] mm";
        report << " (" << coupling->get_active_set().n_changes()
               << " active set changes)\n"
               << std::scientific << std::setprecision(2)
               << "  complementarity: max tension "
               << complementarity.max_tension_relative << ", max penetration/d "
               << complementarity.max_penetration_relative << ", max |p gap| "
               << complementarity.max_pressure_gap_relative << std::fixed
               << std::setprecision(4) << '\n';
      }
    std::ostringstream middle; // "0" for the half model's mid-plane
    middle << parameters.geometry.joint_middle();
    report << "  pressure at z = " << middle.str() << ": "
           << pressure.at_mid_plane << " MPa, mean: " << pressure.mean
           << " MPa, Lame: " << pressure.lame << " MPa\n"
           << "  pressure min: " << pressure.min
           << " MPa at z = " << pressure.z_of_min
           << " mm, max: " << pressure.max
           << " MPa at z = " << pressure.z_of_max
           << (parameters.sections
                   && !parameters.sections->rounded_ends().empty() ?
                 " mm (near a rounded edge's tangent point: finite, but "
                 "steep and mesh-dependent)\n" :
                 " mm (corner value is singular)\n");
    for (const std::string &w : warnings)
      report << "  warning: " << w << '\n';
    out << report.str();
  }



  void
  CoaxialFit::output_results(const std::string &directory)
  {
    const PressureSummary pressure = pressure_summary();
    const Complementarity complementarity(*interface, *coupling);
    design = std::make_unique<FitDesign>(state_design());
    if (parameters.design.corner_trend
        && parameters.mesh.global_refinements > 0)
      {
        TimerOutput::Scope        scope(timer, "corner_trend");
        const std::vector<double> coarser = coarser_corner_values();
        for (unsigned int i = 0; i < coarser.size(); ++i)
          design->surface_maxima[i].corner_coarser = coarser[i];
      }
    std::unique_ptr<OperationAnalysis> operation;
    {
      TimerOutput::Scope scope(timer, "operation");
      operation = std::make_unique<OperationAnalysis>(parameters, *this);
    }
    // The parts are pressed together at assembly, not in service.
    design->press_in_force     = operation->assembly.press_in_force;
    design->press_in_force_din = operation->assembly.press_in_force_din;
    design->safety_yield_shaft_assembly
      = operation->assembly.safety_yield_shaft;
    design->safety_yield_hub_assembly = operation->assembly.safety_yield_hub;
    std::vector<std::string> warning_list = parameters.input_warnings();
    for (const auto &list : {warnings(pressure),
                             design->warnings(parameters),
                             operation->warnings(parameters)})
      warning_list.insert(warning_list.end(), list.begin(), list.end());
    if (operation->has_loads && !operation->holds)
      warning_list.push_back(operation->verdict);
    verdict = std::make_unique<Verdict>(parameters,
                                        *operation,
                                        coupling->converged());
    print_report(pressure, complementarity, warning_list);
    print_design(out, parameters, *design);
    operation->print(out);
    out << "  " << verdict->line() << '\n';

    std::map<std::string, double> timing;
    const RunResults              results{parameters,
                             scene,
                             fields,
                             *interface,
                             *coupling,
                             statistics,
                             pressure,
                             complementarity,
                             *design,
                             *operation,
                             timing,
                             warning_list,
                             *verdict};
    std::vector<std::string>      lines;
    {
      TimerOutput::Scope scope(timer, "output");
      // The files are independent (each writer its own), except the
      // report, which shows the plots that exist: it comes last.
      const auto writers
        = make_result_writers(parameters.output, Scene::body_keys(parameters));
      lines.resize(writers.size());
      std::vector<std::function<void()>> jobs;
      for (unsigned int i = 0; i < writers.size(); ++i)
        if (!writers[i]->needs_the_other_files())
          jobs.emplace_back(
            [&, i]() { lines[i] = writers[i]->write(results, directory); });
      each_on_own_thread(jobs);
      for (unsigned int i = 0; i < writers.size(); ++i)
        if (writers[i]->needs_the_other_files())
          lines[i] = writers[i]->write(results, directory);
    }
    for (const std::string phase : {"setup",
                                    "loads",
                                    "factorization",
                                    "condensation",
                                    "coarse_case",
                                    "coupling",
                                    "corner_trend",
                                    "operation",
                                    "output"})
      timing[phase] = 0.;
    for (const auto &[phase, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timing[phase] = seconds;
    double total = 0.;
    for (const auto &[phase, seconds] : timing)
      total += seconds;
    timing["total"] = total;
    lines.push_back(SummaryWriter().write(results, directory));

    for (const std::string &line : lines)
      pcout << "  " << line << '\n';
    if (parameters.output.print_timing)
      pcout << std::fixed << std::setprecision(3) << "  wall time: setup "
            << timing["setup"] << " s, loads " << timing["loads"]
            << " s, factorization " << timing["factorization"]
            << " s, condensation " << timing["condensation"]
            << " s, coarse case " << timing["coarse_case"] << " s, coupling "
            << timing["coupling"] << " s, corner trend "
            << timing["corner_trend"] << " s, output " << timing["output"]
            << " s, total " << timing["total"] << " s\n";
  }



  std::vector<double>
  CoaxialFit::coarser_corner_values()
  {
    const Parameters coarse = coarser_parameters();
    // Solved already when the coupling started from it.
    if (twin_state == TwinState::stale)
      {
        if (coarse_twin)
          coarse_twin->reuse_for(coarse);
        else
          prepare_corner_trend();
        try
          {
            coarse_twin->solve(nullptr);
            twin_state = TwinState::solved;
          }
        catch (const SolverError &)
          {
            twin_state = TwinState::failed;
          }
      }
    // Only a figure of the report depends on it: said there as not
    // available; the run itself is unaffected.
    if (twin_state == TwinState::failed)
      return {};
    const FitDesign     coarse_design = coarse_twin->state_design();
    std::vector<double> values;
    for (const FitDesign::SurfaceMaximum &m : coarse_design.surface_maxima)
      values.push_back(m.corner);
    return values;
  }



  bool
  CoaxialFit::run()
  {
    // Memory and the output directory are checked first, so that a run
    // that cannot finish or cannot be written stops before any work.
    check_memory(parameters);
    ResultDirectory directory(parameters.output_directory(),
                              all_result_file_names());
    const bool      converged = run_in(directory.staging_path());
    directory.commit(out);
    pcout << "  results in " << parameters.output_directory() << '\n';
    return converged;
  }



  Parameters
  CoaxialFit::coarser_parameters() const
  {
    Parameters coarse = parameters;
    --coarse.mesh.global_refinements;
    coarse.design.corner_trend   = false;
    coarse.coupling.coarse_model = false;
    // The coarser case of a monolithic run (its corner trend) is solved by
    // the staggered solver: the same discrete problem to the coupling
    // tolerance, in a tenth of the time (variant 17, refinement 5: the
    // monolithic twin took 46.7 s of 356 s). It is a diagnostic of the
    // corner, never a design figure.
    coarse.solver.method = SolverMethod::staggered;
    return coarse;
  }



  void
  CoaxialFit::set_up_coarse_twin()
  {
    if (coarse_twin)
      return;
    coarse_twin
      = std::make_unique<CoaxialFit>(coarser_parameters(), out, false);
    coarse_twin->setup_system();
  }



  void
  CoaxialFit::prepare_corner_trend()
  {
    if (coarse_twin || !(parameters.design.corner_trend || wants_coarse_model())
        || parameters.mesh.global_refinements == 0)
      return;
    set_up_coarse_twin();
    if (wants_coarse_model()
        && coarse_twin->interface->n_points() <= max_condensed_points)
      coarse_twin->condense();
  }



  bool
  CoaxialFit::reusable_across(const std::string &entry)
  {
    for (const std::string section :
         {"Fit/", "Operation/", "Coupling/", "Contact/", "Design/", "Output/"})
      if (entry.compare(0, section.size(), section) == 0)
        return true;
    return false;
  }



  void
  CoaxialFit::reuse_for(const Parameters &other)
  {
    Assert(is_set_up, ExcMessage("reuse_for() needs a set-up case"));
    parameters = other;
    // The timings of this case are its own (the setup was shared).
    timer.reset();
    scene.set_loads(parameters);
    coupling.reset();
    design.reset();
    verdict.reset();
    twin_state = TwinState::stale;
    setup_loads();
  }



  bool
  CoaxialFit::run_in(const std::string &directory)
  {
    if (!is_set_up)
      setup_system();
    pcout << "coaxfit: case " << parameters.case_name << '\n';
    for (const Body &body : scene.bodies)
      pcout << "  " << body.key() << ": " << body.discretization->n_cells()
            << " cells, " << body.discretization->n_dofs() << " DoFs;";
    pcout << "  " << interface->n_points() << " interface points, FE_Q("
          << parameters.mesh.degree << ")\n";
    if (parameters.sections && parameters.sections->shoulder_face())
      {
        const auto &face = *parameters.sections->shoulder_face();
        pcout << "  shoulder: the sections also touch on the face at z = "
              << face.z << " (D " << face.diameter_inner << " to "
              << face.diameter_outer
              << "); nothing loads the bodies along the axis, so it carries "
                 "no force: modelled free, both held axially at the joint's "
                 "end there\n";
      }
    const bool converged = solve(pcout.is_active() ? &out : nullptr);
    output_results(directory);
    return converged;
  }
} // namespace coaxfit
