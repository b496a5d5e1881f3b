// Loads of operation against closed forms worked independently here (not
// with the program's own Din7190): steel-like parts, D_F = 200 mm, hub
// D_aA = 400 mm, nu = 0.3 in both (with equal nu and equal lengths the
// plane-stress solutions of temperature and pressure are exact for the
// free-ended cylinders, so the finite element answer must match them to
// discretization accuracy):
//
// 1. Temperature, equal lengths: the two-material Lame pressure with the
//    effective interference U - D_F (alpha_hub dT_hub - alpha_shaft
//    dT_shaft); equal coefficients and one temperature change nothing.
// 2. Bore pressure q on a hollow shaft (D_iI = 120 mm), equal lengths: the
//    shaft's free outer surface moves by 2 q R0^2 R1 / (E (R1^2 - R0^2)),
//    which adds to the radial interference.
// 3. Rotation of a long pair (both 1200 mm long, solid steel shaft,
//    aluminium hub) at the mid-plane against the rotating-cylinder solution
//    with free ends (generalized plane strain: the plane-strain state plus
//    the uniform axial stress that removes the axial force, each body its
//    own). For these two pairs its joint pressure equals that of
//    plane-stress rings to five digits (printed beside it).
// 4. Rotation of a thin pair (both 10 mm long: plane stress) against the
//    rotating-disc solution; plane stress is not exact for a disc of
//    finite thickness, the difference is stated.
// 5. Loosening speed of the thin pair against the disc formula
//    omega^2 = 4 E d / (rho R1 (3 + nu) R2^2) (same material, solid
//    shaft), and the joining temperatures against DIN 7190's
//    dT = (U + clearance) / (alpha D_F).
// 6. A clearance (U = -0.1 mm): no contact at rest, exit as a converged
//    answer; the same clearance closed by heating the shaft.

#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/design/operation_analysis.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
  constexpr double E = 2.1e5, nu = 0.3, rho = 7850.;

  coaxfit::Parameters
  pair(const double length, const double U, const double bore = 0.)
  {
    coaxfit::Parameters p;
    p.drawing.joint_diameter      = 200.;
    p.drawing.shaft_bore_diameter = bore;
    p.drawing.hub_outer_diameter  = 400.;
    p.drawing.hub_length = p.drawing.shaft_length = length;
    p.fit_limits.U_min = p.fit_limits.U_max = U;
    for (coaxfit::Material *m : {&p.shaft, &p.hub})
      {
        m->E                 = E;
        m->nu                = nu;
        m->density           = rho;
        m->thermal_expansion = 11.5e-6;
      }
    p.mesh.global_refinements = 1;
    p.design.corner_trend     = false;
    p.derive_model();
    return p;
  }

  struct Result
  {
    bool                       converged;
    coaxfit::PressureSummary   pressure;
    coaxfit::OperationAnalysis operation;
  };

  Result
  solve(const coaxfit::Parameters &p)
  {
    std::ostringstream  quiet;
    coaxfit::CoaxialFit fit(p, quiet, false);
    fit.setup_system();
    const bool converged = fit.solve(nullptr);
    return {converged,
            fit.pressure_summary(),
            coaxfit::OperationAnalysis(p, fit)};
  }

  /** Plane-stress compliance term of the pair: p = d / (R1 K). */
  double
  pair_compliance(const double R0, const double R1, const double R2)
  {
    return ((R2 * R2 + R1 * R1) / (R2 * R2 - R1 * R1) + nu) / E
           + ((R1 * R1 + R0 * R0) / (R1 * R1 - R0 * R0) - nu) / E;
  }

  void
  compare(const std::string &what,
          const double       fe,
          const double       hand,
          const double       tolerance)
  {
    const double difference
      = hand == 0. ? std::abs(fe) : std::abs(fe / hand - 1.);
    std::cout << "  " << std::left << std::setw(50) << what << std::right
              << std::fixed << std::setprecision(3) << std::setw(11) << fe
              << "  hand " << std::setw(11) << hand << "  "
              << (difference <= tolerance ? "within " : "OUTSIDE ")
              << std::scientific << std::setprecision(0) << tolerance
              << std::defaultfloat << '\n';
  }

  /**
   * The radial displacement per (rad/s)^2 at r = b of a free ring a <= r <=
   * b (a = 0: solid) rotating with free ends, generalized plane strain:
   * u = C1 r + C2 / r - k r^3 with k = rho' (1 + nu)(1 - 2 nu) / (8 E (1 -
   * nu)) and sigma_r = 0 at both radii, plus nu s r / E for the uniform
   * axial stress s = -mean(sigma_z) that frees the ends. Evaluated at
   * @p r_eval; @p p_a, @p p_b add pressures (per unit).
   */
  double
  rotating_cylinder_u(const double a,
                      const double b,
                      const double omega_squared,
                      const double p_a,
                      const double p_b,
                      const double r_eval,
                      const double E   = ::E,
                      const double nu  = ::nu,
                      const double rho = ::rho)
  {
    const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    const double mu     = E / (2. * (1. + nu));
    const double load   = 1e-12 * rho * omega_squared;
    const double k = load * (1. + nu) * (1. - 2. * nu) / (8. * E * (1. - nu));
    // sigma_r(r) = (lambda + 2 mu) u' + lambda u / r for u = C1 r + C2/r -
    // k r^3: 2 (lambda + mu) C1 - 2 mu C2 / r^2 - (3 lambda + 6 mu + lambda)
    // k r^2.
    double C1, C2;
    if (a == 0.)
      {
        C2 = 0.;
        C1
          = (-p_b + (4. * lambda + 6. * mu) * k * b * b) / (2. * (lambda + mu));
      }
    else
      {
        // Two equations in C1, C2: s_r(a) = -p_a, s_r(b) = -p_b.
        const double m11 = 2. * (lambda + mu), m12a = -2. * mu / (a * a),
                     m12b = -2. * mu / (b * b);
        const double r1   = -p_a + (4. * lambda + 6. * mu) * k * a * a;
        const double r2   = -p_b + (4. * lambda + 6. * mu) * k * b * b;
        C2                = (r1 - r2) / (m12a - m12b);
        C1                = (r1 - m12a * C2) / m11;
      }
    // sigma_z = lambda (u' + u/r) = lambda (2 C1 - 4 k r^2): its mean over
    // the section int r dr.
    const double mean_sigma_z
      = lambda * (2. * C1 - 4. * k * (a * a + b * b) / 2.);
    return C1 * r_eval + (r_eval > 0. ? C2 / r_eval : 0.)
           - k * std::pow(r_eval, 3) + nu * mean_sigma_z * r_eval / E;
  }
} // namespace



