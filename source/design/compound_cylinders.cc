#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/design/compound_cylinders.h>

#include <cmath>
#include <stdexcept>

namespace coaxfit
{
  using namespace dealii;

  CompoundCylinders::CompoundCylinders(const std::vector<Ring>   &rings,
                                       const std::vector<double> &interferences,
                                       const double inner_pressure,
                                       const double outer_pressure,
                                       const bool   unilateral)
    : rings(rings)
  {
    const unsigned int n = rings.size();
    if (n < 2)
      throw std::invalid_argument("CompoundCylinders: at least two rings");
    if (interferences.size() != n - 1)
      throw std::invalid_argument(
        "CompoundCylinders: one interference per joint ("
        + std::to_string(n - 1) + "), given "
        + std::to_string(interferences.size()));
    for (unsigned int i = 0; i < n; ++i)
      {
        const Ring &ring = rings[i];
        if (!(ring.E > 0.) || !(ring.nu > -1.) || !(ring.nu < 0.5)
            || !(ring.outer_diameter > ring.inner_diameter)
            || !(ring.inner_diameter >= 0.)
            || (i > 0 && !(ring.inner_diameter > 0.)))
          throw std::invalid_argument(
            "CompoundCylinders: ring " + std::to_string(i)
            + " needs 0 <= inner < outer diameter (0 only for the core), E "
              "> 0 and -1 < nu < 0.5");
        if (i > 0
            && std::abs(ring.inner_diameter - rings[i - 1].outer_diameter)
                 > 1e-9 * ring.outer_diameter)
          throw std::invalid_argument(
            "CompoundCylinders: ring " + std::to_string(i)
            + " does not meet ring " + std::to_string(i - 1)
            + " (inner diameter " + std::to_string(ring.inner_diameter)
            + " mm against outer diameter "
            + std::to_string(rings[i - 1].outer_diameter) + " mm)");
      }

    // Active set over the joints: all closed first; a joint in tension
    // opens, an open one that overlaps closes again.
    std::vector<bool> closed(n - 1, true);
    for (unsigned int pass = 0; pass < (1u << std::min(n - 1, 20u)) + 1; ++pass)
      {
        solve(interferences, closed, inner_pressure, outer_pressure);
        bool changed = false;
        for (unsigned int k = 0; k + 1 < n && unilateral; ++k)
          {
            const double R = 0.5 * rings[k].outer_diameter;
            if (closed[k] && -radial_stress(k, R) < 0.)
              closed[k] = false, changed = true;
            else if (!closed[k]
                     && radial_displacement(k + 1, R)
                            - radial_displacement(k, R) - 0.5 * interferences[k]
                          < 0.)
              closed[k] = true, changed = true;
          }
        if (!changed)
          break;
      }
    pressures.assign(n - 1, 0.);
    gaps.assign(n - 1, 0.);
    for (unsigned int k = 0; k + 1 < n; ++k)
      {
        const double R = 0.5 * rings[k].outer_diameter;
        if (closed[k])
          pressures[k] = -radial_stress(k, R);
        else
          gaps[k] = radial_displacement(k + 1, R) - radial_displacement(k, R)
                    - 0.5 * interferences[k];
      }
  }



  void
  CompoundCylinders::solve(const std::vector<double> &interferences,
                           const std::vector<bool>   &closed,
                           const double               inner_pressure,
                           const double               outer_pressure)
  {
    const unsigned int n = rings.size();
    FullMatrix<double> M(2 * n, 2 * n);
    Vector<double>     rhs(2 * n);
    // sigma_r / (E / (1 - nu^2)) of ring i at r: (1 + nu) A - (1 - nu) B /
    // r^2; the rows of stresses are divided by each ring's E / (1 - nu^2).
    const auto stress_row = [&](const unsigned int row,
                                const unsigned int i,
                                const double       r,
                                const double       sign) {
      const double nu = rings[i].nu;
      M(row, 2 * i) += sign * (1. + nu);
      M(row, 2 * i + 1) += -sign * (1. - nu) / (r * r);
    };
    const auto modulus = [&](const unsigned int i) {
      return rings[i].E / (1. - rings[i].nu * rings[i].nu);
    };
    unsigned int row = 0;
    // The core's bore, or B_0 = 0 for a solid core.
    if (rings[0].inner_diameter > 0.)
      {
        stress_row(row, 0, 0.5 * rings[0].inner_diameter, 1.);
        rhs(row) = -inner_pressure / modulus(0);
      }
    else
      M(row, 1) = 1.;
    ++row;
    for (unsigned int k = 0; k + 1 < n; ++k)
      {
        const double R = 0.5 * rings[k].outer_diameter;
        if (closed[k])
          {
            // sigma_r continuous (scaled by the inner ring's modulus).
            stress_row(row, k, R, 1.);
            stress_row(row, k + 1, R, -modulus(k + 1) / modulus(k));
            ++row;
            // u_{k+1} - u_k = U_k / 2.
            M(row, 2 * k + 2) = R;
            M(row, 2 * k + 3) = 1. / R;
            M(row, 2 * k)     = -R;
            M(row, 2 * k + 1) = -1. / R;
            rhs(row)          = 0.5 * interferences[k];
            ++row;
          }
        else
          {
            // Both surfaces free.
            stress_row(row++, k, R, 1.);
            stress_row(row++, k + 1, R, 1.);
          }
      }
    stress_row(row, n - 1, 0.5 * rings[n - 1].outer_diameter, 1.);
    rhs(row) = -outer_pressure / modulus(n - 1);

    M.gauss_jordan();
    Vector<double> x(2 * n);
    M.vmult(x, rhs);
    A.resize(n);
    B.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        A[i] = x(2 * i);
        B[i] = x(2 * i + 1);
      }
  }



  double
  CompoundCylinders::radial_displacement(const unsigned int i,
                                         const double       r) const
  {
    return A[i] * r + (B[i] == 0. ? 0. : B[i] / r);
  }



  double
  CompoundCylinders::radial_stress(const unsigned int i, const double r) const
  {
    const double nu = rings[i].nu;
    return rings[i].E / (1. - nu * nu)
           * ((1. + nu) * A[i]
              - (B[i] == 0. ? 0. : (1. - nu) * B[i] / (r * r)));
  }



  double
  CompoundCylinders::hoop_stress(const unsigned int i, const double r) const
  {
    const double nu = rings[i].nu;
    return rings[i].E / (1. - nu * nu)
           * ((1. + nu) * A[i]
              + (B[i] == 0. ? 0. : (1. - nu) * B[i] / (r * r)));
  }


  double
  free_ring_displacement(const CompoundCylinders::Ring &ring,
                         const double                   r,
                         const double                   thermal_strain,
                         const double                   rho_omega_squared)
  {
    const double a = ring.inner_diameter / 2., b = ring.outer_diameter / 2.;
    const double nu = ring.nu, q = rho_omega_squared;
    const double sigma_r
      = (3. + nu) / 8. * q * (a * a + b * b - a * a * b * b / (r * r) - r * r);
    const double sigma_t
      = (3. + nu) / 8. * q * (a * a + b * b + a * a * b * b / (r * r))
        - (1. + 3. * nu) / 8. * q * r * r;
    return thermal_strain * r + r / ring.E * (sigma_t - nu * sigma_r);
  }
} // namespace coaxfit
