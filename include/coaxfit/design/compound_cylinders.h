#ifndef coaxfit_compound_cylinders_h
#define coaxfit_compound_cylinders_h

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * N coaxial rings of equal length shrunk into each other (a compound
   * cylinder: a shaft in a sleeve in a hub, a bushing in a housing, the
   * layers of a shrunk pressure vessel), each in a plane-stress Lame state:
   * with free ends and frictionless joints this is the exact elastic
   * solution of the assembly, against which a finite element model of the
   * same rings converges, and the plain-cylinder estimate of each joint's
   * pressure in an assembly of several bodies (DIN 7190-1's formulas are
   * its case N = 2).
   *
   * In ring i (a_i <= r <= b_i, Young's modulus E_i, Poisson's ratio
   * nu_i) the radial displacement is u = A_i r + B_i / r, and
   *   sigma_r = E_i / (1 - nu_i^2) ((1 + nu_i) A_i - (1 - nu_i) B_i / r^2),
   *   sigma_t = E_i / (1 - nu_i^2) ((1 + nu_i) A_i + (1 - nu_i) B_i / r^2)
   * (B_0 = 0 for a solid core). The conditions: sigma_r = -p_in at the
   * core's bore and -p_out at the outer surface; at the joint k between
   * ring k and ring k + 1 (radius R_k = b_k = a_{k+1}) the radial stress
   * continuous, -p_k, and the diametral interference U_k closed,
   * u_{k+1}(R_k) - u_k(R_k) = U_k / 2 (the outer ring's bore is drawn U_k
   * smaller than the inner ring's outer diameter). A joint whose pressure
   * would be negative (a clearance, or one opened by the others) is open
   * instead: p_k = 0 and its gap u_{k+1} - u_k - U_k / 2 >= 0, found by an
   * active set over the joints (exact, at most 2^(N-1) solves, in practice
   * one or two).
   */
  class CompoundCylinders
  {
  public:
    /** One ring (diameters in mm, E in MPa). */
    struct Ring
    {
      double inner_diameter; ///< 0: a solid core (the first ring only)
      double outer_diameter;
      double E;
      double nu;
    };

    /**
     * Solve the rings @p rings (inside out; each ring's inner diameter
     * the previous one's outer diameter) with the diametral interferences
     * @p interferences (mm, one per joint, negative: a clearance) and the
     * pressures @p inner_pressure on the core's bore (a hollow core) and
     * @p outer_pressure on the outer surface (MPa).
     * @throws std::invalid_argument for fewer than two rings, rings that
     * do not meet, a number of interferences that is not the number of
     * joints, or material constants out of range. Without @p unilateral
     * every joint stays closed (bonded radially: a clearance pulls).
     */
    CompoundCylinders(const std::vector<Ring>   &rings,
                      const std::vector<double> &interferences,
                      double                     inner_pressure = 0.,
                      double                     outer_pressure = 0.,
                      bool                       unilateral     = true);

    /** The contact pressure of joint @p k (MPa; 0 if open). */
    double
    pressure(unsigned int k) const
    {
      return pressures[k];
    }

    /** The radial gap of joint @p k (mm; 0 if closed). */
    double
    gap(unsigned int k) const
    {
      return gaps[k];
    }

    /** The number of joints, N - 1. */
    unsigned int
    n_joints() const
    {
      return pressures.size();
    }

    /** The radial displacement (mm) of ring @p i at radius @p r. */
    double
    radial_displacement(unsigned int i, double r) const;

    /** The radial stress (MPa) of ring @p i at radius @p r. */
    double
    radial_stress(unsigned int i, double r) const;

    /** The hoop stress (MPa) of ring @p i at radius @p r. */
    double
    hoop_stress(unsigned int i, double r) const;

  private:
    std::vector<Ring>   rings;
    std::vector<double> A, B;
    std::vector<double> pressures, gaps;

    /**
     * Solve for A and B with the joints @p closed in contact and the
     * others free.
     */
    void
    solve(const std::vector<double> &interferences,
          const std::vector<bool>   &closed,
          double                     inner_pressure,
          double                     outer_pressure);
  };
  /**
   * The radial displacement (mm) at radius @p r of the ring @p ring
   * standing free (no pressure on its surfaces) under the uniform thermal
   * strain @p thermal_strain = alpha (T - T_assembly) and the rotation
   * @p rho_omega_squared = rho omega^2 (MPa/mm^2: 1e-12 times rho in
   * kg/m^3 and omega^2 in (rad/s)^2), in plane stress:
   *   u = thermal_strain r + r / E (sigma_t - nu sigma_r),
   *   sigma_r = (3 + nu) / 8 q (a^2 + b^2 - a^2 b^2 / r^2 - r^2),
   *   sigma_t = (3 + nu) / 8 q (a^2 + b^2 + a^2 b^2 / r^2)
   *             - (1 + 3 nu) / 8 q r^2
   * (the rotating disc; a = 0 for a solid one). The bodies are linear, so
   * rings that carry these loads in contact have the pressures of
   * unloaded rings with each joint's diametral interference less twice
   * the free rings' u_outer - u_inner there: exact for the thermal
   * strain, the plane-stress estimate for the rotation.
   */
  double
  free_ring_displacement(const CompoundCylinders::Ring &ring,
                         double                         r,
                         double                         thermal_strain,
                         double                         rho_omega_squared);
} // namespace coaxfit

#endif
