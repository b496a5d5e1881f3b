#ifndef coaxfit_required_loads_h
#define coaxfit_required_loads_h

#include <coaxfit/parameters/scene_parameters.h>

#include <cmath>

namespace coaxfit
{
  /**
   * DIN 7190's resultant (N) of the loads a joint of diameter @p
   * joint_diameter (mm) must carry: the circumferential force 2 M / D_F of
   * Design/Required torque and Design/Required axial force combined, times
   * Design/Application factor K_A. The safety against slip of a cylindrical
   * joint is its friction force over this one (0: no load required).
   */
  inline double
  required_friction_force(const DesignParameters &design,
                          const double            joint_diameter)
  {
    const double circumferential
      = 2e3 * design.required_torque / joint_diameter;
    return design.application_factor
           * std::hypot(circumferential, design.required_axial_force);
  }
} // namespace coaxfit

#endif
