#include <coaxfit/coupling/contact_interface.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace coaxfit
{
  double
  z_range_scale(const std::vector<double> &z)
  {
    return z.empty() ?
             1. :
             std::max(
               {std::abs(z.front()), std::abs(z.back()), z.back() - z.front()});
  }



  bool
  matching_points(const BodyDiscretization &a, const BodyDiscretization &b)
  {
    const std::vector<double> &za = a.interface_z(), &zb = b.interface_z();
    if (za.size() != zb.size())
      return false;
    const double scale = z_range_scale(za);
    for (unsigned int i = 0; i < za.size(); ++i)
      if (std::abs(zb[i] - za[i]) > 1e-9 * scale)
        return false;
    return true;
  }



  ContactInterface::ContactInterface(const BodyDiscretization &shaft,
                                     const BodyDiscretization &hub,
                                     const double              interference)
    : ContactInterface(shaft,
                       hub,
                       interference,
                       Vector<double>(shaft.n_interface_points()),
                       Vector<double>(shaft.n_interface_points()))
  {}



  ContactInterface::ContactInterface(const BodyDiscretization &shaft,
                                     const BodyDiscretization &hub,
                                     const double              interference,
                                     const Vector<double>     &u1_load,
                                     const Vector<double>     &u2_load)
    : d(interference)
    , z_coordinates(shaft.interface_z())
    , lumped_weights(shaft.interface_weights())
    , u1_load(u1_load)
    , u2_load(u2_load)
    , d_load(u1_load.size())
    , scale(std::max(std::abs(d), 1e-12 * shaft.geometry().r_outer))
  {
    AssertDimension(u1_load.size(), z_coordinates.size());
    AssertDimension(u2_load.size(), z_coordinates.size());
    for (unsigned int i = 0; i < d_load.size(); ++i)
      {
        d_load[i] = d + u1_load[i] - u2_load[i];
        scale     = std::max(scale, std::abs(d_load[i]));
      }
    if (z_coordinates.size() < 2 || !matching_points(shaft, hub))
      throw std::logic_error("the contact surfaces of shaft and hub do not "
                             "have matching points");
  }



  ContactInterface::ContactInterface(const BodyDiscretization &side,
                                     const double              interference,
                                     const Vector<double>     &u1_load,
                                     const Vector<double>     &u2_load)
    : ContactInterface(side, side, interference, u1_load, u2_load)
  {}



  Vector<double>
  ContactInterface::gap(const Vector<double> &u1,
                        const Vector<double> &u2) const
  {
    Vector<double> g(u2);
    g -= u1;
    g -= d_load;
    return g;
  }



  double
  ContactInterface::relative_gap_residual(const Vector<double>    &u1,
                                          const Vector<double>    &u2,
                                          const std::vector<bool> &contact,
                                          const bool with_penetration) const
  {
    double mismatch = 0.;
    for (unsigned int i = 0; i < u1.size(); ++i)
      {
        const double g = u2[i] - u1[i] - d_load[i];
        if (contact[i])
          mismatch = std::max(mismatch, std::abs(g));
        else if (with_penetration)
          mismatch = std::max(mismatch, -g);
      }
    const double r = mismatch / scale;
    return std::isfinite(r) ? r : std::numeric_limits<double>::quiet_NaN();
  }



  Vector<double>
  ContactInterface::pressure(const Vector<double> &force) const
  {
    Vector<double> p(force.size());
    for (unsigned int i = 0; i < force.size(); ++i)
      p[i] = force[i] / lumped_weights[i];
    return p;
  }



  double
  ContactInterface::max_pressure(const Vector<double> &force) const
  {
    double m = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      m = std::max(m, std::abs(force[i]) / lumped_weights[i]);
    return m;
  }



  double
  ContactInterface::max_pressure_difference(const Vector<double> &force1,
                                            const Vector<double> &force2) const
  {
    double m = 0.;
    for (unsigned int i = 0; i < force1.size(); ++i)
      m = std::max(m, std::abs(force2[i] - force1[i]) / lumped_weights[i]);
    return m;
  }



  double
  ContactInterface::max_tension(const Vector<double> &force) const
  {
    double m = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      m = std::max(m, -force[i] / lumped_weights[i]);
    return m;
  }



  double
  ContactInterface::mean_pressure(const Vector<double> &force) const
  {
    double total = 0., area = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      {
        total += force[i];
        // A rounded edge counts where it touches.
        if (shape_gap.size() == 0 || shape_gap[i] == 0. || force[i] != 0.)
          area += lumped_weights[i];
      }
    return total / area;
  }



  void
  ContactInterface::set_shape_gap(const Vector<double> &gap)
  {
    AssertDimension(gap.size(), d_load.size());
    shape_gap = gap;
    for (unsigned int i = 0; i < d_load.size(); ++i)
      d_load[i] -= gap[i];
  }
} // namespace coaxfit
