#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

namespace coaxfit
{
  namespace
  {
    using Json = nlohmann::ordered_json;

    /** The result files of an elastic-plastic run. */
    std::set<std::string>
    plastic_result_files()
    {
      return {"summary.json",
              "parameters.prm",
              "contact_pressure.csv",
              "load_path.csv",
              "shaft.vtu",
              "hub.vtu",
              "solution.pvd"};
    }
  } // namespace



  int
  PlasticFit::run()
  {
    const auto start = std::chrono::steady_clock::now();
    check_scope();
    out << "coaxfit: " << parameters.case_name << ", elastic-plastic ("
        << (parameters.shaft.plastic ? "shaft" : "")
        << (parameters.shaft.plastic && parameters.hub.plastic ? " and " : "")
        << (parameters.hub.plastic ? "hub" : "") << " von Mises), U "
        << 2. * parameters.geometry.d << " mm\n";
    check_memory(parameters);
    // The target is checked before any work; it may hold the files of an
    // elastic run of the same case.
    std::set<std::string> files = all_result_file_names();
    for (const std::string &f : plastic_result_files())
      files.insert(f);
    auto directory
      = std::make_unique<ResultDirectory>(parameters.output_directory(), files);

    setup_system();
    const double fraction = elastic_limit_fraction();
    if (fraction >= 1.)
      {
        // Nothing yields: the elastic code's answer is the answer.
        if (fraction < 1e100)
          out << "  the fit stays elastic: its largest von Mises stress is "
              << std::setprecision(4) << 100. / fraction
              << " % of the yield strength; the elastic results follow\n"
              << std::defaultfloat;
        else
          out << "  the fit stays elastic: no stress in the bodies that may "
                 "yield; the elastic results follow\n";
        directory.reset();
        bodies.clear();
        coupling.reset();
        // The elastic code's run: nothing yields, so the bodies are elastic.
        Parameters elastic        = parameters;
        elastic.shaft.plastic     = false;
        elastic.hub.plastic       = false;
        const CaseFigures figures = run_case(elastic, out, verbose);
        return figures.converged ? 0 : 2;
      }
    if (!method_note.empty())
      out << "  " << method_note << '\n';
    out << "  first yield at " << std::setprecision(4) << 100. * fraction
        << " % of the interference (U " << 2. * parameters.geometry.d * fraction
        << " mm); " << parameters.load_path.increments
        << " increments to the full interference, "
        << (coupling->monolithic() ? "monolithic (Newton on the joint)" :
                                     "staggered (Dirichlet-Neumann, IQN-ILS)")
        << '\n'
        << std::defaultfloat;
    solve();
    postprocess();
    output_results(directory->staging_path());
    directory->commit(out);
    out << "  results in " << parameters.output_directory() << '\n';
    (void)start;
    if (!completed)
      {
        std::cerr << "coaxfit: " << failure << "; the state at "
                  << std::setprecision(4) << 100. * reached
                  << " % of the interference is written, marked not "
                     "converged"
                  << std::endl;
        return 2;
      }
    return 0;
  }



