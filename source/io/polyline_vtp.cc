#include <coaxfit/io/polyline_vtp.h>

namespace coaxfit
{
  void
  PolylineVtp::write(std::ostream &out) const
  {
    const std::size_t n = points.size();
    // Full precision: the two sides of a joint meet to round-off.
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << line_starts.size() + 1
        << "\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "<PointData Scalars=\""
        << (scalars.empty() ? std::string() : scalars[0].name)
        << "\" Vectors=\""
        << (vectors.empty() ? std::string() : vectors[0].name) << "\">\n";
    for (const VectorArray &v : vectors)
      {
        out << "<DataArray type=\"Float64\" Name=\"" << v.name
            << "\" units=\"mm\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &u : v.values)
          out << u[0] << ' ' << u[1] << " 0\n";
        out << "</DataArray>\n";
      }
    for (const ScalarArray &s : scalars)
      {
        out << "<DataArray type=\"Float64\" Name=\"" << s.name << '"'
            << (s.unit.empty() ? "" : " units=\"" + s.unit + '"')
            << " format=\"ascii\">\n";
        for (std::size_t i = 0; i < n; ++i)
          out << s.values[i] << (i + 1 < n ? ' ' : '\n');
        out << "</DataArray>\n";
      }
    out << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &p : points)
      out << p[0] << ' ' << p[1] << " 0\n";
    out << "</DataArray>\n</Points>\n<Lines>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (std::size_t i = 0; i < n; ++i)
      out << i << (i + 1 < n ? ' ' : '\n');
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (const std::size_t start : line_starts)
      out << start << ' ';
    out << n << "\n</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  }
} // namespace coaxfit
