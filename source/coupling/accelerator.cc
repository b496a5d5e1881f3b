#include <coaxfit/coupling/accelerator.h>

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



  IQNILSAcceleration::Model
  IQNILSAcceleration::factor() const
  {
    Model model;
    if (residuals.size() < 2)
      return model;
    const unsigned int m = residuals.size() - 1;
    // Columns newest first; modified Gram-Schmidt with the QR filter: a
    // column whose part orthogonal to the newer ones is below filter times
    // its norm carries no new information and is dropped.
    for (unsigned int k = m; k-- > 0;)
      {
        Vector<double> v(residuals[k + 1]);
        v -= residuals[k];
        const Vector<double> original(v);
        const double         norm_v = v.l2_norm();
        std::vector<double>  coefficients;
        for (const auto &qj : model.q)
          {
            const double a = qj * v;
            v.add(-a, qj);
            coefficients.push_back(a);
          }
        const double norm = v.l2_norm();
        if (!(norm > filter * norm_v) || norm_v == 0.)
          continue;
        v /= norm;
        model.q.push_back(v);
        coefficients.push_back(norm);
        model.R.push_back(coefficients);
        model.v.push_back(original);
        model.w.push_back(outputs[k + 1]);
        model.w.back() -= outputs[k];
      }
    // With a prior, its product with V is needed for every step.
    if (!prior.empty())
      for (const Vector<double> &v : model.v)
        {
          model.prior_v.emplace_back(v.size());
          multiply_prior(v, model.prior_v.back());
        }
    return model;
  }



  void
  IQNILSAcceleration::multiply_prior(const Vector<double> &x,
                                     Vector<double>       &out) const
  {
    const unsigned int n = x.size();
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int k = 0; k < n; ++k)
        out[i] += prior[i * n + k] * x[k];
  }



  void
  IQNILSAcceleration::add_model_step(const Model          &model,
                                     const Vector<double> &r,
                                     Vector<double>       &out) const
  {
    // c = argmin |V c + r|: R c = -Q^T r by back substitution (R[j] holds
    // column j).
    const unsigned int  n_cols = model.q.size();
    std::vector<double> c(n_cols);
    for (unsigned int j = n_cols; j-- > 0;)
      {
        double s = -(model.q[j] * r);
        for (unsigned int k = j + 1; k < n_cols; ++k)
          s -= model.R[k][j] * c[k];
        c[j] = s / model.R[j][j];
      }
    // J r = W c (+ J_prior r + (J_prior V) c with a prior).
    for (unsigned int j = 0; j < n_cols; ++j)
      out.add(c[j], model.w[j]);
    if (prior.empty())
      return;
    multiply_prior(r, out);
    for (unsigned int j = 0; j < n_cols; ++j)
      out.add(c[j], model.prior_v[j]);
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
    add_model_step(factor(), residuals.back(), g);
  }



  void
  IQNILSAcceleration::keep_model(const std::vector<bool> &changed)
  {
    // J = J_prior - (W + J_prior V)(V^T V)^-1 V^T, applied to the unit
    // vectors: column k of J is J e_k (one factorization of the history
    // serves all n columns).
    const unsigned int n = changed.size();
    if (residuals.size() < 2 || residuals.back().size() != n)
      {
        restart();
        return;
      }
    const Model         history = factor();
    std::vector<double> model(n * n, 0.);
    Vector<double>      unit(n), column(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        if (changed[k])
          continue;
        unit    = 0.;
        unit[k] = 1.;
        column  = 0.;
        add_model_step(history, unit, column);
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
    prior = base_prior;
  }



  void
  IQNILSAcceleration::set_prior(std::vector<double> new_prior)
  {
    base_prior = std::move(new_prior);
    prior      = base_prior;
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
