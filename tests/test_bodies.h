// Shared set-up of the single-body tests: a thick hollow cylinder and a
// solid cylinder on small uniform meshes, and the nodal forces of a uniform
// pressure on the contact surface.
#ifndef coaxfit_tests_test_bodies_h
#define coaxfit_tests_test_bodies_h

#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/fe/lame.h>
#include <coaxfit/solvers/body_solver.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <vector>

namespace coaxfit_test
{
  using namespace coaxfit;

  /**
   * One body for the single-body tests: the discretization and its solver,
   * with interface data as std::vector and the last solution kept for the
   * error against an exact solution.
   */
  class Body
  {
  public:
    Body(const std::string  &name,
         const BodyGeometry &geometry,
         const Material     &material,
         const unsigned int  degree)
      : discretization(name, geometry, material, degree)
    {}

    void
    setup_system()
    {
      discretization.setup_system();
    }

    void
    assemble_system()
    {
      discretization.assemble_system();
      solver = std::make_unique<BodySolver>(discretization);
    }

    void
    solve(const std::vector<bool>   &prescribed,
          const std::vector<double> &displacement,
          const std::vector<double> &force,
          std::vector<double>       &u_r,
          std::vector<double>       &force_out)
    {
      const Vector<double> u_in(displacement.begin(), displacement.end());
      const Vector<double> f_in(force.begin(), force.end());
      solution = solver->solve_field(prescribed, u_in, f_in);
      Vector<double> u, f;
      discretization.interface_values(prescribed, f_in, solution, u, f);
      u_r.assign(u.begin(), u.end());
      force_out.assign(f.begin(), f.end());
    }

    void
    solve_neumann(const std::vector<double> &force, std::vector<double> &u_r)
    {
      std::vector<double> f;
      solve(std::vector<bool>(force.size(), false),
            std::vector<double>(force.size(), 0.),
            force,
            u_r,
            f);
    }

    void
    solve_dirichlet(const std::vector<double> &u_r, std::vector<double> &force)
    {
      std::vector<double> u;
      solve(std::vector<bool>(u_r.size(), true),
            u_r,
            std::vector<double>(u_r.size(), 0.),
            u,
            force);
    }

    void
    interface_compliance(FullMatrix<double> &compliance)
    {
      solver->interface_compliance(compliance);
    }

    unsigned int
    n_interface_points() const
    {
      return discretization.n_interface_points();
    }

    unsigned int
    n_dofs() const
    {
      return discretization.n_dofs();
    }

    const BodyGeometry &
    geometry() const
    {
      return discretization.geometry();
    }

    const std::vector<double> &
    interface_z() const
    {
      return discretization.interface_z();
    }

    unsigned int
    n_factorizations() const
    {
      return solver->n_factorizations();
    }

    unsigned int
    n_solves() const
    {
      return solver->n_solves();
    }

    /** Errors of the last solution against @p exact. */
    LameErrors
    errors(const LameCylinder &exact) const
    {
      return lame_errors(discretization, solution, exact);
    }

    BodyDiscretization          discretization;
    std::unique_ptr<BodySolver> solver;
    Vector<double>              solution;
  };

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
    const Vector<double> &w = body.discretization.interface_weights();
    return std::vector<double>(w.begin(), w.end());
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
