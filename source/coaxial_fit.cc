#include <deal.II/base/multithread_info.h>

#include <coaxfit/blas_threads.h>
#include <coaxfit/coaxial_fit.h>
#include <coaxfit/concurrency.h>
#include <coaxfit/design_report.h>
#include <coaxfit/input_error.h>
#include <coaxfit/monolithic_solver.h>
#include <coaxfit/resources.h>
#include <coaxfit/result_directory.h>
#include <coaxfit/result_writers.h>
#include <coaxfit/staggered_coupling.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    BodyGeometry
    common_mesh_settings(const Parameters &parameters)
    {
      BodyGeometry g;
      g.contact_length     = parameters.geometry.contact_length();
      g.axial_cells        = parameters.mesh.axial_cells;
      g.radial_cells       = parameters.mesh.radial_cells;
      g.grading_ratio      = parameters.mesh.grading_ratio;
      g.global_refinements = parameters.mesh.global_refinements;
      return g;
    }
  } // namespace



  BodyGeometry
  shaft_geometry(const Parameters &parameters)
  {
    BodyGeometry g            = common_mesh_settings(parameters);
    g.r_inner                 = parameters.geometry.R0;
    g.r_outer                 = parameters.geometry.R1;
    g.length                  = parameters.geometry.L1;
    g.contact_at_outer_radius = true;
    return g;
  }



  BodyGeometry
  hub_geometry(const Parameters &parameters)
  {
    BodyGeometry g            = common_mesh_settings(parameters);
    g.r_inner                 = parameters.geometry.R1;
    g.r_outer                 = parameters.geometry.R2;
    g.length                  = parameters.geometry.L2;
    g.contact_at_outer_radius = false;
    return g;
  }



  std::unique_ptr<BodyDiscretization>
  make_body(const Parameters &parameters, const bool shaft)
  {
    return std::make_unique<BodyDiscretization>(
      shaft ? shaft_geometry(parameters) : hub_geometry(parameters),
      shaft ? parameters.shaft : parameters.hub,
      parameters.mesh.degree,
      parameters.mesh.reduced_volumetric_integration());
  }



  CoaxialFit::CoaxialFit(const Parameters &parameters,
                         std::ostream     &out,
                         const bool        verbose)
    : parameters(parameters)
    , out(out)
    , pcout(out, verbose)
    , shaft(make_body(parameters, true))
    , hub(make_body(parameters, false))
    , timer(out, TimerOutput::never, TimerOutput::wall_times)
  {}



  void
  CoaxialFit::setup_system()
  {
    {
      TimerOutput::Scope scope(timer, "setup");
      shaft->setup_system();
      hub->setup_system();
      shaft->assemble_system();
      hub->assemble_system();
      interface    = std::make_unique<ContactInterface>(*shaft,
                                                     *hub,
                                                     parameters.geometry.d);
      shaft_solver = std::make_unique<BodySolver>(*shaft);
      hub_solver   = std::make_unique<BodySolver>(*hub);
    }

    // The free body's factorization is needed by every staggered run (the
    // Neumann answer, the compliance of the condensed operator, the final
    // fields), so both bodies make it now, concurrently. Factorizations
    // with prescribed points are made when the coupling first asks for
    // them (the condensed operator never does). The monolithic solver
    // factorizes its own system.
    if (parameters.solver.method == SolverMethod::monolithic)
      {
        set_blas_threads(MultithreadInfo::n_cores());
        return;
      }
    set_blas_threads(1);
    TimerOutput::Scope      scope(timer, "factorization");
    const std::vector<bool> none(interface->n_points(), false);
    concurrently([&]() { shaft_solver->factorize(none); },
                 [&]() { hub_solver->factorize(none); });
  }



  std::unique_ptr<InterfaceSolver>
  CoaxialFit::make_staggered_coupling()
  {
    InterfaceOperator *shaft_operator = shaft_solver.get();
    InterfaceOperator *hub_operator   = hub_solver.get();
    if (use_condensed_operator())
      {
        TimerOutput::Scope scope(timer, "condensation");
        concurrently(
          [&]() {
            condensed_shaft = std::make_unique<CondensedBody>(*shaft_solver);
          },
          [&]() {
            condensed_hub = std::make_unique<CondensedBody>(*hub_solver);
          });
        shaft_operator = condensed_shaft.get();
        hub_operator   = condensed_hub.get();
      }
    return std::make_unique<StaggeredCoupling>(
      *shaft_solver,
      *hub_solver,
      *shaft_operator,
      *hub_operator,
      *interface,
      parameters.coupling,
      UnilateralActiveSet(interface->n_points(),
                          parameters.contact.unilateral,
                          active_set_mode()),
      parameters.contact.active_set_tolerance);
  }



  bool
  CoaxialFit::solve(std::ostream *progress)
  {
    if (parameters.solver.method == SolverMethod::monolithic)
      coupling = std::make_unique<MonolithicSolver>(
        *shaft,
        *hub,
        *interface,
        UnilateralActiveSet(interface->n_points(),
                            parameters.contact.unilateral,
                            UnilateralActiveSet::Update::when_converged),
        parameters.coupling.max_steps);
    else
      coupling = make_staggered_coupling();

    TimerOutput::Scope scope(timer, "coupling");
    const bool         converged     = coupling->run(progress);
    std::tie(shaft_field, hub_field) = coupling->solve_fields();
    return converged;
  }



  bool
  CoaxialFit::use_condensed_operator() const
  {
    const InterfaceOperatorType type = parameters.coupling.interface_operator;
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
          interface->z(), parameters.geometry.contact_length());
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
    report << "  pressure at z = 0: " << pressure.at_mid_plane
           << " MPa, mean: " << pressure.mean << " MPa, Lame: " << pressure.lame
           << " MPa\n"
           << "  pressure min: " << pressure.min
           << " MPa at z = " << pressure.z_of_min
           << " mm, max: " << pressure.max
           << " MPa at z = " << pressure.z_of_max
           << " mm (corner value is singular)\n";
    for (const std::string &w : warnings)
      report << "  warning: " << w << '\n';
    out << report.str();
  }



  void
  CoaxialFit::output_results(const std::string &directory)
  {
    const PressureSummary pressure = pressure_summary();
    const Complementarity complementarity(*interface, *coupling);
    design = std::make_unique<FitDesign>(parameters,
                                         *shaft,
                                         shaft_field,
                                         *hub,
                                         hub_field,
                                         coupling->contact_force());
    if (parameters.design.corner_trend
        && parameters.mesh.global_refinements > 0)
      {
        TimerOutput::Scope        scope(timer, "corner_trend");
        const std::vector<double> coarser = coarser_corner_values();
        for (unsigned int i = 0; i < coarser.size(); ++i)
          design->surface_maxima[i].corner_coarser = coarser[i];
      }
    std::vector<std::string> warning_list = parameters.input_warnings();
    for (const auto &list : {warnings(pressure), design->warnings(parameters)})
      warning_list.insert(warning_list.end(), list.begin(), list.end());
    print_report(pressure, complementarity, warning_list);
    print_design(out, parameters, *design);

    std::map<std::string, double> timing;
    const RunResults              results{parameters,
                             *shaft,
                             *hub,
                             shaft_field,
                             hub_field,
                             *interface,
                             *coupling,
                             pressure,
                             complementarity,
                             *design,
                             timing,
                             warning_list};
    std::vector<std::string>      lines;
    {
      TimerOutput::Scope scope(timer, "output");
      for (const auto &writer : make_result_writers(parameters.output))
        lines.push_back(writer->write(results, directory));
    }
    for (const std::string phase : {"setup",
                                    "factorization",
                                    "condensation",
                                    "coupling",
                                    "corner_trend",
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
            << timing["setup"] << " s, factorization "
            << timing["factorization"] << " s, condensation "
            << timing["condensation"] << " s, coupling " << timing["coupling"]
            << " s, corner trend " << timing["corner_trend"] << " s, output "
            << timing["output"] << " s, total " << timing["total"] << " s\n";
  }



  std::vector<double>
  CoaxialFit::coarser_corner_values() const
  {
    Parameters coarse = parameters;
    --coarse.mesh.global_refinements;
    coarse.design.corner_trend = false;
    CoaxialFit fit(coarse, out, false);
    fit.setup_system();
    try
      {
        fit.solve(nullptr);
      }
    catch (const SolverError &)
      {
        // Only a figure of the report depends on it: said there as not
        // available; the run itself is unaffected.
        return {};
      }
    const FitDesign     coarse_design(coarse,
                                  *fit.shaft,
                                  fit.shaft_field,
                                  *fit.hub,
                                  fit.hub_field,
                                  fit.coupling->contact_force());
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
    directory.commit();
    pcout << "  results in " << parameters.output_directory() << '\n';
    return converged;
  }



  bool
  CoaxialFit::run_in(const std::string &directory)
  {
    setup_system();
    pcout << "coaxfit: case " << parameters.case_name << '\n'
          << "  shaft: " << shaft->n_cells() << " cells, " << shaft->n_dofs()
          << " DoFs;  hub: " << hub->n_cells() << " cells, " << hub->n_dofs()
          << " DoFs;  " << interface->n_points() << " interface points, FE_Q("
          << parameters.mesh.degree << ")\n";
    const bool converged = solve(pcout.is_active() ? &out : nullptr);
    output_results(directory);
    return converged;
  }
} // namespace coaxfit
