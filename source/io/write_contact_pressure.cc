#include <coaxfit/fe/section_scene.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <fstream>

namespace coaxfit
{
  std::string
  ContactPressureWriter::write(const RunResults  &results,
                               const std::string &directory) const
  {
    const std::string      name   = file_names()[0];
    std::ofstream          out    = open_result_file(directory + "/" + name);
    const InterfaceSolver &solver = results.solver;
    const Vector<double>   gap
      = results.interface.gap(solver.u_shaft(), solver.u_hub());
    // Total displacements: the contact answer plus the loads of operation.
    const Vector<double> &load1
      = results.interface.load_displacement(ContactInterface::Side::inner);
    const Vector<double> &load2
      = results.interface.load_displacement(ContactInterface::Side::outer);
    // Sections: the drawing's z as well (a half model's z is measured
    // from its plane of symmetry).
    // A cone: the displacements are along the joint's normal, and the arc
    // length s runs along the joint from its end of smaller z.
    const SectionScene *sections = results.parameters.sections.get();
    const bool          cone     = sections && sections->conical();
    out << (cone ? "z_mm,pressure_MPa,u_n_shaft_mm,u_n_hub_mm,gap_mm,status" :
                   "z_mm,pressure_MPa,u_r_shaft_mm,u_r_hub_mm,gap_mm,status")
        << (sections ? ",z_drawing_mm" : "") << (cone ? ",s_mm\n" : "\n");
    const double ds_dz
      = cone ? std::sqrt(1. + std::pow(0.5 * sections->taper(), 2)) : 1.;
    for (unsigned int i = 0; i < results.interface.n_points(); ++i)
      {
        out << results.interface.z()[i] << ',' << results.pressure.pressure[i]
            << ',' << solver.u_shaft()[i] + load1[i] << ','
            << solver.u_hub()[i] + load2[i] << ',' << gap[i]
            << (solver.get_active_set().in_contact()[i] ? ",contact" :
                                                          ",separated");
        if (sections)
          out << ',' << results.interface.z()[i] + sections->drawing_offset();
        if (cone)
          out << ','
              << (results.interface.z()[i] - results.interface.z()[0]) * ds_dz;
        out << '\n';
      }
    close_result_file(out, directory + "/" + name);
    return name + ": pressure and gap at "
           + std::to_string(results.interface.n_points()) + " points";
  }


  std::vector<std::string>
  ContactPressureWriter::file_names() const
  {
    return {"contact_pressure.csv"};
  }
} // namespace coaxfit
