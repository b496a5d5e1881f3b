#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/coupling/coarse_interface_model.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace coaxfit
{
  CoarseInterfaceModel::CoarseInterfaceModel(
    InterfaceOperator                        &coarse_shaft,
    InterfaceOperator                        &coarse_hub,
    const ContactInterface                   &coarse,
    const ContactInterface                   &fine,
    const std::array<ShortWaveCompliance, 2> &short_waves,
    const unsigned int                        degree)
    : coarse_shaft(coarse_shaft)
    , coarse_hub(coarse_hub)
    , coarse_weights(coarse.weights())
    , fine_weights(fine.weights())
  {
    coarse_index = fine_points_at(coarse, fine);
    AssertThrow(!coarse_index.empty(),
                ExcMessage("every point of the coarse interface (at least "
                           "two) must be a point of the fine one"));
    const std::vector<double> &zc = coarse.z();
    for (const double z : fine.z())
      {
        const auto         upper = std::upper_bound(zc.begin(), zc.end(), z);
        const unsigned int l
          = std::min<unsigned int>(std::max<long>(upper - zc.begin(), 1) - 1,
                                   zc.size() - 2);
        const double t = std::clamp((z - zc[l]) / (zc[l + 1] - zc[l]), 0., 1.);
        left.push_back(l);
        interpolation.push_back({{1. - t, t}});
      }
    // The transfer of pressures: the coarse elements' own interpolation,
    // quadratic on each pair of coarse intervals (vertex, midpoint, vertex)
    // for FE_Q(2), linear otherwise. With it the coarse weights are the
    // restricted fine ones (w_c = P^T w_f, the shape functions nest), so
    // the restriction below conserves force.
    for (unsigned int i = 0; i < fine.z().size(); ++i)
      {
        const double z = fine.z()[i];
        if (degree == 2 && zc.size() % 2 == 1)
          {
            const long cell
              = std::upper_bound(zc.begin(), zc.end(), z) - zc.begin() - 1;
            const unsigned int m
              = std::min<unsigned int>(2 * (std::max<long>(cell, 0) / 2),
                                       zc.size() - 3);
            const double xi = (z - zc[m]) / (zc[m + 2] - zc[m]);
            transfer.push_back({{m, 2. * (xi - 0.5) * (xi - 1.)},
                                {m + 1, 4. * xi * (1. - xi)},
                                {m + 2, 2. * xi * (xi - 0.5)}});
          }
        else
          transfer.push_back({{left[i], interpolation[i][0]},
                              {left[i] + 1, interpolation[i][1]}});
      }
    const std::vector<double> &zf = fine.z();
    for (unsigned int i = 0; i < zf.size(); ++i)
      {
        const double h = (zf[std::min<unsigned int>(i + 1, zf.size() - 1)]
                          - zf[i > 0 ? i - 1 : 0])
                         / ((i > 0 && i + 1 < zf.size()) ? 2. : 1.);
        for (unsigned int b = 0; b < 2; ++b)
          short_wave[b].push_back(
            short_waves[b](numbers::PI / (h * numbers::SQRT2)));
      }
  }



  std::vector<unsigned int>
  CoarseInterfaceModel::fine_points_at(const ContactInterface &coarse,
                                       const ContactInterface &fine)
  {
    const std::vector<double> &zc = coarse.z();
    const std::vector<double> &zf = fine.z();
    if (zc.size() < 2 || zf.size() < zc.size())
      return {};
    // Both lists increase (from z = 0 for a half model).
    const double tolerance
      = 1e-9 * std::max(z_range_scale(zf), z_range_scale(zc));
    std::vector<unsigned int> index;
    unsigned int              i = 0;
    for (const double z : zc)
      {
        while (i < zf.size() && zf[i] < z - tolerance)
          ++i;
        if (i == zf.size() || std::abs(zf[i] - z) > tolerance)
          return {};
        index.push_back(i);
      }
    return index;
  }



  bool
  CoarseInterfaceModel::nested(const ContactInterface &coarse,
                               const ContactInterface &fine)
  {
    return !fine_points_at(coarse, fine).empty();
  }



  Vector<double>
  CoarseInterfaceModel::prolongate(const Vector<double> &coarse_force) const
  {
    AssertDimension(coarse_force.size(), coarse_weights.size());
    Vector<double> force(fine_weights.size());
    for (unsigned int i = 0; i < force.size(); ++i)
      for (const auto &[a, p] : transfer[i])
        force[i] += fine_weights[i] * p * coarse_force[a] / coarse_weights[a];
    return force;
  }



  std::vector<bool>
  CoarseInterfaceModel::prolongate(
    const std::vector<bool> &coarse_contact) const
  {
    AssertDimension(coarse_contact.size(), coarse_weights.size());
    std::vector<bool> contact(fine_weights.size());
    for (unsigned int i = 0; i < contact.size(); ++i)
      contact[i] = (interpolation[i][0] > 0. && coarse_contact[left[i]])
                   || (interpolation[i][1] > 0. && coarse_contact[left[i] + 1]);
    return contact;
  }



  void
  CoarseInterfaceModel::map_column(const unsigned int         j,
                                   const std::vector<double> &alpha,
                                   const std::vector<bool>   &contact,
                                   Vector<double>            &column)
  {
    // One Neumann and one Dirichlet step of the coarse process without
    // interference (the linear part of the map), for a unit force at j.
    const unsigned int n = coarse_weights.size();
    Vector<double>     force(n), u1(n), u2(n), u(n), zero(n), f1, f2, unused;
    force[j] = 1.;
    coarse_shaft.solve_neumann(force, u1);
    coarse_hub.solve_neumann(force, u2);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = u1[i] + (1. - alpha[i]) * (u2[i] - u1[i]);
    coarse_shaft.solve(contact, u, zero, unused, f1);
    coarse_hub.solve(contact, u, zero, unused, f2);
    column.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      column[i] = f1[i] + alpha[i] * (f2[i] - f1[i]);
  }



  std::vector<double>
  CoarseInterfaceModel::inverse_jacobian_prior(
    const std::vector<double> &fine_alpha,
    const std::vector<bool>   &fine_contact)
  {
    const unsigned int  nc = coarse_index.size();
    const unsigned int  nf = fine_weights.size();
    std::vector<double> alpha(nc);
    std::vector<bool>   contact(nc);
    for (unsigned int j = 0; j < nc; ++j)
      {
        alpha[j]   = fine_alpha[coarse_index[j]];
        contact[j] = fine_contact[coarse_index[j]];
      }

    // B = (I - E)^-1 - I on the coarse interface.
    LAPACKFullMatrix<double> M(nc, nc);
    Vector<double>           column;
    for (unsigned int j = 0; j < nc; ++j)
      {
        map_column(j, alpha, contact, column);
        for (unsigned int i = 0; i < nc; ++i)
          M(i, j) = (i == j ? 1. : 0.) - column[i];
      }
    M.invert();
    for (unsigned int i = 0; i < nc; ++i)
      M(i, i) -= 1.;

    // The transfers (pressures p = F / w): P interpolates coarse
    // pressures, Q = (P^T W_f P)^-1 P^T W_f their weighted least-squares
    // restriction (Q P = I, so that W_f P Q W_f^-1 is a projection onto
    // what the coarse mesh represents). With B^ = W_c^-1 B W_c,
    // J = W_f P B^ Q W_f^-1 + (Omega - I)(I - W_f P Q W_f^-1).
    const Vector<double>          &wf          = fine_weights;
    const Vector<double>          &wc          = coarse_weights;
    const LAPACKFullMatrix<double> restriction = force_restriction();
    LAPACKFullMatrix<double>       scaled(nc, nc), T(nc, nf);
    for (unsigned int a = 0; a < nc; ++a)
      for (unsigned int b = 0; b < nc; ++b)
        scaled(a, b) = M(a, b) * wc[b] / wc[a];
    scaled.mmult(T, restriction);

    // Short waves: both bodies answer as half-spaces or shells
    // (ShortWaveCompliance), with the ratio lambda of their compliances at
    // each point; the double step multiplies their error by
    // N = -(alpha sqrt(lambda) - (1 - alpha) / sqrt(lambda))^2 (4.17), so
    // the exact step there is 1 / (1 - N).
    std::vector<double> J(nf * nf);
    for (unsigned int i = 0; i < nf; ++i)
      {
        const double root  = std::sqrt(short_wave[0][i] / short_wave[1][i]);
        const double s     = fine_alpha[i] * root - (1. - fine_alpha[i]) / root;
        const double omega = fine_contact[i] ? 1. / (1. + s * s) : 1.;
        // Separated points are traction free whatever the force: the plain
        // step is exact there and their residuals say nothing about the
        // others.
        if (!fine_contact[i])
          continue;
        for (unsigned int k = 0; k < nf; ++k)
          if (fine_contact[k])
            {
              double projection = 0., coarse = 0.;
              for (const auto &[a, p] : transfer[i])
                {
                  projection += wf[i] * p * restriction(a, k);
                  coarse += wf[i] * p * T(a, k);
                }
              J[i * nf + k]
                = coarse + (omega - 1.) * ((i == k ? 1. : 0.) - projection);
            }
      }
    return J;
  }



  LAPACKFullMatrix<double>
  CoarseInterfaceModel::force_restriction() const
  {
    const unsigned int       nc = coarse_index.size();
    const unsigned int       nf = fine_weights.size();
    LAPACKFullMatrix<double> mass(nc, nc);
    for (unsigned int i = 0; i < nf; ++i)
      for (const auto &[a, pa] : transfer[i])
        for (const auto &[b, pb] : transfer[i])
          mass(a, b) += pa * fine_weights[i] * pb;
    mass.invert();
    LAPACKFullMatrix<double> restriction(nc, nf);
    for (unsigned int a = 0; a < nc; ++a)
      for (unsigned int k = 0; k < nf; ++k)
        for (const auto &[b, pb] : transfer[k])
          restriction(a, k) += mass(a, b) * pb;
    return restriction;
  }



  std::vector<double>
  CoarseInterfaceModel::compliance_prior(const unsigned int body)
  {
    const unsigned int nc = coarse_index.size();
    const unsigned int nf = fine_weights.size();
    InterfaceOperator &op = body == 0 ? coarse_shaft : coarse_hub;
    // The coarse compliance C_c, column by column.
    LAPACKFullMatrix<double> Cc(nc, nc);
    Vector<double>           unit(nc), u(nc);
    for (unsigned int j = 0; j < nc; ++j)
      {
        unit    = 0.;
        unit[j] = 1.;
        op.solve_neumann(unit, u);
        for (unsigned int i = 0; i < nc; ++i)
          Cc(i, j) = u[i];
      }
    // The shaft moves inwards under compression: its compliance and the
    // short-wave term below are negative.
    const double sign = Cc(0, 0) < 0. ? -1. : 1.;

    // C = P C_c P^T + S (W_f^-1 - P M^-1 P^T) S, M = P^T W_f P,
    // S = diag(sqrt(c_i)) (symmetric, as the fine compliance is).
    // - P C_c P^T is the coarse body's answer to the coarse nodal forces
    //   P^T F (consistent: P is the elements' interpolation, so P^T conserves
    //   force and gives a uniform pressure's coarse forces exactly),
    //   interpolated: the Galerkin (Ritz) approximation.
    // - W_f^-1 - P M^-1 P^T = W_f^-1/2 (I - projection) W_f^-1/2 takes from
    //   the pressure F / w what the coarse mesh represents; the rest, the
    //   short waves, gets the compliance c_i = c(k) of ShortWaveCompliance.
    const LAPACKFullMatrix<double> restriction = force_restriction();
    LAPACKFullMatrix<double>       G(nc, nf); // C_c P^T
    for (unsigned int a = 0; a < nc; ++a)
      for (unsigned int k = 0; k < nf; ++k)
        for (const auto &[b, pb] : transfer[k])
          G(a, k) += Cc(a, b) * pb;
    std::vector<double> C(nf * nf);
    for (unsigned int i = 0; i < nf; ++i)
      for (unsigned int k = 0; k < nf; ++k)
        {
          double projection = 0., coarse = 0.;
          for (const auto &[a, p] : transfer[i])
            {
              projection += p * restriction(a, k);
              coarse += p * G(a, k);
            }
          C[i * nf + k]
            = coarse
              + sign * std::sqrt(short_wave[body][i] * short_wave[body][k])
                  * ((i == k ? 1. / fine_weights[i] : 0.) - projection);
        }
    return C;
  }



  double
  ShortWaveCompliance::operator()(const double k) const
  {
    const double half_space = 2. * (1. - nu * nu) / (E * k);
    if (!(wall > 0.))
      return half_space;
    const double D = E * wall * wall * wall / (12. * (1. - nu * nu));
    const double shell
      = 1. / (D * k * k * k * k + E * wall / (radius * radius));
    return std::max(half_space, shell);
  }
} // namespace coaxfit
