#include <coaxfit/design/design_report.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    std::string
    material_line(const Material &m)
    {
      std::ostringstream s;
      const auto         given = [](const double x, const std::string &unit) {
        return x > 0. ? design_figure(x) + unit : std::string("not given");
      };
      s << m.name << ": E " << m.E << " MPa, nu " << m.nu << ", yield "
        << given(m.yield_strength, " MPa") << ", R_m "
        << given(m.tensile_strength, " MPa") << ", " << to_string(m.kind)
        << "; expansion heating " << given(m.thermal_expansion, "/K")
        << ", cooling " << given(m.cooling_expansion, "/K")
        << "; temperature limit " << given(m.temperature_limit, " C");
      if (!m.temperature_limit_reason.empty())
        s << " (" << m.temperature_limit_reason << ")";
      return s.str();
    }

    /** The inputs in the terms of a drawing and of DIN 7190. */
    void
    write_inputs(std::ostream &out, const RunResults &results)
    {
      const Parameters         &p = results.parameters;
      const GeometryParameters &g = p.geometry;
      std::string               cells;
      unsigned int              dofs = 0;
      for (const Body &body : results.scene.bodies)
        {
          cells += (cells.empty() ? "" : " + ")
                   + std::to_string(body.discretization->n_cells());
          dofs += body.discretization->n_dofs();
        }
      out << "## Inputs\n\n| | |\n|---|---|\n"
          << "| joint diameter D_F | " << 2. * g.R1 << " mm |\n"
          << "| shaft bore diameter D_iI | "
          << (g.R0 > 0. ? design_figure(2. * g.R0) + " mm" :
                          std::string("solid"))
          << " |\n"
          << "| hub outer diameter D_aA | " << 2. * g.R2 << " mm |\n"
          << "| hub length, shaft length | " << 2. * g.L2 << " mm, "
          << 2. * g.L1 << " mm (hub centred; joint length "
          << 2. * g.contact_length() << " mm) |\n"
          << (p.sections ?
                "| shaft section (z, D) | " + p.drawing.shaft_section
                  + " |\n| hub section (z, D) | " + p.drawing.hub_section
                  + " |\n| model | the half z >= "
                  + design_figure(p.sections->drawing_offset())
                  + " of both sections (symmetric), D_aA "
                    "above averaged over the joint |\n" :
                std::string())
          << "| interference | " << interference_line(p) << " |\n"
          << "| shaft | " << material_line(p.shaft) << " |\n"
          << "| hub | " << material_line(p.hub) << " |\n"
          << "| friction: slip, press-in | " << p.design.friction_coefficient
          << " (" << p.design.friction_source << "), "
          << p.design.press_in_friction_coefficient << " |\n"
          << "| required torque, axial force | " << p.design.required_torque
          << " N m, " << p.design.required_axial_force << " N |\n"
          << "| mesh | " << cells << " cells, " << dofs << " DoFs, FE_Q("
          << p.mesh.degree << ") |\n\n";
    }
  } // namespace



  std::string
  ReportWriter::write(const RunResults  &results,
                      const std::string &directory) const
  {
    const std::string name = directory + "/" + file_names()[0];
    std::ofstream     out  = open_result_file(name);
    const FitDesign  &d    = results.design;
    const Parameters &p    = results.parameters;
    out << std::setprecision(6) << "# coaxfit report: " << p.case_name << "\n\n"
        << (results.solver.converged() ? "Converged" : "**NOT converged**")
        << " in " << results.solver.n_steps()
        << " coupling steps. Units: mm, MPa, N, N m.\n\n";
    out << "## Verdict\n\n";
    if (results.verdict.ok())
      out << "OK: the surfaces touch, the joint carries the required loads "
             "with Design/Slip safety = "
          << p.design.slip_safety
          << ", shaft and hub keep Design/Yield safety = "
          << p.design.yield_safety
          << " at assembly and in service, and the joint can be "
             "assembled.\n\n";
    else
      {
        out << "**FAILED:**\n\n";
        for (const std::string &f : results.verdict.failed)
          out << "- " << f << '\n';
        out << '\n';
      }
    write_inputs(out, results);

    out << "## Design: finite elements next to DIN 7190\n\n"
        << "| figure | FE | DIN 7190 |\n|---|---:|---:|\n";
    for (const DesignRow &row : design_rows(d))
      out << "| " << row.label << " | " << design_figure(row.fe) << " | "
          << design_figure(row.din) << " |\n";
    out << "\nDIN 7190 assumes a hub and shaft of equal length (Lame's plane "
           "stress); the finite element column includes the end effects. "
           "Von Mises stress: of the full stress state for FE, of Lame's "
           "plane stress for DIN 7190. DIN 7190 checks slip with the smallest "
           "interference (Fit/Case = min) and strength and the press-in "
           "force with the largest (max); Fit/Case = all gives both. The yield "
           "safeties come from the mid-plane points and the largest stress "
           "over the middle half of the joint, which converge under "
           "refinement; the end of the joint is assessed as a notch on its "
           "own, from the largest stress at least "
        << d.edge_distance
        << " mm from the end (Design/Edge distance), for the stresses are "
           "singular at the end itself (there: ";
    for (const FitDesign::SurfaceMaximum &m : d.surface_maxima)
      out << corner_text(m) << (&m == &d.surface_maxima.back() ? "" : "; ");
    out << "; these grow under mesh refinement and are not design "
           "figures).\n\n";

    const PressureSummary &ps = results.pressure;
    out << "## Contact\n\npressure at the mid-plane "
        << design_figure(ps.at_mid_plane) << " MPa, mean "
        << design_figure(ps.mean) << " MPa, Lame " << design_figure(ps.lame)
        << " MPa; largest " << design_figure(ps.max)
        << " MPa at z = " << design_figure(ps.z_of_max)
        << " mm (singular). Separated zones: ";
    const auto zones = results.solver.get_active_set().separated_zones(
      results.interface.z(), p.geometry.joint_start(), p.geometry.joint_end());
    if (zones.empty())
      out << "none";
    for (const auto &zone : zones)
      out << "[" << design_figure(zone.first) << ", "
          << design_figure(zone.second) << "] mm ";
    out << ".\n\n## Operation\n\n";
    results.operation.print_markdown(out);
    out << "\n## Warnings\n\n";
    if (results.warnings.empty())
      out << "none\n";
    for (const std::string &w : results.warnings)
      out << "- " << w << '\n';

    out << "\n## Plots\n\n";
    bool any = false;
    for (const std::string png :
         {"contact_pressure.png", "surface_stresses.png", "convergence.png"})
      if (std::filesystem::exists(directory + "/" + png))
        {
          out << "![" << png << "](" << png << ")\n\n";
          any = true;
        }
    if (!any)
      out << "none (Output/Write plots = false, or gnuplot not "
             "installed)\n";
    close_result_file(out, name);
    return file_names()[0] + ": inputs, design table, warnings, plots";
  }



  std::vector<std::string>
  ReportWriter::file_names() const
  {
    return {"report.md"};
  }
} // namespace coaxfit
