#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/design/design_report.h>
#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/required_loads.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** "after joining", "in operation", ... */
    std::string
    state_words(const LoadPathParameters::Stage kind)
    {
      return FitSelection::stage_words(to_string(kind));
    }

    /** A figure in words (4 digits). */
    std::string
    text(const double x)
    {
      return figure_text(x, 4);
    }
  } // namespace



  double
  PlasticFit::slip_safety(const StageResult &stage) const
  {
    const double required
      = required_friction_force(parameters.design, 2. * parameters.geometry.R1);
    return required > 0. ? parameters.design.friction_coefficient
                             * stage.normal_force / required :
                           std::nan("");
  }



  std::vector<std::string>
  PlasticFit::verdict_failures() const
  {
    using Stage = LoadPathParameters::Stage;
    std::vector<std::string> failed;
    if (!completed)
      failed.push_back("not converged: " + failure);
    // The states the fit is used in: disassembly takes it apart.
    const StageResult *least = nullptr;
    for (const StageResult &stage : stages)
      {
        if (stage.kind == Stage::disassembly)
          continue;
        if (stage.separated_points == stage.pressure.size())
          failed.push_back("the surfaces do not touch "
                           + state_words(stage.kind));
        if (!least || stage.normal_force < least->normal_force)
          least = &stage;
      }
    const double S = parameters.design.slip_safety;
    if (least && slip_safety(*least) < S)
      failed.push_back("safety against slip " + text(slip_safety(*least))
                       + " < " + text(S) + " " + state_words(least->kind)
                       + " (K_A times the required loads)");
    // The hub may yield as far as Design/Plastic utilisation allows; the
    // shaft not at all (a solid shaft plastic about its axis is lost).
    const double allowed    = parameters.design.plastic_utilisation;
    const double used       = largest_hub_utilisation();
    bool         hub_yields = false, shaft_yields = false;
    for (const StageResult &stage : stages)
      {
        shaft_yields = shaft_yields || stage.figures[0].yields;
        hub_yields   = hub_yields || stage.figures[1].yields;
      }
    if (hub_yields && used > allowed)
      failed.push_back(
        "plastic utilisation of the hub " + text(used) + " > " + text(allowed)
        + (allowed > 0. ? " (Design/Plastic utilisation)" :
                          " (Design/Plastic utilisation = 0 allows the hub "
                          "no yield: set the utilisation you allow)"));
    if (shaft_yields)
      failed.push_back("the shaft yields");
    return failed;
  }



  void
  PlasticFit::write_report(const std::string              &directory,
                           const std::vector<std::string> &failed) const
  {
    const GeometryParameters &g    = parameters.geometry;
    const std::string         name = directory + "/report.md";
    std::ofstream             md   = open_result_file(name);
    const double              U    = 2. * g.d;
    md << "# coaxfit report: elastic-plastic fit " << parameters.case_name
       << "\n\nD_F " << text(2. * g.R1) << " mm, hub D_aA " << text(2. * g.R2)
       << " mm, U " << text(U) << " mm; ";
    for (const Material *m : {&parameters.shaft, &parameters.hub})
      md << (m == &parameters.shaft ? "shaft " : ", hub ")
         << (m->plastic ? "von Mises, R_e " + text(m->yield_strength)
                            + " MPa, H " + text(m->hardening_modulus) + " MPa" :
                          std::string("elastic"));
    md << ".\n\n## Verdict\n\n";
    if (failed.empty())
      md << "Verdict: OK\n\n";
    else
      {
        md << "Verdict: FAILED\n\n";
        for (const std::string &f : failed)
          md << "- " << f << '\n';
        md << '\n';
      }
    md << "## The state after each stage\n\n| stage | U (mm) | loads x | "
          "p(0) (MPa) | mean (MPa) | min (MPa) | torque capacity (N m) | "
          "slip safety | hub D_p (mm) | hub utilisation | bore change (mm) "
          "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const StageResult &s : stages)
      {
        const BodyFigures &hub = s.figures[1];
        md << "| " << to_string(s.kind) << (s.completed ? "" : " (failed)")
           << " | " << text(s.fraction * U) << " | " << text(s.load_factor)
           << " | " << text(s.p_mid) << " | " << text(s.p_mean) << " | "
           << text(s.p_min) << " | " << text(s.torque_capacity) << " | "
           << (std::isnan(slip_safety(s)) ? std::string("-") :
                                            text(slip_safety(s)))
           << " | "
           << (hub.yields ? text(hub.plastic_diameter_mid) : std::string("-"))
           << " | " << text(hub.utilisation) << " | " << text(s.hub_bore_change)
           << " |\n";
      }
    md << "\nThe hub's plastic zone: D_p at the mid-plane, utilisation (D_p "
          "- D_F) / (D_aA - D_F); bore change: of the hub's bore diameter "
          "at the mid-plane (after disassembly the permanent one).\n\n"
       << "## Beside the finite elements (after joining)\n\n";
    if (parameters.hub.plastic && stages.front().figures[1].yields)
      md << "- thick-walled cylinder, p = (2 R_e / sqrt 3)(ln(D_p / D_F) + (1 "
            "- (D_p / D_aA)^2) / 2) at the FE's D_p: "
         << text(din_estimate) << " MPa (fully plastic " << text(din_limit)
         << " MPa)\n";
    if (radial_valid)
      md << "- radial model (plane stress, von Mises): p "
         << text(radial.pressure) << " MPa, hub plastic to D "
         << text(radial.plastic_diameter[1]) << " mm\n";
    if (g.d > 0.)
      md << "- elastic (Lame, plane stress): p " << text(elastic_lame)
         << " MPa\n";
    md << "\n## Load path\n\n"
       << increments.size() << " increments, " << total_steps
       << " coupling steps, " << total_halvings << " halvings; "
       << (elastic_fraction < 1. ?
             "first yield at " + text(100. * elastic_fraction)
               + " % of the interference" :
             std::string("joining stays elastic"))
       << ". Per increment: load_path.csv; per "
          "stage: contact_pressure_<stage>.csv and the VTU files "
          "(solution.pvd); all figures: summary.json.\n";
    close_result_file(md, name);
  }
} // namespace coaxfit
