#include <coaxfit/app/stack_fit.h>
#include <coaxfit/coupling/stack_coupling.h>
#include <coaxfit/design/din7190.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/parameters/operation_entries.h>
#include <coaxfit/solvers/condensed_body.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

// The stack's parts on their own (StackFit): each joint alone, the
// part-assemblies of Assembly/Order, and from them each joint's press-in
// and joining figures.

namespace coaxfit
{
  namespace
  {
    /** The block of @p C from row and column @p at, @p n of each. */
    FullMatrix<double>
    block(const FullMatrix<double> &C,
          const unsigned int        at,
          const unsigned int        n)
    {
      FullMatrix<double> B(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          B(i, j) = C(at + i, at + j);
      return B;
    }
  } // namespace



  std::vector<double>
  StackFit::radial_interferences(const std::vector<double> &U) const
  {
    std::vector<double> radial;
    for (unsigned int k = 0; k < U.size(); ++k)
      radial.push_back(0.5 * (U[k] - parameters.fits[k].smoothing_loss));
    return radial;
  }



  std::vector<double>
  StackFit::radial_interferences(const bool largest) const
  {
    if (!largest)
      {
        std::vector<double> radial;
        for (const StackJoint &joint : stack_joints)
          radial.push_back(joint.interference);
        return radial;
      }
    std::vector<double> U;
    for (const JointFit &fit : parameters.fits)
      U.push_back(fit.largest_interference);
    return radial_interferences(U);
  }



  StackState
  StackFit::part_assembly(const unsigned int         first,
                          const unsigned int         last,
                          const std::vector<double> &radial,
                          const double               heating,
                          const bool                 cooling) const
  {
    // Each body's compliance on the points of the joints inside the
    // part: the first body's bore and the last one's outside are free.
    std::vector<FullMatrix<double>> C;
    for (unsigned int b = first; b <= last; ++b)
      {
        const unsigned int n_in = b > 0 ? stack_joints[b - 1].n_points() : 0;
        const unsigned int n_out
          = b + 1 < bodies.size() ? stack_joints[b].n_points() : 0;
        const unsigned int at = b == first ? n_in : 0;
        C.push_back(block(compliance(b),
                          at,
                          (b == first ? 0 : n_in) + (b == last ? 0 : n_out)));
      }
    // At the assembly temperature: no loads of operation.
    std::vector<StackJoint> joints(stack_joints.begin() + first,
                                   stack_joints.begin() + last);
    for (unsigned int j = first; j < last; ++j)
      {
        StackJoint &joint = joints[j - first];
        joint.load_shift.reinit(0);
        joint.interference = radial[j];
        // Heated (cooled) as a whole by @p heating: the free bodies grow
        // apart by (alpha_outer - alpha_inner) dT R.
        if (heating != 0.)
          {
            const double R = parameters.joint_diameter(j) / 2.;
            joint.load_shift.reinit(joint.n_points());
            joint.load_shift
              = (expansion(j + 1, cooling) - expansion(j, cooling)) * heating
                * R;
          }
      }
    // Unilateral whatever Contact/Unilateral says: parts being pressed
    // together cannot bond.
    unsigned int set_steps = 0;
    return solve_stack_contact(C, joints, true, set_steps);
  }



  void
  StackFit::pressing(const unsigned int k, JointFigures &f) const
  {
    const auto [first, last] = parameters.joined_parts(k);
    f.press_order            = std::find(parameters.joining_order.begin(),
                              parameters.joining_order.end(),
                              k)
                    - parameters.joining_order.begin() + 1;
    const auto &names  = parameters.bodies;
    f.press_inner_part = {names.begin() + first, names.begin() + k + 1};
    f.press_outer_part = {names.begin() + k + 1, names.begin() + last + 1};
    f.press_in_friction_coefficient
      = parameters.fits[k].press_in_friction_coefficient;
    // The part-assembly's joint k is its joint k - first.
    const StackJoint  &joint   = stack_joints[k];
    const unsigned int in_part = k - first;
    const auto         p_mean  = [&](const StackState &state) {
      return state.force[in_part].mean_value() * state.force[in_part].size()
             / (joint.weights.mean_value() * joint.weights.size());
    };
    const std::vector<double> in_use  = radial_interferences(false),
                              largest = radial_interferences(true);
    f.press_p_mean = p_mean(part_assembly(first, last, in_use));
    // F = nu_e N, the normal force N = p_mean pi D l over the joint's
    // length l.
    const double area = M_PI * f.diameter * joint.length();
    f.press_in_force  = f.press_in_friction_coefficient * f.press_p_mean * area;
    f.press_in_force_largest = f.press_in_friction_coefficient
                               * p_mean(part_assembly(first, last, largest))
                               * area;
    f.press_in_force_estimate
      = f.press_in_friction_coefficient
        * plane_stress(first, last, false, true).pressure(in_part) * area;

    const Vector<double> growth = joining_growth(k, largest);
    f.joining_growth = *std::max_element(growth.begin(), growth.end());
  }



