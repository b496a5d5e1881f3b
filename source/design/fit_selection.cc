#include <coaxfit/design/design_report.h>
#include <coaxfit/design/din7190.h>
#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/design/required_loads.h>
#include <coaxfit/fe/section_scene.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace coaxfit
{
  namespace
  {
    /** What one end of the band answers to. */
    enum class Criterion
    {
      slip,
      yield_hub,
      yield_shaft,
      fracture_hub
    };

    std::string
    name_of(const Criterion c)
    {
      switch (c)
        {
          case Criterion::slip:
            return "slip";
          case Criterion::yield_hub:
            return "yield of the hub";
          case Criterion::yield_shaft:
            return "yield of the shaft";
          default:
            return "fracture of the brittle hub";
        }
    }

    /**
     * The criteria of @p parameters: slip, and for each part with a known
     * strength its yield (a brittle hub: fracture).
     */
    std::vector<Criterion>
    criteria_of(const Parameters &parameters)
    {
      std::vector<Criterion> list{Criterion::slip};
      if (parameters.hub.kind == MaterialKind::brittle)
        {
          if (parameters.hub.tensile_strength > 0.)
            list.push_back(Criterion::fracture_hub);
        }
      else if (parameters.hub.yield_strength > 0.
               && !(parameters.design.plastic_utilisation > 0.))
        // A hub allowed to yield answers to its plastic utilisation
        // instead (compute_plastic()).
        list.push_back(Criterion::yield_hub);
      if (parameters.shaft.yield_strength > 0.)
        list.push_back(Criterion::yield_shaft);
      return list;
    }

    /** The required safety of criterion @p c. */
    double
    required_safety(const DesignParameters &design, const Criterion c)
    {
      return c == Criterion::slip         ? design.slip_safety :
             c == Criterion::fracture_hub ? design.fracture_safety :
                                            design.yield_safety;
    }

    /**
     * The FE safety of criterion @p c in the state @p state (an unloaded
     * part: infinite; a lost contact: slip safety 0).
     */
    double
    safety_of(const SolvedState &state, const Criterion c)
    {
      const FitDesign &d = state.design;
      const double     s = c == Criterion::slip        ? d.safety_slip :
                           c == Criterion::yield_hub   ? d.safety_yield_hub :
                           c == Criterion::yield_shaft ? d.safety_yield_shaft :
                                                         d.safety_fracture_hub;
      if (std::isnan(s))
        return c == Criterion::slip ? 0. : FitSelection::infinite;
      return s;
    }

    /**
     * The figure of criterion @p c that is (nearly) affine in the
     * interference: the safety against slip (the normal force over the
     * required one), or the stress over the strength, 1/safety.
     */
    double
    affine_figure(const Criterion c, const double safety)
    {
      return c == Criterion::slip ? safety : 1. / safety;
    }

    /**
     * The value of affine_figure() an end aims at: the required safety and
     * 1e-4 more, so that an end found to 0.1 % is on the safe side.
     */
    double
    target_of(const DesignParameters &design, const Criterion c)
    {
      return affine_figure(c, (1. + 1e-4) * required_safety(design, c));
    }

    /**
     * DIN 7190's safety of criterion @p c for the effective interference
     * @p U_w (mm) under @p loads, as FitDesign gives it: the capacity of
     * Lame's pressure, the equivalent (hoop for a brittle hub) stress at
     * the check points.
     */
    double
    din_safety(const Parameters     &parameters,
               const Din7190::Loads &loads,
               const Criterion       c,
               const double          U_w)
    {
      GeometryParameters model = parameters.geometry;
      model.d                  = 0.5 * U_w;
      const Din7190 din(model, parameters.shaft, parameters.hub, loads);
      const DesignParameters &design = parameters.design;
      if (c == Criterion::slip)
        {
          // On a cone the normal force is p pi D_F l_F / cos(beta), its
          // friction shared as FitDesign shares it.
          if (parameters.sections && parameters.sections->conical())
            {
              const double taper = parameters.sections->taper();
              const double N     = din.axial_force(din.pressure(), 1.)
                               / FitDesign::cone_half_angle(taper)[1];
              return FitDesign::cone_slip_safety(
                N,
                design.friction_coefficient,
                taper,
                design.application_factor * 1e3 * design.required_torque
                  / model.R1,
                design.application_factor * design.required_axial_force);
            }
          return din.axial_force(din.pressure(), design.friction_coefficient)
                 / required_friction_force(design, 2. * model.R1);
        }
      const auto ratio = [](const double strength, const double stress) {
        return stress > 0. ? strength / stress : FitSelection::infinite;
      };
      if (c == Criterion::yield_hub)
        return ratio(parameters.hub.yield_strength,
                     std::max(din.hub_bore().equivalent(),
                              din.hub_outer().equivalent()));
      if (c == Criterion::yield_shaft)
        return ratio(parameters.shaft.yield_strength,
                     std::max(din.shaft_outer().equivalent(),
                              din.shaft_inner().equivalent()));
      return ratio(parameters.hub.tensile_strength,
                   std::max(din.hub_bore().hoop, din.hub_outer().hoop));
    }

    /** An interference (mm) in words. */
    std::string
    mm(const double x)
    {
      return figure_text(x, 5);
    }

    /** A safety in words. */
    std::string
    safety_text(const double x)
    {
      return figure_text(x, 4);
    }
  } // namespace



  Parameters
  FitSelection::at_interference(const Parameters &parameters, const double U)
  {
    Parameters p                 = parameters;
    p.fit.iso_fit                = "";
    p.fit.fit_case               = FitCase::mean;
    p.fit.diametral_interference = U;
    const double smoothing       = parameters.fit_limits.smoothing_loss;
    p.fit_limits                 = FitLimits();
    p.fit_limits.smoothing_loss  = smoothing;
    p.fit_limits.U_min           = U;
    p.fit_limits.U_max           = U;
    p.geometry.d                 = 0.5 * (U - smoothing);
    p.design.corner_trend        = false;
    if (p.sections && p.sections->conical())
      p.fit.push_on_distance = U / p.sections->taper();
    return p;
  }



  FitSelection::FitSelection(const Parameters   &parameters,
                             const Solve        &solve,
                             const PlasticSolve &plastic)
    : diameter(parameters.drawing.joint_diameter)
    , design(parameters.design)
    , brittle_hub(parameters.hub.kind == MaterialKind::brittle)
    , allowed_utilisation(parameters.design.plastic_utilisation)
  {
    // The largest interference the model takes: U_w = 0.1 D_F, on a cone
    // also a = l_F / 10 (complete_taper() requires the same of a run).
    if (parameters.sections && parameters.sections->conical())
      {
        taper   = parameters.sections->taper();
        U_limit = std::min(0.1 * diameter,
                           0.1 * parameters.sections->joint_length() * taper);
      }
    else
      U_limit = 0.1 * diameter + parameters.fit_limits.smoothing_loss;
    // Select mode chooses the fit: what Fit gives for a check is unused.
    if (!parameters.fit.iso_fit.empty()
        || parameters.fit.fit_case != FitCase::mean)
      notes.push_back(
        "Fit/ISO fit and Fit/Case are not used in select mode (given: "
        + (parameters.fit.iso_fit.empty() ? std::string("no ISO fit") :
                                            parameters.fit.iso_fit)
        + ", case " + to_string(parameters.fit.fit_case)
        + "): the selection chooses the fit");
    compute_din(parameters);
    if (allowed_utilisation > 0.)
      compute_din_plastic(parameters);
    compute_fe(parameters, solve);
    if (allowed_utilisation > 0.)
      {
        if (!plastic)
          throw std::logic_error("a plastic selection needs its solve");
        compute_plastic(parameters, plastic);
      }
    compute_joining(parameters);
    rank_fits();
    note_fits();
  }



  void
  FitSelection::compute_joining(const Parameters &parameters)
  {
    const OperationParameters &o = parameters.operation;
    joining_clearance            = o.joining_clearance(diameter);
    const JoiningMethod method   = parameters.design.joining;
    if (method != JoiningMethod::shrink
        && method != JoiningMethod::shrink_degreased)
      return;
    if (taper_fit())
      {
        // A taper is pushed on to its distance; heating the hub only eases
        // the push (no ISO fit to open).
        notes.push_back("joining by temperature is not judged for a taper "
                        "fit: it is pushed on by a (Design/Joining gives the "
                        "friction)");
        return;
      }
    const Material &hub = parameters.hub, &shaft = parameters.shaft;
    if (!(hub.thermal_expansion > 0.) || !(hub.temperature_limit > 0.))
      {
        // Heating without a known limit: any fit.
        notes.push_back(
          std::string("joining by temperature is not judged: Material/Hub "
                      "has no ")
          + (hub.thermal_expansion > 0. ? "Temperature limit" :
                                          "Thermal expansion")
          + " (a Name from the library gives it)");
        return;
      }
    if (!(shaft.cooling_expansion > 0.) && shaft.thermal_expansion > 0.)
      notes.push_back("the shaft is cooled with its heating coefficient "
                      "(Material/Shaft/Cooling expansion not given): its "
                      "share of the joining opening is too large");
    const double heating = hub.thermal_expansion
                           * (hub.temperature_limit - o.assembly_temperature);
    const double cooling
      = shaft.joining_cooling_expansion()
        * (o.assembly_temperature - OperationAnalysis::coldest_coolant);
    joining_opening
      = diameter * (std::max(heating, 0.) + std::max(cooling, 0.));
  }



  void
  FitSelection::note_fits()
  {
    std::ostringstream text;
    text << std::setprecision(4);
    if (!unjoinable.empty())
      {
        const std::size_t n = unjoinable.size();
        text << n << " of the " << n + fits.size()
             << " fits inside the band cannot be joined by temperature and "
                "are left out (the hub at its limit and the shaft at -196 C "
                "open "
             << joining_opening
             << " mm, less than their U_max plus the joining clearance "
             << joining_clearance << " mm; e.g. " << unjoinable.front().name
             << "): joined by pressure oil or pressed in, a fit would need "
                "the friction of that method (Design/Joining)";
        notes.push_back(text.str());
        text.str("");
      }
    unsigned int outside_din = 0;
    for (const IsoFit &f : fits)
      outside_din += inside_din_band(f) ? 0 : 1;
    if (outside_din > 0)
      {
        text << outside_din << " of the " << fits.size() << " fit"
             << (fits.size() == 1 ? "" : "s") << " lie"
             << (outside_din == 1 ? "s" : "") << " outside DIN 7190's band ["
             << least_din.U << ", " << largest_din.U
             << "] mm (DIN 7190 'no'): the finite elements accept "
             << (outside_din == 1 ? "it" : "them")
             << ", the plain-cylinder formulas do not";
        if (!inside_din_band(fits.front()))
          text << "; the first fit " << fits.front().name << " is one";
        notes.push_back(text.str());
      }
  }



  void
  FitSelection::compute_din(const Parameters &parameters)
  {
    const double smoothing = parameters.fit_limits.smoothing_loss;
    const double U_w_limit = 0.1 * diameter; // the largest the model allows
    std::vector<std::pair<std::string, Din7190::Loads>> states{
      {"at assembly", Din7190::Loads()}};
    if (parameters.operation.has_loads())
      states.emplace_back("in service", operating_loads(parameters));
    least_din   = {-infinite, "", "", 0., 0};
    largest_din = {infinite, "", "", 0., 0};
    for (const auto &[state, loads] : states)
      for (const Criterion c : criteria_of(parameters))
        {
          const double S = required_safety(parameters.design, c);
          // Bisection of the closed form on 0 <= U_w <= 0.1 D_F: the slip
          // safety grows with U_w, the stress safety falls.
          const auto holds = [&](const double U_w) {
            return din_safety(parameters, loads, c, U_w) >= S;
          };
          double U_w;
          if (c == Criterion::slip)
            {
              if (!holds(U_w_limit))
                U_w = infinite;
              else
                {
                  double lo = 0., hi = U_w_limit;
                  for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
                    (holds(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
                  U_w = hi;
                }
              if (U_w + smoothing > least_din.U)
                least_din = {U_w + smoothing, state, name_of(c), S, 0};
            }
          else
            {
              if (holds(U_w_limit))
                U_w = infinite;
              else if (!holds(0.))
                U_w = 0.;
              else
                {
                  double lo = 0., hi = U_w_limit;
                  for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
                    (holds(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
                  U_w = lo;
                }
              if (U_w + smoothing < largest_din.U)
                largest_din = {U_w + smoothing, state, name_of(c), S, 0};
            }
        }
  }



  void
  FitSelection::compute_fe(const Parameters &parameters, const Solve &solve)
  {
    const DesignParameters &design    = parameters.design;
    const double            smoothing = parameters.fit_limits.smoothing_loss;
    std::vector<std::pair<std::string, Parameters>> states{
      {"at assembly", at_assembly(parameters)}};
    if (parameters.operation.has_loads())
      {
        Parameters service          = parameters;
        service.design.corner_trend = false;
        states.emplace_back("in service", service);
      }

    // The two interferences of the straight lines: DIN 7190's ends when
    // they are usable, else the run's interference and 1.5 times it
    // (effective interferences).
    double U_a = least_din.U, U_b = largest_din.U;
    if (!(std::isfinite(U_a) && std::isfinite(U_b) && U_a > smoothing
          && U_b > smoothing && U_a < U_limit && U_b < U_limit
          && std::abs(U_b - U_a) > 0.01 * (U_b - smoothing)))
      {
        U_a
          = std::max(parameters.fit_limits.used(), smoothing + 5e-4 * diameter);
        U_a = std::min(U_a, smoothing + 0.05 * diameter);
        if (taper_fit())
          U_a = std::min(U_a, 0.5 * U_limit);
        U_b = smoothing + 1.5 * (U_a - smoothing);
      }
    // The lines' slopes are judged from U_a to U_b: in order (DIN 7190's
    // U_min lies above its U_max where no interference suits).
    if (U_b < U_a)
      std::swap(U_a, U_b);

    // Every solve is kept: (state, U) -> its state.
    std::map<std::pair<unsigned int, double>, SolvedState> solved;
    const auto                                             state_at
      = [&](const unsigned int s, const double U) -> const SolvedState & {
      const auto key   = std::make_pair(s, U);
      auto       known = solved.find(key);
      if (known == solved.end())
        {
          ++n_solves;
          known
            = solved.emplace(key, solve(at_interference(states[s].second, U)))
                .first;
        }
      return known->second;
    };

    // The straight line of each state and criterion.
    struct Estimate
    {
      unsigned int state;
      Criterion    criterion;
      double       U;
    };
    std::vector<Estimate> estimates;
    for (unsigned int s = 0; s < states.size(); ++s)
      for (const Criterion c : criteria_of(parameters))
        {
          const double t   = target_of(design, c);
          const double f_a = affine_figure(c, safety_of(state_at(s, U_a), c));
          const double f_b = affine_figure(c, safety_of(state_at(s, U_b), c));
          double       U;
          if (f_b != f_a && std::isfinite(f_a) && std::isfinite(f_b))
            U = U_a + (t - f_a) * (U_b - U_a) / (f_b - f_a);
          else
            U = (c == Criterion::slip) == (f_a >= t) ? -infinite : infinite;
          // A slope of the wrong sign: the criterion never holds (slip) or
          // never limits (stress) on this line.
          if (c == Criterion::slip && !(f_b > f_a) && f_a < t)
            U = infinite;
          if (c != Criterion::slip && !(f_b > f_a) && f_a <= t)
            U = infinite;
          estimates.push_back({s, c, U});
        }

    // Solve the criterion @p e again at its interference until its safety
    // is the required one to 0.1 %: secant steps on the last two solves,
    // bisection when a step leaves the bracket.
    const auto refine = [&](const Estimate &e) {
      const Criterion c         = e.criterion;
      const double    t         = target_of(design, c);
      const double    S         = required_safety(design, c);
      const auto      figure_at = [&](const double U) {
        return affine_figure(c, safety_of(state_at(e.state, U), c));
      };
      End end;
      end.state     = states[e.state].first;
      end.criterion = name_of(c);
      // The figure grows with U for every criterion: below the target
      // (f < t) the end is further up.
      double below = -infinite, above = infinite;
      for (const double U : {U_a, U_b})
        if (figure_at(U) < t)
          below = std::max(below, U);
        else
          above = std::min(above, U);
      double U_last = U_b, f_last = figure_at(U_b);
      double U = std::clamp(e.U, smoothing + 1e-6 * diameter, U_limit);
      const unsigned int before = n_solves;
      // A stress criterion whose line ends beyond the largest interference
      // the model takes and that holds there does not end the band: the
      // model's limit does.
      if (c != Criterion::slip && e.U >= U_limit)
        {
          end.U      = U_limit;
          end.safety = safety_of(state_at(e.state, U_limit), c);
          if (end.safety >= S)
            {
              end.U      = infinite;
              end.solves = n_solves - before;
              return end;
            }
        }
      for (unsigned int step = 0; step < 7; ++step)
        {
          const double safety = safety_of(state_at(e.state, U), c);
          const double f      = affine_figure(c, safety);
          end.U               = U;
          end.safety          = safety;
          if (safety >= S && safety <= (1. + 1e-3) * S)
            break;
          (f < t ? below : above) = U;
          double next             = f != f_last ?
                                      U + (t - f) * (U - U_last) / (f - f_last) :
                                      std::nan("");
          U_last                  = U;
          f_last                  = f;
          const bool bracketed = std::isfinite(below) && std::isfinite(above);
          if (!(next > smoothing && next <= U_limit)
              || (bracketed && !(next > below && next < above)))
            next = bracketed            ? 0.5 * (below + above) :
                   std::isfinite(above) ? 0.5 * (smoothing + above) :
                                          0.5 * (U + U_limit);
          U = next;
        }
      end.solves = n_solves - before;
      // Slip still below its safety at the largest interference the model
      // takes (0.1 D): no interference carries the loads.
      if (c == Criterion::slip && end.safety < S
          && end.U >= (1. - 1e-9) * U_limit)
        {
          notes.push_back(
            "no interference up to the model's limit ("
            + std::string(taper_fit() ? "U = a C with a = l_F / 10, or 0.1 D" :
                                        "U_w = 0.1 D")
            + ") carries the loads: safety against slip "
            + safety_text(end.safety) + " at U = " + mm(end.U) + " mm");
          end.U = infinite;
          return end;
        }
      if (!(end.safety >= S && end.safety <= (1. + 1e-3) * S))
        notes.push_back("the " + end.criterion + " " + end.state
                        + " did not reach its safety (to 0.1 %, not below) "
                          "within the steps (safety "
                        + safety_text(end.safety) + " at U = " + mm(end.U)
                        + " mm)");
      return end;
    };

    // The governing estimate of each end, refined; then every state is
    // checked at both ends, and a criterion that fails there governs
    // instead (refined in turn).
    least   = {-infinite, "", "", 0., 0};
    largest = {infinite, "", "", 0., 0};
    std::vector<bool> refined(estimates.size(), false);
    const auto        govern = [&](const unsigned int i) {
      refined[i]        = true;
      const Estimate &e = estimates[i];
      if (!std::isfinite(e.U))
        {
          End end{e.U, states[e.state].first, name_of(e.criterion), 0., 0};
          return end;
        }
      return refine(e);
    };
    for (unsigned int round = 0; round < 4; ++round)
      {
        // The most restrictive estimate not yet refined, at each end.
        int lo = -1, hi = -1;
        for (unsigned int i = 0; i < estimates.size(); ++i)
          {
            if (refined[i])
              continue;
            const bool slip = estimates[i].criterion == Criterion::slip;
            if (slip && estimates[i].U >= least.U
                && (lo < 0 || estimates[i].U > estimates[lo].U))
              lo = i;
            if (!slip && estimates[i].U <= largest.U
                && (hi < 0 || estimates[i].U < estimates[hi].U))
              hi = i;
          }
        if (lo >= 0)
          {
            const End end = govern(lo);
            if (end.U > least.U)
              least = end;
          }
        if (hi >= 0)
          {
            const End end = govern(hi);
            if (end.U < largest.U)
              largest = end;
          }
        if (lo < 0 && hi < 0)
          break;
        // The others' estimates at the ends found: still behind them?
        bool again = false;
        for (unsigned int i = 0; i < estimates.size(); ++i)
          if (!refined[i])
            {
              const bool   slip = estimates[i].criterion == Criterion::slip;
              const double U    = slip ? least.U : largest.U;
              if (!std::isfinite(U) || U <= smoothing || U > U_limit)
                continue;
              const double safety = safety_of(state_at(estimates[i].state, U),
                                              estimates[i].criterion);
              const double S = required_safety(design, estimates[i].criterion);
              if (safety < S)
                {
                  // It fails at the end found: its own end is further in.
                  estimates[i].U = slip ? std::max(estimates[i].U, U) :
                                          std::min(estimates[i].U, U);
                  again          = true;
                }
              else
                refined[i] = true; // holds at the end: it does not govern
            }
        if (!again)
          break;
      }

    // A taper's cases are run at the band's ends: U_min at least what a
    // run takes (U_w of 1e-6 D_F, far above the 1e-9 D_F it allows).
    if (taper_fit() && std::isfinite(least.U)
        && least.U < smoothing + 1e-6 * diameter)
      {
        least.U = smoothing + 1e-6 * diameter;
        notes.push_back("the loads are carried at any push-on distance: a_min "
                        "is set to "
                        + mm(push_on(least.U)) + " mm (U_w = 1e-6 D_F)");
      }

    // A taper's band is one of push-on distances: where no stress
    // criterion ends it, the model's limit does.
    if (taper_fit() && std::isfinite(least.U) && !std::isfinite(largest.U))
      {
        largest = {U_limit, "", "the model's limit", 0., 0};
        notes.push_back("no stress criterion ends the band up to the model's "
                        "limit U = "
                        + mm(U_limit) + " mm (a = " + mm(push_on(U_limit))
                        + " mm: a <= l_F / 10 and U <= 0.1 D_F), which ends "
                          "it"
                        + (criteria_of(parameters).size() == 1 ?
                             "; give the yield strengths (Material/.../Yield "
                             "strength) for a band the parts bear" :
                             ""));
      }

    // Each end in each state: the criteria and the contact zone there.
    for (const auto &[end_name, end] :
         {std::make_pair(std::string("U_min"), &least),
          std::make_pair(std::string("U_max"), &largest)})
      {
        if (!std::isfinite(end->U) || end->U <= smoothing || end->U > U_limit)
          continue;
        for (unsigned int s = 0; s < states.size(); ++s)
          {
            const SolvedState &state = state_at(s, end->U);
            Check              check;
            check.end                 = end_name;
            check.state               = states[s].first;
            check.U                   = end->U;
            check.safety_slip         = safety_of(state, Criterion::slip);
            check.safety_yield_hub    = state.design.safety_yield_hub;
            check.safety_yield_shaft  = state.design.safety_yield_shaft;
            check.safety_fracture_hub = state.design.safety_fracture_hub;
            check.converged           = state.converged;
            for (const auto &[start, stop] : state.separated_zones)
              check.separated_length += stop - start;
            check.contact_lost = !(state.pressure.max > 0.);
            checks.push_back(check);
            // The contact zone against the straight line's solves: the
            // same zones, the line holds; other zones, it is approximate
            // there (the governing end was corrected by solves at it).
            const auto &zones = state.separated_zones;
            bool        same  = true;
            for (const double U : {U_a, U_b})
              same = same && state_at(s, U).separated_zones == zones;
            std::ostringstream note;
            note << std::setprecision(4);
            if (check.contact_lost)
              note << "at " << end_name << " " << check.state
                   << " the contact is lost: the straight line does not hold "
                      "there; the end comes from the secant and bisection "
                      "steps";
            else if (!same)
              note << "at " << end_name << " " << check.state
                   << " the contact zone differs from the line's solves (open "
                   << check.separated_length
                   << " mm of the half joint): the straight line is "
                      "approximate there, the governing end was corrected by "
                      "solves at it";
            else if (check.separated_length > 0.)
              note << "at " << end_name << " " << check.state
                   << " the joint is open over " << check.separated_length
                   << " mm of the half joint, the same zone as at the line's "
                      "solves";
            if (!note.str().empty())
              notes.push_back(note.str());
            // Whatever the steps left: a criterion below its safety at
            // its end is said.
            for (const Criterion c : criteria_of(parameters))
              if ((c == Criterion::slip) == (end_name == "U_min")
                  && safety_of(state, c) < required_safety(design, c))
                notes.push_back("at " + end_name + " " + check.state
                                + " the safety against " + name_of(c) + " "
                                + safety_text(safety_of(state, c))
                                + " is below the required "
                                + safety_text(required_safety(design, c)));
            if (!check.converged)
              notes.push_back("the solve at " + end_name + " " + check.state
                              + " did not converge");
          }
      }
  }



  void
  FitSelection::rank_fits()
  {
    fits.clear();
    if (taper_fit() || !(least.U <= largest.U))
      return;
    unjoinable.clear();
    for (const IsoFit &f : candidate_fits(diameter))
      if (1e-3 * f.min_interference() >= least.U
          && 1e-3 * f.max_interference() <= largest.U)
        (joinable(f) ? fits : unjoinable).push_back(f);
    const double centre = 0.5 * (least.U + largest.U);
    const auto   offset = [centre](const IsoFit &f) {
      return std::abs(0.5e-3 * (f.min_interference() + f.max_interference())
                      - centre);
    };
    std::stable_sort(fits.begin(),
                     fits.end(),
                     [&](const IsoFit &a, const IsoFit &b) {
                       if (preference_key(a) != preference_key(b))
                         return preference_key(a) < preference_key(b);
                       if (offset(a) != offset(b))
                         return offset(a) < offset(b);
                       return a.name < b.name;
                     });
  }



  namespace
  {
    /** What the selection asks: the loads, K_A and the safeties. */
    std::string
    requirement(const DesignParameters &design, const bool brittle)
    {
      std::ostringstream s;
      s << std::setprecision(6) << "required torque " << design.required_torque
        << " N m and axial force " << design.required_axial_force
        << " N times K_A " << design.application_factor << ", mu "
        << design.friction_coefficient << ", slip safety " << design.slip_safety
        << ", yield safety " << design.yield_safety;
      if (brittle)
        s << ", fracture safety " << design.fracture_safety;
      if (design.plastic_utilisation > 0.)
        s << " (the shaft's), plastic utilisation of the hub "
          << design.plastic_utilisation;
      return s.str();
    }
  } // namespace



  std::string
  FitSelection::conflict() const
  {
    if (found())
      return "";
    std::ostringstream text;
    text << std::setprecision(4);
    const double tan_beta = 0.5 * taper;
    if (taper_fit() && !(design.friction_coefficient > tan_beta))
      text << "the taper is not self-locking (mu = "
           << design.friction_coefficient
           << " <= tan(half angle) = " << tan_beta
           << "): friction alone does not hold the hub on the cone at any "
              "push-on distance; secure it axially (a nut) and check it "
              "with Design/Mode = check, or choose a slimmer taper";
    else if (!std::isfinite(least.U) && taper_fit())
      text << "no push-on distance up to the model's limit a = "
           << push_on(U_limit)
           << " mm (a <= l_F / 10, U <= 0.1 D_F) carries the required loads ("
           << least.criterion << " " << least.state << ")";
    else if (!std::isfinite(least.U))
      text << "no interference carries the required loads (" << least.criterion
           << " " << least.state << ")";
    else if (least.U > largest.U)
      {
        text << "U_min " << least.U << " mm (" << least.criterion << " "
             << least.state << ") > U_max " << largest.U << " mm ("
             << largest.criterion << " " << largest.state
             << "): no interference both carries the loads and is borne";
        if (taper_fit())
          text << " (push-on distances a_min " << push_on(least.U)
               << " mm > a_max " << push_on(largest.U) << " mm)";
      }
    else if (taper_fit())
      text << "no push-on distance carries the loads and is borne";
    else if (!unjoinable.empty())
      text << "the " << unjoinable.size() << " ISO 286 fits inside U_min "
           << least.U << " to U_max " << largest.U
           << " mm cannot be joined by temperature (the hub at its limit "
              "and the shaft at -196 C open "
           << joining_opening << " mm; " << unjoinable.front().name << " needs "
           << 1e-3 * unjoinable.front().max_interference()
           << " mm plus the joining clearance " << joining_clearance
           << " mm): join by pressure oil or a press (Design/Joining, with "
              "its friction) or choose a hub that can be heated further";
    else if (candidate_fits(diameter).empty())
      text << "no ISO 286 fit at D_F = " << diameter
           << " mm (covered: over 1 up to 500 mm) for the band " << least.U
           << " to " << largest.U << " mm";
    else
      text << "no ISO 286 fit lies inside U_min " << least.U << " to U_max "
           << largest.U << " mm (band " << 1e3 * (largest.U - least.U)
           << " um)";
    return text.str();
  }



  std::vector<FitSelection::BandRow>
  FitSelection::band_rows() const
  {
    const auto by = [](const End &end) {
      return end.criterion.empty() ? std::string("-") : end.governed_by();
    };
    std::vector<BandRow> rows{
      {"U_min (mm)", least.U, least_din.U, by(least), by(least_din)},
      {"U_max (mm)", largest.U, largest_din.U, by(largest), by(largest_din)}};
    if (taper_fit())
      {
        // a = U / C, governed as U is.
        rows.push_back({"a_min (mm, push-on)",
                        push_on(least.U),
                        push_on(least_din.U),
                        by(least),
                        by(least_din)});
        rows.push_back({"a_max (mm, push-on)",
                        push_on(largest.U),
                        push_on(largest_din.U),
                        by(largest),
                        by(largest_din)});
      }
    return rows;
  }



  void
  FitSelection::print(std::ostream &out, const unsigned int max_fits) const
  {
    std::ostringstream s;
    s << "  fit selection (measured diametral interference, smoothing loss "
         "included):\n"
      << "    " << requirement(design, brittle_hub) << '\n'
      << "    " << std::left << std::setw(22) << "" << std::right
      << std::setw(12) << "FE" << std::setw(12) << "DIN 7190"
      << "  governed by (FE; DIN 7190)\n";
    for (const BandRow &row : band_rows())
      s << "    " << std::left << std::setw(22) << row.label << std::right
        << std::setw(12) << mm(row.fe) << std::setw(12) << mm(row.din) << "  "
        << row.fe_by << "; " << row.din_by << '\n';
    s << "    FE solves: " << n_solves << '\n';
    for (const Check &c : checks)
      s << "    " << c.end << ", " << std::left << std::setw(12)
        << c.state + ":" << std::right << " slip " << safety_text(c.safety_slip)
        << ", yield hub " << safety_text(c.safety_yield_hub) << ", yield shaft "
        << safety_text(c.safety_yield_shaft)
        << (std::isnan(c.safety_fracture_hub) ?
              std::string() :
              ", fracture hub " + safety_text(c.safety_fracture_hub))
        << ", open " << std::setprecision(4) << c.separated_length << " mm"
        << (c.contact_lost ? " (contact lost)" : "") << '\n';
    if (!plastic_checks.empty())
      s << "    elastic-plastic load paths followed: " << n_plastic_solves
        << "; the band's ends on their load paths:\n";
    for (const PlasticCheck &c : plastic_checks)
      s << "    " << c.end << ", elastic-plastic: U " << mm(c.U)
        << " mm, hub utilisation " << safety_text(c.state.utilisation)
        << " (D_p " << safety_text(c.state.plastic_diameter) << " mm), slip "
        << safety_text(c.safety_slip) << " " << stage_words(c.state.least_stage)
        << ", joined mean p " << safety_text(c.state.joined_pressure) << " MPa"
        << (c.state.completed ? "" : " (load path not completed)") << '\n';
    for (const std::string &n : notes)
      s << "    note: " << n << '\n';
    if (taper_fit() && found())
      s << "    push-on distance: from " << mm(push_on(least.U)) << " to "
        << mm(push_on(largest.U)) << " mm (the taper C = " << taper
        << " has no ISO fit; a = " << mm(push_on(0.5 * (least.U + largest.U)))
        << " mm +- " << mm(push_on(0.5 * (largest.U - least.U)))
        << " mm, checked at both ends and the middle)\n";
    else if (found())
      {
        s << "    fits inside [U_min, U_max]: " << fits.size()
          << " (ranked: ISO 286-1's preferred first, then the widest "
             "tolerances, then the best centred)\n"
          << "    " << std::left << std::setw(6) << "rank" << std::setw(10)
          << "fit" << std::right << std::setw(14) << "U_min (um)"
          << std::setw(14) << "U_max (um)"
          << "  preferred  DIN 7190\n";
        for (unsigned int i = 0; i < fits.size() && i < max_fits; ++i)
          s << "    " << std::left << std::setw(6) << i + 1 << std::setw(10)
            << fits[i].name << std::right << std::setw(14)
            << fits[i].min_interference() << std::setw(14)
            << fits[i].max_interference() << "  " << std::left << std::setw(11)
            << (is_preferred_fit(fits[i].name) ? "yes" : "no")
            << (inside_din_band(fits[i]) ? "yes" : "no") << std::right << '\n';
        if (fits.size() > max_fits)
          s << "    (" << fits.size() - max_fits
            << " more in fit_selection.csv)\n";
      }
    else
      s << "    no fit: " << conflict() << '\n';
    out << s.str();
  }



  void
  FitSelection::print_markdown(std::ostream &out) const
  {
    out << "## Fit selection\n\n"
        << "Measured (drawing) diametral interference, smoothing loss "
           "included; "
        << requirement(design, brittle_hub) << ".\n\n"
        << "| | FE | DIN 7190 | governed by (FE) | governed by (DIN 7190) "
           "|\n|---|---:|---:|---|---|\n";
    for (const BandRow &row : band_rows())
      out << "| " << row.label << " | " << mm(row.fe) << " | " << mm(row.din)
          << " | " << row.fe_by << " | " << row.din_by << " |\n";
    out << "\nFE solves: " << n_solves << ".\n\n";
    if (!checks.empty())
      {
        out << "| end | state | U (mm) | slip | yield hub | yield shaft | "
               "open (mm) |\n|---|---|---:|---:|---:|---:|---:|\n";
        for (const Check &c : checks)
          out << "| " << c.end << " | " << c.state << " | " << mm(c.U) << " | "
              << safety_text(c.safety_slip) << " | "
              << safety_text(c.safety_yield_hub) << " | "
              << safety_text(c.safety_yield_shaft) << " | "
              << mm(c.separated_length) << " |\n";
        out << '\n';
      }
    if (!plastic_checks.empty())
      {
        out
          << "The band's ends on their elastic-plastic load paths ("
          << n_plastic_solves
          << " load paths followed in all):\n\n| end | U (mm) | hub utilisation | D_p (mm) "
             "| slip | least | joined mean p (MPa) |\n|---|---:|---:|"
             "---:|---:|---|---:|\n";
        for (const PlasticCheck &c : plastic_checks)
          out << "| " << c.end << " | " << mm(c.U) << " | "
              << safety_text(c.state.utilisation) << " | "
              << safety_text(c.state.plastic_diameter) << " | "
              << safety_text(c.safety_slip) << " | "
              << stage_words(c.state.least_stage) << " | "
              << safety_text(c.state.joined_pressure) << " |\n";
        out << '\n';
      }
    for (const std::string &n : notes)
      out << "Note: " << n << ".\n\n";
    if (taper_fit() && found())
      out << "Push-on distance: from " << mm(push_on(least.U)) << " to "
          << mm(push_on(largest.U)) << " mm (a taper has no ISO fit; a = "
          << mm(push_on(0.5 * (least.U + largest.U))) << " mm +- "
          << mm(push_on(0.5 * (largest.U - least.U)))
          << " mm), checked below at both ends and the middle.\n\n";
    else if (found())
      {
        out << "Fits inside [U_min, U_max], ranked (ISO 286-1's preferred "
               "first, then the widest tolerances, then the best centred; "
               "DIN 7190: inside DIN 7190's band):\n\n| rank | fit | U_min "
               "(um) | U_max (um) | preferred | DIN 7190 |\n|---:|---|---:|"
               "---:|---|---|\n";
        for (unsigned int i = 0; i < fits.size(); ++i)
          out << "| " << i + 1 << " | " << fits[i].name << " | "
              << fits[i].min_interference() << " | "
              << fits[i].max_interference() << " | "
              << (is_preferred_fit(fits[i].name) ? "yes" : "no") << " | "
              << (inside_din_band(fits[i]) ? "yes" : "no") << " |\n";
        out << '\n';
      }
    else
      out << "No fit: " << conflict() << ".\n\n";
  }
} // namespace coaxfit
