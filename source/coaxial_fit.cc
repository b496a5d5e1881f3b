#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>

#include <coaxfit/alpha_controller.h>
#include <coaxfit/blas_threads.h>
#include <coaxfit/coaxial_fit.h>
#include <coaxfit/contact_interface.h>
#include <coaxfit/input_error.h>
#include <coaxfit/results.h>
#include <coaxfit/staggered_coupling.h>

#include <filesystem>
#include <fstream>
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
      g.contact_length     = parameters.contact_length();
      g.axial_cells        = parameters.axial_cells;
      g.radial_cells       = parameters.radial_cells;
      g.grading_ratio      = parameters.grading_ratio;
      g.global_refinements = parameters.global_refinements;
      return g;
    }

    void
    make_output_directory(const std::string &directory)
    {
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      if (error || !std::filesystem::is_directory(directory))
        throw InputError("parameter Output/Directory = " + directory
                         + ": cannot create the directory (" + error.message()
                         + ")");
    }
  } // namespace



  BodyGeometry
  CoaxialFit::shaft_geometry(const Parameters &parameters)
  {
    BodyGeometry g            = common_mesh_settings(parameters);
    g.r_inner                 = parameters.R0;
    g.r_outer                 = parameters.R1;
    g.length                  = parameters.L1;
    g.contact_at_outer_radius = true;
    return g;
  }



  BodyGeometry
  CoaxialFit::hub_geometry(const Parameters &parameters)
  {
    BodyGeometry g            = common_mesh_settings(parameters);
    g.r_inner                 = parameters.R1;
    g.r_outer                 = parameters.R2;
    g.length                  = parameters.L2;
    g.contact_at_outer_radius = false;
    return g;
  }



  CoaxialFit::CoaxialFit(const Parameters &parameters)
    : parameters(parameters)
    , shaft("shaft",
            shaft_geometry(parameters),
            parameters.shaft,
            parameters.degree,
            parameters.reduced_volumetric_integration)
    , hub("hub",
          hub_geometry(parameters),
          parameters.hub,
          parameters.degree,
          parameters.reduced_volumetric_integration)
  {}



  void
  CoaxialFit::setup_system()
  {
    Timer timer;
    shaft.setup_system();
    hub.setup_system();
    shaft.assemble_system();
    hub.assemble_system();
    interface    = std::make_unique<ContactInterface>(shaft, hub, parameters.d);
    timing.setup = timer.wall_time();

    // The free body's factorization is needed by every staggered run (the
    // Neumann answer, the compliance of the condensed operator, the final
    // fields), so both bodies make it now, concurrently. Factorizations
    // with prescribed points are made when the coupling first asks for
    // them (the condensed operator never does). The monolithic solver
    // factorizes its own system.
    if (parameters.solver_method == "monolithic")
      {
        set_blas_threads(MultithreadInfo::n_cores());
        return;
      }
    set_blas_threads(1);
    timer.restart();
    const std::vector<bool> none(interface->n_points(), false);
    Threads::Task<void>     task
      = Threads::new_task([&]() { shaft.factorize(none); });
    hub.factorize(none);
    task.join();
    timing.factorization = timer.wall_time();
  }



  bool
  CoaxialFit::solve(std::ostream *progress)
  {
    Timer timer;
    controller = make_alpha_controller(parameters);
    if (parameters.solver_method == "monolithic")
      {
        coupling = std::make_unique<MonolithicSolver>(
          shaft,
          hub,
          *interface,
          UnilateralActiveSet(interface->n_points(),
                              parameters.unilateral,
                              UnilateralActiveSet::Update::when_converged),
          parameters.max_steps);
        const bool converged = coupling->run(progress);
        timing.coupling      = timer.wall_time();
        return converged;
      }
    InterfaceOperator *shaft_operator = &shaft;
    InterfaceOperator *hub_operator   = &hub;
    if (use_condensed_operator())
      {
        Timer               condensation;
        Threads::Task<void> task = Threads::new_task(
          [&]() { condensed_shaft = std::make_unique<CondensedBody>(shaft); });
        condensed_hub = std::make_unique<CondensedBody>(hub);
        task.join();
        timing.condensation = condensation.wall_time();
        shaft_operator      = condensed_shaft.get();
        hub_operator        = condensed_hub.get();
      }
    coupling = std::make_unique<StaggeredCoupling>(
      *shaft_operator,
      *hub_operator,
      *interface,
      *controller,
      parameters.tolerance,
      parameters.max_steps,
      UnilateralActiveSet(interface->n_points(),
                          parameters.unilateral,
                          active_set_mode()),
      parameters.active_set_tolerance);
    const bool converged = coupling->run(progress);
    if (use_condensed_operator())
      {
        // The fields of the final state: one full solve per body with the
        // final contact force.
        std::vector<double> u;
        Threads::Task<void> task = Threads::new_task(
          [&]() { shaft.solve_neumann(coupling->contact_force(), u); });
        std::vector<double> u_hub;
        hub.solve_neumann(coupling->contact_force(), u_hub);
        task.join();
      }
    timing.coupling = timer.wall_time() - timing.condensation;
    return converged;
  }



  bool
  CoaxialFit::use_condensed_operator() const
  {
    return parameters.interface_operator == "condensed"
           || (parameters.interface_operator == "auto"
               && interface->n_points() <= max_condensed_points);
  }



  UnilateralActiveSet::Update
  CoaxialFit::active_set_mode() const
  {
    const std::string &mode = parameters.active_set_update;
    if (mode == "every step"
        || (mode == "auto" && parameters.alpha_controller == "fixed"))
      return UnilateralActiveSet::Update::every_step;
    return UnilateralActiveSet::Update::when_converged;
  }



  PressureSummary
  CoaxialFit::pressure_summary() const
  {
    return PressureSummary(parameters, *interface, coupling->contact_force());
  }



  void
  CoaxialFit::output_results(std::ostream &out)
  {
    Timer                    timer;
    const PressureSummary    pressure = pressure_summary();
    std::vector<std::string> warnings;
    std::ostringstream       report;
    report << std::fixed << std::setprecision(4);
    if (coupling->converged())
      report << "  converged in " << coupling->n_steps() << " steps ("
             << coupling->steps_to_displacement_mismatch(1e-2)
             << " to the paper's criterion max|du|/d < 1e-2)\n";
    else
      {
        std::ostringstream w;
        w << "not converged within Coupling/Max steps = "
          << parameters.max_steps << " (|du|/d = " << std::scientific
          << std::setprecision(3) << coupling->displacement_residual()
          << ", |dp|/p = " << coupling->traction_residual() << ")";
        warnings.push_back(w.str());
      }
    const Complementarity complementarity(*interface, *coupling);
    if (!parameters.unilateral && pressure.min < 0.)
      {
        std::ostringstream w;
        w << std::setprecision(4)
          << "the bilateral contact pressure is tensile (min " << pressure.min
          << " MPa at z = " << pressure.z_of_min
          << " mm): the surfaces want to separate there, which "
          << "Contact/Unilateral = false does not allow";
        warnings.push_back(w.str());
      }
    if (parameters.unilateral)
      {
        const auto zones = coupling->get_active_set().separated_zones(
          interface->z(), parameters.contact_length());
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

    const std::string dir = parameters.output_directory + "/";
    write_contact_pressure(dir + "contact_pressure.csv",
                           *interface,
                           pressure,
                           *coupling);
    write_convergence(dir + "convergence.csv", *coupling);
    if (parameters.write_vtu)
      {
        shaft.output_results(dir + "shaft.vtu");
        hub.output_results(dir + "hub.vtu");
        write_interface_vtp(
          dir + "interface.vtp", parameters, *interface, pressure, *coupling);
        // One time step, three parts: ParaView shows them together.
        std::ofstream pvd(dir + "solution.pvd");
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<Collection>\n";
        unsigned int part = 0;
        for (const std::string file : {"shaft.vtu", "hub.vtu", "interface.vtp"})
          pvd << "<DataSet timestep=\"0\" group=\"\" part=\"" << part++
              << "\" file=\"" << file << "\"/>\n";
        pvd << "</Collection>\n</VTKFile>\n";
      }
    timing.output = timer.wall_time();
    timing.total  = timing.setup + timing.factorization + timing.condensation
                   + timing.coupling + timing.output;
    write_summary(dir + "summary.json",
                  {parameters,
                   shaft,
                   hub,
                   *interface,
                   *coupling,
                   pressure,
                   timing,
                   complementarity,
                   parameters.solver_method == "monolithic" ?
                     std::string("monolithic") :
                     controller->name(),
                   warnings});

    out << "  results in " << parameters.output_directory << '\n';
    if (parameters.print_timing)
      out << std::fixed << std::setprecision(3) << "  wall time: setup "
          << timing.setup << " s, factorization " << timing.factorization
          << " s, condensation " << timing.condensation << " s, coupling "
          << timing.coupling << " s, output " << timing.output << " s, total "
          << timing.total << " s\n";
  }



  bool
  CoaxialFit::run(std::ostream &out)
  {
    // Created first, so that a directory that cannot be made stops the run
    // before any work; removed again if the run fails before writing.
    const bool created = !std::filesystem::exists(parameters.output_directory);
    make_output_directory(parameters.output_directory);
    setup_system();
    out << "coaxfit: case " << parameters.case_name << '\n'
        << "  shaft: " << shaft.n_cells() << " cells, " << shaft.n_dofs()
        << " DoFs;  hub: " << hub.n_cells() << " cells, " << hub.n_dofs()
        << " DoFs;  " << interface->n_points() << " interface points, FE_Q("
        << parameters.degree << ")\n";
    bool converged = false;
    try
      {
        converged = solve(&out);
      }
    catch (const SolverError &)
      {
        if (created && std::filesystem::is_empty(parameters.output_directory))
          std::filesystem::remove(parameters.output_directory);
        throw;
      }
    output_results(out);
    return converged;
  }
} // namespace coaxfit
