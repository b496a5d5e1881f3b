// Shared by the coupled tests: the paper's tube variants (17 separates)
// and the comparison of two pressure profiles.
#ifndef coaxfit_tests_coupled_cases_h
#define coaxfit_tests_coupled_cases_h

#include <coaxfit/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace coaxfit_test
{
  /** The tube variants: beta2 = 2, l1 = 3, l2 = 2, delta = 0.005. */
  inline coaxfit::Parameters
  tube_variant(const double beta1, const double alpha)
  {
    coaxfit::Parameters p;
    p.geometry.R0    = 100. * beta1;
    p.geometry.R2    = 200.;
    p.geometry.L1    = 300.;
    p.geometry.L2    = 200.;
    p.geometry.d     = 0.5;
    p.coupling.alpha = alpha;
    return p;
  }

  /** Variant 17: beta1 = 0.988, beta2 = 2, l1 = 3, l2 = 2, delta = 0.005. */
  inline coaxfit::Parameters
  variant_17()
  {
    return tube_variant(0.988, 0.017);
  }

  /** max_i |a_i - b_i| / max_i |b_i|. */
  template <typename VectorType>
  inline double
  relative_difference(const VectorType &a, const VectorType &b)
  {
    double difference = 0., magnitude = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, std::abs(a[i] - b[i]));
        magnitude  = std::max(magnitude, std::abs(b[i]));
      }
    return difference / magnitude;
  }
} // namespace coaxfit_test

#endif