  Vector<double>
  StackFit::joining_growth(const unsigned int         k,
                           const std::vector<double> &radial) const
  {
    // What the parts add to the joint's interference before it is made:
    // the inner part's outside grown, the outer part's bore closed by the
    // joints already made.
    const auto [first, last] = parameters.joined_parts(k);
    Vector<double> change(stack_joints[k].n_points());
    if (k > first)
      change += part_surface(k, first, part_assembly(first, k, radial));
    if (last > k + 1)
      change -= part_surface(k, k + 1, part_assembly(k + 1, last, radial));
    change *= 2.;
    return change;
  }



  StackState
  StackFit::joint_alone(const unsigned int k,
                        unsigned int      &staggered_steps) const
  {
    // The sides' compliances on this joint's points only: the other
    // surfaces free.
    const unsigned int            n     = stack_joints[k].n_points();
    const unsigned int            at_in = bodies[k]->n_inner_interface_points();
    const FullMatrix<double>      C_in  = block(compliance(k), at_in, n);
    const FullMatrix<double>      C_out = block(compliance(k + 1), 0, n);
    const std::vector<StackJoint> pair  = {stack_joints[k]};
    unsigned int                  set_steps = 0;
    const StackState              state     = solve_stack_contact({C_in, C_out},
                                                 pair,
                                                 parameters.unilateral,
                                                 set_steps);

    // The staggered process of the pair alone, for the step count.
    CondensedBody                    inner(C_in), outer(C_out);
    std::vector<InterfaceOperator *> ops = {&inner, &outer};
    StackCoupling coupling(ops, pair, parameters, {alpha[k]});
    coupling.run(nullptr);
    staggered_steps = coupling.n_steps();
    return state;
  }



  void
  StackFit::joining(const unsigned int k, JointFigures &f) const
  {
    const double D = parameters.joint_diameter(k);
    const double T = parameters.operation.assembly_temperature;
    // A clearance needs no more than the joining clearance.
    f.joining_interference = parameters.fits[k].largest_interference;
    f.joining_clearance
      = joining_clearance_entry(parameters.operation.joining_clearance_text, D);
    const double U       = std::max(f.joining_interference + f.joining_growth,
                              -f.joining_clearance);
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    // The parts as they are when the joint is made: heated or cooled as a
    // whole, each with the coefficient that opens the joint per kelvin
    // (DIN 7190's alpha of one body, or a part's, joints included).
    const auto [first, last] = parameters.joined_parts(k);
    const double opening     = U + f.joining_clearance;
    const double heat_alpha  = part_expansion(k, k + 1, last, false, opening);
    const double cool_alpha  = part_expansion(k, first, k, true, opening);
    f.heat_outer_to
      = heat_alpha > 0. ?
          joining_temperature(true, U, f.joining_clearance, D, heat_alpha, T) :
          unknown;
    std::tie(f.heat_limit, f.heat_limit_body) = heating_limit(k);
    f.heat_above_limit                        = f.heat_outer_to > f.heat_limit;
    f.cooling_from_heating                    = false;
    for (unsigned int b = first; b <= k; ++b)
      f.cooling_from_heating
        = f.cooling_from_heating
          || !(parameters.materials[b].cooling_expansion > 0.);
    f.cool_inner_to
      = cool_alpha > 0. ?
          joining_temperature(false, U, f.joining_clearance, D, cool_alpha, T) :
          unknown;
    f.cool_reachable = !(f.cool_inner_to < OperationAnalysis::coldest_coolant);

    // Neither alone: both, the outer part at its limit and the inner part
    // cooled by what is left (DIN 7190 allows both at once).
    f.both_cool_inner_to = unknown;
    if (f.heat_above_limit && !f.cool_reachable)
      {
        const double heated = part_opening(
          k, k + 1, last, false, f.heat_limit - T, radial_interferences(true));
        const double left  = opening - std::max(0., heated);
        const double alpha = part_expansion(k, first, k, true, left);
        if (alpha > 0.)
          f.both_cool_inner_to = T - left / (alpha * D);
      }
  }



