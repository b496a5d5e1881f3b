#include <coaxfit/accelerator.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  std::string
  NoAcceleration::name() const
  {
    return "none";
  }



  void
  NoAcceleration::accelerate(const Vector<double> &, Vector<double> &)
  {}



  void
  NoAcceleration::restart()
  {}



  AitkenAcceleration::AitkenAcceleration(const double initial_omega)
    : initial_omega(initial_omega)
    , omega(initial_omega)
  {}



  std::string
  AitkenAcceleration::name() const
  {
    return "aitken";
  }



  void
  AitkenAcceleration::accelerate(const Vector<double> &x, Vector<double> &g)
  {
    Vector<double> residual(g);
    residual -= x;
    if (last_residual.size() > 0)
      {
        Vector<double> change(residual);
        change -= last_residual;
        const double norm2 = change.norm_sqr();
        if (norm2 > 0.)
          omega
            = std::clamp(-omega * (last_residual * change) / norm2, 1e-3, 2.);
      }
    last_residual = residual;
    g             = x;
    g.add(omega, residual);
  }



  void
  NoAcceleration::forget_points(const std::vector<bool> &)
  {}



  void
  AitkenAcceleration::forget_points(const std::vector<bool> &changed)
  {
    if (last_residual.size() == changed.size())
      for (unsigned int i = 0; i < changed.size(); ++i)
        if (changed[i])
          last_residual[i] = 0.;
  }



  void
  AitkenAcceleration::restart()
  {
    omega = initial_omega;
    last_residual.reinit(0);
  }



  IQNILSAcceleration::IQNILSAcceleration(const unsigned int max_columns,
                                         const double       filter)
    : max_columns(max_columns)
    , filter(filter)
  {}



  std::string
  IQNILSAcceleration::name() const
  {
    return "iqn-ils";
  }



  void
  IQNILSAcceleration::fit(const Vector<double>        &r,
                          std::vector<Vector<double>> &v_kept,
                          std::vector<Vector<double>> &w,
                          std::vector<double>         &c) const
  {
    v_kept.clear();
    w.clear();
    c.clear();
    if (residuals.size() < 2)
      return;
    const unsigned int m = residuals.size() - 1;
    // Columns newest first; modified Gram-Schmidt with the QR filter: a
    // column whose part orthogonal to the newer ones is below filter times
    // its norm carries no new information and is dropped.
    std::vector<Vector<double>>      q;
    std::vector<std::vector<double>> R; // R[j][k], upper triangular
    for (unsigned int k = m; k-- > 0;)
      {
        Vector<double> v(residuals[k + 1]);
        v -= residuals[k];
        const Vector<double> original(v);
        const double         norm_v = v.l2_norm();
        std::vector<double>  coefficients;
        for (const auto &qj : q)
          {
            const double a = qj * v;
            v.add(-a, qj);
            coefficients.push_back(a);
          }
        const double norm = v.l2_norm();
        if (!(norm > filter * norm_v) || norm_v == 0.)
          continue;
        v /= norm;
        q.push_back(v);
        coefficients.push_back(norm);
        R.push_back(coefficients);
        v_kept.push_back(original);
        w.push_back(outputs[k + 1]);
        w.back() -= outputs[k];
      }
    // R c = -Q^T r by back substitution (R[j] holds column j).
    const unsigned int n_cols = q.size();
    c.assign(n_cols, 0.);
    for (unsigned int j = n_cols; j-- > 0;)
      {
        double s = -(q[j] * r);
        for (unsigned int k = j + 1; k < n_cols; ++k)
          s -= R[k][j] * c[k];
        c[j] = s / R[j][j];
      }
  }



  void
  IQNILSAcceleration::accelerate(const Vector<double> &x, Vector<double> &g)
  {
    residuals.push_back(g);
    residuals.back() -= x;
    outputs.push_back(g);
    if (residuals.size() > max_columns + 1)
      {
        residuals.erase(residuals.begin());
        outputs.erase(outputs.begin());
      }
    // x_{k+1} = G(x_k) + J r_k with the model J of the history.
    add_model_step(Vector<double>(residuals.back()), g);
  }



  void
  IQNILSAcceleration::add_model_step(const Vector<double> &r,
                                     Vector<double>       &out) const
  {
    // J r = W c (+ J_prior (r + V c) with a prior), c = argmin |V c + r|.
    std::vector<Vector<double>> v, w;
    std::vector<double>         c;
    fit(r, v, w, c);
    for (unsigned int j = 0; j < c.size(); ++j)
      out.add(c[j], w[j]);
    if (prior.empty())
      return;
    Vector<double> rest(r);
    for (unsigned int j = 0; j < c.size(); ++j)
      rest.add(c[j], v[j]);
    const unsigned int n = r.size();
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int k = 0; k < n; ++k)
        out[i] += prior[i * n + k] * rest[k];
  }



  void
  IQNILSAcceleration::keep_model(const std::vector<bool> &changed)
  {
    // J = J_prior - (W + J_prior V)(V^T V)^-1 V^T, applied to the unit
    // vectors: column k of J is J e_k, and (V^T V)^-1 V^T e_k = -c(e_k)
    // with the fit's c for r = e_k.
    const unsigned int n = changed.size();
    if (residuals.size() < 2 || residuals.back().size() != n)
      {
        restart();
        return;
      }
    std::vector<double> model(n * n, 0.);
    Vector<double>      unit(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        if (changed[k])
          continue;
        unit    = 0.;
        unit[k] = 1.;
        Vector<double> column(n);
        add_model_step(unit, column);
        for (unsigned int i = 0; i < n; ++i)
          if (!changed[i])
            model[i * n + k] = column[i];
      }
    residuals.clear();
    outputs.clear();
    prior = std::move(model);
  }



  void
  IQNILSAcceleration::restart()
  {
    residuals.clear();
    outputs.clear();
    prior.clear();
  }



  void
  IQNILSAcceleration::forget_points(const std::vector<bool> &changed)
  {
    for (auto *history : {&residuals, &outputs})
      for (Vector<double> &v : *history)
        for (unsigned int i = 0; i < changed.size(); ++i)
          if (changed[i])
            v[i] = 0.;
  }



  std::unique_ptr<Accelerator>
  make_accelerator(const CouplingParameters &parameters)
  {
    switch (parameters.accelerator())
      {
        case AcceleratorType::aitken:
          return std::make_unique<AitkenAcceleration>(parameters.aitken_omega);
        case AcceleratorType::iqn_ils:
          return std::make_unique<IQNILSAcceleration>(parameters.iqn_columns,
                                                      parameters.iqn_filter);
        default:
          return std::make_unique<NoAcceleration>();
      }
  }
} // namespace coaxfit
