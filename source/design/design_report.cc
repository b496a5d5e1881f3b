#include <coaxfit/design/design_report.h>
#include <coaxfit/fe/section_scene.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace coaxfit
{
  std::vector<DesignRow>
  design_rows(const FitDesign &design)
  {
    const double           nan = FitDesign::unknown;
    std::vector<DesignRow> rows{
      {"joint pressure, mean (MPa)", design.mean_pressure, design.pressure_din},
      {"torque capacity (N m)",
       design.torque_capacity,
       design.torque_capacity_din},
      {"axial force capacity (N)",
       design.axial_force_capacity,
       design.axial_force_capacity_din},
      {"press-in force (N)", design.press_in_force, design.press_in_force_din},
      {"safety against slip", design.safety_slip, design.safety_slip_din}};
    for (const FitDesign::CheckPoint &c : design.check_points)
      {
        rows.push_back(
          {c.name + ": hoop stress (MPa)", c.fe.hoop(), c.din.hoop});
        rows.push_back(
          {c.name + ": radial stress (MPa)", c.fe.radial(), c.din.radial});
        rows.push_back({c.name + ": von Mises stress (MPa)",
                        c.fe.von_mises(),
                        c.din.equivalent()});
      }
    for (const FitDesign::SurfaceMaximum &m : design.surface_maxima)
      {
        std::ostringstream label;
        label << std::fixed << std::setprecision(2) << m.name
              << ": max von Mises, middle half (MPa, z " << m.interior_z << ")";
        rows.push_back({label.str(), m.interior, nan});
        label.str("");
        label << m.name << ": max von Mises, off the ends (MPa, z " << m.z
              << ")";
        rows.push_back({label.str(), m.von_mises, nan});
      }
    rows.push_back({"safety against yield, hub",
                    design.safety_yield_hub,
                    design.safety_yield_hub_din});
    rows.push_back({"safety against yield with the end (notch), hub",
                    design.safety_yield_hub_edge,
                    nan});
    if (!std::isnan(design.hoop_stress_max_hub))
      {
        rows.push_back({"hub (brittle): max hoop stress (MPa)",
                        design.hoop_stress_max_hub,
                        design.hoop_stress_max_hub_din});
        rows.push_back({"safety against fracture (brittle, sigma_t vs R_m)",
                        design.safety_fracture_hub,
                        design.safety_fracture_hub_din});
      }
    rows.push_back({"safety against yield, shaft",
                    design.safety_yield_shaft,
                    design.safety_yield_shaft_din});
    rows.push_back({"safety against yield with the end (notch), shaft",
                    design.safety_yield_shaft_edge,
                    nan});
    return rows;
  }



  std::string
  figure_text(const double value, const int precision)
  {
    if (std::isnan(value))
      return "-";
    if (std::isinf(value))
      return value > 0. ? "infinite" : "-infinite";
    std::ostringstream s;
    s << std::setprecision(precision) << value;
    return s.str();
  }



  std::string
  design_figure(const double value)
  {
    // +infinity: a safety of an unloaded part; -infinity is not a figure.
    if (std::isinf(value) && value < 0.)
      return "-";
    return figure_text(value, std::abs(value) >= 1e5 ? 4 : 5);
  }



  std::string
  corner_text(const FitDesign::SurfaceMaximum &m)
  {
    std::ostringstream text;
    text << m.name << " " << std::setprecision(4) << m.corner << " MPa";
    if (std::isfinite(m.corner_coarser) && m.corner_coarser > 0.)
      text << " (one refinement coarser " << m.corner_coarser << " MPa: x"
           << std::setprecision(3) << m.corner / m.corner_coarser
           << " per refinement, singular)";
    else
      text << " (singular, grows with refinement)";
    return text.str();
  }



  std::string
  interference_line(const Parameters &parameters)
  {
    const FitLimits   &f = parameters.fit_limits;
    std::ostringstream line;
    line << std::setprecision(4) << "U = " << f.used() << " mm";
    if (!f.iso_fit.empty())
      line << " (" << f.iso_fit << " at D_F = " << 2. * parameters.geometry.R1
           << " mm: U_min " << f.U_min << ", U_max " << f.U_max << " mm; case "
           << to_string(f.fit_case) << ")";
    if (parameters.sections && parameters.sections->conical())
      line << " (taper C = " << parameters.sections->taper() << ", half angle "
           << std::atan(0.5 * parameters.sections->taper()) * 180. / M_PI
           << " degrees, pushed on by a = " << parameters.fit.push_on_distance
           << " mm: U = a C)";
    line << ", smoothing loss " << f.smoothing_loss
         << " mm, effective U_w = " << 2. * parameters.geometry.d << " mm";
    return line.str();
  }



  void
  print_design(std::ostream     &out,
               const Parameters &parameters,
               const FitDesign  &design)
  {
    std::ostringstream table;
    table << "  design: " << interference_line(parameters) << '\n'
          << "    friction against slip "
          << parameters.design.friction_coefficient << " ("
          << parameters.design.friction_source << ")\n"
          << "    " << std::left << std::setw(56) << "" << std::right
          << std::setw(12) << "FE" << std::setw(12) << "DIN 7190" << '\n';
    for (const DesignRow &row : design_rows(design))
      {
        table << "    " << std::left << std::setw(56) << row.label
              << std::right;
        for (const double value : {row.fe, row.din})
          {
            table << std::setw(12) << design_figure(value);
          }
        table << '\n';
      }
    table << "    (von Mises: FE of its full stress state, DIN 7190 of "
             "Lame's plane stress; the yield safeties from the mid-plane "
             "points and the middle half of the joint, where the FE "
             "stresses converge under refinement; the notch safeties from "
             "the maxima near the end, at least "
          << std::setprecision(3) << design.edge_distance
          << " mm from it (Design/Edge distance; they depend on it and on "
             "the mesh)";
    for (const FitDesign::SurfaceMaximum &m : design.surface_maxima)
      table << "; at the end, " << corner_text(m);
    table << ")\n";
    if (design.cone_sin > 0.)
      {
        const double tan_beta = design.cone_sin / design.cone_cos;
        const double mu       = parameters.design.friction_coefficient;
        table << std::setprecision(5)
              << "    (taper: the hub is held where it is pushed on by "
              << design.push_on_force
              << " N without friction (FE; thick-walled estimate "
              << design.push_on_force_din
              << " N), the press-in force adds friction along the cone; "
              << (mu > tan_beta ? "self-locking" : "NOT self-locking")
              << ": mu = " << mu << (mu > tan_beta ? " > " : " <= ")
              << "tan(half angle) = " << tan_beta
              << (mu > tan_beta ?
                    ", the axial force capacity is what holds the hub "
                    "against pulling off)\n" :
                    ", the hub slides off when the push-on force is "
                    "released: secure it axially)\n");
      }
    if (parameters.sections)
      table << "    (sections: the DIN 7190 column is the plain-cylinder "
               "estimate, a hub of D_aA = "
            << design_figure(2. * parameters.geometry.R2)
            << " mm (its outer diameter averaged over the joint) and l_F = "
            << design_figure(2. * parameters.geometry.contact_length())
            << " mm; FE's hub outer surface is the section's largest "
               "diameter on the mid-plane, D = "
            << design_figure(2.
                             * parameters.sections->hub_outer_radius_at_plane())
            << " mm)\n";
    out << table.str();
  }
} // namespace coaxfit
