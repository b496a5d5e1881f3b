#include <coaxfit/io/result_writers.h>

#include <array>
#include <fstream>

namespace coaxfit
{
  std::string
  InterfaceVtpWriter::write(const RunResults  &results,
                            const std::string &directory) const
  {
    const std::string name = file_names()[0];
    for (const Vector<double> &field : results.fields)
      check_values_for_output(field, directory + "/" + name);
    std::ofstream           out = open_result_file(directory + "/" + name);
    const ContactInterface &interface = results.interface;
    const InterfaceSolver  &solver    = results.solver;
    const unsigned int      n         = interface.n_points();
    const Vector<double> gap = interface.gap(solver.u_shaft(), solver.u_hub());
    // Written in full precision: the surfaces meet to round-off.
    out.precision(17);

    // The total displacement (u_r, u_z) of each body's surface point i:
    // the body's own field (contact answer plus loads of operation), the
    // inner side's plus its oversize d (it is made larger than the mesh
    // at the joint radius, see AssembledDisplacement).
    const Scene      &scene = results.scene;
    const JointSides &joint = scene.joint();
    // Each body's u_r and u_z at the interface points (by the mortar
    // transfer for a side whose joint nodes are not these points).
    std::vector<std::array<Vector<double>, 2>> joint_field(scene.bodies.size());
    for (unsigned int body = 0; body < scene.bodies.size(); ++body)
      {
        const BodyDiscretization &d     = *scene.bodies[body].discretization;
        const Vector<double>     &field = results.fields[body];
        Vector<double>            u_z(d.n_interface_points());
        for (unsigned int i = 0; i < u_z.size(); ++i)
          u_z[i] = field[d.get_interface_axial_dofs()[i]];
        joint_field[body]
          = {{scene.joint_values(body, d.interface_radial_values(field)),
              scene.joint_values(body, u_z)}};
      }
    const auto surface = [&](const unsigned int body, const unsigned int i) {
      return std::array<double, 2>{
        {joint_field[body][0][i]
           + (body == joint.inner ? interface.interference() : 0.),
         joint_field[body][1][i]}};
    };
    const auto scalar =
      [&](const std::string &array_name, const std::string &unit, auto value) {
        out << "<DataArray type=\"Float64\" Name=\"" << array_name << '"'
            << (unit.empty() ? "" : " units=\"" + unit + '"')
            << " format=\"ascii\">\n";
        for (unsigned int i = 0; i < n; ++i)
          out << value(i) << (i + 1 < n ? ' ' : '\n');
        out << "</DataArray>\n";
      };
    const auto vector
      = [&](const std::string &array_name, const unsigned int body) {
          out << "<DataArray type=\"Float64\" Name=\"" << array_name
              << "\" units=\"mm\" NumberOfComponents=\"3\" format=\"ascii\">\n";
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto u = surface(body, i);
              out << u[0] << ' ' << u[1] << " 0\n";
            }
          out << "</DataArray>\n";
        };

    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"1\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "<PointData Scalars=\"contact_pressure_MPa\" "
           "Vectors=\"displacement_mm\">\n";
    // The outer side (the hub's bore), in place; the inner side's surface
    // meets it where the two are in contact.
    vector("displacement_mm", joint.outer);
    vector(scene.bodies[joint.inner].key() + "_displacement_mm", joint.inner);
    scalar("contact_pressure_MPa", "MPa", [&](unsigned int i) {
      return results.pressure.pressure[i];
    });
    scalar("gap_mm", "mm", [&](unsigned int i) { return gap[i]; });
    scalar("contact_status", "", [&](unsigned int i) {
      return solver.get_active_set().in_contact()[i] ? 1. : 0.;
    });
    scalar("body_id", "", [](unsigned int) { return 2.; });
    out << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      out << scene
               .bodies[scene.has_transfer() ? scene.point_body() : joint.outer]
               .discretization->interface_points()[i][0]
          << ' ' << interface.z()[i] << " 0\n";
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
