#include <coaxfit/coupling/interface_pressure.h>

#include <limits>

namespace coaxfit
{
  Vector<double>
  nodal_pressure(const InterfaceSide &side, const Vector<double> &force)
  {
    AssertDimension(force.size(), side.n_nodes());
    Vector<double> p(force.size());
    for (unsigned int i = 0; i < force.size(); ++i)
      p[i] = side.weights()[i] > 0. ? force[i] / side.weights()[i] :
                                      std::numeric_limits<double>::quiet_NaN();
    return p;
  }



  Vector<double>
  nodal_force(const InterfaceSide &side, const Vector<double> &pressure)
  {
    AssertDimension(pressure.size(), side.n_nodes());
    Vector<double> force(pressure);
    force.scale(side.weights());
    return force;
  }



  Vector<double>
  uniform_pressure_force(const InterfaceSide &side, const double pressure)
  {
    Vector<double> force(side.weights());
    force *= pressure;
    return force;
  }



  double
  mean_pressure(const InterfaceSide &side, const Vector<double> &force)
  {
    AssertDimension(force.size(), side.n_nodes());
    double total = 0.;
    for (const double f : force)
      total += f;
    return total / side.area();
  }
} // namespace coaxfit
