#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/coarse_interface_model.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  CoarseInterfaceModel::CoarseInterfaceModel(InterfaceOperator &coarse_shaft,
                                             InterfaceOperator &coarse_hub,
                                             const ContactInterface &coarse,
                                             const ContactInterface &fine,
                                             const double short_wave_ratio)
    : coarse_shaft(coarse_shaft)
    , coarse_hub(coarse_hub)
    , coarse_weights(coarse.weights())
    , fine_weights(fine.weights())
    , short_wave_ratio(short_wave_ratio)
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
  }



  std::vector<unsigned int>
  CoarseInterfaceModel::fine_points_at(const ContactInterface &coarse,
                                       const ContactInterface &fine)
  {
    const std::vector<double> &zc = coarse.z();
    const std::vector<double> &zf = fine.z();
    if (zc.size() < 2 || zf.size() < zc.size())
      return {};
    const double tolerance = 1e-9 * std::max(zf.back(), zc.back());
    // Both lists increase from z = 0.
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
      force[i] = fine_weights[i]
                 * (interpolation[i][0] * coarse_force[left[i]]
                      / coarse_weights[left[i]]
                    + interpolation[i][1] * coarse_force[left[i] + 1]
                        / coarse_weights[left[i] + 1]);
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
    const Vector<double>    &wf = fine_weights;
    const Vector<double>    &wc = coarse_weights;
    LAPACKFullMatrix<double> mass(nc, nc);
    for (unsigned int i = 0; i < nf; ++i)
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          mass(left[i] + a, left[i] + b)
            += interpolation[i][a] * wf[i] * interpolation[i][b];
    mass.invert();
    // Q W_f^-1 (nc x nf): the restriction of forces to coarse pressures.
    LAPACKFullMatrix<double> restriction(nc, nf);
    for (unsigned int a = 0; a < nc; ++a)
      for (unsigned int k = 0; k < nf; ++k)
        restriction(a, k) = mass(a, left[k]) * interpolation[k][0]
                            + mass(a, left[k] + 1) * interpolation[k][1];
    LAPACKFullMatrix<double> scaled(nc, nc), T(nc, nf);
    for (unsigned int a = 0; a < nc; ++a)
      for (unsigned int b = 0; b < nc; ++b)
        scaled(a, b) = M(a, b) * wc[b] / wc[a];
    scaled.mmult(T, restriction);

    // Short waves: both bodies answer as half-spaces, one mode ratio
    // lambda of the compliances; the double step multiplies their error by
    // N = -(alpha sqrt(lambda) - (1 - alpha) / sqrt(lambda))^2 (4.17), so
    // the exact step there is 1 / (1 - N).
    const double        root = std::sqrt(short_wave_ratio);
    std::vector<double> J(nf * nf);
    for (unsigned int i = 0; i < nf; ++i)
      {
        const double s     = fine_alpha[i] * root - (1. - fine_alpha[i]) / root;
        const double omega = fine_contact[i] ? 1. / (1. + s * s) : 1.;
        const unsigned int l  = left[i];
        const double       c0 = wf[i] * interpolation[i][0];
        const double       c1 = wf[i] * interpolation[i][1];
        // Separated points are traction free whatever the force: the plain
        // step is exact there and their residuals say nothing about the
        // others.
        if (!fine_contact[i])
          continue;
        for (unsigned int k = 0; k < nf; ++k)
          if (fine_contact[k])
            {
              const double projection
                = c0 * restriction(l, k) + c1 * restriction(l + 1, k);
              J[i * nf + k]
                = c0 * T(l, k) + c1 * T(l + 1, k)
                  + (omega - 1.) * ((i == k ? 1. : 0.) - projection);
            }
      }
    return J;
  }
} // namespace coaxfit
