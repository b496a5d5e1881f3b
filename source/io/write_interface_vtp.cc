#include <coaxfit/io/polyline_vtp.h>
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
    PolylineVtp vtp;
    for (unsigned int i = 0; i < n; ++i)
      vtp.points.push_back(
        {{scene.bodies[scene.has_transfer() ? scene.point_body() : joint.outer]
            .discretization->interface_points()[i][0],
          interface.z()[i]}});
    // The outer side (the hub's bore), in place; the inner side's surface
    // meets it where the two are in contact.
    for (const unsigned int body : {joint.outer, joint.inner})
      {
        PolylineVtp::VectorArray side{body == joint.outer ?
                                        std::string("displacement_mm") :
                                        scene.bodies[joint.inner].key()
                                          + "_displacement_mm",
                                      {}};
        for (unsigned int i = 0; i < n; ++i)
          side.values.push_back(surface(body, i));
        vtp.vectors.push_back(side);
      }
    std::vector<double> status(n), body_id(n, 2.);
    for (unsigned int i = 0; i < n; ++i)
      status[i] = solver.get_active_set().in_contact()[i] ? 1. : 0.;
    vtp.scalars
      = {{"contact_pressure_MPa",
          "MPa",
          std::vector<double>(results.pressure.pressure.begin(),
                              results.pressure.pressure.end())},
         {"gap_mm", "mm", std::vector<double>(gap.begin(), gap.end())},
         {"contact_status", "", status},
         {"body_id", "", body_id}};
    vtp.write(out);
    close_result_file(out, directory + "/" + name);
    return name + ": the contact surface";
  }


  std::vector<std::string>
  InterfaceVtpWriter::file_names() const
  {
    return {"interface.vtp"};
  }
} // namespace coaxfit
