// Stacks of N plain rings of equal length with frictionless joints: each
// ring is in a plane-stress Lame state, so CompoundCylinders (the closed
// form) is the exact answer the FE model converges to. For N = 2, 3, 5 with
// solid and hollow cores and several materials, at the mesh of stack():
// FE_Q(2), 4 x 6 equal cells per body refined once (850 DoFs per body),
// every joint's pressure at the mid-plane and its mean within 1e-6 of the
// closed form, the nodal extremes within 1e-3 (the lumped pressure of the
// node at the joint's free end carries the largest discretization error,
// 3e-4 to 7e-7 here); the staggered process in both orderings against the
// monolithic solution of the same discrete problem (1e-8 of the largest
// pressure); each joint alone against the two-ring closed form; a sleeve
// with clearance in its hub (that joint open, p = 0, the other the
// two-ring answer).

#include <coaxfit/app/stack_fit.h>
#include <coaxfit/design/compound_cylinders.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace coaxfit;

namespace
{
  struct RingSpec
  {
    double      d_in, d_out, E, nu;
    std::string name;
  };

  /** A stack of @p rings with the interferences @p U, 40 mm long. */
  StackParameters
  stack(const std::vector<RingSpec> &rings,
        const std::vector<double>   &U,
        const SolverMethod           method,
        const StackOrdering          ordering)
  {
    StackParameters p;
    for (const RingSpec &r : rings)
      {
        p.bodies.push_back(r.name);
        p.rings.push_back({r.d_in, r.d_out, 40.});
        Material m;
        m.E  = r.E;
        m.nu = r.nu;
        p.materials.push_back(m);
      }
    for (const double u : U)
      {
        coaxfit::JointFit fit;
        fit.diametral_interference = fit.nominal_interference = u;
        p.fits.push_back(fit);
      }
    p.mesh.axial_cells        = 4;
    p.mesh.radial_cells       = 6;
    p.mesh.grading_ratio      = 1.;
    p.mesh.global_refinements = 1;
    p.mesh.degree             = 2;
    p.method                  = method;
    p.ordering                = ordering;
    p.tolerance               = 1e-12;
    return p;
  }

  /**
   * Relative deviation of a joint's pressure at the mid-plane and mean
   * from @p exact (absolute in MPa for an open joint, exact = 0).
   */
  double
  deviation(const JointFigures &f, const double exact)
  {
    const double scale = exact != 0. ? std::abs(exact) : 1.;
    return std::max(std::abs(f.p_mid - exact), std::abs(f.p_mean - exact))
           / scale;
  }

  /**
   * The same of the nodal extremes (min, max): the lumped pressure of the
   * node at the joint's free end carries the largest discretization error.
   */
  double
  extremes_deviation(const JointFigures &f, const double exact)
  {
    const double scale = exact != 0. ? std::abs(exact) : 1.;
    return std::max(std::abs(f.p_min - exact), std::abs(f.p_max - exact))
           / scale;
  }

  void
  check(const std::string           &title,
        const std::vector<RingSpec> &rings,
        const std::vector<double>   &U)
  {
    std::cout << title << '\n';
    std::vector<CompoundCylinders::Ring> exact_rings;
    for (const RingSpec &r : rings)
      exact_rings.push_back({r.d_in, r.d_out, r.E, r.nu});
    const CompoundCylinders exact(exact_rings, U);

    const StackParameters mono
      = stack(rings, U, SolverMethod::monolithic, StackOrdering::gauss_seidel);
    StackFit reference(mono);
    reference.setup_system();
    reference.solve(nullptr);
    reference.postprocess();
    for (const JointFigures &f : reference.joint_figures())
      {
        const unsigned int k = &f - &reference.joint_figures()[0];
        const double       e = exact.pressure(k);
        const double       alone
          = CompoundCylinders({exact_rings[k], exact_rings[k + 1]}, {U[k]})
              .pressure(0);
        const double alone_deviation
          = std::max(std::abs(f.alone_p_mean - alone),
                     std::abs(f.alone_p_mid - alone))
            / (alone != 0. ? alone : 1.);
        std::cout << "  " << std::left << std::setw(14) << f.name << std::right
                  << " exact p " << std::setprecision(8) << std::setw(12) << e
                  << "  FE p(0), mean "
                  << (deviation(f, e) < 1e-6 ? "within 1e-6" : "OFF")
                  << ", nodal min/max "
                  << (extremes_deviation(f, e) < 1e-3 ? "within 1e-3" : "OFF")
                  << (f.closed ? "" : " (open)") << "; alone: exact " << alone
                  << ", FE " << (alone_deviation < 1e-6 ? "within 1e-6" : "OFF")
                  << '\n';
      }
    for (const StackOrdering ordering :
         {StackOrdering::gauss_seidel, StackOrdering::jacobi})
      {
        const StackParameters staggered
          = stack(rings, U, SolverMethod::staggered, ordering);
        StackFit fit(staggered);
        fit.setup_system();
        const bool converged  = fit.solve(nullptr);
        double     difference = 0., scale = 0.;
        for (unsigned int k = 0; k < fit.joints().size(); ++k)
          {
            const Vector<double> p = fit.state().pressure(fit.joints(), k);
            const Vector<double> q
              = reference.state().pressure(reference.joints(), k);
            for (unsigned int i = 0; i < p.size(); ++i)
              {
                difference = std::max(difference, std::abs(p[i] - q[i]));
                scale      = std::max(scale, std::abs(q[i]));
              }
          }
        std::cout << "  staggered "
                  << (ordering == StackOrdering::jacobi ? "jacobi      " :
                                                          "gauss-seidel")
                  << (converged ? " converged" : " NOT converged") << " in "
                  << fit.n_steps() << " steps, = monolithic "
                  << (difference <= 1e-8 * scale ? "to 1e-8" : "NOT to 1e-8")
                  << '\n';
      }
  }
} // namespace

int
main()
{
  const RingSpec steel_shaft{0., 60., 210000., 0.3, "Shaft"};
  check("two rings: steel shaft D 60 in a steel hub D 60-120, U 0.06 mm",
        {steel_shaft, {60., 120., 210000., 0.3, "Hub"}},
        {0.06});
  check("three rings (three_rings.prm): steel, bronze, aluminium",
        {steel_shaft,
         {60., 90., 110000., 0.34, "Sleeve"},
         {90., 160., 70000., 0.33, "Hub"}},
        {0.04, 0.06});
  check("five rings on a hollow core D 20-40",
        {{20., 40., 210000., 0.3, "Core"},
         {40., 55., 110000., 0.34, "Layer1"},
         {55., 70., 200000., 0.28, "Layer2"},
         {70., 90., 70000., 0.33, "Layer3"},
         {90., 130., 170000., 0.26, "Jacket"}},
        {0.03, 0.05, 0.02, 0.07});
  check("a sleeve 0.04 mm loose in its hub: that joint opens",
        {steel_shaft,
         {60., 90., 110000., 0.34, "Sleeve"},
         {90., 160., 70000., 0.33, "Hub"}},
        {0.04, -0.04});
}
