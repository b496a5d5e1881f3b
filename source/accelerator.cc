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
    const unsigned int m = residuals.size() - 1;
    if (m == 0)
      return; // no model yet: the plain step x_{k+1} = G(x_k)

    // Columns newest first; modified Gram-Schmidt with the QR filter: a
    // column whose part orthogonal to the newer ones is below filter times
    // its norm carries no new information and is dropped.
    const Vector<double>            &r = residuals.back();
    std::vector<Vector<double>>      q, w;
    std::vector<std::vector<double>> R; // R[j][k], upper triangular
    for (unsigned int k = m; k-- > 0;)
      {
        Vector<double> v(residuals[k + 1]);
        v -= residuals[k];
        const double        norm_v = v.l2_norm();
        std::vector<double> coefficients;
        for (const auto &qj : q)
          {
            const double c = qj * v;
            v.add(-c, qj);
            coefficients.push_back(c);
          }
        const double norm = v.l2_norm();
        if (!(norm > filter * norm_v) || norm_v == 0.)
          continue;
        v /= norm;
        q.push_back(v);
        coefficients.push_back(norm);
        R.push_back(coefficients);
        w.push_back(outputs[k + 1]);
        w.back() -= outputs[k];
      }
    if (q.empty())
      return;

    // R c = -Q^T r by back substitution (R[j] holds column j).
    const unsigned int  n_cols = q.size();
    std::vector<double> c(n_cols);
    for (unsigned int j = n_cols; j-- > 0;)
      {
        double s = -(q[j] * r);
        for (unsigned int k = j + 1; k < n_cols; ++k)
          s -= R[k][j] * c[k];
        c[j] = s / R[j][j];
      }
    for (unsigned int j = 0; j < n_cols; ++j)
      g.add(c[j], w[j]);
  }



  void
  IQNILSAcceleration::restart()
  {
    residuals.clear();
    outputs.clear();
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
