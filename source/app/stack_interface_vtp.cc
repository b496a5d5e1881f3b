#include <coaxfit/app/stack_fit.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/io/polyline_vtp.h>
#include <coaxfit/io/result_writers.h>

namespace coaxfit
{
  void
  StackFit::write_interface(const std::string &directory,
                            const unsigned int k) const
  {
    const StackJoint    &joint = stack_joints[k];
    const StackLayout    layout(stack_joints);
    const unsigned int   n        = joint.n_points();
    const std::string    file     = "interface_" + joint.name + ".vtp";
    const Vector<double> pressure = solution.pressure(stack_joints, k);
    check_values_for_output(pressure, file);

    // Each side's (u_r, u_z) at the joint's points: body k's outer surface
    // (its points after those of its bore) and body k + 1's bore (its
    // first points). The inner side is drawn with its oversize, the radial
    // interference, added (as in its VTU): the sides meet where they touch.
    PolylineVtp vtp;
    for (const unsigned int b : {k + 1, k})
      {
        const BodyDiscretization &body = *bodies[b];
        const Vector<double>      u_r = body.interface_radial_values(fields[b]);
        const unsigned int        offset = layout.offset(b, k);
        PolylineVtp::VectorArray  side{b == k ?
                                         Body::key_of(parameters.bodies[k])
                                          + "_displacement_mm" :
                                         std::string("displacement_mm"),
                                      {}};
        for (unsigned int i = 0; i < n; ++i)
          side.values.push_back(
            {{u_r[offset + i] + (b == k ? joint.interference : 0.),
              fields[b][body.get_interface_axial_dofs()[offset + i]]}});
        vtp.vectors.push_back(side);
      }
    std::vector<double> gap(n), status(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        vtp.points.push_back({{parameters.joint_diameter(k) / 2., joint.z[i]}});
        // A new line after a relief groove.
        if (i > 0 && !joint.bearing(i - 1))
          vtp.line_starts.push_back(i);
        // The radial gap u_outer - u_inner - d (round-off where in
        // contact).
        gap[i]    = vtp.vectors[0].values[i][0] - vtp.vectors[1].values[i][0];
        status[i] = solution.contact[k][i] ? 1. : 0.;
      }
    // The bodies are 0 to N - 1, the joints follow.
    vtp.scalars = {{"contact_pressure_MPa",
                    "MPa",
                    std::vector<double>(pressure.begin(), pressure.end())},
                   {"gap_mm", "mm", gap},
                   {"contact_status", "", status},
                   {"body_id", "", std::vector<double>(n, bodies.size() + k)}};
    write_result_file(directory + "/" + file,
                      [&](std::ostream &out) { vtp.write(out); });
  }
} // namespace coaxfit
