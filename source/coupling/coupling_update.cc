#include <coaxfit/coupling/block_model_update.h>
#include <coaxfit/coupling/coupling_update.h>
#include <coaxfit/coupling/relaxation_update.h>

#include <cmath>
#include <limits>

namespace coaxfit
{
  CouplingUpdate::CouplingUpdate(const ContactInterface &interface,
                                 UnilateralActiveSet    &active_set)
    : interface(interface)
    , active_set(active_set)
  {}



  void
  CouplingUpdate::sample_neumann(const InterfaceState &)
  {}



  void
  CouplingUpdate::use_coarse_model(CoarseInterfaceModel *model)
  {
    coarse_model = model;
  }



  double
  CouplingUpdate::relative_to_pressure(const double            mismatch,
                                       const Vector<double>   &f_inner,
                                       const Vector<double>   &f_outer,
                                       const ContactInterface &interface)
  {
    const double magnitude = std::max(interface.max_pressure(f_inner),
                                      interface.max_pressure(f_outer));
    // No force anywhere (every point separated, or no interference): the
    // bodies agree exactly.
    const double relative = magnitude > 0. ? mismatch / magnitude : 0.;
    return std::isfinite(relative) ? relative :
                                     std::numeric_limits<double>::quiet_NaN();
  }



  double
  winkler_compliance(const Vector<double> &u,
                     const Vector<double> &force,
                     const Vector<double> &weights)
  {
    double work = 0., load = 0.;
    for (unsigned int i = 0; i < force.size(); ++i)
      {
        work += std::abs(u[i] * force[i]);
        load += force[i] * force[i] / weights[i];
      }
    const double k = work / load;
    return (load > 0. && std::isfinite(k)) ? k : 0.;
  }



  std::unique_ptr<CouplingUpdate>
  make_coupling_update(const CouplingParameters &parameters,
                       const ContactInterface   &interface,
                       UnilateralActiveSet      &active_set,
                       const double              active_set_tolerance)
  {
    if (parameters.accelerator() == AcceleratorType::ibqn)
      return std::make_unique<BlockModelUpdate>(parameters,
                                                interface,
                                                active_set);
    return std::make_unique<RelaxationUpdate>(parameters,
                                              interface,
                                              active_set,
                                              active_set_tolerance);
  }
} // namespace coaxfit
