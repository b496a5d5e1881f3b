#include <coaxfit/design/design_report.h>
#include <coaxfit/design/din7190.h>
#include <coaxfit/design/fit_selection.h>
#include <coaxfit/design/radial_plastic_fit.h>
#include <coaxfit/design/required_loads.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace coaxfit
{
  namespace
  {
    /**
     * The effective diametral interference U_w (mm) of a hub plastic to
     * @p D_p on an elastic shaft, in the thick-walled cylinder that gives
     * elastic_plastic_hub_pressure(): the elastic ring D_p..D_aA at its
     * first yield under (R_e / sqrt 3)(1 - Q_p^2), Q_p = D_p / D_aA,
     * widens D_p by D_p (R_e / (sqrt 3 E_A)) ((1 + Q_p^2) + nu_A (1 -
     * Q_p^2)); the plastic zone keeps its volume (u r constant), so the
     * bore widens by that strain times (D_p / D_F)^2; the shaft narrows
     * by D_F p / E_I ((1 + Q_I^2) / (1 - Q_I^2) - nu_I) (Lame). At D_p =
     * D_F this is Lame's interference of the elastic limit.
     */
    double
    plastic_interference(const Parameters &parameters, const double D_p)
    {
      const double DF  = parameters.drawing.joint_diameter;
      const double DaA = parameters.drawing.hub_outer_diameter;
      const double DiI = parameters.drawing.shaft_bore_diameter;
      const double Re  = parameters.hub.yield_strength;
      const double p   = elastic_plastic_hub_pressure(Re, DF, DaA, D_p);
      const double Qp = D_p / DaA, QI = DiI / DF;
      const double hub = Re / (std::sqrt(3.) * parameters.hub.E)
                         * ((1. + Qp * Qp) + parameters.hub.nu * (1. - Qp * Qp))
                         * (D_p / DF) * (D_p / DF);
      const double shaft
        = p / parameters.shaft.E
          * ((1. + QI * QI) / (1. - QI * QI) - parameters.shaft.nu);
      return DF * (hub + shaft);
    }

  } // namespace



  double
  FitSelection::slip_safety_of(const double N) const
  {
    return design.friction_coefficient * N
           / required_friction_force(design, diameter);
  }



  void
  FitSelection::compute_din_plastic(const Parameters &parameters)
  {
    const double smoothing = parameters.fit_limits.smoothing_loss;
    const double DF        = parameters.drawing.joint_diameter;
    const double DaA       = parameters.drawing.hub_outer_diameter;
    const double Re        = parameters.hub.yield_strength;
    if (parameters.operation.has_loads())
      notes.push_back("DIN 7190's U_max and U_min of the yielding hub are "
                      "those at assembly (the thick-walled cylinder takes no "
                      "loads of operation); the FE ends follow the load path "
                      "through operation and unloading");
    // U_max: the hub plastic to the allowed utilisation.
    const double D_p   = DF + allowed_utilisation * (DaA - DF);
    const double U_max = plastic_interference(parameters, D_p) + smoothing;
    if (U_max < largest_din.U)
      largest_din = {U_max,
                     "at assembly",
                     "plastic utilisation of the hub",
                     allowed_utilisation,
                     0};
    // U_min at assembly: the pressure slip needs, carried by a hub that
    // yields when it is above the hub's elastic limit.
    GeometryParameters model = parameters.geometry;
    model.d                  = 0.5 * (least_din.U - smoothing);
    const Din7190 din(model,
                      parameters.shaft,
                      parameters.hub,
                      Din7190::Loads());
    const double  p_needed
      = design.slip_safety / slip_safety_of(din.axial_force(1., 1.));
    if (!(p_needed > elastic_plastic_hub_pressure(Re, DF, DaA, DF)))
      return;
    if (p_needed >= elastic_plastic_hub_pressure(Re, DF, DaA, DaA))
      {
        least_din = {infinite, "at assembly", "slip", 0., 0};
        return;
      }
    double lo = DF, hi = DaA; // the pressure grows with D_p
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-13 * DaA; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (elastic_plastic_hub_pressure(Re, DF, DaA, mid) < p_needed ? lo : hi)
          = mid;
      }
    const double U_min = plastic_interference(parameters, hi) + smoothing;
    if (U_min > least_din.U)
      least_din = {U_min, "at assembly", "slip", design.slip_safety, 0};
  }



  void
  FitSelection::compute_plastic(const Parameters   &parameters,
                                const PlasticSolve &solve)
  {
    const double smoothing = parameters.fit_limits.smoothing_loss;
    const double P         = allowed_utilisation;
    const double S         = design.slip_safety;
    const auto   text      = [](const double x) { return figure_text(x, 5); };

    // Every load path followed is kept: U -> its state.
    std::map<double, PlasticState> solved;
    const auto state_at = [&](const double U) -> const PlasticState & {
      auto known = solved.find(U);
      if (known == solved.end())
        {
          ++n_plastic_solves;
          Parameters p            = at_interference(parameters, U);
          p.design.mode           = DesignMode::check;
          p.load_path.stages_text = load_path_stages(parameters);
          known                   = solved.emplace(U, solve(p)).first;
        }
      return known->second;
    };
    const auto slip_at = [&](const double U) {
      return slip_safety_of(state_at(U).least_normal_force);
    };

    // The first yield: the elastic limit of one path, scaled (the state of
    // assembly is linear in U_w up to it). Started where the thick-walled
    // cylinder yields.
    const double U_start
      = std::clamp(plastic_interference(parameters,
                                        parameters.drawing.joint_diameter)
                     + smoothing,
                   smoothing + 1e-4 * diameter,
                   U_limit);
    const double fraction = state_at(U_start).elastic_fraction;
    const double U_yield
      = std::min(U_limit, smoothing + fraction * (U_start - smoothing));

    // U_max: the utilisation of the hub reaches P (aimed 0.25 % below,
    // taken within 0.5 % below and not above).
    End end;
    end.criterion    = "plastic utilisation of the hub";
    const double aim = (1. - 2.5e-3) * P;
    double       lo = U_yield, u_lo = 0., hi = infinite, u_hi = 0.;
    double U = std::min(U_limit, U_yield + 3. * P * (U_yield - smoothing));
    bool   found_max          = false;
    const unsigned int before = n_plastic_solves;
    for (unsigned int step = 0; step < 12; ++step)
      {
        const PlasticState &state = state_at(U);
        // A path that could not be followed to U: beyond what the hub
        // carries, so above the end.
        const double u = state.completed ? state.utilisation : infinite;
        end.U          = U;
        end.safety     = u;
        end.state      = stage_words(state.utilisation_stage.empty() ?
                                  std::string("joining") :
                                  state.utilisation_stage);
        if (u >= (1. - 5e-3) * P && u <= P)
          {
            found_max = true;
            break;
          }
        // The secant through the last two points below (unbracketed).
        const double U_below = lo, u_below = u_lo;
        if (u < P)
          lo = U, u_lo = u;
        else
          hi = U, u_hi = u;
        if (!std::isfinite(hi) && U >= U_limit)
          break; // below P up to the model's limit
        double next = std::nan("");
        if (std::isfinite(hi) && std::isfinite(u_hi))
          next = lo + (aim - u_lo) * (hi - lo) / (u_hi - u_lo);
        else if (!std::isfinite(hi) && u > u_below && U > U_below)
          next = U + (aim - u) * (U - U_below) / (u - u_below);
        if (!std::isfinite(hi))
          {
            // Not yet bracketed: at most twice as far from the first yield.
            const double far = std::min(U_limit, U_yield + 2. * (U - U_yield));
            next = std::isfinite(next) ? std::min(std::max(next, U), far) : far;
            if (next <= U)
              next = far;
          }
        else if (!(next > lo && next < hi))
          next = 0.5 * (lo + hi);
        U = next;
      }
    end.solves = n_plastic_solves - before;
    if (!found_max && !std::isfinite(hi) && end.U >= U_limit)
      notes.push_back("the hub's plastic utilisation stays below "
                      + figure_text(P, 4) + " up to the model's limit U = "
                      + text(U_limit) + " mm (" + figure_text(end.safety, 4)
                      + " there): it does not end the band");
    else
      {
        if (!found_max)
          notes.push_back("the hub's plastic utilisation did not reach "
                          + figure_text(P, 4) + " to 0.5 % within the steps ("
                          + figure_text(end.safety, 4) + " at U = "
                          + text(end.U) + " mm); U_max is the last below");
        if (!found_max && std::isfinite(u_lo) && lo > U_yield)
          end.U = lo, end.safety = u_lo;
        else if (!found_max)
          end.U = U_yield, end.safety = 0.;
        if (end.U < largest.U)
          largest = end;
      }

    // U_min: where the hub yields at the elastic U_min, the slip safety of
    // the load path's least normal force (aimed 0.01 % above S, taken
    // within 0.1 %).
    if (std::isfinite(least.U) && least.U > smoothing && least.U <= U_limit)
      {
        const PlasticState &state = state_at(least.U);
        const bool          yields
          = state.elastic_fraction < 1. || state.utilisation > 0.;
        if (yields && slip_at(least.U) < S)
          {
            End slip;
            slip.criterion                 = "slip";
            const unsigned int before_slip = n_plastic_solves;
            const double       t           = (1. + 1e-4) * S;
            double             below = least.U, s_below = slip_at(least.U);
            double             above = infinite, s_above = 0.;
            double             U_slip    = least.U * (1. + (S - s_below) / S);
            bool               found_min = false;
            for (unsigned int step = 0; step < 12; ++step)
              {
                U_slip                  = std::min(U_slip, U_limit);
                const PlasticState &now = state_at(U_slip);
                const double        s   = now.completed ? slip_at(U_slip) : 0.;
                slip.U                  = U_slip;
                slip.safety             = s;
                slip.state              = stage_words(now.least_stage);
                if (s >= S && s <= (1. + 1e-3) * S)
                  {
                    found_min = true;
                    break;
                  }
                if (s < S)
                  below = U_slip, s_below = s;
                else
                  above = U_slip, s_above = s;
                if (!std::isfinite(above) && U_slip >= U_limit)
                  break;
                double next = std::isfinite(above) ?
                                below
                                  + (t - s_below) * (above - below)
                                      / (s_above - s_below) :
                                std::nan("");
                if (!std::isfinite(above))
                  // Not yet bracketed: the pressure grows more slowly than
                  // U_w once the hub yields.
                  next = std::min(U_limit,
                                  smoothing
                                    + (below - smoothing)
                                        * std::max(1.02, 1.5 * t / s_below));
                else if (!(next > below && next < above))
                  next = 0.5 * (below + above);
                U_slip = next;
              }
            slip.solves = n_plastic_solves - before_slip;
            if (!found_min && !std::isfinite(above))
              {
                notes.push_back(
                  "no interference up to the model's limit carries the "
                  "loads with the hub yielding: safety against slip "
                  + figure_text(slip.safety, 4) + " at U = " + text(slip.U)
                  + " mm on the elastic-plastic load path");
                slip.U = infinite;
              }
            else if (!found_min)
              {
                notes.push_back("the slip safety on the elastic-plastic load "
                                "path did not reach "
                                + figure_text(S, 4)
                                + " to 0.1 % within the steps; U_min is the "
                                  "first interference above it");
                slip.U      = above;
                slip.safety = s_above;
              }
            if (slip.U > least.U)
              least = slip;
          }
      }

    // The elastic rows of an end the load path moved belong to the
    // elastic end: left out (the rows on the load path hold).
    checks.erase(std::remove_if(checks.begin(),
                                checks.end(),
                                [&](const Check &c) {
                                  return c.U
                                         != (c.end == "U_min" ? least.U :
                                                                largest.U);
                                }),
                 checks.end());

    // Each end on the load path.
    for (const auto &[name, U_end] :
         {std::make_pair(std::string("U_min"), least.U),
          std::make_pair(std::string("U_max"), largest.U)})
      if (std::isfinite(U_end) && U_end > smoothing && U_end <= U_limit)
        {
          const PlasticState &state = state_at(U_end);
          plastic_checks.push_back(
            {name, U_end, state, slip_safety_of(state.least_normal_force)});
          if (!state.completed)
            notes.push_back("the load path at " + name
                            + " was not completed: " + state.failure);
        }
  }
} // namespace coaxfit
