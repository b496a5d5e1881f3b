#include <coaxfit/alpha_controller.h>
#include <coaxfit/input_error.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace coaxfit
{
  namespace
  {
    double
    dot(const std::vector<double> &a, const std::vector<double> &b)
    {
      return std::inner_product(a.begin(), a.end(), b.begin(), 0.);
    }

    std::vector<double>
    difference(const std::vector<double> &a, const std::vector<double> &b)
    {
      std::vector<double> c(a.size());
      for (unsigned int i = 0; i < a.size(); ++i)
        c[i] = a[i] - b[i];
      return c;
    }
  } // namespace



  void
  AlphaController::accelerate(const std::vector<double> &,
                              std::vector<double> &)
  {}



  void
  AlphaController::restart()
  {}



  FixedAlphaController::FixedAlphaController(const double alpha)
    : value(alpha)
  {}



  std::string
  FixedAlphaController::name() const
  {
    return "fixed";
  }



  void
  FixedAlphaController::update(const NeumannState &)
  {}



  double
  FixedAlphaController::alpha(const unsigned int) const
  {
    return value;
  }



  double
  FixedAlphaController::representative_alpha() const
  {
    return value;
  }



  WinklerAlphaController::WinklerAlphaController(const double initial_alpha,
                                                 const bool   freeze)
    : FixedAlphaController(initial_alpha)
    , freeze(freeze)
  {}



  std::string
  WinklerAlphaController::name() const
  {
    return "winkler";
  }



  void
  WinklerAlphaController::update(const NeumannState &state)
  {
    if (freeze && estimated)
      return;
    double work1 = 0., work2 = 0.;
    for (unsigned int i = 0; i < state.force.size(); ++i)
      {
        work1 += std::abs(state.u_shaft[i] * state.force[i]);
        work2 += std::abs(state.u_hub[i] * state.force[i]);
      }
    // k2 / (k1 + k2); the common factor sum F^2/w cancels.
    if (work1 + work2 > 0. && std::isfinite(work1 + work2))
      {
        value     = work2 / (work1 + work2);
        estimated = true;
      }
  }



  bool
  WinklerAlphaController::alpha_changed()
  {
    const bool changed = (value != alpha_of_history);
    alpha_of_history   = value;
    return changed;
  }



  PointwiseAlphaController::PointwiseAlphaController(const double initial_alpha,
                                                     const double beta)
    : WinklerAlphaController(initial_alpha)
    , beta(beta > 0. ? beta : 0.5)
    , automatic(beta == 0.)
    , searching(beta == 0.)
  {}



  std::string
  PointwiseAlphaController::name() const
  {
    return "pointwise";
  }



  void
  PointwiseAlphaController::update(const NeumannState &state)
  {
    WinklerAlphaController::update(state);
    const unsigned int n = state.force.size();
    values.assign(n, value);
    if (dot(state.force, state.force) == 0.)
      return;

    // Automatic beta: one double step per candidate, then keep the best.
    if (automatic && searching)
      {
        if (last_mismatch > 0.)
          {
            tried.emplace_back(beta,
                               state.displacement_mismatch / last_mismatch);
            if (tried.size() == 1)
              beta = 0.3;
            else if (tried.size() == 2)
              beta = (tried[1].second < tried[0].second) ? 0.15 : 0.7;
            else
              {
                searching = false;
                beta      = std::min_element(tried.begin(),
                                        tried.end(),
                                        [](const auto &a, const auto &b) {
                                          return a.second < b.second;
                                        })
                         ->first;
              }
          }
        last_mismatch = state.displacement_mismatch;
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        const double u1          = std::abs(state.u_shaft[i]);
        const double u2          = std::abs(state.u_hub[i]);
        const double denominator = (1. - beta) * u1 + beta * u2;
        if (denominator > 0. && std::isfinite(denominator))
          values[i] = std::clamp(beta * u2 / denominator, 1e-6, 1. - 1e-6);
      }
  }



  double
  PointwiseAlphaController::alpha(const unsigned int i) const
  {
    return values.empty() ? value : values[i];
  }



  AitkenController::AitkenController(const double initial_alpha,
                                     const double initial_omega)
    : WinklerAlphaController(initial_alpha, true)
    , initial_omega(initial_omega)
    , omega(initial_omega)
  {}



  std::string
  AitkenController::name() const
  {
    return "aitken";
  }



  void
  AitkenController::accelerate(const std::vector<double> &applied,
                               std::vector<double>       &next)
  {
    if (alpha_changed())
      restart();
    const std::vector<double> residual = difference(next, applied);
    if (!last_residual.empty())
      {
        const std::vector<double> change = difference(residual, last_residual);
        const double              norm2  = dot(change, change);
        if (norm2 > 0.)
          omega
            = std::clamp(-omega * dot(last_residual, change) / norm2, 1e-3, 2.);
      }
    last_residual = residual;
    for (unsigned int i = 0; i < next.size(); ++i)
      next[i] = applied[i] + omega * residual[i];
  }



  void
  AitkenController::restart()
  {
    omega = initial_omega;
    last_residual.clear();
  }



  IQNILSController::IQNILSController(const double       initial_alpha,
                                     const unsigned int max_columns,
                                     const double       filter)
    : WinklerAlphaController(initial_alpha, true)
    , max_columns(max_columns)
    , filter(filter)
  {}



  std::string
  IQNILSController::name() const
  {
    return "iqn-ils";
  }



  void
  IQNILSController::accelerate(const std::vector<double> &applied,
                               std::vector<double>       &next)
  {
    if (alpha_changed())
      restart();
    residuals.push_back(difference(next, applied));
    outputs.push_back(next);
    if (residuals.size() > max_columns + 1)
      {
        residuals.erase(residuals.begin());
        outputs.erase(outputs.begin());
      }
    const unsigned int m = residuals.size() - 1;
    if (m == 0)
      return; // no model yet: the plain step x_{k+1} = G(x_k)

    // Columns newest first; modified Gram-Schmidt with the QR filter: a
    // column whose part orthogonal to the newer ones is below filter times
    // its norm carries no new information and is dropped.
    const std::vector<double>       &r = residuals.back();
    std::vector<std::vector<double>> q, w;
    std::vector<std::vector<double>> R; // R[j][k], upper triangular
    for (unsigned int k = m; k-- > 0;)
      {
        std::vector<double> v      = difference(residuals[k + 1], residuals[k]);
        const double        norm_v = std::sqrt(dot(v, v));
        std::vector<double> coefficients;
        for (const auto &qj : q)
          {
            const double c = dot(qj, v);
            for (unsigned int i = 0; i < v.size(); ++i)
              v[i] -= c * qj[i];
            coefficients.push_back(c);
          }
        const double norm = std::sqrt(dot(v, v));
        if (!(norm > filter * norm_v) || norm_v == 0.)
          continue;
        for (double &x : v)
          x /= norm;
        q.push_back(v);
        coefficients.push_back(norm);
        R.push_back(coefficients);
        w.push_back(difference(outputs[k + 1], outputs[k]));
      }
    if (q.empty())
      return;

    // R c = -Q^T r by back substitution (R[j] holds column j).
    const unsigned int  n_cols = q.size();
    std::vector<double> c(n_cols);
    for (unsigned int j = n_cols; j-- > 0;)
      {
        double s = -dot(q[j], r);
        for (unsigned int k = j + 1; k < n_cols; ++k)
          s -= R[k][j] * c[k];
        c[j] = s / R[j][j];
      }
    for (unsigned int j = 0; j < n_cols; ++j)
      for (unsigned int i = 0; i < next.size(); ++i)
        next[i] += c[j] * w[j][i];
  }



  void
  IQNILSController::restart()
  {
    residuals.clear();
    outputs.clear();
  }



  std::unique_ptr<AlphaController>
  make_alpha_controller(const Parameters &parameters)
  {
    const std::string &name = parameters.alpha_controller;
    if (name == "fixed")
      return std::make_unique<FixedAlphaController>(parameters.alpha);
    if (name == "winkler")
      return std::make_unique<WinklerAlphaController>(parameters.alpha);
    if (name == "pointwise")
      return std::make_unique<PointwiseAlphaController>(parameters.alpha,
                                                        parameters.beta);

    if (name == "aitken")
      return std::make_unique<AitkenController>(parameters.alpha,
                                                parameters.aitken_omega);
    if (name == "iqn-ils")
      return std::make_unique<IQNILSController>(parameters.alpha,
                                                parameters.iqn_columns,
                                                parameters.iqn_filter);
    throw InputError("parameter Coupling/Alpha controller = " + name
                     + " is not known: allowed are fixed, winkler, pointwise, "
                       "aitken, iqn-ils.");
  }
} // namespace coaxfit
