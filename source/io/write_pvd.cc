#include <coaxfit/io/result_writers.h>

#include <fstream>
#include <utility>

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
    // Named blocks (ParaView 5.11's reader shows the names).
    std::vector<std::pair<std::string, std::string>> blocks;
    for (const std::string &key : body_keys)
      blocks.emplace_back(key, key + ".vtu");
    blocks.emplace_back("contact_surface", "interface.vtp");
    unsigned int part = 0;
    for (const auto &[block, file] : blocks)
      out << "<DataSet timestep=\"0\" group=\"\" part=\"" << part++
          << "\" name=\"" << block << "\" file=\"" << file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
    close_result_file(out, directory + "/" + name);
    return name + ": open this one in ParaView";
  }


  PvdWriter::PvdWriter(const std::vector<std::string> &body_keys)
    : body_keys(body_keys)
  {}



  std::vector<std::string>
  PvdWriter::file_names() const
  {
    return {"solution.pvd"};
  }
} // namespace coaxfit
