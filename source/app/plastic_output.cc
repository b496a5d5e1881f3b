#include <coaxfit/app/case_batch.h>
#include <coaxfit/app/fit_case_study.h>
#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_directory.h>
#include <coaxfit/io/result_writers.h>

#include <algorithm>
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

    /** The file name @p base + @p extension of a stage (joining: none). */
    std::string
    stage_file(const std::string              &base,
               const LoadPathParameters::Stage stage,
               const std::string              &extension)
    {
      return stage == LoadPathParameters::Stage::joining ?
               base + extension :
               base + "_" + to_string(stage) + extension;
    }

    /** A number for JSON, null where it is not finite. */
    Json
    number(const double x)
    {
      return std::isfinite(x) ? Json(x) : Json(nullptr);
    }

    /** The plastic figures of one body as JSON. */
    Json
    figures_json(const PlasticFit::BodyFigures &f)
    {
      Json b
        = {{"name", f.name},
           {"plasticity", f.plastic_model ? "von Mises" : "none"},
           {"yields", f.yields},
           {"fully_plastic", f.fully_plastic},
           {"max_von_mises", f.max_von_mises},
           {"max_equivalent_plastic_strain", f.max_equivalent_plastic_strain}};
      if (f.yields)
        b["plastic_zone"] = {{"diameter_at_mid_plane", f.plastic_diameter_mid},
                             {"utilisation", f.utilisation},
                             {"r_min", f.r_min},
                             {"r_max", f.r_max},
                             {"z_max", f.z_max}};
      return b;
    }

    /** The report lines of the bodies' plastic figures. */
    void
    print_figures(std::ostream                               &out,
                  const std::vector<PlasticFit::BodyFigures> &figures,
                  const bool                                  loaded)
    {
      for (const PlasticFit::BodyFigures &f : figures)
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
                << (!f.fully_plastic ? "" :
                    loaded           ? "; FULLY PLASTIC through its wall: the "
                                       "pressure is near the limit the part "
                                       "can carry" :
                                       "; plastic through its wall (in an "
                                       "earlier stage)")
                << '\n';
        }
    }
  } // namespace



  std::set<std::string>
  PlasticFit::file_names()
  {
    std::set<std::string> names
      = {"summary.json", "parameters.prm", "load_path.csv", "solution.pvd"};
    for (const auto stage : {LoadPathParameters::Stage::joining,
                             LoadPathParameters::Stage::operation,
                             LoadPathParameters::Stage::unloading,
                             LoadPathParameters::Stage::disassembly})
      for (const std::string base : {"contact_pressure", "shaft", "hub"})
        names.insert(stage_file(base,
                                stage,
                                base == "contact_pressure" ? ".csv" : ".vtu"));
    return names;
  }



  int
  PlasticFit::run()
  {
    check_scope();
    stage_list = parameters.load_path.stages(parameters.operation.has_loads(),
                                             parameters.contact.unilateral);
    out << "coaxfit: " << parameters.case_name << ", elastic-plastic ("
        << (parameters.shaft.plastic ? "shaft" : "")
        << (parameters.shaft.plastic && parameters.hub.plastic ? " and " : "")
        << (parameters.hub.plastic ? "hub" : "") << " von Mises), U "
        << 2. * parameters.geometry.d << " mm\n";
    check_memory(parameters);
    // The target is checked before any work; it may hold the files of an
    // elastic run of the same case.
    std::set<std::string> files = all_result_file_names();
    for (const std::string &f : file_names())
      files.insert(f);
    auto directory
      = std::make_unique<ResultDirectory>(parameters.output_directory(), files);

    setup_system();
    if (stays_elastic())
      {
        // The elastic code writes its own directory.
        directory.reset();
        return run_elastic("");
      }
    print_path();
    solve();
    postprocess();
    output_results(directory->staging_path());
    directory->commit(out);
    out << "  results in " << parameters.output_directory() << '\n';
    if (!completed)
      report_failure();
    return completed ? 0 : 2;
  }



  int
  PlasticFit::run_in(const std::string &directory)
  {
    // The selection that called it writes report.md.
    checks_a_selection = true;
    check_scope();
    stage_list = parameters.load_path.stages(parameters.operation.has_loads(),
                                             parameters.contact.unilateral);
    setup_system();
    if (stays_elastic())
      return run_elastic(directory);
    print_path();
    solve();
    postprocess();
    output_results(directory);
    if (!completed)
      report_failure();
    return completed ? 0 : 2;
  }



  bool
  PlasticFit::compute()
  {
    check_scope();
    stage_list = parameters.load_path.stages(parameters.operation.has_loads(),
                                             parameters.contact.unilateral);
    setup_system();
    elastic_limit_fraction();
    return solve();
  }



  bool
  PlasticFit::stays_elastic()
  {
    using Stage       = LoadPathParameters::Stage;
    const auto listed = [&](const Stage s) {
      return std::find(stage_list.begin(), stage_list.end(), s)
             != stage_list.end();
    };
    // The state of operation first: the state of assembly is the one the
    // load path starts from.
    const double operation_ratio
      = listed(Stage::operation) ? operation_yield_ratio() : 0.;
    const double fraction = elastic_limit_fraction();
    if (!(fraction >= 1. && operation_ratio < 1. && !listed(Stage::unloading)
          && !listed(Stage::disassembly)))
      return false;
    // Nothing yields: the elastic code's answer is the answer.
    if (fraction < 1e100 || operation_ratio > 0.)
      {
        out << "  the fit stays elastic: its largest von Mises stress is "
            << std::setprecision(4) << 100. / fraction
            << " % of the yield strength";
        if (listed(Stage::operation))
          out << " after joining, " << 100. * operation_ratio
              << " % in operation";
        out << "; the elastic results follow\n" << std::defaultfloat;
      }
    else
      out << "  the fit stays elastic: no stress in the bodies that may "
             "yield; the elastic results follow\n";
    return true;
  }



  int
  PlasticFit::run_elastic(const std::string &directory)
  {
    bodies.clear();
    coupling.reset();
    // The elastic code's run: nothing yields, so the bodies are elastic.
    Parameters elastic        = parameters;
    elastic.shaft.plastic     = false;
    elastic.hub.plastic       = false;
    const CaseFigures figures = run_case(elastic, out, verbose, directory);
    return figures.converged ? 0 : 2;
  }



  void
  PlasticFit::print_path() const
  {
    if (!method_note.empty())
      out << "  " << method_note << '\n';
    if (elastic_fraction < 1.)
      out << "  first yield at " << std::setprecision(4)
          << 100. * elastic_fraction << " % of the interference (U "
          << 2. * parameters.geometry.d * elastic_fraction << " mm); ";
    else
      out << "  joining stays elastic (" << std::setprecision(4)
          << 100. / elastic_fraction << " % of the yield strength); ";
    out << "stages";
    for (const LoadPathParameters::Stage s : stage_list)
      out << (s == stage_list.front() ? " " : ", ") << to_string(s);
    out << ", " << parameters.load_path.increments << " increments each, "
        << (coupling->monolithic() ? "monolithic (Newton on the joint)" :
                                     "staggered (Dirichlet-Neumann, IQN-ILS)")
        << '\n'
        << std::defaultfloat;
  }



  void
  PlasticFit::report_failure() const
  {
    const StageResult &last = stages.back();
    std::cerr << "coaxfit: " << failure << "; the last converged state ("
              << to_string(last.kind) << " at " << std::setprecision(4)
              << 100. * last.fraction << " % of the interference, "
              << 100. * last.load_factor
              << " % of the loads of operation) is written, marked not "
                 "converged"
              << std::endl;
  }



  void
  PlasticFit::output_results(const std::string &directory) const
  {
    using Stage               = LoadPathParameters::Stage;
    const auto         start  = std::chrono::steady_clock::now();
    const double       U      = 2. * parameters.geometry.d;
    const double       DF     = 2. * parameters.geometry.R1;
    const StageResult &joined = stages.front();

    // The report: the state after each stage.
    out << '\n' << std::fixed << std::setprecision(2);
    for (const StageResult &stage : stages)
      {
        out << "  state after " << to_string(stage.kind)
            << (stage.completed ? "" : " (NOT COMPLETED)") << ": U "
            << std::setprecision(4) << stage.fraction * U << " mm";
        if (parameters.operation.has_loads())
          out << ", loads of operation x " << std::setprecision(2)
              << stage.load_factor;
        out << '\n' << std::setprecision(2);
        if (stage.separated_points == stage.pressure.size())
          out << "  the joint is open everywhere (no contact)\n";
        else
          out << "  pressure p(0) " << stage.p_mid << " MPa, mean "
              << stage.p_mean << " MPa, min " << stage.p_min << ", max "
              << stage.p_max << " MPa at z " << stage.z_of_max
              << " mm; torque capacity " << stage.torque_capacity << " N m\n";
        print_figures(out,
                      stage.figures,
                      stage.kind == Stage::joining
                        || stage.kind == Stage::operation);
        if (stage.kind == Stage::disassembly)
          {
            // Below the digits printed (a body that stayed elastic comes
            // back to round-off): no change.
            const auto shown
              = [](const double x) { return std::abs(x) < 5e-6 ? 0. : x; };
            out << "  permanent change of diameter: hub bore "
                << std::setprecision(5) << shown(stage.hub_bore_change)
                << " mm, shaft " << shown(stage.shaft_diameter_change)
                << " mm\n"
                << std::setprecision(2);
          }
      }
    out << "  " << increments.size() << " increments, " << total_steps
        << " coupling steps, " << body_solves << " body solves\n";
    if (parameters.hub.plastic && joined.figures[1].yields)
      out << "  estimate (thick-walled cylinder, 2 R_e / sqrt 3): p "
          << din_estimate << " MPa at the FE's D_p after joining, fully "
          << "plastic " << din_limit << " MPa\n";
    else if (parameters.hub.plastic)
      out << "  estimate (thick-walled cylinder): the hub stays elastic in "
          << "joining, fully plastic at " << din_limit << " MPa\n";
    if (radial_valid)
      out << "  radial model (plane stress): p " << radial.pressure
          << " MPa, hub plastic to D " << radial.plastic_diameter[1] << " mm; ";
    else
      out << "  radial model (plane stress): "
          << (parameters.geometry.d > 0. ? "did not converge; " :
                                           "no interference (a clearance)");
    if (parameters.geometry.d > 0.)
      out << "elastic (Lame) p " << elastic_lame << " MPa";
    out << "\n"
        << "  torque capacity after joining " << joined.torque_capacity
        << " N m (mu " << parameters.design.friction_coefficient << ")";
    if (joined.slip_safety > 0.)
      out << ", safety against slip " << joined.slip_safety;
    out << '\n';
    const StageResult &least = least_torque_stage();
    if (&least != &joined)
      {
        out << "  least torque capacity " << least.torque_capacity
            << " N m, after " << to_string(least.kind);
        if (least.slip_safety > 0.)
          out << ", safety against slip " << least.slip_safety
              << (least.slip_safety < 1. ? " (BELOW 1: the fit slips)" : "");
        out << '\n';
      }
    if (parameters.design.plastic_utilisation > 0.)
      {
        // Check mode with an allowed utilisation: the hub's, largest over
        // the stages (the zone never shrinks), against it.
        const double used = largest_hub_utilisation();
        out << "  plastic utilisation of the hub " << std::setprecision(1)
            << 100. * used << " % against the allowed "
            << 100. * parameters.design.plastic_utilisation << " %"
            << (used > parameters.design.plastic_utilisation ?
                  ": BEYOND the allowed (Design/Plastic utilisation)" :
                  ": within")
            << std::setprecision(2) << '\n';
      }
    const std::vector<std::string> failed = verdict_failures();
    out << "Verdict: " << (failed.empty() ? "OK" : "FAILED");
    for (const std::string &f : failed)
      out << (&f == &failed.front() ? ": " : "; ") << f;
    out << '\n';
    if (parameters.output.write_report)
      write_report(directory, failed);
    if (parameters.output.write_plots && !checks_a_selection)
      out
        << "  (the plots are written by the elastic code; "
           "an elastic-plastic run writes summary.json, report.md, the CSV and VTU "
           "files)\n";
    out << std::defaultfloat;

    // parameters.prm: repeats the run.
    {
      const std::string name = directory + "/parameters.prm";
      std::ofstream     file = open_result_file(name);
      file << parameters.used_prm;
      close_result_file(file, name);
    }
    // contact_pressure.csv (joining, as the elastic run writes it) and one
    // per further stage.
    for (const StageResult &stage : stages)
      {
        const std::string name
          = directory + "/"
            + stage_file("contact_pressure", stage.kind, ".csv");
        std::ofstream file = open_result_file(name);
        file << stage.contact_csv;
        close_result_file(file, name);
      }
    // load_path.csv: the increments.
    {
      const std::string name = directory + "/load_path.csv";
      std::ofstream     file = open_result_file(name);
      file << "increment,stage,fraction,U_mm,load_factor,coupling_steps,"
              "max_newton_iterations,halvings,mean_pressure_MPa\n"
           << std::setprecision(10);
      for (unsigned int k = 0; k < increments.size(); ++k)
        {
          const Increment &i = increments[k];
          file << k + 1 << ',' << to_string(stages[i.stage].kind) << ','
               << i.fraction << ',' << i.fraction * U << ',' << i.load_factor
               << ',' << i.steps << ',' << i.max_iterations << ',' << i.halvings
               << ',' << i.mean_pressure << '\n';
        }
      close_result_file(file, name);
    }
    // A VTU per body and stage; solution.pvd with the stages as time steps.
    if (parameters.output.write_vtu)
      {
        const char *keys[2] = {"shaft", "hub"};
        for (const StageResult &stage : stages)
          for (unsigned int b = 0; b < 2; ++b)
            write_result_file(directory + "/"
                                + stage_file(keys[b], stage.kind, ".vtu"),
                              [&](std::ostream &vtu) { vtu << stage.vtu[b]; });
        const std::string name = directory + "/solution.pvd";
        std::ofstream     pvd  = open_result_file(name);
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
        for (unsigned int k = 0; k < stages.size(); ++k)
          for (unsigned int b = 0; b < 2; ++b)
            pvd << "<DataSet timestep=\"" << k << "\" group=\"\" part=\"" << b
                << "\" name=\"" << keys[b] << "\" file=\""
                << stage_file(keys[b], stages[k].kind, ".vtu") << "\"/>\n";
        pvd << "</Collection>\n</VTKFile>\n";
        close_result_file(pvd, name);
      }

    // summary.json, last.
    const auto pressure_json = [](const StageResult &stage) {
      return Json{{"at_mid_plane", number(stage.p_mid)},
                  {"mean", number(stage.p_mean)},
                  {"min", number(stage.p_min)},
                  {"max", number(stage.p_max)},
                  {"z_of_max", stage.z_of_max}};
    };
    Json j;
    j["case"]        = parameters.case_name;
    j["variant"]     = parameters.case_name;
    j["model"]       = "elastic-plastic";
    j["converged"]   = completed;
    j["verdict"]     = {{"ok", failed.empty()}, {"failed", failed}};
    j["iterations"]  = total_steps;
    Json pressure    = pressure_json(joined);
    pressure["lame"] = elastic_lame;
    j["pressure"]    = pressure;
    j["contact"]     = {{"separated_points", joined.separated_points}};
    j["fit"]         = {{"U_used", U}};
    Json joint       = {{"name", "Shaft-Hub"},
                        {"diameter", DF},
                        {"diametral_interference", U},
                        {"pressure", pressure},
                        {"contact",
                         {{"closed", joined.separated_points == 0},
                          {"separated_points", joined.separated_points}}}};
    j["joints"]      = Json::array({joint});
    Json plasticity;
    plasticity["elastic_limit_fraction"] = elastic_fraction;
    plasticity["elastic_limit_U"]        = elastic_fraction * U;
    Json bodies_json                     = Json::array();
    for (const BodyFigures &f : joined.figures)
      bodies_json.push_back(figures_json(f));
    plasticity["bodies"] = bodies_json;
    if (parameters.hub.plastic)
      plasticity["estimate"]
        = {{"formula",
            "p = (2 R_e / sqrt 3) (ln(D_p / D_F) + (1 - (D_p / D_aA)^2) / 2)"},
           {"pressure_at_fe_plastic_diameter",
            joined.figures[1].yields ? Json(din_estimate) : Json(nullptr)},
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
    // Every stage's state, joining first.
    Json stages_json = Json::array();
    for (const StageResult &stage : stages)
      {
        Json s = {{"name", to_string(stage.kind)},
                  {"completed", stage.completed},
                  {"U", stage.fraction * U},
                  {"load_factor", stage.load_factor},
                  {"pressure", pressure_json(stage)},
                  {"contact",
                   {{"closed", stage.separated_points == 0},
                    {"open_everywhere",
                     stage.separated_points == stage.pressure.size()},
                    {"separated_points", stage.separated_points}}},
                  {"torque_capacity", stage.torque_capacity}};
        if (stage.slip_safety > 0.)
          s["safety_slip"] = stage.slip_safety;
        s["hub_bore_diameter_change"] = stage.hub_bore_change;
        s["shaft_diameter_change"]    = stage.shaft_diameter_change;
        Json b                        = Json::array();
        for (const BodyFigures &f : stage.figures)
          b.push_back(figures_json(f));
        s["bodies"] = b;
        s["files"]  = {{"contact_pressure",
                        stage_file("contact_pressure", stage.kind, ".csv")},
                       {"shaft",
                       parameters.output.write_vtu ?
                          Json(stage_file("shaft", stage.kind, ".vtu")) :
                          Json(nullptr)},
                       {"hub",
                       parameters.output.write_vtu ?
                          Json(stage_file("hub", stage.kind, ".vtu")) :
                          Json(nullptr)}};
        stages_json.push_back(s);
      }
    j["stages"] = stages_json;
    Json path;
    Json names = Json::array();
    for (const Stage s : stage_list)
      names.push_back(to_string(s));
    path["stages"]           = names;
    path["reached_fraction"] = reached;
    path["increments"]       = increments.size();
    path["failure"]          = failure;
    path["halvings"]         = total_halvings;
    path["method_note"]      = method_note;
    j["load_path"]           = path;
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
         {"torque_capacity", joined.torque_capacity}};
    if (joined.slip_safety > 0.)
      design["safety_slip"] = joined.slip_safety;
    {
      // The stage in which the fit carries least (disassembly aside).
      const StageResult &least = least_torque_stage();
      design["least_torque_capacity"]
        = {{"stage", to_string(least.kind)},
           {"torque_capacity", least.torque_capacity},
           {"safety_slip",
            least.slip_safety > 0. ? Json(least.slip_safety) : Json(nullptr)}};
    }
    if (parameters.design.plastic_utilisation > 0.)
      design["plastic_utilisation"]
        = {{"hub", largest_hub_utilisation()},
           {"allowed", parameters.design.plastic_utilisation},
           {"within",
            largest_hub_utilisation()
              <= parameters.design.plastic_utilisation}};
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
