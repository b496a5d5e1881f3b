#include <coaxfit/contact_interface.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace coaxfit
{
  ContactInterface::ContactInterface(const Body  &shaft,
                                     const Body  &hub,
                                     const double interference)
    : d(interference)
    , z_coordinates(shaft.interface_z())
  {
    const unsigned int n = z_coordinates.size();
    const double scale   = z_coordinates.empty() ? 1. : z_coordinates.back();
    if (n < 2 || hub.n_interface_points() != n)
      throw std::logic_error("the contact surfaces of shaft and hub do not "
                             "have matching points");
    for (unsigned int i = 0; i < n; ++i)
      if (std::abs(hub.interface_z()[i] - z_coordinates[i]) > 1e-9 * scale)
        throw std::logic_error("the contact surfaces of shaft and hub do not "
                               "have matching points");

    lumped_weights.assign(n, 0.);
    for (const auto &[ij, value] : shaft.interface_mass())
      lumped_weights[ij.first] += value;
  }



  std::vector<double>
  ContactInterface::lumped_pressure(const std::vector<double> &force) const
  {
    std::vector<double> p(force.size());
    for (unsigned int i = 0; i < force.size(); ++i)
      p[i] = force[i] / lumped_weights[i];
    return p;
  }



  double
  ContactInterface::mean_pressure(const std::vector<double> &force) const
  {
    return std::accumulate(force.begin(), force.end(), 0.)
           / std::accumulate(lumped_weights.begin(), lumped_weights.end(), 0.);
  }
} // namespace coaxfit
