#include <coaxfit/design/verdict.h>

#include <cmath>
#include <sstream>
#include <utility>

namespace coaxfit
{
  namespace
  {
    /** @p x with @p digits significant digits. */
    std::string
    figure(const double x, const int digits)
    {
      std::ostringstream text;
      text.precision(digits);
      text << x;
      return text.str();
    }
  } // namespace



  std::string
  Verdict::below(const double a, const double b)
  {
    int digits = 3;
    while (digits < 15 && figure(a, digits) == figure(b, digits))
      ++digits;
    return figure(a, digits) + " < " + figure(b, digits);
  }



  Verdict::Verdict(const Parameters        &parameters,
                   const OperationAnalysis &operation,
                   const bool               converged)
  {
    const DesignParameters &design = parameters.design;
    if (!converged)
      failed.push_back("the coupling did not converge (the figures are not "
                       "those of the solution)");

    // The states: at assembly and in service (the same state without loads
    // of operation; then no state is named).
    std::vector<const OperationAnalysis::State *> states{&operation.assembly};
    if (operation.has_loads)
      states.push_back(&operation.operation);
    const auto where = [&](const OperationAnalysis::State &state) {
      return operation.has_loads ?
               (state.name == "assembly" ? " at assembly" : " in service") :
               std::string();
    };
    // The state with the smallest value of @p safety (NaN: not known, and
    // left out; with @p touching_only also a state whose contact is lost);
    // null if none is left.
    const auto worst = [&](double OperationAnalysis::State::*safety,
                           const bool touching_only = false) {
      const OperationAnalysis::State *state = nullptr;
      for (const OperationAnalysis::State *s : states)
        if (!std::isnan(s->*safety) && !(touching_only && s->contact_lost)
            && (state == nullptr || s->*safety < state->*safety))
          state = s;
      return state;
    };

    for (const OperationAnalysis::State *s : states)
      if (s->contact_lost)
        failed.push_back("contact lost" + where(*s)
                         + ": the surfaces do not touch");

    // Slip in the worst state whose surfaces still touch (a lost contact
    // is said above).
    if (design.required_torque > 0. || design.required_axial_force > 0.)
      if (const auto *s = worst(&OperationAnalysis::State::safety_slip, true))
        if (s->safety_slip < design.slip_safety)
          failed.push_back("slip" + where(*s) + ": safety against slip "
                           + below(s->safety_slip, design.slip_safety)
                           + " (Design/Slip safety)");

    const bool brittle_hub
      = !std::isnan(operation.assembly.safety_fracture_hub);
    const std::vector<
      std::pair<std::string, double OperationAnalysis::State::*>>
      parts{{"shaft", &OperationAnalysis::State::safety_yield_shaft},
            {"hub", &OperationAnalysis::State::safety_yield_hub}};
    for (const auto &[part, safety] : parts)
      if (!(part == "hub" && brittle_hub))
        if (const auto *s = worst(safety))
          if (s->*safety < design.yield_safety)
            failed.push_back("yield of the " + part + where(*s)
                             + ": safety against yield "
                             + below(s->*safety, design.yield_safety)
                             + " (Design/Yield safety)");
    if (brittle_hub)
      if (const auto *s = worst(&OperationAnalysis::State::safety_fracture_hub))
        if (s->safety_fracture_hub < design.fracture_safety)
          failed.push_back(
            "fracture of the brittle hub" + where(*s)
            + ": safety against fracture "
            + below(s->safety_fracture_hub, design.fracture_safety)
            + " (Design/Fracture safety)");

    // Joining: either way is enough, or both at once (the hub at its
    // limit, the shaft in liquid nitrogen).
    const bool heating_known = !std::isnan(operation.joining_temperature_hub);
    const bool cooling_known = !std::isnan(operation.joining_temperature_shaft);
    const bool heating_ok = heating_known && !operation.joining_hub_above_limit;
    const bool cooling_ok
      = cooling_known && operation.joining_cooling_reachable;
    const bool both_ok = operation.joining_by_both >= operation.joining_needed;
    // A joint made by pressure oil or pressed in is not joined by
    // temperature: its joining temperatures are information only.
    const bool by_temperature
      = design.joining == JoiningMethod::shrink
        || design.joining == JoiningMethod::shrink_degreased;
    if (by_temperature && (heating_known || cooling_known) && !heating_ok
        && !cooling_ok && !both_ok)
      failed.push_back(
        "joining temperature not reachable: the hub "
        + (heating_known ? "at " + celsius(operation.joining_temperature_hub)
                             + " is above its temperature limit" :
                           std::string("cannot be heated (no thermal "
                                       "expansion)"))
        + ", the shaft "
        + (cooling_known ? "at " + celsius(operation.joining_temperature_shaft)
                             + " is below liquid nitrogen" :
                           std::string("cannot be cooled (no thermal "
                                       "expansion)")));
  }



  Verdict::Verdict(std::vector<std::string> failed)
    : failed(std::move(failed))
  {}



  Verdict
  Verdict::no_fit(const std::string &conflict)
  {
    Verdict verdict;
    verdict.failed.push_back("no fit: " + conflict);
    return verdict;
  }



  std::string
  Verdict::line() const
  {
    if (ok())
      return "Verdict: OK";
    std::string text = "Verdict: FAILED: ";
    for (unsigned int i = 0; i < failed.size(); ++i)
      text += (i > 0 ? "; " : "") + failed[i];
    return text;
  }
} // namespace coaxfit
