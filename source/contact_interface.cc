#include <cmath>
#include <coaxfit/contact_interface.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>
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

    DynamicSparsityPattern dsp(n, n);
    for (const auto &entry : shaft.interface_mass())
      dsp.add(entry.first.first, entry.first.second);
    sparsity.copy_from(dsp);
    mass_matrix.reinit(sparsity);
    lumped_weights.assign(n, 0.);
    for (const auto &[ij, value] : shaft.interface_mass())
      {
        mass_matrix.add(ij.first, ij.second, value);
        lumped_weights[ij.first] += value;
      }
    mass_solver.initialize(mass_matrix);
  }



  std::vector<double>
  ContactInterface::pressure(const std::vector<double> &force) const
  {
    Vector<double> p(force.begin(), force.end());
    mass_solver.solve(p);
    return std::vector<double>(p.begin(), p.end());
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
