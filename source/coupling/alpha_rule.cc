#include <coaxfit/coupling/alpha_rule.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  FixedAlpha::FixedAlpha(const double alpha)
    : value(alpha)
  {}



  std::string
  FixedAlpha::name() const
  {
    return "fixed";
  }



  void
  FixedAlpha::update(const NeumannState &)
  {}



  bool
  FixedAlpha::estimated() const
  {
    return true;
  }



  void
  FixedAlpha::seed(const double)
  {}



  bool
  FixedAlpha::adaptive() const
  {
    return false;
  }



  double
  FixedAlpha::alpha(const unsigned int) const
  {
    return value;
  }



  double
  FixedAlpha::representative_alpha() const
  {
    return value;
  }



  WinklerAlpha::WinklerAlpha(const double initial_alpha)
    : FixedAlpha(initial_alpha)
  {}



  std::string
  WinklerAlpha::name() const
  {
    return "winkler";
  }



  bool
  WinklerAlpha::estimated() const
  {
    return has_estimate;
  }



  void
  WinklerAlpha::seed(const double alpha)
  {
    value = alpha;
  }



  bool
  WinklerAlpha::adaptive() const
  {
    return true;
  }



  void
  WinklerAlpha::update(const NeumannState &state)
  {
    double work1 = 0., work2 = 0.;
    for (unsigned int i = 0; i < state.force.size(); ++i)
      {
        work1 += std::abs(state.u_shaft[i] * state.force[i]);
        work2 += std::abs(state.u_hub[i] * state.force[i]);
      }
    // k2 / (k1 + k2); the common factor sum F^2/w cancels.
    if (work1 + work2 > 0. && std::isfinite(work1 + work2))
      {
        value        = work2 / (work1 + work2);
        has_estimate = true;
      }
  }



  PointwiseAlpha::PointwiseAlpha(const double initial_alpha, const double beta)
    : WinklerAlpha(initial_alpha)
    , beta(beta > 0. ? beta : 0.5)
    , searching(beta == 0.)
  {}



  std::string
  PointwiseAlpha::name() const
  {
    return "pointwise";
  }



  void
  PointwiseAlpha::search_beta(const double displacement_mismatch)
  {
    // One double step per candidate, then keep the best.
    if (last_mismatch > 0.)
      {
        tried.emplace_back(beta, displacement_mismatch / last_mismatch);
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
    last_mismatch = displacement_mismatch;
  }



  void
  PointwiseAlpha::update(const NeumannState &state)
  {
    WinklerAlpha::update(state);
    const unsigned int n = state.force.size();
    values.assign(n, value);
    if (state.force.norm_sqr() == 0.)
      return;
    if (searching)
      search_beta(state.displacement_mismatch);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double u1          = std::abs(state.u_shaft[i]);
        const double u2          = std::abs(state.u_hub[i]);
        const double denominator = (1. - beta) * u1 + beta * u2;
        if (denominator > 0. && std::isfinite(denominator))
          values[i] = std::clamp(beta * u2 / denominator, 1e-6, 1. - 1e-6);
      }
  }



  void
  PointwiseAlpha::seed(const double alpha)
  {
    WinklerAlpha::seed(alpha);
    std::fill(values.begin(), values.end(), alpha);
  }



  double
  PointwiseAlpha::alpha(const unsigned int i) const
  {
    return values.empty() ? value : values[i];
  }



  std::unique_ptr<AlphaRule>
  make_alpha_rule(const CouplingParameters &parameters)
  {
    switch (parameters.alpha_rule())
      {
        case AlphaRuleType::winkler:
          return std::make_unique<WinklerAlpha>(parameters.alpha);
        case AlphaRuleType::pointwise:
          return std::make_unique<PointwiseAlpha>(parameters.alpha,
                                                  parameters.beta);
        default:
          return std::make_unique<FixedAlpha>(parameters.alpha);
      }
  }
} // namespace coaxfit
