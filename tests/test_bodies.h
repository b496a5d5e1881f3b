// Shared set-up of the single-body tests: a thick hollow cylinder and a
// solid cylinder on small uniform meshes, and the nodal forces of a uniform
// pressure on the contact surface.
#ifndef coaxfit_tests_test_bodies_h
#define coaxfit_tests_test_bodies_h

#include <coaxfit/body.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

namespace coaxfit_test
{
  using namespace coaxfit;

  /** Hollow cylinder a <= r <= b, half length 50 mm, loaded on r = a. */
  inline BodyGeometry
  hollow_cylinder(const double       a,
                  const double       b,
                  const unsigned int refinements)
  {
    BodyGeometry g;
    g.r_inner                 = a;
    g.r_outer                 = b;
    g.length                  = 50.;
    g.contact_length          = 50.;
    g.contact_at_outer_radius = false;
    g.axial_cells             = 2;
    g.radial_cells            = 2;
    g.grading_ratio           = 1.;
    g.global_refinements      = refinements;
    return g;
  }

  /** Solid cylinder 0 <= r <= b, half length 50 mm, loaded on r = b. */
  inline BodyGeometry
  solid_cylinder(const double b, const unsigned int refinements)
  {
    BodyGeometry g            = hollow_cylinder(0., b, refinements);
    g.contact_at_outer_radius = true;
    g.grading_ratio           = 1.4; // graded towards the surface, as in use
    return g;
  }

  /** Lumped weights w_i = int_S N_i r dz of a body's interface points. */
  inline std::vector<double>
  interface_weights(const Body &body)
  {
    std::vector<double> w(body.n_interface_points(), 0.);
    for (const auto &[ij, value] : body.interface_mass())
      w[ij.first] += value;
    return w;
  }

  /** Consistent nodal forces of a uniform pressure p: F_i = p w_i. */
  inline std::vector<double>
  uniform_pressure_forces(const Body &body, const double p)
  {
    std::vector<double> f = interface_weights(body);
    for (double &x : f)
      x *= p;
    return f;
  }

  /** Observed order of convergence between two errors on meshes h, h/2. */
  inline double
  order(const double coarse, const double fine)
  {
    return std::log2(coarse / fine);
  }
} // namespace coaxfit_test

#endif
