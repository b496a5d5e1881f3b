#include <coaxfit/coupling/active_set.h>

#include <algorithm>

namespace coaxfit
{
  UnilateralActiveSet::UnilateralActiveSet(const unsigned int n_points,
                                           const bool         enabled,
                                           const Update       update)
    : is_enabled(enabled)
    , mode(update)
    , contact(n_points, true)
  {}



  void
  UnilateralActiveSet::assume(const std::vector<bool> &flags)
  {
    AssertDimension(flags.size(), contact.size());
    if (is_enabled)
      contact = flags;
  }



  bool
  UnilateralActiveSet::set(const std::vector<bool> &flags)
  {
    AssertDimension(flags.size(), contact.size());
    if (!is_enabled || flags == contact)
      return false;
    contact = flags;
    ++changes;
    return true;
  }



  unsigned int
  UnilateralActiveSet::clamp(Vector<double> &force) const
  {
    unsigned int n = 0;
    if (is_enabled && mode == Update::every_step)
      for (double &f : force)
        if (f < 0.)
          {
            f = 0.;
            ++n;
          }
    return n;
  }



  bool
  UnilateralActiveSet::update(const Vector<double> &force,
                              const Vector<double> &gap)
  {
    if (!is_enabled)
      return false;
    bool changed = false;
    for (unsigned int i = 0; i < contact.size(); ++i)
      {
        const bool now = (mode == Update::every_step) ?
                           !(force[i] <= 0. && gap[i] >= 0.) :
                           (contact[i] ? force[i] >= 0. : gap[i] < 0.);
        if (now != contact[i])
          changed = true;
        contact[i] = now;
      }
    changes += changed;
    return changed;
  }



  unsigned int
  UnilateralActiveSet::n_separated() const
  {
    return std::count(contact.begin(), contact.end(), false);
  }



  std::vector<std::pair<double, double>>
  UnilateralActiveSet::separated_zones(const std::vector<double> &z,
                                       const double               start,
                                       const double               end) const
  {
    std::vector<std::pair<double, double>> zones;
    const unsigned int                     n = contact.size();
    for (unsigned int i = 0; i < n; ++i)
      if (!contact[i])
        {
          unsigned int j = i;
          while (j + 1 < n && !contact[j + 1])
            ++j;
          // Clipped to the joint: points beyond it (a rounded edge the
          // contact may spread onto) are open by their shape.
          const double a
            = std::max(start, (i == 0) ? start : 0.5 * (z[i - 1] + z[i]));
          const double b
            = std::min(end, (j + 1 == n) ? end : 0.5 * (z[j] + z[j + 1]));
          if (b > a)
            zones.emplace_back(a, b);
          i = j;
        }
    return zones;
  }
} // namespace coaxfit
