// The boundary parts of a scene, by id: a tube shaft longer than its hub
// (so that part of the shaft's joint radius lies beyond the joint and is
// free outer surface) and a solid shaft (with an axis). For each body and
// each id: the number of faces and the r-weighted area int r ds (mm^2 per
// radian, zero on the axis, whose length is printed instead), against the
// exact values of the section; the joint's normals (+e_r on the shaft,
// -e_r on the hub, exactly) and interface weights (their sum is R1 times
// the joint length); and the loaded faces: the load vector of a unit
// pressure on the bore and on the outer surface sums, over u_r, to
// +-1 MPa times the loaded area (the traction -p n along the outward
// normal), with nothing in u_z.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <coaxfit/coupling/scene.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

namespace
{
  using namespace coaxfit;

  /** Faces and int r ds, int ds of every boundary id of @p body. */
  struct Part
  {
    unsigned int faces  = 0;
    double       area   = 0.; ///< int r ds
    double       length = 0.; ///< int ds
  };

  std::map<types::boundary_id, Part>
  boundary_parts(const BodyDiscretization &body)
  {
    const QGauss<1>    quadrature(2); // exact for r linear along a face
    const MappingQ1<2> mapping;
    FEFaceValues<2>    values(mapping,
                           body.get_dof_handler().get_fe(),
                           quadrature,
                           update_quadrature_points | update_JxW_values);
    std::map<types::boundary_id, Part> parts;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            Part &part = parts[face->boundary_id()];
            ++part.faces;
            values.reinit(cell, face);
            for (const unsigned int q : values.quadrature_point_indices())
              {
                part.area += values.quadrature_point(q)[0] * values.JxW(q);
                part.length += values.JxW(q);
              }
          }
    return parts;
  }

  /** The sums of the load vector over u_r and u_z DoFs. */
  std::pair<double, double>
  load_sums(const BodyDiscretization &body, const BodyLoad &load)
  {
    const Vector<double>                 f  = body.assemble_load_vector(load);
    const auto                          &fe = body.get_dof_handler().get_fe();
    std::vector<bool>                    radial(body.n_dofs(), false);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          radial[dofs[i]] = fe.system_to_component_index(i).first == 0;
      }
    double sum_r = 0., sum_z = 0.;
    for (unsigned int i = 0; i < f.size(); ++i)
      (radial[i] ? sum_r : sum_z) += f[i];
    return {sum_r, sum_z};
  }

  void
  check(const std::string &label, const double value, const double exact)
  {
    const double error
      = std::abs(value - exact) / std::max(std::abs(exact), 1.);
    std::cout << "    " << std::left << std::setw(34) << label << std::right
              << std::setprecision(10) << std::setw(16) << value << "  exact "
              << std::setw(12) << exact << "  "
              << (error < 1e-12 ? "ok" : "WRONG") << '\n';
  }

  void
  run(const std::string &title, const Parameters &p)
  {
    std::cout << title << '\n';
    Scene                     scene(p);
    const GeometryParameters &g     = p.geometry;
    const double              joint = g.contact_length();
    for (Body &body : scene.bodies)
      {
        BodyDiscretization &d = *body.discretization;
        d.setup_system();
        d.assemble_system();
        const bool   inner = &body == &scene.inner(scene.joints[0]);
        const double a = inner ? g.R0 : g.R1, b = inner ? g.R1 : g.R2;
        const double length = inner ? g.L1 : g.L2;
        std::cout << "  " << body.name() << ": " << d.n_cells() << " cells\n";
        // Exact r-weighted areas of the section a <= r <= b, 0 <= z <= L.
        std::map<types::boundary_id, double> exact{
          {BoundaryId::symmetry, (b * b - a * a) / 2.},
          {BoundaryId::end, (b * b - a * a) / 2.},
          {BoundaryId::joint, (inner ? b : a) * joint}};
        if (a > 0.)
          exact[BoundaryId::bore] = a * (inner ? length : length - joint);
        exact[BoundaryId::outer] = b * (inner ? length - joint : length);
        if (a == 0.)
          exact[BoundaryId::axis] = 0.;
        const auto parts = boundary_parts(d);
        for (const auto &[id, part] : parts)
          {
            std::cout << "   " << BoundaryId::name(id) << " (id " << id
                      << "): " << part.faces << " faces\n";
            check("int r ds (mm^2)", part.area, exact.at(id));
            if (id == BoundaryId::axis)
              check("int ds (mm)", part.length, length);
          }
        for (const auto &[id, area] : exact)
          if (area > 0. && parts.count(id) == 0)
            std::cout << "   " << BoundaryId::name(id) << ": NO FACES\n";

        double       weights  = 0.;
        unsigned int n_normal = 0;
        for (unsigned int i = 0; i < d.n_interface_points(); ++i)
          {
            weights += d.interface_weights()[i];
            const Tensor<1, 2> &n = d.interface_normals()[i];
            n_normal += (n[0] == (inner ? 1. : -1.) && n[1] == 0.);
          }
        std::cout << "   joint: " << d.n_interface_points()
                  << " points, normal " << (inner ? "+e_r" : "-e_r")
                  << " exactly at " << n_normal << '\n';
        check("sum of interface weights", weights, exact.at(BoundaryId::joint));

        BodyLoad bore, outer;
        bore.inner_pressure           = 1.;
        outer.outer_pressure          = 1.;
        const auto [bore_r, bore_z]   = load_sums(d, bore);
        const auto [outer_r, outer_z] = load_sums(d, outer);
        const double bore_area
          = exact.count(BoundaryId::bore) ? exact.at(BoundaryId::bore) : 0.;
        check("bore pressure 1: sum over u_r", bore_r, bore_area);
        check("outer pressure 1: sum over u_r",
              outer_r,
              0. - exact.at(BoundaryId::outer));
        check("  and over u_z (both)",
              std::abs(bore_z) + std::abs(outer_z),
              0.);
      }
  }
} // namespace

int
main()
{
  Parameters p;
  p.geometry.R0             = 50.;
  p.geometry.R1             = 100.;
  p.geometry.R2             = 200.;
  p.geometry.L1             = 300.;
  p.geometry.L2             = 200.;
  p.mesh.axial_cells        = 4;
  p.mesh.radial_cells       = 3;
  p.mesh.global_refinements = 1;
  run("Tube shaft 100/200 x 600 in a hub 200/400 x 400 (mm), FE_Q(2):", p);

  p.geometry.R0 = 0.;
  p.geometry.L1 = 200.;
  p.geometry.L2 = 250.;
  run("Solid shaft 200 x 400 in a longer hub 200/400 x 500:", p);
}
