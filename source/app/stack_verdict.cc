#include <coaxfit/app/stack_fit.h>
#include <coaxfit/parameters/parameter_checks.h>

namespace coaxfit
{
  std::vector<std::string>
  StackFit::failed_criteria() const
  {
    std::vector<std::string> failed;
    if (!converged)
      failed.push_back("the coupling did not converge");
    // Without loads the one state is that of assembly; with loads both
    // states are judged (a torque passes at rest as in service; heat or
    // rotation may loosen a joint or load a body more).
    struct Judged
    {
      const std::vector<JointFigures> &joints;
      const std::vector<BodyFigures>  &bodies;
      std::string                      when;
    };
    std::vector<Judged> states = {{joints_out, bodies_out, ""}};
    if (has_loads())
      {
        states[0].when = " in operation";
        states.push_back(
          {joints_assembly, bodies_assembly, " in the state of assembly"});
      }
    for (const Judged &state : states)
      {
        for (const JointFigures &f : state.joints)
          {
            // A joint with clearance may stand open (a running fit); one
            // drawn with an interference that touches nowhere carries
            // nothing (its roughness, heat or rotation may have eaten the
            // interference).
            if (f.diametral_interference > 0. && f.contact_length <= 0.)
              failed.push_back(
                "the joint " + f.name + " has lost contact over its whole "
                + "length" + state.when
                + (f.smoothing_loss > 0. ?
                     " (U " + number(f.diametral_interference, 6)
                       + " mm, after the smoothing loss U_w "
                       + number(f.effective_interference, 6) + " mm)" :
                     std::string()));
            // A running fit keeps Design/Running clearance.
            if (parameters.running_clearance > 0.
                && f.diametral_interference < 0.
                && f.gap_min < parameters.running_clearance)
              failed.push_back(
                "running clearance of the joint " + f.name + state.when + ": "
                + (f.closed || f.gap_min <= 0. ?
                     std::string("closed") :
                     number(f.gap_min, 6) + " mm left")
                + ", less than " + number(parameters.running_clearance, 6)
                + " mm (Design/Running clearance)");
            if (parameters.slip_judged(&f - &state.joints[0])
                && f.slip_safety < parameters.slip_safety)
              failed.push_back(
                "slip of the joint " + f.name + state.when
                + ": safety against slip "
                + Verdict::below(f.slip_safety, parameters.slip_safety)
                + " (Design/Slip safety)");
          }
        for (const BodyFigures &f : state.bodies)
          if (f.brittle)
            {
              if (f.tensile_strength > 0.
                  && f.fracture_safety < parameters.fracture_safety)
                failed.push_back("fracture of the brittle " + f.name
                                 + state.when + ": safety against fracture "
                                 + Verdict::below(f.fracture_safety,
                                                  parameters.fracture_safety)
                                 + " (Design/Fracture safety)");
            }
          else if (f.yield_strength > 0.
                   && f.yield_safety < parameters.yield_safety)
            failed.push_back(
              "yield of the " + f.name + state.when + ": safety against yield "
              + Verdict::below(f.yield_safety, parameters.yield_safety)
              + " (Design/Yield safety)");
      }
    return failed;
  }
} // namespace coaxfit
