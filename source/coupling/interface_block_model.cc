#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/interface_block_model.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace coaxfit
{
  InterfaceBlockModel::InterfaceBlockModel(const unsigned int n_points,
                                           const unsigned int max_samples,
                                           const double       filter)
    : n(n_points)
    , max_samples(std::max(2u, max_samples))
    , filter(filter)
  {}



  void
  InterfaceBlockModel::set_prior(const unsigned int  body,
                                 std::vector<double> compliance)
  {
    AssertDimension(compliance.size(), n * n);
    prior[body] = std::move(compliance);
  }



  void
  InterfaceBlockModel::set_winkler_prior(const unsigned int    body,
                                         const double          k,
                                         const Vector<double> &weights)
  {
    std::vector<double> diagonal(n * n);
    for (unsigned int i = 0; i < n; ++i)
      diagonal[i * n + i] = k / weights[i];
    set_prior(body, std::move(diagonal));
  }



  bool
  InterfaceBlockModel::has_prior() const
  {
    return !prior[shaft].empty() && !prior[hub].empty();
  }



  void
  InterfaceBlockModel::add_sample(const unsigned int    body,
                                  const Vector<double> &force,
                                  const Vector<double> &u)
  {
    samples[body].push_back({force, u});
    if (samples[body].size() > max_samples)
      samples[body].erase(samples[body].begin());
  }



  std::vector<double>
  InterfaceBlockModel::compliance(const unsigned int body) const
  {
    Assert(!prior[body].empty(), ExcMessage("no prior"));
    std::vector<double>        B = prior[body];
    const std::vector<Sample> &s = samples[body];
    if (s.size() < 2)
      return B;
    const Sample &newest = s.back();
    // Differences to the newest sample, newest first, orthonormalized by
    // modified Gram-Schmidt (dF = Q R); a difference that is nearly
    // dependent on the newer ones, or at the round-off level of the
    // forces, carries no information and is dropped.
    const double                     floor = 1e-13 * newest.force.l2_norm();
    std::vector<Vector<double>>      q, z;
    std::vector<std::vector<double>> R; // R[j][i]: coefficient of q_i
    for (unsigned int k = s.size() - 1; k-- > 0;)
      {
        Vector<double> dF(s[k].force);
        dF -= newest.force;
        const double        norm_dF = dF.l2_norm();
        std::vector<double> r;
        for (const Vector<double> &qi : q)
          {
            const double a = qi * dF;
            dF.add(-a, qi);
            r.push_back(a);
          }
        const double norm = dF.l2_norm();
        if (!(norm > filter * norm_dF) || !(norm_dF > floor))
          continue;
        dF /= norm;
        r.push_back(norm);
        // z = dU - B0 dF (with the original dF = Q r).
        Vector<double> zj(s[k].u);
        zj -= newest.u;
        for (unsigned int i = 0; i < n; ++i)
          {
            double b0_dF = 0.;
            for (unsigned int l = 0; l < n; ++l)
              b0_dF
                += prior[body][i * n + l] * (s[k].force[l] - newest.force[l]);
            zj[i] -= b0_dF;
          }
        q.push_back(dF);
        z.push_back(zj);
        R.push_back(r);
      }
    // B = B0 + Z R^-1 Q^T: Y = Z R^-1 column by column (Y R = Z, R upper
    // triangular), then B += sum_j y_j q_j^T.
    const unsigned int          m = q.size();
    std::vector<Vector<double>> y(m);
    for (unsigned int j = 0; j < m; ++j)
      {
        y[j] = z[j];
        for (unsigned int i = 0; i < j; ++i)
          y[j].add(-R[j][i], y[i]);
        y[j] /= R[j][j];
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int l = 0; l < n; ++l)
            B[i * n + l] += y[j][i] * q[j][l];
      }
    return B;
  }



  bool
  InterfaceBlockModel::predict(const std::vector<double> &interference,
                               const bool                 unilateral,
                               std::vector<bool>         &contact,
                               Vector<double>            &force,
                               Vector<double>            &u_shaft) const
  {
    Assert(!samples[shaft].empty() && !samples[hub].empty(),
           ExcMessage("each body needs a sample"));
    const std::vector<double> Bs = compliance(shaft);
    const std::vector<double> Bh = compliance(hub);
    const Sample             &s  = samples[shaft].back();
    const Sample             &h  = samples[hub].back();

    // g(F) = g0 + S F with S = B_hub - B_shaft and
    // g0 = u_h - B_hub F_h - (u_s - B_shaft F_s) - d.
    std::vector<double> S(n * n);
    Vector<double>      g0(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        double gi = h.u[i] - s.u[i] - interference[i];
        for (unsigned int l = 0; l < n; ++l)
          {
            S[i * n + l] = Bh[i * n + l] - Bs[i * n + l];
            gi += Bs[i * n + l] * s.force[l] - Bh[i * n + l] * h.force[l];
          }
        g0[i] = gi;
      }
    if (!unilateral)
      std::fill(contact.begin(), contact.end(), true);
    // Nothing to close or open (no interference anywhere, e.g. a speed
    // solve at rest): the solution is F = 0, u = 0 whatever the flags; an
    // active-set iteration would only sort the round-off.
    if (std::all_of(interference.begin(), interference.end(), [](double d) {
          return d == 0.;
        }))
      {
        force.reinit(n);
        u_shaft.reinit(n);
        return true;
      }

    // Primal-dual active set: F = 0 at separated points, g = 0 at contact
    // points; then a contact point with a tensile force separates and a
    // separated point that penetrates closes, until the flags repeat.
    std::set<std::vector<bool>> visited;
    bool                        settled = false;
    force.reinit(n);
    for (unsigned int iteration = 0; iteration < 2 * n + 10; ++iteration)
      {
        std::vector<unsigned int> active;
        for (unsigned int i = 0; i < n; ++i)
          if (contact[i])
            active.push_back(i);
        force = 0.;
        if (!active.empty())
          {
            const unsigned int       m = active.size();
            LAPACKFullMatrix<double> A(m, m);
            Vector<double>           rhs(m);
            for (unsigned int a = 0; a < m; ++a)
              {
                rhs[a] = -g0[active[a]];
                for (unsigned int b = 0; b < m; ++b)
                  A(a, b) = S[active[a] * n + active[b]];
              }
            A.compute_lu_factorization();
            A.solve(rhs);
            for (unsigned int a = 0; a < m; ++a)
              force[active[a]] = rhs[a];
          }
        for (const double f : force)
          if (!std::isfinite(f))
            throw SolverError("the interface block model of the bodies' "
                              "compliances is singular (non-finite "
                              "predicted force)");
        if (!unilateral)
          {
            settled = true;
            break;
          }
        visited.insert(contact);
        std::vector<bool> next(contact);
        for (unsigned int i = 0; i < n; ++i)
          if (contact[i])
            next[i] = force[i] >= 0.;
          else
            {
              double gi = g0[i];
              for (unsigned int l = 0; l < n; ++l)
                gi += S[i * n + l] * force[l];
              next[i] = gi < 0.;
            }
        if (next == contact)
          {
            settled = true;
            break;
          }
        if (visited.count(next))
          break;
        contact = next;
      }
    if (unilateral)
      for (double &f : force)
        f = std::max(f, 0.);

    u_shaft = s.u;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int l = 0; l < n; ++l)
        u_shaft[i] += Bs[i * n + l] * (force[l] - s.force[l]);
    return settled;
  }
} // namespace coaxfit
