// CompoundCylinders, the exact plane-stress solution of N rings shrunk into
// each other, against an independent formulation: the flexibility method
// with Lame's thick-walled ring under an inner pressure p_i and an outer
// pressure p_o (plane stress),
//   u(r) = ((1 - nu) (p_i a^2 - p_o b^2) r + (1 + nu) (p_i - p_o) a^2 b^2 /
//          r) / (E (b^2 - a^2)),   a solid core u(r) = -(1 - nu) p_o r / E,
// each joint k closing its interference, u_{k+1}(R_k) - u_k(R_k) = U_k / 2,
// a linear system in the joint pressures solved here by Gauss elimination.
//
// 1. Two rings: DIN 7190-1's p = U / (D_F K), K = ((1 + Q_A^2) / (1 -
//    Q_A^2) + nu_A) / E_A + (1 - nu_I) / E_I: a solid steel shaft D 50 in a
//    steel hub D 100, U = 0.05 mm: K = 2.66667 / 210000, p = 78.75 MPa.
// 2. Three rings (the three_rings example): a steel shaft D 60
//    (210000, 0.3), a bronze sleeve D 60-90 (110000, 0.34), an aluminium hub
//    D 90-160 (70000, 0.33); U = 0.04 mm at D 60, 0.06 mm at D 90.
// 3. Five rings on a hollow core with an inner pressure of 30 MPa and an
//    outer one of 5 MPa.
// 4. A clearance: the sleeve 0.04 mm loose in the hub (U = -0.04 mm): that
//    joint opens (p = 0, its gap the radial clearance 0.02 mm less the
//    sleeve's expansion) and the shaft's joint is the two-ring problem's.
//    (0.02 mm loose the joint closes all the same: the shaft's fit widens
//    the sleeve by 0.0145 mm, more than the radial clearance 0.01 mm.)
// 5. Bad input: one ring, rings that do not meet, a missing interference.
// Required: 1e-10 relative between the two formulations.

