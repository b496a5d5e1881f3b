#include <coaxfit/result_writers.h>

#include <fstream>

namespace coaxfit
{
  std::string
  PvdWriter::write(const RunResults &, const std::string &directory) const
  {
    // One time step, three parts: ParaView shows them together.
    const std::string name = file_names()[0];
    std::ofstream     out  = open_result_file(directory + "/" + name);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "<Collection>\n";
    unsigned int part = 0;
    for (const std::string file : {"shaft.vtu", "hub.vtu", "interface.vtp"})
      out << "<DataSet timestep=\"0\" group=\"\" part=\"" << part++
          << "\" file=\"" << file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
    close_result_file(out, directory + "/" + name);
    return name + ": open this one in ParaView";
  }


  std::vector<std::string>
  PvdWriter::file_names() const
  {
    return {"solution.pvd"};
  }
} // namespace coaxfit
