// DIN 7190's elastic design against hand formulas. For two parts of one
// material the joint pressure has the closed forms
//   solid shaft:  p = U E (1 - Q_A^2) / (2 D_F)
//   hollow shaft: p = U E (1 - Q_A^2)(1 - Q_I^2) / (2 D_F (1 - Q_A^2 Q_I^2))
// (nu cancels); for a steel shaft (E 210000, nu 0.3) in an aluminium hub
// (E 70000, nu 0.33) of D_F = 40 mm, D_aA = 80 mm and U = 0.05 mm the
// compliance worked by hand is K = (5/3 + 0.33)/70000 + 0.7/210000
// = 3.185714e-5 1/MPa, p = 0.05/(40 K) = 39.2377 MPa. Stresses at the check
// points (Lame) with their plane-stress von Mises stress (hub bore
// sqrt(s_t^2 + p^2 + s_t p), free surfaces |s_t|, solid shaft p, hollow
// shaft bore 2p/(1 - Q_I^2)), torque M = p pi D_F^2 l_F mu / 2 and axial force
// F = p pi D_F l_F mu are checked on the same cases; relative differences
// must be at round-off.

#include <coaxfit/design/din7190.h>

#include <cmath>
#include <iomanip>
#include <iostream>

namespace
{
  coaxfit::GeometryParameters
  joint(const double D_F,
        const double D_iI,
        const double D_aA,
        const double l_F,
        const double U)
  {
    coaxfit::GeometryParameters g;
    g.R0 = D_iI / 2.;
    g.R1 = D_F / 2.;
    g.R2 = D_aA / 2.;
    g.L1 = g.L2 = l_F / 2.;
    g.d         = U / 2.;
    return g;
  }

  void
  report(const std::string &what, const double value, const double hand)
  {
    std::cout << "  " << std::left << std::setw(26) << what << std::right
              << std::setprecision(7) << std::setw(14) << value << "  hand "
              << std::setw(14) << hand << "  rel. difference "
              << (std::abs(value - hand) <= 1e-12 * std::abs(hand) ? "< 1e-12" :
                                                                     "LARGE")
              << '\n';
  }
} // namespace



int
main()
{
  using coaxfit::Din7190;
  coaxfit::Material steel;
  steel.E  = 210000.;
  steel.nu = 0.3;
  coaxfit::Material aluminium;
  aluminium.E     = 70000.;
  aluminium.nu    = 0.33;
  const double mu = 0.12, pi = 3.14159265358979323846;

  {
    std::cout << "steel on steel, solid shaft, D_F 40, D_aA 80, l_F 40, U "
                 "0.05 mm\n";
    const Din7190 din(joint(40., 0., 80., 40., 0.05), steel, steel);
    const double  Q = 0.5, p = 0.05 * 210000. * (1. - Q * Q) / (2. * 40.);
    report("pressure (MPa)", din.pressure(), p);
    report("hub bore hoop (MPa)",
           din.hub_bore().hoop,
           p * (1. + Q * Q) / (1. - Q * Q));
    report("hub outer hoop (MPa)",
           din.hub_outer().hoop,
           2. * p * Q * Q / (1. - Q * Q));
    const double t = p * (1. + Q * Q) / (1. - Q * Q);
    report("hub bore von Mises (MPa)",
           din.hub_bore().equivalent(),
           std::sqrt(t * t + p * p + t * p));
    report("hub outer von Mises",
           din.hub_outer().equivalent(),
           2. * p * Q * Q / (1. - Q * Q));
    report("shaft axis von Mises", din.shaft_inner().equivalent(), p);
    report("torque (N m)",
           din.torque(p, mu),
           1e-3 * p * pi * 40. * 40. * 40. * mu / 2.);
    report("axial force (N)", din.axial_force(p, mu), p * pi * 40. * 40. * mu);
  }
  {
    std::cout << "steel on steel, hollow shaft D_iI 120, D_F 200, D_aA 300, "
                 "l_F 100, U 0.2 mm\n";
    const Din7190 din(joint(200., 120., 300., 100., 0.2), steel, steel);
    const double  A = 200. / 300., I = 120. / 200.;
    const double  p = 0.2 * 210000. * (1. - A * A) * (1. - I * I)
                     / (2. * 200. * (1. - A * A * I * I));
    report("pressure (MPa)", din.pressure(), p);
    report("shaft bore hoop (MPa)",
           din.shaft_inner().hoop,
           -2. * p / (1. - I * I));
    report("shaft bore von Mises",
           din.shaft_inner().equivalent(),
           2. * p / (1. - I * I));
    report("shaft surface hoop (MPa)",
           din.shaft_outer().hoop,
           -p * (1. + I * I) / (1. - I * I));
  }
  {
    std::cout << "steel shaft in an aluminium hub, D_F 40, D_aA 80, U 0.05 "
                 "mm\n";
    const Din7190 din(joint(40., 0., 80., 30., 0.05), steel, aluminium);
    report("pressure (MPa)",
           din.pressure(),
           0.05 / (40. * 3.185714285714286e-5));
    std::cout << "  worked by hand (4 digits): 39.24 MPa\n";
  }
}