#include <coaxfit/design/compound_cylinders.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace
{
  using coaxfit::CompoundCylinders;
  using Ring = CompoundCylinders::Ring;

  /** u at r of a ring a..b (a = 0: solid) under p_i and p_o (Lame). */
  double
  lame_u(const Ring &ring, const double r, const double p_i, const double p_o)
  {
    const double a = 0.5 * ring.inner_diameter, b = 0.5 * ring.outer_diameter;
    const double E = ring.E, nu = ring.nu;
    if (a == 0.)
      return -(1. - nu) * p_o * r / E;
    return ((1. - nu) * (p_i * a * a - p_o * b * b) * r
            + (1. + nu) * (p_i - p_o) * a * a * b * b / r)
           / (E * (b * b - a * a));
  }

  /**
   * The joint pressures by the flexibility method, the joints @p open
   * left out (pressure 0).
   */
  std::vector<double>
  flexibility(const std::vector<Ring>   &rings,
              const std::vector<double> &U,
              const double               p_in,
              const double               p_out,
              const std::vector<bool>   &open)
  {
    const unsigned int m = U.size();
    // u_{k+1}(R_k) - u_k(R_k) as a function of all pressures, linear: its
    // coefficients by unit pressures, its constant by the given ones.
    const auto jump = [&](const unsigned int         k,
                          const std::vector<double> &p,
                          const double               in,
                          const double               out) {
      const double R = 0.5 * rings[k].outer_diameter;
      const auto   inner_p
        = [&](const unsigned int i) { return i == 0 ? in : p[i - 1]; };
      const auto outer_p
        = [&](const unsigned int i) { return i == m ? out : p[i]; };
      return lame_u(rings[k + 1], R, inner_p(k + 1), outer_p(k + 1))
             - lame_u(rings[k], R, inner_p(k), outer_p(k));
    };
    std::vector<std::vector<double>> J(m, std::vector<double>(m + 1, 0.));
    const std::vector<double>        zero(m, 0.);
    for (unsigned int k = 0; k < m; ++k)
      {
        if (open[k])
          {
            J[k][k] = 1.; // p_k = 0
            continue;
          }
        const double constant = jump(k, zero, p_in, p_out);
        for (unsigned int j = 0; j < m; ++j)
          if (!open[j])
            {
              std::vector<double> unit(m, 0.);
              unit[j] = 1.;
              J[k][j] = jump(k, unit, 0., 0.);
            }
        J[k][m] = 0.5 * U[k] - constant;
      }
    // Gauss elimination with partial pivoting.
    for (unsigned int c = 0; c < m; ++c)
      {
        unsigned int pivot = c;
        for (unsigned int r = c + 1; r < m; ++r)
          if (std::abs(J[r][c]) > std::abs(J[pivot][c]))
            pivot = r;
        std::swap(J[c], J[pivot]);
        for (unsigned int r = 0; r < m; ++r)
          if (r != c)
            {
              const double f = J[r][c] / J[c][c];
              for (unsigned int j = c; j <= m; ++j)
                J[r][j] -= f * J[c][j];
            }
      }
    std::vector<double> p(m);
    for (unsigned int k = 0; k < m; ++k)
      p[k] = J[k][m] / J[k][k];
    return p;
  }

  /** Both formulations; the largest relative difference printed. */
  void
  compare(const std::string         &name,
          const std::vector<Ring>   &rings,
          const std::vector<double> &U,
          const double               p_in  = 0.,
          const double               p_out = 0.)
  {
    const CompoundCylinders exact(rings, U, p_in, p_out);
    std::vector<bool>       open(U.size());
    for (unsigned int k = 0; k < U.size(); ++k)
      open[k] = exact.pressure(k) == 0.;
    const std::vector<double> p = flexibility(rings, U, p_in, p_out, open);
    double                    largest = 0., difference = 0.;
    std::cout << name << ": p =";
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        std::cout << ' ' << exact.pressure(k);
        largest    = std::max(largest, std::abs(p[k]));
        difference = std::max(difference, std::abs(p[k] - exact.pressure(k)));
      }
    // Continuity of sigma_r at each closed joint, equilibrium at the
    // surfaces.
    double mismatch = 0.;
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        const double R = 0.5 * rings[k].outer_diameter;
        mismatch       = std::max(mismatch,
                            std::abs(exact.radial_stress(k, R)
                                     - exact.radial_stress(k + 1, R)));
      }
    std::cout << " MPa; flexibility method "
              << (difference <= 1e-10 * largest ? "agrees" : "DIFFERS")
              << "; sigma_r continuous "
              << (mismatch <= 1e-10 * largest ? "yes" : "NO") << '\n';
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(7);

  // 1. Two rings against DIN 7190-1.
  {
    const std::vector<Ring> rings{{0., 50., 210000., 0.3},
                                  {50., 100., 210000., 0.3}};
    const CompoundCylinders two(rings, {0.05});
    const double            Q = 0.5;
    const double            K
      = ((1. + Q * Q) / (1. - Q * Q) + 0.3) / 210000. + (1. - 0.3) / 210000.;
    const double p = 0.05 / (50. * K);
    std::cout << "two rings: p = " << two.pressure(0) << " MPa, DIN 7190 " << p
              << " MPa: "
              << (std::abs(two.pressure(0) - p) <= 1e-12 * p ? "agrees" :
                                                               "DIFFERS")
              << "; hub bore hoop stress " << two.hoop_stress(1, 25.)
              << " MPa (p (1 + Q^2) / (1 - Q^2) = "
              << p * (1. + Q * Q) / (1. - Q * Q) << ")\n";
  }

  // 2. Three rings.
  const std::vector<Ring> three{{0., 60., 210000., 0.3},
                                {60., 90., 110000., 0.34},
                                {90., 160., 70000., 0.33}};
  compare("three rings", three, {0.04, 0.06});
  {
    // The shaft's joint with the hub removed: the hub's share of it.
    const CompoundCylinders inner({three[0], three[1]}, {0.04});
    std::cout << "  shaft-sleeve alone (no hub): p = " << inner.pressure(0)
              << " MPa\n";
  }

  // 3. Five rings on a hollow core with pressures.
  compare("five rings, hollow core",
          {{20., 40., 210000., 0.3},
           {40., 55., 110000., 0.34},
           {55., 70., 70000., 0.33},
           {70., 90., 200000., 0.29},
           {90., 120., 120000., 0.25}},
          {0.03, 0.02, 0.05, 0.04},
          30.,
          5.);

  // 4. A clearance between the sleeve and the hub.
  {
    compare("sleeve 0.04 mm loose in the hub", three, {0.04, -0.04});
    const CompoundCylinders loose(three, {0.04, -0.04});
    const CompoundCylinders two({three[0], three[1]}, {0.04});
    std::cout << "  shaft-sleeve joint as the two rings alone: "
              << (std::abs(loose.pressure(0) - two.pressure(0))
                      <= 1e-12 * two.pressure(0) ?
                    "yes" :
                    "NO")
              << "; gap " << loose.gap(1)
              << " mm = radial clearance 0.02 mm less "
              << "the sleeve's expansion " << two.radial_displacement(1, 45.)
              << " mm\n";
  }

  // 5. Bad input.
  for (const auto &[rings, U] :
       {std::make_pair(std::vector<Ring>{{0., 50., 210000., 0.3}},
                       std::vector<double>{}),
        std::make_pair(std::vector<Ring>{{0., 50., 210000., 0.3},
                                         {52., 100., 210000., 0.3}},
                       std::vector<double>{0.05}),
        std::make_pair(std::vector<Ring>{{0., 50., 210000., 0.3},
                                         {50., 100., 210000., 0.3}},
                       std::vector<double>{})})
    try
      {
        CompoundCylinders bad(rings, U);
        std::cout << "accepted: NOT refused\n";
      }
    catch (const std::invalid_argument &e)
      {
        std::cout << "refused: " << e.what() << '\n';
      }
}
