#include <coaxfit/lame.h>
#include <coaxfit/monolithic_solver.h>
#include <coaxfit/results.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace coaxfit
{
  namespace
  {
    std::ofstream
    open(const std::string &filename)
    {
      std::ofstream out(filename);
      if (!out)
        throw std::runtime_error("cannot write '" + filename + "'");
      out << std::setprecision(15);
      return out;
    }

    std::string
    quoted(const std::string &s)
    {
      std::string out = "\"";
      for (const char c : s)
        {
          if (c == '"' || c == '\\')
            out += '\\';
          out += c;
        }
      return out + "\"";
    }
  } // namespace



  PressureSummary::PressureSummary(const Parameters          &parameters,
                                   const ContactInterface    &interface,
                                   const std::vector<double> &force)
    : pressure(interface.lumped_pressure(force))
    , at_mid_plane(pressure.front())
    , mean(interface.mean_pressure(force))
    , lame(lame_pressure(parameters.R0,
                         parameters.R1,
                         parameters.R2,
                         parameters.d,
                         parameters.shaft,
                         parameters.hub))
  {
    const auto [lo, hi] = std::minmax_element(pressure.begin(), pressure.end());
    min                 = *lo;
    z_of_min            = interface.z()[lo - pressure.begin()];
    max                 = *hi;
    z_of_max            = interface.z()[hi - pressure.begin()];
  }



  Complementarity::Complementarity(const ContactInterface &interface,
                                   const InterfaceSolver  &coupling)
    : max_tension_relative(0.)
    , max_penetration_relative(0.)
    , max_pressure_gap_relative(0.)
  {
    const std::vector<double> p
      = interface.lumped_pressure(coupling.contact_force());
    const double d     = interface.interference();
    double       p_max = 0.;
    for (const double x : p)
      p_max = std::max(p_max, std::abs(x));
    if (p_max == 0.)
      p_max = 1.;
    for (unsigned int i = 0; i < p.size(); ++i)
      {
        const double gap     = coupling.u_hub()[i] - coupling.u_shaft()[i] - d;
        max_tension_relative = std::max(max_tension_relative, -p[i] / p_max);
        max_penetration_relative = std::max(max_penetration_relative, -gap / d);
        max_pressure_gap_relative
          = std::max(max_pressure_gap_relative,
                     std::abs(p[i] * gap) / (p_max * d));
      }
  }



  void
  write_interface_vtp(const std::string      &filename,
                      const Parameters       &parameters,
                      const ContactInterface &interface,
                      const PressureSummary  &pressure,
                      const InterfaceSolver  &coupling)
  {
    std::ofstream      out   = open(filename);
    const unsigned int n     = interface.n_points();
    const auto         array = [&](const std::string &name, auto value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" format=\"ascii\">\n";
      for (unsigned int i = 0; i < n; ++i)
        out << value(i) << (i + 1 < n ? ' ' : '\n');
      out << "</DataArray>\n";
    };
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"1\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "<PointData Scalars=\"contact_pressure\">\n";
    array("contact_pressure",
          [&](unsigned int i) { return pressure.pressure[i]; });
    array("gap", [&](unsigned int i) {
      return coupling.u_hub()[i] - coupling.u_shaft()[i]
             - interface.interference();
    });
    array("contact_status", [&](unsigned int i) {
      return coupling.get_active_set().in_contact()[i] ? 1. : 0.;
    });
    out << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      out << parameters.R1 << ' ' << interface.z()[i] << " 0\n";
    out << "</DataArray>\n</Points>\n<Lines>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      out << i << (i + 1 < n ? ' ' : '\n');
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n"
        << n << "\n</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  }



  void
  write_contact_pressure(const std::string      &filename,
                         const ContactInterface &interface,
                         const PressureSummary  &pressure,
                         const InterfaceSolver  &coupling)
  {
    std::ofstream out = open(filename);
    out << "z_mm,pressure_MPa,u_r_shaft_mm,u_r_hub_mm,gap_mm,status\n";
    for (unsigned int i = 0; i < interface.n_points(); ++i)
      out << interface.z()[i] << ',' << pressure.pressure[i] << ','
          << coupling.u_shaft()[i] << ',' << coupling.u_hub()[i] << ','
          << coupling.u_hub()[i] - coupling.u_shaft()[i]
               - interface.interference()
          << (coupling.get_active_set().in_contact()[i] ? ",contact\n" :
                                                          ",separated\n");
  }



  void
  write_convergence(const std::string     &filename,
                    const InterfaceSolver &coupling)
  {
    std::ofstream out = open(filename);
    out << "step,kind,alpha,displacement_mismatch_relative,"
           "traction_mismatch_relative\n";
    for (const CouplingStep &s : coupling.history())
      out << s.step << ',' << (s.neumann ? "neumann" : "dirichlet") << ','
          << s.alpha << ',' << s.displacement_mismatch << ','
          << s.traction_mismatch << '\n';
  }



  void
  write_summary(const std::string &filename, const SummaryData &data)
  {
    const Parameters      &p   = data.parameters;
    const PressureSummary &ps  = data.pressure;
    std::ofstream          out = open(filename);

    out << "{\n"
        << "  \"case\": " << quoted(p.case_name) << ",\n"
        << "  \"converged\": " << (data.coupling.converged() ? "true" : "false")
        << ",\n"
        << "  \"iterations\": " << data.coupling.n_steps() << ",\n"
        << "  \"iterations_to_paper_criterion\": "
        << data.coupling.steps_to_displacement_mismatch(1e-2) << ",\n";

    out << "  \"geometry\": {\"R0\": " << p.R0 << ", \"R1\": " << p.R1
        << ", \"R2\": " << p.R2 << ", \"L1\": " << p.L1 << ", \"L2\": " << p.L2
        << ", \"d\": " << p.d << ", \"contact_length\": " << p.contact_length()
        << ", \"units\": \"mm, L1 and L2 are half lengths\"},\n";
    out << "  \"material\": {\"shaft\": {\"E\": " << p.shaft.E
        << ", \"nu\": " << p.shaft.nu << "}, \"hub\": {\"E\": " << p.hub.E
        << ", \"nu\": " << p.hub.nu << "}},\n";
    out << "  \"mesh\": {\"degree\": " << p.degree
        << ", \"global_refinements\": " << p.global_refinements
        << ", \"cells\": {\"shaft\": " << data.shaft.n_cells()
        << ", \"hub\": " << data.hub.n_cells() << "}"
        << ", \"dofs\": {\"shaft\": " << data.shaft.n_dofs()
        << ", \"hub\": " << data.hub.n_dofs() << "}"
        << ", \"interface_points\": " << data.interface.n_points() << "},\n";

    out << "  \"coupling\": {\"controller\": " << quoted(data.controller)
        << ", \"tolerance\": " << p.tolerance
        << ", \"max_steps\": " << p.max_steps << ", \"alpha_history\": [";
    for (unsigned int i = 0; i < data.coupling.history().size(); ++i)
      out << (i ? ", " : "") << data.coupling.history()[i].alpha;
    out << "]},\n";

    out << "  \"residuals\": {\"displacement_relative\": "
        << data.coupling.displacement_residual()
        << ", \"traction_relative\": " << data.coupling.traction_residual()
        << "},\n";

    out << "  \"pressure\": {\"units\": \"MPa, compression positive\""
        << ", \"at_mid_plane\": " << ps.at_mid_plane
        << ", \"mean\": " << ps.mean << ", \"min\": " << ps.min
        << ", \"z_of_min\": " << ps.z_of_min << ", \"max\": " << ps.max
        << ", \"z_of_max\": " << ps.z_of_max << ", \"lame\": " << ps.lame
        << ", \"tensile\": " << (ps.min < 0. ? "true" : "false") << "},\n";

    const UnilateralActiveSet &set = data.coupling.get_active_set();
    const auto                 zones
      = set.separated_zones(data.interface.z(), p.contact_length());
    double separated = 0.;
    for (const auto &zone : zones)
      separated += zone.second - zone.first;
    out << "  \"contact\": {\"unilateral\": "
        << (set.enabled() ? "true" : "false") << ", \"active_set_update\": "
        << (set.update_mode() == UnilateralActiveSet::Update::every_step ?
              "\"every step\"" :
              "\"when converged\"")
        << ", \"contact_length\": " << p.contact_length() - separated
        << ", \"separated_length\": " << separated
        << ", \"separated_points\": " << set.n_separated()
        << ", \"separated_zones\": [";
    for (unsigned int i = 0; i < zones.size(); ++i)
      out << (i ? ", " : "") << "[" << zones[i].first << ", " << zones[i].second
          << "]";
    out << "]},\n";
    out << "  \"active_set\": {\"changes\": " << set.n_changes() << "},\n";
    out << "  \"complementarity\": {\"max_tension_relative\": "
        << data.complementarity.max_tension_relative
        << ", \"max_penetration_relative\": "
        << data.complementarity.max_penetration_relative
        << ", \"max_pressure_gap_relative\": "
        << data.complementarity.max_pressure_gap_relative << "},\n";

    const auto *monolithic
      = dynamic_cast<const MonolithicSolver *>(&data.coupling);
    out << "  \"solver\": {\"method\": "
        << (monolithic ? "\"monolithic\"" : "\"staggered\"")
        << ", \"factorizations\": {\"coupled\": "
        << (monolithic ? monolithic->n_factorizations() : 0)
        << ", \"shaft\": " << data.shaft.n_factorizations()
        << ", \"hub\": " << data.hub.n_factorizations()
        << "}, \"solves\": {\"shaft\": " << data.shaft.n_solves()
        << ", \"hub\": " << data.hub.n_solves() << "}},\n";

    out << "  \"warnings\": [";
    for (unsigned int i = 0; i < data.warnings.size(); ++i)
      out << (i ? ", " : "") << quoted(data.warnings[i]);
    out << "],\n";

    out << "  \"timing\": {\"setup\": " << data.timing.setup
        << ", \"factorization\": " << data.timing.factorization
        << ", \"condensation\": " << data.timing.condensation
        << ", \"coupling\": " << data.timing.coupling
        << ", \"output\": " << data.timing.output
        << ", \"total\": " << data.timing.total << ", \"units\": \"s\"}\n"
        << "}\n";
  }
} // namespace coaxfit
