// A body whose mesh comes from a section outline (make_section_mesh, gmsh)
// instead of the plain cylinder builder solves the same problem as the
// plain builder's body: the half (z >= 0) of a hollow cylinder D 50-100 mm
// (an outline "0, 50; 20, 50; 20, 100; 0, 100; 0, 50" with the joint on
// the bore and the symmetry plane z = 0 tagged) and a solid cylinder D 50
// (its axis found by the mesher), each under a uniform pressure of 100 MPa
// on its joint surface (the bore of the hollow one, the outer surface of
// the solid one), against Lame's solution for free ends, which is exact for
// this finite body (u_r independent of z, u_z = -2 nu A z / E). Printed
// per global refinement for both meshes: the relative L2 errors of the
// displacement and of the hoop stress, the radial displacement of the
// joint's middle and end points against Lame's, and the mean of u_r over
// the joint (weights int N_i r dz).
#include <coaxfit/fe/section_mesh.h>

#include "test_bodies.h"

#include <sstream>
#include <string>

namespace
{
  using namespace coaxfit;
  using namespace coaxfit_test;

  /** @p x in two digits, or "<1e-11" at round-off (the linear field of
   * the solid cylinder is exact). */
  std::string
  figure(const double x)
  {
    if (std::abs(x) < 1e-11)
      return "<1e-11";
    std::ostringstream s;
    s << std::scientific << std::setprecision(2) << x;
    return s.str();
  }

  void
  report(const std::string  &label,
         Body               &body,
         const LameCylinder &exact,
         const double        R,
         const double        p)
  {
    body.setup_system();
    body.assemble_system();
    std::vector<double> u;
    body.solve_neumann(uniform_pressure_forces(body, p), u);
    const LameErrors          e    = body.errors(exact);
    const std::vector<double> w    = interface_weights(body);
    double                    mean = 0., weight = 0.;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        mean += w[i] * u[i];
        weight += w[i];
      }
    const double u_exact = exact.u_r(R);
    std::cout << "  " << std::left << std::setw(8) << label << std::right
              << std::setw(6) << body.discretization.n_dofs() / 2 << " nodes, "
              << std::setw(3) << u.size() << " joint points: L2 error u "
              << figure(e.displacement_L2) << ", hoop "
              << figure(e.hoop_stress_L2) << "; u_r(z = 0) "
              << figure(std::abs(u.front() / u_exact - 1.)) << ", u_r(end) "
              << figure(std::abs(u.back() / u_exact - 1.)) << ", mean u_r "
              << figure(std::abs(mean / weight / u_exact - 1.)) << '\n';
  }

  /** The body of @p outline with joint and symmetry tagged, meshed. */
  void
  use_section(Body              &body,
              const std::string &outline,
              const double       R,
              const double       z_end,
              const double       r_far,
              const unsigned int refinements)
  {
    const SectionOutline section
      = SectionOutline::parse(outline, "Geometry/Hub section");
    SectionBoundary boundary;
    boundary.segments = {
      TaggedSegment::from_drawing(0., 2. * R, z_end, 2. * R, BoundaryId::joint),
      TaggedSegment::from_drawing(
        0., 2. * R, 0., 2. * r_far, BoundaryId::symmetry)};
    SectionMeshSettings settings;
    settings.cell_size          = 2.5;
    settings.grading_ratio      = 1.2;
    settings.global_refinements = refinements;
    body.discretization.set_mesh_builder(
      [section, boundary, settings](Triangulation<2> &t) {
        make_section_mesh(t, section, boundary, settings);
      });
  }
} // namespace



int
main()
{
  Material steel;
  steel.E        = 210000.;
  steel.nu       = 0.3;
  const double p = 100.;

  std::cout << "hollow cylinder D 50-100 mm, half length 20 mm, pressure " << p
            << " MPa on the bore; Lame u_r(25) = "
            << LameCylinder(25., 50., steel, p, 0.).u_r(25.) << " mm\n";
  for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      std::cout << "refinement " << refinement << ":\n";
      BodyGeometry g   = hollow_cylinder(25., 50., refinement);
      g.length         = 20.;
      g.contact_length = 20.;
      g.axial_cells    = 8;
      g.radial_cells   = 10;
      g.grading_ratio  = 1.2;
      Body plain("Hub", g, steel, 2);
      report("plain", plain, LameCylinder(25., 50., steel, p, 0.), 25., p);
      Body section("Hub", g, steel, 2);
      use_section(section,
                  "0, 50; 20, 50; 20, 100; 0, 100; 0, 50",
                  25.,
                  20.,
                  50.,
                  refinement);
      report("section", section, LameCylinder(25., 50., steel, p, 0.), 25., p);
    }

  std::cout << "solid cylinder D 50 mm, half length 20 mm, pressure " << p
            << " MPa on the outer surface; Lame u_r(25) = "
            << LameCylinder(0., 25., steel, 0., p).u_r(25.) << " mm\n";
  for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      std::cout << "refinement " << refinement << ":\n";
      BodyGeometry g   = solid_cylinder(25., refinement);
      g.length         = 20.;
      g.contact_length = 20.;
      g.axial_cells    = 8;
      g.radial_cells   = 10;
      g.grading_ratio  = 1.2;
      Body plain("Shaft", g, steel, 2);
      report("plain", plain, LameCylinder(0., 25., steel, 0., p), 25., p);
      Body section("Shaft", g, steel, 2);
      use_section(
        section, "0, 0; 20, 0; 20, 50; 0, 50; 0, 0", 25., 20., 0., refinement);
      report("section", section, LameCylinder(0., 25., steel, 0., p), 25., p);
    }
}
