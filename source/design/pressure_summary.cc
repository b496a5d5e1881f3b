#include <coaxfit/design/din7190.h>
#include <coaxfit/design/pressure_summary.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  PressureSummary::PressureSummary(const Parameters       &parameters,
                                   const ContactInterface &interface,
                                   const Vector<double>   &force)
    : pressure(interface.pressure(force))
    , at_mid_plane(pressure[0])
    , mean(interface.mean_pressure(force))
    , lame(Din7190(parameters.geometry,
                   parameters.shaft,
                   parameters.hub,
                   operating_loads(parameters))
             .pressure())
  {
    // A whole model: the point nearest the joint's middle (a vertex).
    if (parameters.geometry.whole)
      {
        const double middle = parameters.geometry.joint_middle();
        unsigned int best   = 0;
        for (unsigned int i = 1; i < pressure.size(); ++i)
          if (std::abs(interface.z()[i] - middle)
              < std::abs(interface.z()[best] - middle))
            best = i;
        at_mid_plane = pressure[best];
      }
    const auto [lo, hi] = std::minmax_element(pressure.begin(), pressure.end());
    min                 = *lo;
    z_of_min            = interface.z()[lo - pressure.begin()];
    max                 = *hi;
    z_of_max            = interface.z()[hi - pressure.begin()];
  }



  Complementarity::Complementarity(const ContactInterface &interface,
                                   const InterfaceSolver  &coupling)
    : max_tension_relative(0.)
    , max_penetration_relative(0.)
    , max_pressure_gap_relative(0.)
  {
    const Vector<double> p = interface.pressure(coupling.contact_force());
    const Vector<double> gap
      = interface.gap(coupling.u_shaft(), coupling.u_hub());
    const double d     = interface.displacement_scale();
    double       p_max = interface.max_pressure(coupling.contact_force());
    if (p_max == 0.)
      p_max = 1.;
    for (unsigned int i = 0; i < p.size(); ++i)
      {
        max_tension_relative = std::max(max_tension_relative, -p[i] / p_max);
        max_penetration_relative
          = std::max(max_penetration_relative, -gap[i] / d);
        max_pressure_gap_relative
          = std::max(max_pressure_gap_relative,
                     std::abs(p[i] * gap[i]) / (p_max * d));
      }
  }
} // namespace coaxfit
