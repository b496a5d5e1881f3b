#include <coaxfit/result_writers.h>

#include <fstream>

namespace coaxfit
{
  std::string
  InterfaceVtpWriter::write(const RunResults  &results,
                            const std::string &directory) const
  {
    const std::string       name = file_names()[0];
    std::ofstream           out  = open_result_file(directory + "/" + name);
    const ContactInterface &interface = results.interface;
    const InterfaceSolver  &solver    = results.solver;
    const unsigned int      n         = interface.n_points();
    const Vector<double> gap = interface.gap(solver.u_shaft(), solver.u_hub());
    const auto array         = [&](const std::string &array_name, auto value) {
      out << "<DataArray type=\"Float64\" Name=\"" << array_name
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
          [&](unsigned int i) { return results.pressure.pressure[i]; });
    array("gap", [&](unsigned int i) { return gap[i]; });
    array("contact_status", [&](unsigned int i) {
      return solver.get_active_set().in_contact()[i] ? 1. : 0.;
    });
    out << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      out << results.parameters.geometry.R1 << ' ' << interface.z()[i]
          << " 0\n";
    out << "</DataArray>\n</Points>\n<Lines>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      out << i << (i + 1 < n ? ' ' : '\n');
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n"
        << n << "\n</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
    close_result_file(out, directory + "/" + name);
    return name + ": the contact surface";
  }


  std::vector<std::string>
  InterfaceVtpWriter::file_names() const
  {
    return {"interface.vtp"};
  }
} // namespace coaxfit