int
main()
{
  const double R1 = 100., R2 = 200.;
  const double U = 0.5; // mm, d = 0.25 mm
  const double d = U / 2.;

  std::cout << "1. temperature, equal lengths (200 mm)\n";
  {
    coaxfit::Parameters p              = pair(200., U);
    p.hub.thermal_expansion            = 23e-6;
    p.operation.shaft_temperature_text = "70";
    p.operation.hub_temperature_text   = "70";
    const Result r                     = solve(p);
    const double U_eff                 = U - 200. * (23e-6 - 11.5e-6) * 50.;
    const double hand = U_eff / 2. / (R1 * pair_compliance(0., R1, R2));
    std::cout << "  converged " << (r.converged ? "yes" : "no") << '\n';
    compare("pressure at z = 0 (MPa)", r.pressure.at_mid_plane, hand, 1e-4);
    compare("mean pressure (MPa)", r.pressure.mean, hand, 1e-4);
    compare("assembly state, mean pressure (MPa)",
            r.operation.assembly.pressure_mean,
            d / (R1 * pair_compliance(0., R1, R2)),
            1e-4);

    coaxfit::Parameters same              = pair(200., U);
    same.operation.shaft_temperature_text = "120";
    same.operation.hub_temperature_text   = "120";
    const Result s                        = solve(same);
    compare("equal coefficients, 100 K: mean pressure (MPa)",
            s.pressure.mean,
            d / (R1 * pair_compliance(0., R1, R2)),
            1e-4);
  }

  std::cout << "2. bore pressure 100 MPa, hollow shaft D_iI = 120 mm\n";
  {
    coaxfit::Parameters p           = pair(200., U, 120.);
    p.operation.shaft_bore_pressure = 100.;
    const Result r                  = solve(p);
    const double R0 = 60., q = 100.;
    const double lift = 2. * q * R0 * R0 * R1 / (E * (R1 * R1 - R0 * R0));
    const double hand = (d + lift) / (R1 * pair_compliance(R0, R1, R2));
    compare("pressure at z = 0 (MPa)", r.pressure.at_mid_plane, hand, 1e-4);
    compare("mean pressure (MPa)", r.pressure.mean, hand, 1e-4);
  }

  std::cout << "3. rotation 10000 1/min, long pair (1200 mm), aluminium "
               "hub (E 70000, nu 0.33, rho 2700), mid-plane\n";
  {
    coaxfit::Parameters p = pair(1200., U);
    p.hub.E               = 7e4;
    p.hub.nu              = 0.33;
    p.hub.density         = 2700.;
    p.operation.speed     = 10000.;
    const double omega    = 2. * M_PI * 10000. / 60.;
    const Result r        = solve(p);
    // Contact pressure P closes d between the hub's and the shaft's u at
    // R1, each linear in P: u = u(rotation) + P u(unit pressure).
    const double w2 = omega * omega;
    const double hub0
      = rotating_cylinder_u(R1, R2, w2, 0., 0., R1, 7e4, 0.33, 2700.);
    const double hub1
      = rotating_cylinder_u(R1, R2, 0., 1., 0., R1, 7e4, 0.33, 2700.);
    const double sh0  = rotating_cylinder_u(0., R1, w2, 0., 0., R1);
    const double sh1  = rotating_cylinder_u(0., R1, 0., 0., 1., R1);
    const double hand = (d - (hub0 - sh0)) / (hub1 - sh1);
    compare("pressure at z = 0 (MPa)", r.pressure.at_mid_plane, hand, 1e-3);
    std::cout << "  (plane-stress rings give " << std::fixed
              << std::setprecision(3) << r.pressure.lame << " MPa)\n"
              << std::defaultfloat;
  }

  std::cout << "4. rotation 10000 1/min, thin pair (10 mm), mid-plane\n";
  double thin_hand_omega = 0.;
  {
    coaxfit::Parameters p = pair(10., U);
    p.operation.speed     = 10000.;
    const double omega    = 2. * M_PI * 10000. / 60.;
    const Result r        = solve(p);
    // Plane-stress discs: the free hub's bore moves by
    // rho' omega^2 R1 ((3 + nu) R2^2 + (1 - nu) R1^2) / (4 E), the solid
    // shaft's rim by rho' omega^2 (1 - nu) R1^3 / (4 E).
    const double c    = 1e-12 * rho * omega * omega;
    const double loss = c * R1 * (3. + nu) * R2 * R2 / (4. * E);
    const double hand = (d - loss) / (R1 * pair_compliance(0., R1, R2));
    compare("pressure at z = 0 (MPa)", r.pressure.at_mid_plane, hand, 5e-3);
    thin_hand_omega
      = std::sqrt(4. * E * d / (1e-12 * rho * R1 * (3. + nu) * R2 * R2));

    std::cout << "5. loosening speed and joining temperatures, thin pair\n";
    const double hand_speed = thin_hand_omega * 60. / (2. * M_PI);
    compare("loosening speed, first point (1/min)",
            r.operation.loosening_speed_first,
            hand_speed,
            5e-3);
    compare("loosening speed, whole joint (1/min)",
            r.operation.loosening_speed_whole,
            hand_speed,
            5e-3);
    compare("loosening speed, DIN 7190 (1/min)",
            r.operation.loosening_speed_din,
            hand_speed,
            1e-10);
    std::cout << "  confirmation: min pressure at the first speed "
              << (std::abs(r.operation.min_pressure_at_first) < 1e-6 ? "0" :
                                                                       "NOT 0")
              << ", separated points 1 % below "
              << r.operation.separated_below_first << ", 1 % above "
              << (r.operation.separated_above_first > 0 ? "some" : "none")
              << ", max pressure at the whole-joint speed "
              << (std::abs(r.operation.max_pressure_at_whole) < 1e-6 ? "0" :
                                                                       "NOT 0")
              << '\n';
    // clearance auto = 0.001 D_F = 0.2 mm.
    compare("joining: hub heated to (C)",
            r.operation.joining_temperature_hub,
            20. + (U + 0.2) / (11.5e-6 * 200.),
            1e-12);
    compare("joining: shaft cooled to (C)",
            r.operation.joining_temperature_shaft,
            20. - (U + 0.2) / (11.5e-6 * 200.),
            1e-12);
  }

  std::cout << "6. clearance U = -0.1 mm, equal lengths\n";
  {
    const Result r = solve(pair(200., -0.1));
    std::cout << "  at rest: converged " << (r.converged ? "yes" : "no")
              << ", contact "
              << (r.operation.operation.contact_lost ? "lost" : "HELD")
              << ", max pressure " << r.pressure.max << " MPa\n";
    // Heat the shaft by 0.2 mm / (alpha D_F): U_eff = +0.1 mm.
    coaxfit::Parameters p = pair(200., -0.1);
    std::ostringstream  T;
    T << std::setprecision(17) << 20. + 0.2 / (11.5e-6 * 200.);
    p.operation.shaft_temperature_text = T.str();
    const Result h                     = solve(p);
    std::cout << "  shaft heated: converged " << (h.converged ? "yes" : "no")
              << '\n';
    compare("shaft heated: mean pressure (MPa)",
            h.pressure.mean,
            0.05 / (R1 * pair_compliance(0., R1, R2)),
            1e-4);
  }
}
