#include <coaxfit/design/fit_design.h>
#include <coaxfit/design/required_loads.h>
#include <coaxfit/fe/section_scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** @p strength / @p stress, or unknown without a strength. */
    double
    safety(const double strength, const double stress)
    {
      // A stress at round-off (contact lost, no loads) leaves the part
      // unloaded: an infinite safety, not 1e12.
      if (strength > 0. && stress >= 0. && stress <= 1e-9 * strength)
        return std::numeric_limits<double>::infinity();
      return strength > 0. && stress > 0. ? strength / stress :
                                            FitDesign::unknown;
    }
  } // namespace



  FitDesign::FitDesign(const Parameters         &parameters,
                       const BodyDiscretization &shaft,
                       const Vector<double>     &shaft_field,
                       const BodyDiscretization &hub,
                       const Vector<double>     &hub_field,
                       const Vector<double>     &contact_force)
  {
    const Din7190 din(parameters.geometry,
                      parameters.shaft,
                      parameters.hub,
                      operating_loads(parameters));
    double        sum = 0.;
    for (const double F : contact_force)
      sum += F;
    // 2 pi per radian, twice for a half model (its mirror image).
    normal_force = 2. * M_PI * parameters.geometry.mirror_factor() * sum;
    // A cone's surface is pi D_F l_F / cos(beta), beta its half angle.
    if (parameters.sections && parameters.sections->conical())
      {
        const auto angle = cone_half_angle(parameters.sections->taper());
        cone_cos         = angle[1];
        cone_sin         = angle[2];
      }
    mean_pressure = normal_force * cone_cos
                    / (M_PI * 2. * parameters.geometry.R1 * din.joint_length());
    pressure_din = din.pressure();
    compute_capacity(parameters, din);
    compute_strength(parameters, din, shaft, shaft_field, hub, hub_field);
  }



  std::array<double, 3>
  FitDesign::cone_half_angle(const double taper)
  {
    const double tan_beta = 0.5 * taper;
    const double cos_beta = 1. / std::sqrt(1. + tan_beta * tan_beta);
    return {{tan_beta, cos_beta, tan_beta * cos_beta}};
  }



  double
  FitDesign::cone_pull_off_capacity(const double N,
                                    const double mu,
                                    const double taper)
  {
    const auto [tan_beta, cos_beta, sin_beta] = cone_half_angle(taper);
    return std::max(0., N * (mu * cos_beta - sin_beta));
  }



  double
  FitDesign::cone_circumferential_capacity(const double N,
                                           const double mu,
                                           const double taper)
  {
    const double tan_beta = cone_half_angle(taper)[0];
    return N * std::sqrt(std::max(0., mu * mu - tan_beta * tan_beta));
  }



  double
  FitDesign::cone_slip_safety(const double N,
                              const double mu,
                              const double taper,
                              const double circumferential,
                              const double pull)
  {
    const auto [tan_beta, cos_beta, sin_beta] = cone_half_angle(taper);
    // a S^2 + b S + c = 0 with c < 0 for a self-locking cone: one
    // positive root.
    const double a
      = pull * pull / (cos_beta * cos_beta) + circumferential * circumferential;
    const double b = 2. * N * sin_beta * pull / (cos_beta * cos_beta);
    const double c = N * N * (tan_beta * tan_beta - mu * mu);
    if (!(c < 0.))
      return 0.;
    if (!(a > 0.))
      return FitDesign::unknown;
    return 2. * -c / (b + std::sqrt(b * b - 4. * a * c));
  }



  void
  FitDesign::compute_capacity(const Parameters &parameters, const Din7190 &din)
  {
    const DesignParameters &design = parameters.design;
    const double            mu     = design.friction_coefficient;
    const double            R_F    = parameters.geometry.R1;
    torque_capacity                = 1e-3 * mu * R_F * normal_force;
    axial_force_capacity           = mu * normal_force;
    torque_capacity_din            = din.torque(pressure_din, mu);
    axial_force_capacity_din       = din.axial_force(pressure_din, mu);
    press_in_force = design.press_in_friction_coefficient * normal_force;
    press_in_force_din
      = din.axial_force(pressure_din, design.press_in_friction_coefficient);
    // A cone: the normal force N over its surface (the estimate's
    // p pi D_F l_F / cos), its axial part N sin against pushing on,
    // friction mu N cos along the cone. Held against pulling off by
    // N (mu cos - sin): none unless mu > tan(beta) (self-locking).
    const bool   cone  = cone_sin > 0.;
    const double taper = cone ? parameters.sections->taper() : 0.;
    const double N_din = din.axial_force(pressure_din, 1.) / cone_cos;
    if (cone)
      {
        const double mu_e    = design.press_in_friction_coefficient;
        push_on_force        = normal_force * cone_sin;
        push_on_force_din    = N_din * cone_sin;
        press_in_force       = normal_force * (cone_sin + mu_e * cone_cos);
        press_in_force_din   = N_din * (cone_sin + mu_e * cone_cos);
        axial_force_capacity = cone_pull_off_capacity(normal_force, mu, taper);
        axial_force_capacity_din = cone_pull_off_capacity(N_din, mu, taper);
        torque_capacity
          = 1e-3 * R_F * cone_circumferential_capacity(normal_force, mu, taper);
        torque_capacity_din
          = 1e-3 * R_F * cone_circumferential_capacity(N_din, mu, taper);
      }

    // DIN 7190's resultant of a torque and an axial force on the joint
    // (required_friction_force()); a cone shares the circumferential force
    // 2 M / D_F and the axial force with its push-off.
    const double circumferential = 2e3 * design.required_torque / (2. * R_F);
    const double required        = required_friction_force(design, 2. * R_F);
    // On a cone the torque and the pull share the friction with the cone's
    // own push-off (the capacities above are each load alone).
    if (!(required > 0.))
      safety_slip = safety_slip_din = FitDesign::unknown;
    else if (!cone)
      {
        safety_slip     = axial_force_capacity / required;
        safety_slip_din = axial_force_capacity_din / required;
      }
    else
      {
        const double K_A = design.application_factor;
        safety_slip      = cone_slip_safety(normal_force,
                                       mu,
                                       taper,
                                       K_A * circumferential,
                                       K_A * design.required_axial_force);
        safety_slip_din  = cone_slip_safety(N_din,
                                           mu,
                                           taper,
                                           K_A * circumferential,
                                           K_A * design.required_axial_force);
      }
  }



  void
  FitDesign::compute_strength(const Parameters         &parameters,
                              const Din7190            &din,
                              const BodyDiscretization &shaft,
                              const Vector<double>     &shaft_field,
                              const BodyDiscretization &hub,
                              const Vector<double>     &hub_field)
  {
    const GeometryParameters &g = parameters.geometry;
    edge_distance
      = parameters.design.edge_distance_for(2. * g.contact_length());
    // On the mid-plane (the joint's middle of a whole model).
    const double z_m = g.joint_middle();
    check_points
      = {{"hub bore", stress_at(hub, hub_field, {g.R1, z_m}), din.hub_bore()},
         {"hub outer surface",
          stress_at(hub,
                    hub_field,
                    {parameters.sections ?
                       parameters.sections->hub_outer_radius_at_plane() :
                       g.R2,
                     z_m}),
          din.hub_outer()},
         {"shaft surface",
          stress_at(shaft, shaft_field, {g.R1, z_m}),
          din.shaft_outer()},
         {g.R0 > 0. ? "shaft bore" : "shaft axis",
          stress_at(shaft, shaft_field, {g.R0, z_m}),
          din.shaft_inner()}};

    // The ends of the joint, where the stresses are singular (one for the
    // half model).
    const double z_corner = g.joint_end();
    const double z_other  = g.whole ? g.joint_start() : g.joint_end();
    // On a cone the joint's faces (r varies along them).
    const bool cone = parameters.sections && parameters.sections->conical();
    hub_bore_stresses
      = cone ? stresses_along_boundary(hub, hub_field, BoundaryId::joint) :
               stresses_along_radius(hub, hub_field, g.R1);
    shaft_surface_stresses
      = cone ? stresses_along_boundary(shaft, shaft_field, BoundaryId::joint) :
               stresses_along_radius(shaft, shaft_field, g.R1);
    surface_maxima.clear();
    for (const auto &[name, states] :
         {std::pair<std::string, const std::vector<StressState> *>{
            "hub bore", &hub_bore_stresses},
          {"shaft surface", &shaft_surface_stresses}})
      {
        SurfaceMaximum m;
        m.name      = name;
        m.von_mises = FitDesign::unknown; // none outside the band
        m.interior  = FitDesign::unknown;
        // The value at each end (the point nearest it); the larger is the
        // corner's (a whole model's other end may be flush, not singular).
        double nearest[2] = {std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::max()};
        double at_end[2]  = {0., 0.};
        for (const StressState &s : *states)
          {
            const double to_end[2]
              = {std::abs(s.z - z_corner), std::abs(s.z - z_other)};
            const double distance = std::min(to_end[0], to_end[1]);
            for (const unsigned int e : {0u, 1u})
              if (to_end[e] < nearest[e])
                {
                  nearest[e] = to_end[e];
                  at_end[e]  = s.von_mises();
                }
            if (distance >= edge_distance
                && !(s.von_mises() <= m.von_mises)) // NaN: the first
              {
                m.von_mises = s.von_mises();
                m.z         = s.z;
              }
            if (std::abs(s.z - z_m)
                  <= 0.25 * g.mirror_factor() * g.modelled_joint_length()
                && !(s.von_mises() <= m.interior))
              {
                m.interior   = s.von_mises();
                m.interior_z = s.z;
              }
          }
        m.corner = std::fmax(at_end[0], at_end[1]);
        surface_maxima.push_back(m);
      }

    // fmax ignores a maximum that does not exist (NaN).
    const auto largest = [](const double a, const double b, const double c) {
      return std::fmax(std::fmax(a, b), c);
    };
    strength_stress_hub   = largest(check_points[0].fe.von_mises(),
                                  check_points[1].fe.von_mises(),
                                  surface_maxima[0].interior);
    strength_stress_shaft = largest(check_points[2].fe.von_mises(),
                                    check_points[3].fe.von_mises(),
                                    surface_maxima[1].interior);
    safety_yield_hub
      = safety(parameters.hub.yield_strength, strength_stress_hub);
    safety_yield_shaft
      = safety(parameters.shaft.yield_strength, strength_stress_shaft);
    // The whole body with the end of the joint: never above the former.
    safety_yield_hub_edge
      = safety(parameters.hub.yield_strength,
               std::fmax(strength_stress_hub, surface_maxima[0].von_mises));
    safety_yield_shaft_edge
      = safety(parameters.shaft.yield_strength,
               std::fmax(strength_stress_shaft, surface_maxima[1].von_mises));
    safety_yield_hub_din   = safety(parameters.hub.yield_strength,
                                  std::max(check_points[0].din.equivalent(),
                                           check_points[1].din.equivalent()));
    safety_yield_shaft_din = safety(parameters.shaft.yield_strength,
                                    std::max(check_points[2].din.equivalent(),
                                             check_points[3].din.equivalent()));

    // A brittle hub: the largest hoop stress against R_m, not yield.
    if (parameters.hub.kind == MaterialKind::brittle)
      {
        hoop_stress_max_hub
          = std::max(check_points[0].fe.hoop(), check_points[1].fe.hoop());
        for (const StressState &s : hub_bore_stresses)
          if (std::abs(s.z - z_corner) >= edge_distance)
            hoop_stress_max_hub = std::max(hoop_stress_max_hub, s.hoop());
        hoop_stress_max_hub_din
          = std::max(check_points[0].din.hoop, check_points[1].din.hoop);
        // No tensile hoop stress anywhere (a hub squeezed from outside):
        // nothing to crack, an infinite safety.
        const double R_m      = parameters.hub.tensile_strength;
        const auto   fracture = [R_m](const double hoop) {
          return R_m > 0. && hoop <= 0. ?
                     std::numeric_limits<double>::infinity() :
                     safety(R_m, hoop);
        };
        safety_fracture_hub     = fracture(hoop_stress_max_hub);
        safety_fracture_hub_din = fracture(hoop_stress_max_hub_din);
        safety_yield_hub = safety_yield_hub_din = safety_yield_hub_edge
          = FitDesign::unknown;
      }
  }



  std::vector<std::string>
  FitDesign::warnings(const Parameters &parameters) const
  {
    std::vector<std::string> list;
    for (const auto &[part, fe, din_value, strength] :
         {std::tuple<std::string, double, double, double>{
            "hub",
            safety_yield_hub,
            safety_yield_hub_din,
            parameters.hub.yield_strength},
          {"shaft",
           safety_yield_shaft,
           safety_yield_shaft_din,
           parameters.shaft.yield_strength}})
      if (fe < 1. || din_value < 1.)
        {
          std::ostringstream w;
          w.precision(3);
          w << "the " << part << " yields: safety against yield " << fe
            << " (FE), " << din_value << " (DIN 7190) with yield strength "
            << strength
            << " MPa; the elastic answer overestimates the pressure";
          list.push_back(w.str());
        }
    // DIN 7190 asks a safety of 2 to 3 against fracture of brittle parts.
    if (safety_fracture_hub < 2. || safety_fracture_hub_din < 2.)
      {
        std::ostringstream w;
        w.precision(3);
        w << "the brittle hub (" << parameters.hub.name
          << ") has a safety against fracture (sigma_t vs R_m) of "
          << safety_fracture_hub << " (FE), " << safety_fracture_hub_din
          << " (DIN 7190): largest hoop stress " << hoop_stress_max_hub
          << " MPa (FE), " << hoop_stress_max_hub_din
          << " MPa (DIN 7190) against R_m " << parameters.hub.tensile_strength
          << " MPa; "
          << (std::fmin(safety_fracture_hub, safety_fracture_hub_din) < 1. ?
                "the hub cracks" :
                "below 2, the least DIN 7190 asks of brittle materials (2 "
                "to 3)");
        list.push_back(w.str());
      }
    if (safety_slip < 1. || safety_slip_din < 1.)
      {
        std::ostringstream w;
        w.precision(3);
        if (safety_slip >= 1.)
          w << "DIN 7190's plain-cylinder estimate has the joint slip under "
               "the required loads (safety against slip "
            << safety_slip_din << "); the finite elements carry them ("
            << safety_slip << ")";
        else
          w << "the joint slips under the required loads: safety against "
               "slip "
            << safety_slip << " (FE), " << safety_slip_din << " (DIN 7190)";
        list.push_back(w.str());
      }
    return list;
  }
} // namespace coaxfit