  double
  StackFit::joining_reach(const unsigned int         k,
                          const std::vector<double> &radial) const
  {
    const double T           = parameters.operation.assembly_temperature;
    const auto [first, last] = parameters.joined_parts(k);
    const auto [limit, body] = heating_limit(k);
    // Heating without a limit opens any joint: not judged.
    if (!std::isfinite(limit))
      return std::numeric_limits<double>::infinity();
    // The openings reached: the outer part heated to its limit, the inner
    // one cooled to -196 C (each part as a whole, its joints opening where
    // its bodies expand differently).
    bool         known = false;
    double       reach = 0.;
    const double heat
      = part_opening(k, k + 1, last, false, std::max(0., limit - T), radial);
    if (!std::isnan(heat))
      {
        known = true;
        reach += std::max(0., heat);
      }
    const double cool
      = part_opening(k,
                     first,
                     k,
                     true,
                     std::max(0., T - OperationAnalysis::coldest_coolant),
                     radial);
    if (!std::isnan(cool))
      {
        known = true;
        reach += std::max(0., cool);
      }
    return known ? reach : std::numeric_limits<double>::infinity();
  }



  std::pair<double, std::string>
  StackFit::heating_limit(const unsigned int k) const
  {
    const unsigned int last  = parameters.joined_parts(k).second;
    double             limit = std::numeric_limits<double>::infinity();
    std::string        body;
    for (unsigned int b = k + 1; b <= last; ++b)
      if (parameters.materials[b].temperature_limit > 0.
          && parameters.materials[b].temperature_limit < limit)
        {
          limit = parameters.materials[b].temperature_limit;
          body  = parameters.bodies[b];
        }
    return {limit, body};
  }



  Vector<double>
  StackFit::part_surface(const unsigned int k,
                         const unsigned int first,
                         const StackState  &state) const
  {
    // The outer part's bore (body k + 1, its outer joint the part's first)
    // or the inner part's outside (body k, its bore joint the part's last).
    const unsigned int n = stack_joints[k].n_points();
    Vector<double>     u(n);
    if (first == k + 1)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < stack_joints[k + 1].n_points(); ++j)
          u[i] += compliance(k + 1)(i, n + j) * state.force[0][j];
    else
      {
        const unsigned int n_in = stack_joints[k - 1].n_points();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n_in; ++j)
            u[i] += compliance(k)(n_in + i, j) * state.force[k - 1 - first][j];
      }
    return u;
  }



  double
  StackFit::expansion(const unsigned int b, const bool cooling) const
  {
    const Material &m = parameters.materials[b];
    return cooling ? m.joining_cooling_expansion() : m.thermal_expansion;
  }



  double
  StackFit::part_opening(const unsigned int         k,
                         const unsigned int         first,
                         const unsigned int         last,
                         const bool                 cooling,
                         const double               dT,
                         const std::vector<double> &radial) const
  {
    for (unsigned int b = first; b <= last; ++b)
      if (!(expansion(b, cooling) > 0.))
        return std::numeric_limits<double>::quiet_NaN();
    // The surface at joint k: the outer part's bore or the inner part's
    // outside, of the joint's own body.
    const bool         bore = first == k + 1;
    const unsigned int b    = bore ? first : last;
    const double       D    = parameters.joint_diameter(k);
    if (first == last || !(dT > 0.))
      return D * expansion(b, cooling) * dT;

    // The body's free growth and what its joint's changed forces add, the
    // least over the points.
    const Vector<double> at_rest
      = part_surface(k, first, part_assembly(first, last, radial));
    const double         signed_dT = cooling ? -dT : dT;
    const Vector<double> u
      = part_surface(k,
                     first,
                     part_assembly(first, last, radial, signed_dT, cooling));
    double least = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const double moved
          = u[i] - at_rest[i] + expansion(b, cooling) * signed_dT * D / 2.;
        least = std::min(least, bore ? moved : -moved);
      }
    return 2. * least;
  }



  double
  StackFit::part_expansion(const unsigned int k,
                           const unsigned int first,
                           const unsigned int last,
                           const bool         cooling,
                           const double       opening) const
  {
    const double D = parameters.joint_diameter(k);
    // The coefficient g(dT) = opening(dT) / (D dT) at the temperature
    // change dT = opening / (D g(dT)): linear while the part's joints stay
    // closed, a few fixed-point steps where one opens.
    const std::vector<double> largest    = radial_interferences(true);
    const auto                per_kelvin = [&](const double dT) {
      return part_opening(k, first, last, cooling, dT, largest) / (D * dT);
    };
    double g = per_kelvin(1.);
    if (first == last || !(opening > 0.))
      return g;
    double dT = 1.;
    for (unsigned int step = 0; step < 20 && g > 0.; ++step)
      {
        const double next = opening / (D * g);
        const bool   done = std::abs(next - dT) <= 1e-10 * next;
        dT                = next;
        if (done)
          break;
        g = per_kelvin(dT);
      }
    return g > 0. ? g : std::numeric_limits<double>::quiet_NaN();
  }
} // namespace coaxfit