  void
  PlasticFit::output_results(const std::string &directory) const
  {
    const auto   start = std::chrono::steady_clock::now();
    const double U     = 2. * parameters.geometry.d;
    const double DF    = 2. * parameters.geometry.R1;

    // The report.
    out << "\n  state after joining" << (completed ? "" : " (NOT COMPLETED)")
        << ": " << increments.size() << " increments, " << total_steps
        << " coupling steps, " << body_solves << " body solves\n"
        << std::fixed << std::setprecision(2) << "  pressure p(0) " << p_mid
        << " MPa, mean " << p_mean << " MPa, min " << p_min << ", max " << p_max
        << " MPa at z " << z_of_max << " mm\n";
    for (const BodyFigures &f : figures)
      {
        out << "  " << f.name << ": ";
        if (!f.yields)
          out << "elastic (max von Mises " << f.max_von_mises << " MPa)\n";
        else
          out << "plastic to D " << f.plastic_diameter_mid
              << " mm at the mid-plane (" << std::setprecision(0)
              << 100. * f.utilisation << " % of the wall)"
              << std::setprecision(2) << ", max equivalent plastic strain "
              << std::scientific << f.max_equivalent_plastic_strain
              << std::fixed
              << (f.fully_plastic ? "; FULLY PLASTIC through its wall: the "
                                    "pressure is near the limit the part "
                                    "can carry" :
                                    "")
              << '\n';
      }
    if (parameters.hub.plastic)
      out << "  estimate (thick-walled cylinder, 2 R_e / sqrt 3): p "
          << din_estimate << " MPa at the FE's D_p, fully plastic " << din_limit
          << " MPa\n";
    if (radial_valid)
      out << "  radial model (plane stress): p " << radial.pressure
          << " MPa, hub plastic to D " << radial.plastic_diameter[1] << " mm; ";
    else
      out << "  radial model (plane stress): did not converge; ";
    out << "elastic (Lame) p " << elastic_lame << " MPa\n"
        << "  torque capacity " << torque_capacity << " N m (mu "
        << parameters.design.friction_coefficient << ")";
    if (slip_safety > 0.)
      out << ", safety against slip " << slip_safety;
    out << '\n' << std::defaultfloat;

    // parameters.prm: repeats the run.
    {
      const std::string name = directory + "/parameters.prm";
      std::ofstream     file = open_result_file(name);
      file << parameters.used_prm;
      close_result_file(file, name);
    }
    // contact_pressure.csv, as the elastic run writes it.
    {
      const std::string         name = directory + "/contact_pressure.csv";
      std::ofstream             file = open_result_file(name);
      const BodyDiscretization &hub  = *scene.bodies[1].discretization;
      const Vector<double>      u1
        = scene.bodies[0].discretization->interface_radial_values(
          bodies[0]->solution());
      const Vector<double> u2
        = hub.interface_radial_values(bodies[1]->solution());
      file << "z_mm,pressure_MPa,u_r_shaft_mm,u_r_hub_mm,gap_mm,status\n"
           << std::setprecision(12);
      for (unsigned int i = 0; i < pressure.size(); ++i)
        file << hub.interface_z()[i] << ',' << pressure[i] << ',' << u1[i]
             << ',' << u2[i] << ',' << coupling->gap()[i] << ','
             << (coupling->active()[i] ? "contact" : "separated") << '\n';
      close_result_file(file, name);
    }
    // load_path.csv: the increments.
    {
      const std::string name = directory + "/load_path.csv";
      std::ofstream     file = open_result_file(name);
      file << "increment,fraction,U_mm,coupling_steps,max_newton_iterations,"
              "halvings,mean_pressure_MPa\n"
           << std::setprecision(10);
      for (unsigned int k = 0; k < increments.size(); ++k)
        file << k + 1 << ',' << increments[k].fraction << ','
             << increments[k].fraction * U << ',' << increments[k].steps << ','
             << increments[k].max_iterations << ',' << increments[k].halvings
             << ',' << increments[k].mean_pressure << '\n';
      close_result_file(file, name);
    }
    // A VTU per body and solution.pvd.
    if (parameters.output.write_vtu)
      {
        const char *keys[2] = {"shaft", "hub"};
        for (unsigned int b = 0; b < 2; ++b)
          {
            const std::string file = std::string(keys[b]) + ".vtu";
            check_values_for_output(bodies[b]->solution(), file);
            write_result_file(directory + "/" + file, [&](std::ostream &vtu) {
              bodies[b]->output_results(vtu, b, scene.oversize(b));
            });
          }
        const std::string name = directory + "/solution.pvd";
        std::ofstream     pvd  = open_result_file(name);
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
        for (unsigned int b = 0; b < 2; ++b)
          pvd << "<DataSet timestep=\"0\" group=\"\" part=\"" << b
              << "\" name=\"" << keys[b] << "\" file=\"" << keys[b]
              << ".vtu\"/>\n";
        pvd << "</Collection>\n</VTKFile>\n";
        close_result_file(pvd, name);
      }

    // summary.json, last.
    auto number = [](const double x) {
      return std::isfinite(x) ? Json(x) : Json(nullptr);
    };
    Json j;
    j["variant"]             = parameters.case_name;
    j["model"]               = "elastic-plastic";
    j["converged"]           = completed;
    j["iterations"]          = total_steps;
    const Json pressure_json = {{"at_mid_plane", number(p_mid)},
                                {"mean", number(p_mean)},
                                {"min", number(p_min)},
                                {"max", number(p_max)},
                                {"z_of_max", z_of_max},
                                {"lame", elastic_lame}};
    j["pressure"]            = pressure_json;
    j["contact"]             = {{"separated_points", separated_points}};
    j["fit"]                 = {{"U_used", U}};
    Json joint               = {{"name", "Shaft-Hub"},
                                {"diameter", DF},
                                {"diametral_interference", U},
                                {"pressure", pressure_json},
                                {"contact",
                                 {{"closed", separated_points == 0},
                                  {"separated_points", separated_points}}}};
    j["joints"]              = Json::array({joint});
    Json plasticity;
    plasticity["elastic_limit_fraction"] = elastic_fraction;
    plasticity["elastic_limit_U"]        = elastic_fraction * U;
    Json bodies_json                     = Json::array();
    for (const BodyFigures &f : figures)
      {
        Json b = {{"name", f.name},
                  {"plasticity", f.plastic_model ? "von Mises" : "none"},
                  {"yields", f.yields},
                  {"fully_plastic", f.fully_plastic},
                  {"max_von_mises", f.max_von_mises},
                  {"max_equivalent_plastic_strain",
                   f.max_equivalent_plastic_strain}};
        if (f.yields)
          b["plastic_zone"]
            = {{"diameter_at_mid_plane", f.plastic_diameter_mid},
               {"utilisation", f.utilisation},
               {"r_min", f.r_min},
               {"r_max", f.r_max},
               {"z_max", f.z_max}};
        bodies_json.push_back(b);
      }
    plasticity["bodies"] = bodies_json;
    if (parameters.hub.plastic)
      plasticity["estimate"]
        = {{"formula",
            "p = (2 R_e / sqrt 3) (ln(D_p / D_F) + (1 - (D_p / D_aA)^2) / 2)"},
           {"pressure_at_fe_plastic_diameter", din_estimate},
           {"pressure_fully_plastic", din_limit}};
    if (radial_valid)
      plasticity["radial_model"]
        = {{"state", "plane stress"},
           {"pressure", radial.pressure},
           {"plastic_diameter_hub", radial.plastic_diameter[1]},
           {"plastic_diameter_shaft", radial.plastic_diameter[0]},
           {"fully_plastic_hub", radial.fully_plastic[1]}};
    else
      plasticity["radial_model"] = nullptr;
    j["plasticity"] = plasticity;
    Json path;
    path["stages"]           = Json::array({"joining"});
    path["reached_fraction"] = reached;
    path["increments"]       = increments.size();
    path["failure"]          = failure;
    unsigned int halvings    = 0;
    for (const Increment &i : increments)
      halvings += i.halvings;
    path["halvings"]    = halvings;
    path["method_note"] = method_note;
    j["load_path"]      = path;
    j["coupling"]
      = {{"method", coupling->monolithic() ? "monolithic" : "staggered"},
         {"steps", total_steps},
         {"body_solves", body_solves},
         {"newton_iterations",
          {{"shaft", bodies[0]->n_newton_iterations()},
           {"hub", bodies[1]->n_newton_iterations()}}},
         {"factorizations",
          {{"shaft", bodies[0]->n_factorizations()},
           {"hub", bodies[1]->n_factorizations()}}}};
    Json design
      = {{"friction_coefficient", parameters.design.friction_coefficient},
         {"torque_capacity", torque_capacity}};
    if (slip_safety > 0.)
      design["safety_slip"] = slip_safety;
    j["design"]            = design;
    j["mesh"]              = {{"cells",
                               {{"shaft", scene.bodies[0].discretization->n_cells()},
                                {"hub", scene.bodies[1].discretization->n_cells()}}},
                              {"n_dofs",
                               {{"shaft", scene.bodies[0].discretization->n_dofs()},
                                {"hub", scene.bodies[1].discretization->n_dofs()}}},
                              {"interface_points",
                               scene.bodies[1].discretization->n_interface_points()}};
    j["timing"]            = {{"setup", time_setup},
                              {"solve", time_solve},
                              {"output",
                               std::chrono::duration<double>(
                      std::chrono::steady_clock::now() - start)
                                 .count()}};
    const std::string name = directory + "/summary.json";
    std::ofstream     file = open_result_file(name);
    file << std::setw(2) << j << '\n';
    close_result_file(file, name);
  }
} // namespace coaxfit
