#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/design/stack_fit_selection.h>
#include <coaxfit/parameters/operation_entries.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace coaxfit
{
  namespace
  {
    constexpr double infinite = std::numeric_limits<double>::infinity();

    /** The squared von Mises stress of @p s. */
    double
    von_mises_squared(const double *s)
    {
      const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
      return 0.5 * (a * a + b * b + c * c) + 3. * s[3] * s[3];
    }

    /** A number as the tables print it. */
    std::string
    figure(const double x, const int digits = 4)
    {
      if (!std::isfinite(x))
        return x > 0 ? "none" : "-";
      if (std::abs(x) < 1e-12)
        return "0";
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }
  } // namespace



  StackFitSelection::StackFitSelection(const StackParameters &parameters,
                                       const Evaluate        &evaluate,
                                       const Reach           &reach)
    : reach_at(reach)
    , parameters(parameters)
  {
    const unsigned int J = parameters.n_joints();
    // The selected joints, and those that keep an ISO fit: their bands
    // are part of every combination's box (one candidate each).
    for (unsigned int k = 0; k < J; ++k)
      if (parameters.selected[k] || !parameters.fits[k].iso_fit.empty())
        {
          selected.push_back(k);
          kept.push_back(!parameters.selected[k]);
        }

    // The joints given a clearance that must keep Design/Running
    // clearance (a bushing's running fit).
    if (parameters.running_clearance > 0.)
      for (unsigned int k = 0; k < J; ++k)
        if (!parameters.selected[k]
            && parameters.fits[k].nominal_interference < 0.)
          running.push_back(k);

    // The linear model holds while the contact zones stay: U_0 is sought
    // where every selected joint touches and every running fit is open in
    // every state (each selected joint at 1, 1/2, 2, 1/4, 4, 1/8 times
    // 0.001 D beyond its smoothing loss), and each slope is taken by a
    // step of a quarter of that, down or, where the zones change, up.
    const auto regime = [&](const std::vector<StackStateFigures> &st) {
      std::vector<bool> r;
      for (const StackStateFigures &state : st)
        {
          for (const unsigned int k : selected)
            r.push_back(state.p_mean[k] > 0.);
          for (const unsigned int k : running)
            for (const double g : state.gap[k])
              r.push_back(g > 0.);
        }
      return r;
    };
    U0.resize(J);
    std::vector<StackStateFigures> base;
    bool                           found_regime = false;
    for (const double beyond : {1., 0.5, 2., 0.25, 4., 0.125})
      {
        for (unsigned int k = 0; k < J; ++k)
          U0[k] = parameters.selected[k] ?
                    parameters.fits[k].smoothing_loss
                      + beyond * 1e-3 * parameters.joint_diameter(k) :
                    parameters.fits[k].nominal_interference;
        base = evaluate(U0);
        n_solves += base.size();
        const std::vector<bool> r = regime(base);
        if (std::find(r.begin(), r.end(), false) == r.end())
          {
            found_regime = true;
            break;
          }
      }
    if (!found_regime)
      {
        for (unsigned int k = 0; k < J; ++k)
          U0[k] = parameters.selected[k] ?
                    parameters.fits[k].smoothing_loss
                      + 1e-3 * parameters.joint_diameter(k) :
                    parameters.fits[k].nominal_interference;
        base = evaluate(U0);
        n_solves += base.size();
        notes.push_back(
          "no interferences from 1/8 to 4 times 0.001 D keep every selected "
          "joint in contact and every running fit open in every state: the "
          "linear model is taken where a contact zone differs, so it may "
          "leave out fits that would do; the FE check judges the chosen "
          "ones");
      }
    n_states = base.size();
    for (const StackStateFigures &s : base)
      state_names.push_back(s.state);
    for (const auto &points : base[0].stress)
      n_points.push_back(points.size());
    for (const unsigned int k : running)
      n_gap_points.push_back(base[0].gap[k].size());
    for (unsigned int k = 0; k < base[0].relief_gap.size(); ++k)
      if (!base[0].relief_gap[k].empty())
        {
          relieved.push_back(k);
          n_relief_points.push_back(base[0].relief_gap[k].size());
        }
    growth0                             = base[0].joining_growth;
    q0                                  = flatten(base);
    const std::vector<bool> base_regime = regime(base);
    for (const unsigned int k : selected)
      {
        std::vector<double> U = U0;
        double h = -0.25 * (U0[k] - parameters.fits[k].smoothing_loss);
        U[k] += h;
        std::vector<StackStateFigures> step = evaluate(U);
        n_solves += n_states;
        if (regime(step) != base_regime)
          {
            h    = -h;
            U[k] = U0[k] + h;
            step = evaluate(U);
            n_solves += n_states;
          }
        const std::vector<double> q = flatten(step);
        slope.emplace_back(q.size());
        for (unsigned int i = 0; i < q.size(); ++i)
          slope.back()[i] = (q[i] - q0[i]) / h;
        growth_slope.push_back(step[0].joining_growth);
        for (unsigned int j = 0; j < J; ++j)
          for (unsigned int i = 0; i < growth0[j].size(); ++i)
            growth_slope.back()[j][i]
              = (growth_slope.back()[j][i] - growth0[j][i]) / h;
      }

    // The criteria, in the order judge() takes them.
    for (unsigned int s = 0; s < n_states; ++s)
      {
        for (unsigned int k = 0; k < J; ++k)
          if (parameters.slip_judged(k))
            criterion_names.push_back("slip of " + parameters.joint_name(k)
                                      + " " + state_names[s]);
        for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
          {
            const Material &m = parameters.materials[b];
            if (m.kind == MaterialKind::brittle ? m.tensile_strength > 0. :
                                                  m.yield_strength > 0.)
              criterion_names.push_back(
                (m.kind == MaterialKind::brittle ? "fracture of " : "yield of ")
                + parameters.bodies[b] + " " + state_names[s]);
          }
        for (const unsigned int k : running)
          criterion_names.push_back("running clearance of "
                                    + parameters.joint_name(k) + " "
                                    + state_names[s]);
        for (const unsigned int k : relieved)
          criterion_names.push_back("a relief of " + parameters.joint_name(k)
                                    + " open " + state_names[s]);
      }
    criterion_names.push_back("no requirement (no Design/Required torque or "
                              "axial force, "
                              "no strength of a body)");
    criterion_names.push_back("contact lost");

    // Each selected joint's candidates, best ranked first.
    const auto rank = [](const IsoFit &a, const IsoFit &b) {
      if (preference_key(a) != preference_key(b))
        return preference_key(a) < preference_key(b);
      return a.name < b.name;
    };
    double n_all = 1.;
    for (unsigned int j = 0; j < selected.size(); ++j)
      {
        const unsigned int  k = selected[j];
        std::vector<IsoFit> fits;
        if (kept[j])
          fits.push_back(
            iso_fit(parameters.fits[k].iso_fit, parameters.joint_diameter(k)));
        else
          {
            unsigned int closing = 0;
            for (const IsoFit &f : candidate_fits(parameters.joint_diameter(k)))
              if (1e-3 * f.min_interference()
                  > parameters.fits[k].smoothing_loss)
                {
                  if (parameters.sections
                      && parameters.sections->closing_relief(
                        k, 1e-3 * f.max_interference()))
                    ++closing;
                  else
                    fits.push_back(f);
                }
            if (closing > 0)
              notes.push_back(
                std::to_string(closing) + " fits of " + parameters.joint_name(k)
                + " were left out: their largest interference would close "
                  "a relief of its sections, which is not modelled");
          }
        std::stable_sort(fits.begin(), fits.end(), rank);
        n_fits.push_back(fits.size());
        candidates.push_back(fits);
      }
    for (const std::vector<IsoFit> &fits : candidates)
      n_all *= std::max<double>(fits.size(), 1.);
    n_all_combinations = n_all;
    prune();
    n_all = 1.;
    for (const std::vector<IsoFit> &fits : candidates)
      n_all *= std::max<double>(fits.size(), 1.);
    if (n_all > max_combinations())
      {
        const unsigned int keep = static_cast<unsigned int>(
          std::floor(std::pow(max_combinations(), 1. / selected.size())));
        for (std::vector<IsoFit> &fits : candidates)
          if (fits.size() > keep)
            fits.resize(keep);
        notes.push_back(
          figure(n_all, 6) + " combinations are more than "
          + std::to_string(max_combinations())
          + ": each joint's candidates were cut to its first "
          + std::to_string(keep)
          + " by rank (preferred fits first, then the widest bands)");
      }
    for (unsigned int j = 0; j < selected.size() && conflict.empty(); ++j)
      if (candidates[j].empty())
        conflict = "the joint " + parameters.joint_name(selected[j])
                   + " has no ISO 286 interference fit at D "
                   + figure(parameters.joint_diameter(selected[j]), 6)
                   + " mm whose smallest interference exceeds its smoothing "
                     "loss "
                   + figure(parameters.fits[selected[j]].smoothing_loss)
                   + " mm";
    if (!conflict.empty())
      return;
    search();
    if (ranked.empty())
      return;
    check(evaluate);
    if (found())
      compute_bands();
  }



  double
  StackFitSelection::joining_growth(const unsigned int         k,
                                    const std::vector<double> &U) const
  {
    if (growth0[k].empty())
      return 0.;
    std::vector<double> g = growth0[k];
    for (unsigned int j = 0; j < selected.size(); ++j)
      {
        const double dU = U[selected[j]] - U0[selected[j]];
        for (unsigned int i = 0; i < g.size(); ++i)
          g[i] += growth_slope[j][k][i] * dU;
      }
    return std::max(0., *std::max_element(g.begin(), g.end()));
  }



  double
  StackFitSelection::reach_of(const unsigned int         k,
                              const std::vector<double> &U) const
  {
    const auto [first, last] = parameters.joined_parts(k);
    std::pair<unsigned int, std::vector<double>> key{k, {}};
    for (unsigned int j = first; j < last; ++j)
      if (j != k)
        key.second.push_back(U[j]);
    const auto known = reached.find(key);
    if (known != reached.end())
      return known->second;
    return reached[key] = reach_at(k, U);
  }



  std::vector<unsigned int>
  StackFitSelection::unjoinable_joints(const std::vector<double> &U) const
  {
    // Every joint with an interference: the selected ones and those that
    // keep theirs (the parts joined before change what they need).
    std::vector<unsigned int> which;
    for (unsigned int k = 0; k < U.size(); ++k)
      if ((U[k] > 0.
           || std::find(selected.begin(), selected.end(), k) != selected.end())
          && !joinable(k, U))
        which.push_back(k);
    return which;
  }



  bool
  StackFitSelection::joinable(const unsigned int         k,
                              const std::vector<double> &U) const
  {
    // Joined by pressure oil or pressed in (Design/Joining): no heat.
    if (parameters.joining != JoiningMethod::shrink
        && parameters.joining != JoiningMethod::shrink_degreased)
      return true;
    const double D     = parameters.joint_diameter(k);
    const double reach = reach_of(k, U);
    return !std::isfinite(reach)
           || U[k] + joining_growth(k, U)
                  + joining_clearance_entry(
                    parameters.operation.joining_clearance_text, D)
                <= reach;
  }



  void
  StackFitSelection::prune()
  {
    const unsigned int J = parameters.n_joints(), J_s = selected.size();
    const std::size_t  per_state = q0.size() / n_states;
    // The affine criteria g(U) >= t: each joint's torque capacity, each
    // chosen joint's mean pressure (> 0).
    std::vector<std::pair<std::size_t, double>> affine;
    std::vector<std::string>                    names;
    for (unsigned int s = 0; s < n_states; ++s)
      {
        for (unsigned int k = 0; k < J; ++k)
          if (parameters.slip_judged(k))
            {
              affine.emplace_back(s * per_state + k,
                                  required_torque(k) * parameters.slip_safety);
              names.push_back("slip of " + parameters.joint_name(k) + " "
                              + state_names[s]);
            }
        for (unsigned int i = 0; i < J_s; ++i)
          if (!kept[i])
            {
              affine.emplace_back(s * per_state + J + selected[i], 0.);
              names.push_back("contact of " + parameters.joint_name(selected[i])
                              + " " + state_names[s]);
            }
        // A running fit's gap at each point, after the bodies' stresses.
        std::size_t at = s * per_state + 2 * J;
        for (const unsigned int n : n_points)
          at += 4 * n;
        for (unsigned int r = 0; r < running.size(); ++r)
          for (unsigned int i = 0; i < n_gap_points[r]; ++i, ++at)
            {
              affine.emplace_back(at, parameters.running_clearance);
              names.push_back("running clearance of "
                              + parameters.joint_name(running[r]) + " "
                              + state_names[s]);
            }
        // Each relief open at each of its planes.
        for (unsigned int r = 0; r < relieved.size(); ++r)
          for (unsigned int i = 0; i < n_relief_points[r]; ++i, ++at)
            {
              affine.emplace_back(at, 0.);
              names.push_back("a relief of "
                              + parameters.joint_name(relieved[r]) + " open "
                              + state_names[s]);
            }
      }
    // Each ductile body's pairs of normal stresses at its points.
    std::vector<std::pair<std::size_t, std::size_t>> yield_pairs;
    std::vector<double>                              yield_limit;
    std::vector<std::string>                         yield_names;
    for (unsigned int s = 0; s < n_states; ++s)
      {
        std::size_t at = s * per_state + 2 * J;
        for (unsigned int b = 0; b < n_points.size(); ++b)
          {
            const Material &m = parameters.materials[b];
            const bool      judged
              = m.kind != MaterialKind::brittle && m.yield_strength > 0.;
            for (unsigned int p = 0; p < n_points[b]; ++p, at += 4)
              if (judged)
                for (const auto &pair : {std::make_pair(0u, 1u),
                                         std::make_pair(1u, 2u),
                                         std::make_pair(2u, 0u)})
                  {
                    yield_pairs.emplace_back(at + pair.first, at + pair.second);
                    yield_limit.push_back(m.yield_strength
                                          / parameters.yield_safety);
                    yield_names.push_back("yield of " + parameters.bodies[b]
                                          + " " + state_names[s]);
                  }
          }
      }
    bool removed = true;
    while (removed)
      {
        removed = false;
        // The envelope of each joint's candidates.
        std::vector<double> low(J_s, infinite), high(J_s, -infinite);
        for (unsigned int i = 0; i < J_s; ++i)
          for (const IsoFit &f : candidates[i])
            {
              low[i]  = std::min(low[i], 1e-3 * f.min_interference());
              high[i] = std::max(high[i], 1e-3 * f.max_interference());
            }
        for (unsigned int j = 0; j < J_s; ++j)
          {
            if (kept[j])
              continue;
            std::vector<IsoFit> left;
            for (const IsoFit &f : candidates[j])
              {
                bool possible = true;
                for (unsigned int c = 0; c < affine.size() && possible; ++c)
                  {
                    const std::size_t at = affine[c].first;
                    // The most the others can give anywhere in theirs.
                    double best = q0[at];
                    for (unsigned int i = 0; i < J_s; ++i)
                      if (i != j)
                        best
                          += std::max(slope[i][at] * (low[i] - U0[selected[i]]),
                                      slope[i][at]
                                        * (high[i] - U0[selected[i]]));
                    for (const double U : {1e-3 * f.min_interference(),
                                           1e-3 * f.max_interference()})
                      if (!(best + slope[j][at] * (U - U0[selected[j]])
                            > affine[c].second))
                        {
                          possible = false;
                          if (candidates[j].size() == 1 || left.empty())
                            last_pruned = names[c];
                        }
                  }
                // Yield: vm >= |s_a - s_b| / sqrt(2) for any two normal
                // stresses, whose difference is affine: its least
                // magnitude over the others' envelope is exact.
                for (unsigned int y = 0; y < yield_pairs.size() && possible;
                     ++y)
                  {
                    const std::size_t at_a = yield_pairs[y].first,
                                      at_b = yield_pairs[y].second;
                    double lo = q0[at_a] - q0[at_b], hi = lo;
                    for (unsigned int i = 0; i < J_s; ++i)
                      if (i != j)
                        {
                          const double g = slope[i][at_a] - slope[i][at_b];
                          const double x = g * (low[i] - U0[selected[i]]),
                                       z = g * (high[i] - U0[selected[i]]);
                          lo += std::min(x, z);
                          hi += std::max(x, z);
                        }
                    for (const double U : {1e-3 * f.min_interference(),
                                           1e-3 * f.max_interference()})
                      {
                        const double own = (slope[j][at_a] - slope[j][at_b])
                                           * (U - U0[selected[j]]);
                        const double least = lo + own > 0. ? lo + own :
                                             hi + own < 0. ? -(hi + own) :
                                                             0.;
                        if (least / std::sqrt(2.) > yield_limit[y])
                          {
                            possible = false;
                            if (left.empty())
                              last_pruned = yield_names[y];
                          }
                      }
                  }
                if (possible)
                  left.push_back(f);
              }
            if (left.size() < candidates[j].size())
              {
                removed = true;
                n_pruned += candidates[j].size() - left.size();
                candidates[j] = left;
                if (left.empty())
                  {
                    conflict = "no fit of " + parameters.joint_name(selected[j])
                               + " meets " + last_pruned
                               + " at both ends of its band, whichever fits "
                                 "the other joints have; lower Design/Required "
                                 "torque or the safeties, or change the "
                                 "materials or sections";
                    return;
                  }
              }
          }
      }
  }



  std::vector<double>
  StackFitSelection::flatten(const std::vector<StackStateFigures> &states) const
  {
    std::vector<double> q;
    for (const StackStateFigures &s : states)
      {
        q.insert(q.end(), s.torque.begin(), s.torque.end());
        q.insert(q.end(), s.p_mean.begin(), s.p_mean.end());
        for (unsigned int b = 0; b < s.stress.size(); ++b)
          {
            if (b >= n_points.size() || s.stress[b].size() != n_points[b])
              throw std::logic_error("the stress points of a stack's body "
                                     "changed between two states");
            for (const Axisymmetric::Vector4 &sigma : s.stress[b])
              q.insert(q.end(), sigma.begin(), sigma.end());
          }
        for (const unsigned int k : running)
          q.insert(q.end(), s.gap[k].begin(), s.gap[k].end());
        for (const unsigned int k : relieved)
          q.insert(q.end(), s.relief_gap[k].begin(), s.relief_gap[k].end());
      }
    if (!q0.empty() && q.size() != q0.size())
      throw std::logic_error("the figures of a stack's states changed size");
    return q;
  }



  StackFitSelection::Judgement
  StackFitSelection::judge(const std::vector<double> &q) const
  {
    const unsigned int J = parameters.n_joints();
    Judgement          j;
    j.margin             = infinite;
    j.which              = criterion_names.size() - 2;
    unsigned int c       = 0;
    std::size_t  o       = 0;
    const auto   improve = [&](const double ratio) {
      if (ratio < j.margin)
        {
          j.margin = ratio;
          j.which  = c;
        }
      ++c;
    };
    for (unsigned int s = 0; s < n_states; ++s)
      {
        for (unsigned int k = 0; k < J; ++k)
          if (parameters.slip_judged(k))
            improve(q[o + k] / (required_torque(k) * parameters.slip_safety));
        for (unsigned int i = 0; i < selected.size(); ++i)
          if (!kept[i])
            j.touches = j.touches && q[o + J + selected[i]] > 0.;
        std::size_t at = o + 2 * J;
        for (unsigned int b = 0; b < n_points.size(); ++b)
          {
            const Material &m       = parameters.materials[b];
            const bool      brittle = m.kind == MaterialKind::brittle;
            double          largest = 0.;
            for (unsigned int p = 0; p < n_points[b]; ++p, at += 4)
              largest
                = std::max(largest,
                           brittle ? q[at + 2] : von_mises_squared(&q[at]));
            if (brittle && m.tensile_strength > 0.)
              improve(largest > 0. ?
                        m.tensile_strength
                          / (largest * parameters.fracture_safety) :
                        infinite);
            else if (!brittle && m.yield_strength > 0.)
              improve(largest > 0. ?
                        m.yield_strength
                          / (std::sqrt(largest) * parameters.yield_safety) :
                        infinite);
          }
        // A running fit's least gap over its points.
        for (unsigned int r = 0; r < running.size(); ++r)
          {
            double least = infinite;
            for (unsigned int i = 0; i < n_gap_points[r]; ++i, ++at)
              least = std::min(least, q[at]);
            improve(least / parameters.running_clearance);
          }
        // A relief's least gap over its clearance, as a ratio 1 + g / c
        // (below 1: closed).
        for (unsigned int r = 0; r < relieved.size(); ++r)
          {
            double least = infinite;
            for (unsigned int i = 0; i < n_relief_points[r]; ++i, ++at)
              least = std::min(least, q[at]);
            improve(1. + least);
          }
        o = at;
      }
    if (!j.touches)
      j.which = criterion_names.size() - 1;
    return j;
  }



  std::vector<double>
  StackFitSelection::linear(const std::vector<double> &U) const
  {
    std::vector<double> q = q0;
    for (unsigned int j = 0; j < selected.size(); ++j)
      {
        const double dU = U[selected[j]] - U0[selected[j]];
        for (unsigned int i = 0; i < q.size(); ++i)
          q[i] += slope[j][i] * dU;
      }
    return q;
  }



  std::vector<double>
  StackFitSelection::corner_of(const Combination &c,
                               const unsigned int corner) const
  {
    std::vector<double> U = U0;
    for (unsigned int j = 0; j < selected.size(); ++j)
      {
        const IsoFit &f = candidates[j][c.choice[j]];
        U[selected[j]]
          = 1e-3
            * ((corner >> j) & 1 ? f.max_interference() : f.min_interference());
      }
    return U;
  }



  void
  StackFitSelection::search()
  {
    const unsigned int J_s = selected.size(), corners = 1u << J_s;
    const std::size_t  Q = q0.size();
    // Each candidate's share of the figures at either end of its band.
    std::vector<std::vector<std::array<std::vector<double>, 2>>> share(J_s);
    for (unsigned int j = 0; j < J_s; ++j)
      for (const IsoFit &f : candidates[j])
        {
          std::array<std::vector<double>, 2> ends;
          for (unsigned int e = 0; e < 2; ++e)
            {
              const double dU
                = 1e-3 * (e ? f.max_interference() : f.min_interference())
                  - U0[selected[j]];
              ends[e].resize(Q);
              for (std::size_t i = 0; i < Q; ++i)
                ends[e][i] = slope[j][i] * dU;
            }
          share[j].push_back(ends);
        }

    std::vector<Combination> feasible;
    Combination              closest; // the largest margin, feasible or not
    closest.margin = -infinite;
    std::vector<unsigned int> choice(J_s, 0);
    std::vector<double>       q(Q);
    while (true)
      {
        ++n_combinations;
        double       margin  = infinite;
        unsigned int which   = criterion_names.size() - 2;
        bool         touches = true;
        for (unsigned int corner = 0;
             corner < corners && touches
             && (margin >= 1. || margin > closest.margin
                 || closest.choice.empty());
             ++corner)
          {
            q = q0;
            for (unsigned int j = 0; j < J_s; ++j)
              {
                const std::vector<double> &d
                  = share[j][choice[j]][(corner >> j) & 1];
                for (std::size_t i = 0; i < Q; ++i)
                  q[i] += d[i];
              }
            const Judgement at = judge(q);
            touches            = touches && at.touches;
            if (at.margin < margin)
              {
                margin = at.margin;
                which  = at.which;
              }
          }
        Combination c;
        c.choice = choice;
        c.margin = touches ? margin : -infinite;
        // A feasible one is joined at its largest interferences (the
        // growth by the parts joined before rises with them).
        const bool is_feasible = touches && margin >= 1.;
        if (is_feasible)
          c.unjoinable = unjoinable_joints(corner_of(c, corners - 1)).size();
        for (unsigned int j = 0; j < J_s; ++j)
          {
            const IsoFit &f = candidates[j][choice[j]];
            c.not_preferred += is_preferred_fit(f.name) ? 0 : 1;
            c.width += f.max_interference() - f.min_interference();
          }
        c.governed_by
          = criterion_names[touches ? which : criterion_names.size() - 1];
        if (is_feasible)
          feasible.push_back(c);
        if (c.margin > closest.margin || closest.choice.empty())
          closest = c;
        // The next combination (an odometer over the joints).
        unsigned int j = 0;
        while (j < J_s && ++choice[j] == candidates[j].size())
          choice[j++] = 0;
        if (j == J_s)
          break;
      }
    n_feasible        = feasible.size();
    const auto better = [](const Combination &a, const Combination &b) {
      if (a.unjoinable != b.unjoinable)
        return a.unjoinable < b.unjoinable;
      if (a.not_preferred != b.not_preferred)
        return a.not_preferred < b.not_preferred;
      if (a.width != b.width)
        return a.width > b.width;
      if (a.margin != b.margin)
        return a.margin > b.margin;
      return a.choice < b.choice;
    };
    const std::size_t keep = std::min<std::size_t>(10, feasible.size());
    std::partial_sort(feasible.begin(),
                      feasible.begin() + keep,
                      feasible.end(),
                      better);
    ranked.assign(feasible.begin(), feasible.begin() + keep);
    if (ranked.empty())
      {
        std::vector<std::string> names;
        for (unsigned int j = 0; j < J_s; ++j)
          names.push_back(candidates[j][closest.choice[j]].name);
        conflict = "no combination of the " + std::to_string(n_combinations)
                   + " judged (of " + figure(n_all_combinations, 12)
                   + ") carries the requirement in every state at every "
                     "corner of its bands: "
                   + (std::isfinite(closest.margin) ?
                        "the closest, " + part_text(names) + ", reaches "
                          + figure(closest.margin, 4) + " of it ("
                          + closest.governed_by + ")" :
                        "in each, a selected joint loses its contact")
                   + "; lower Design/Required torque, Required axial force, "
                     "Application factor or the safeties, or change "
                     "the materials or sections";
      }
  }



  void
  StackFitSelection::check(const Evaluate &evaluate)
  {
    const unsigned int J_s = selected.size(), corners = 1u << J_s;
    for (unsigned int r = 0; r < ranked.size() && r < max_checks(); ++r)
      {
        const Combination        &c = ranked[r];
        std::vector<unsigned int> to_check;
        if (J_s <= 4)
          for (unsigned int corner = 0; corner < corners; ++corner)
            to_check.push_back(corner);
        else
          {
            // Each criterion's worst corner on the linear model.
            std::vector<double>       worst(criterion_names.size(), infinite);
            std::vector<unsigned int> at(criterion_names.size(), 0);
            for (unsigned int corner = 0; corner < corners; ++corner)
              {
                const Judgement jd = judge(linear(corner_of(c, corner)));
                if (jd.margin < worst[jd.which])
                  {
                    worst[jd.which] = jd.margin;
                    at[jd.which]    = corner;
                  }
              }
            for (unsigned int i = 0; i < worst.size(); ++i)
              if (std::isfinite(worst[i])
                  && std::find(to_check.begin(), to_check.end(), at[i])
                       == to_check.end())
                to_check.push_back(at[i]);
          }
        std::vector<Check> done;
        bool               passed = true;
        for (const unsigned int corner : to_check)
          {
            Check check;
            check.U                = corner_of(c, corner);
            const Judgement fe     = judge(flatten(evaluate(check.U)));
            const Judgement linear = judge(this->linear(check.U));
            n_solves += n_states;
            check.margin      = fe.margin;
            check.linear      = linear.margin;
            check.governed_by = criterion_names[fe.which];
            check.touches     = fe.touches;
            passed            = passed && fe.touches && fe.margin >= 1.;
            done.push_back(check);
          }
        std::vector<std::string> names;
        for (unsigned int j = 0; j < J_s; ++j)
          names.push_back(candidates[j][c.choice[j]].name);
        if (passed)
          {
            for (unsigned int j = 0; j < J_s; ++j)
              chosen.push_back(candidates[j][c.choice[j]]);
            const std::vector<double> U_max = corner_of(c, corners - 1);
            for (const unsigned int k : unjoinable_joints(U_max))
              {
                const auto at = std::find(selected.begin(), selected.end(), k);
                notes.push_back(
                  "no combination could be joined by temperature: "
                  + parameters.joint_name(k) + " with "
                  + (at != selected.end() ? chosen[at - selected.begin()].name :
                                            "U " + figure(U_max[k]) + " mm")
                  + " opens only with more heat and cold than its parts "
                    "take (the outer heated to its bodies' lowest "
                    "temperature limit and the inner cooled to -196 C at "
                    "once; the parts joined before add "
                  + figure(1e3 * joining_growth(k, U_max))
                  + " um to its largest interference): it must be pressed "
                    "in");
              }
            checks = done;
            return;
          }
        for (const Check &check : done)
          if (!check.touches || check.margin < 1.)
            {
              notes.push_back(
                part_text(names) + " failed its FE check at U = " +
                [&]() {
                  std::string text;
                  for (const unsigned int k : selected)
                    text += (text.empty() ? "" : ", ") + figure(check.U[k], 5);
                  return text;
                }()
                + " mm: "
                + (check.touches ?
                     check.governed_by + " reaches " + figure(check.margin, 5)
                       + " of its requirement (linear model "
                       + figure(check.linear, 5) + ")" :
                     std::string("a joint loses its contact"))
                + "; the next combination is checked");
              break;
            }
      }
    conflict
      = "none of the "
        + std::to_string(std::min<std::size_t>(ranked.size(), max_checks()))
        + " best combinations passed its FE check (the contact zones "
          "change within their bands)";
  }



  void
  StackFitSelection::compute_bands()
  {
    const unsigned int  J = parameters.n_joints(), J_s = selected.size();
    std::vector<double> U_chosen = U0;
    Combination         c;
    for (unsigned int j = 0; j < J_s; ++j)
      {
        for (unsigned int i = 0; i < candidates[j].size(); ++i)
          if (candidates[j][i].name == chosen[j].name)
            c.choice.push_back(i);
      }
    for (unsigned int j = 0; j < J_s; ++j)
      {
        Band band;
        band.low         = -infinite;
        band.high        = infinite;
        const auto lower = [&](const double U, const std::string &by) {
          if (U > band.low)
            {
              band.low    = U;
              band.low_by = by;
            }
        };
        const auto upper = [&](const double U, const std::string &by) {
          if (U < band.high)
            {
              band.high    = U;
              band.high_by = by;
            }
        };
        // c0 + c1 U >= 0.
        const auto linear_bound
          = [&](const double c0, const double c1, const std::string &by) {
              if (c1 > 0.)
                lower(-c0 / c1, by);
              else if (c1 < 0.)
                upper(-c0 / c1, by);
              else if (c0 < 0.)
                upper(-infinite, by);
            };
        const unsigned int others = 1u << (J_s - 1);
        for (unsigned int o = 0; o < others; ++o)
          {
            // The others at a corner; joint j's figures a + b U.
            const unsigned int corner
              = (o & ((1u << j) - 1)) | ((o >> j) << (j + 1));
            std::vector<double> U           = corner_of(c, corner);
            U[selected[j]]                  = 0.;
            const std::vector<double>  a    = linear(U);
            const std::vector<double> &b    = slope[j];
            std::size_t                at   = 0;
            unsigned int               name = 0;
            for (unsigned int s = 0; s < n_states; ++s)
              {
                const std::size_t o_s = at;
                for (unsigned int k = 0; k < J; ++k)
                  if (parameters.slip_judged(k))
                    {
                      const double need
                        = required_torque(k) * parameters.slip_safety;
                      linear_bound(a[o_s + k] - need,
                                   b[o_s + k],
                                   criterion_names[name++]);
                    }
                for (unsigned int i = 0; i < J_s; ++i)
                  if (!kept[i])
                    linear_bound(a[o_s + J + selected[i]],
                                 b[o_s + J + selected[i]],
                                 "contact of "
                                   + parameters.joint_name(selected[i]) + " "
                                   + state_names[s]);
                at = o_s + 2 * J;
                for (unsigned int body = 0; body < n_points.size(); ++body)
                  {
                    const Material &m       = parameters.materials[body];
                    const bool      brittle = m.kind == MaterialKind::brittle;
                    const bool      judged = brittle ? m.tensile_strength > 0. :
                                                       m.yield_strength > 0.;
                    for (unsigned int p = 0; p < n_points[body]; ++p, at += 4)
                      if (judged && brittle)
                        linear_bound(m.tensile_strength
                                         / parameters.fracture_safety
                                       - a[at + 2],
                                     -b[at + 2],
                                     criterion_names[name]);
                      else if (judged)
                        {
                          // vm^2(a + b U) = A U^2 + B U + C <= L^2.
                          const double L
                            = m.yield_strength / parameters.yield_safety;
                          double sum[4];
                          for (unsigned int i = 0; i < 4; ++i)
                            sum[i] = a[at + i] + b[at + i];
                          const double A  = von_mises_squared(&b[at]);
                          const double C0 = von_mises_squared(&a[at]);
                          const double B  = von_mises_squared(sum) - C0 - A;
                          const double C  = C0 - L * L;
                          if (A <= 1e-300)
                            linear_bound(-C, -B, criterion_names[name]);
                          else
                            {
                              const double d = B * B - 4. * A * C;
                              if (d < 0.)
                                upper(-infinite, criterion_names[name]);
                              else
                                {
                                  lower((-B - std::sqrt(d)) / (2. * A),
                                        criterion_names[name]);
                                  upper((-B + std::sqrt(d)) / (2. * A),
                                        criterion_names[name]);
                                }
                            }
                        }
                    name += judged ? 1 : 0;
                  }
                for (unsigned int r = 0; r < running.size(); ++r, ++name)
                  for (unsigned int i = 0; i < n_gap_points[r]; ++i, ++at)
                    linear_bound(a[at] - parameters.running_clearance,
                                 b[at],
                                 criterion_names[name]);
                for (unsigned int r = 0; r < relieved.size(); ++r, ++name)
                  for (unsigned int i = 0; i < n_relief_points[r]; ++i, ++at)
                    linear_bound(a[at], b[at], criterion_names[name]);
              }
          }
        bands.push_back(band);
      }
  }



  void
  StackFitSelection::print(std::ostream &out) const
  {
    out << "\n  fit selection (Design/Mode = select): ";
    for (unsigned int j = 0; j < selected.size(); ++j)
      out << (j ? ", " : "") << parameters.joint_name(selected[j])
          << (kept[j] ? " keeps its ISO fit" :
                        " from " + std::to_string(n_fits[j]) + " ISO 286 fits");
    out << "; " << figure(n_all_combinations, 12) << " combinations, "
        << n_combinations << " judged on the linear model";
    if (n_pruned > 0)
      out << " (" << n_pruned
          << " candidates left out that fail a criterion whatever fits the "
             "others have)";
    out << ": " << n_feasible << " carry the requirement; " << n_solves
        << " FE states solved\n";
    if (!found())
      out << "  no fits found: " << conflict << '\n';
    else
      {
        std::size_t width = 5;
        for (const unsigned int k : selected)
          width = std::max(width, parameters.joint_name(k).size());
        out << "  " << std::left << std::setw(width) << "joint" << std::right
            << "    D mm  fit       U mm (band)      allowed U mm, the others "
               "in their fits\n";
        for (unsigned int j = 0; j < selected.size(); ++j)
          {
            const IsoFit      &f = chosen[j];
            std::ostringstream band;
            band << std::fixed << std::setprecision(4)
                 << 1e-3 * f.min_interference() << " - "
                 << 1e-3 * f.max_interference();
            out << "  " << std::left << std::setw(width)
                << parameters.joint_name(selected[j]) << std::right
                << std::setw(8)
                << figure(parameters.joint_diameter(selected[j])) << "  "
                << std::left << std::setw(8) << f.name << "  " << std::setw(17)
                << band.str() << std::right << std::fixed
                << std::setprecision(4)
                << (std::isfinite(bands[j].low) ?
                      figure(bands[j].low, 4) + " (" + bands[j].low_by + ")" :
                      std::string("no limit"))
                << " - "
                << (std::isfinite(bands[j].high) ?
                      figure(bands[j].high, 4) + " (" + bands[j].high_by + ")" :
                      std::string("no limit"))
                << std::defaultfloat << '\n';
          }
        const Check *least = least_check();
        out << "  checked by FE at " << checks.size() << " corners of the "
            << "bands: least margin " << figure(least->margin, 5) << " ("
            << least->governed_by << "; 1 = the requirement)\n";
        for (unsigned int r = 1; r < ranked.size() && r < 4; ++r)
          {
            std::vector<std::string> names;
            for (unsigned int j = 0; j < selected.size(); ++j)
              names.push_back(candidates[j][ranked[r].choice[j]].name);
            out << "  also: " << part_text(names) << " (margin "
                << figure(ranked[r].margin, 4) << ")\n";
          }
      }
    for (const std::string &note : notes)
      out << "  note: " << note << '\n';
  }



  void
  StackFitSelection::print_markdown(std::ostream &out) const
  {
    out << "## Fit selection\n\n"
        << "Design/Mode = select: the ISO 286 fits of ";
    for (unsigned int j = 0; j < selected.size(); ++j)
      out << (j ? ", " : "") << parameters.joint_name(selected[j]) << " ("
          << n_fits[j] << " candidates)";
    out << " chosen together: " << figure(n_all_combinations, 12)
        << " combinations, " << n_combinations
        << " judged at every corner of their bands on the linear model ("
        << n_pruned
        << " candidates left out that fail a criterion whatever fits the "
           "others have; "
        << n_feasible << " carry the requirement), the first checked by FE, "
        << n_solves << " FE states solved in all.\n\n";
    if (!found())
      out << "**No fits found:** " << conflict << ".\n\n";
    else
      {
        out << "| joint | D mm | fit | U mm | allowed U mm (the others in "
               "their fits) | ended by |\n|---|---|---|---|---|---|\n";
        for (unsigned int j = 0; j < selected.size(); ++j)
          out << "| " << parameters.joint_name(selected[j]) << " | "
              << figure(parameters.joint_diameter(selected[j])) << " | "
              << chosen[j].name << " | "
              << figure(1e-3 * chosen[j].min_interference()) << " to "
              << figure(1e-3 * chosen[j].max_interference()) << " | "
              << (std::isfinite(bands[j].low) ? figure(bands[j].low) :
                                                "no limit")
              << " to " << figure(bands[j].high) << " | " << bands[j].low_by
              << "; " << (std::isfinite(bands[j].high) ? bands[j].high_by : "-")
              << " |\n";
        out << "\nThe FE check of the chosen fits (margin: the least ratio "
               "of a safety to its requirement):\n\n| U mm | margin FE | "
               "linear model | governed by |\n|---|---|---|---|\n";
        for (const Check &c : checks)
          {
            std::string U;
            for (const unsigned int k : selected)
              U += (U.empty() ? "" : ", ") + figure(c.U[k], 5);
            out << "| " << U << " | " << figure(c.margin, 6) << " | "
                << figure(c.linear, 6) << " | " << c.governed_by << " |\n";
          }
        out << '\n';
      }
    for (const std::string &note : notes)
      out << "- " << note << '\n';
    if (!notes.empty())
      out << '\n';
  }



  void
  StackFitSelection::write_csv(std::ostream &out) const
  {
    out << "rank";
    for (const unsigned int k : selected)
      out << ',' << parameters.joint_name(k);
    out << ",unjoinable,not_preferred,band_sum_um,margin,governed_by\n";
    for (unsigned int r = 0; r < ranked.size(); ++r)
      {
        out << r + 1;
        for (unsigned int j = 0; j < selected.size(); ++j)
          out << ',' << candidates[j][ranked[r].choice[j]].name;
        out << ',' << ranked[r].unjoinable << ',' << ranked[r].not_preferred
            << ',' << ranked[r].width << ',' << std::setprecision(8)
            << ranked[r].margin << ',' << ranked[r].governed_by << '\n';
      }
  }



  std::string
  StackFitSelection::json() const
  {
    const auto quoted = [](const std::string &s) {
      std::string q = "\"";
      for (const char c : s)
        q += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
      return q + "\"";
    };
    const auto number = [](const double x) {
      if (!std::isfinite(x))
        return std::string("null");
      std::ostringstream s;
      s << std::setprecision(10) << x;
      return s.str();
    };
    std::ostringstream s;
    s << "{\"found\": " << (found() ? "true" : "false")
      << ", \"conflict\": " << quoted(conflict)
      << ", \"combinations\": " << n_all_combinations
      << ", \"judged\": " << n_combinations
      << ", \"pruned_candidates\": " << n_pruned
      << ", \"feasible\": " << n_feasible
      << ", \"fe_states_solved\": " << n_solves << ", \"fits\": [";
    for (unsigned int j = 0; j < chosen.size(); ++j)
      s << (j ? ", " : "") << quoted(chosen[j].name);
    // The criterion of the least FE margin at the corners.
    const Check *least = least_check();
    s << "], \"governing\": " << quoted(least ? least->governed_by : "")
      << ", \"least_margin\": " << number(least ? least->margin : infinite)
      << ", \"joints\": [";
    for (unsigned int j = 0; j < selected.size(); ++j)
      {
        s << (j ? ", " : "")
          << "{\"name\": " << quoted(parameters.joint_name(selected[j]))
          << ", \"diameter\": "
          << number(parameters.joint_diameter(selected[j]))
          << ", \"candidates\": " << n_fits[j]
          << ", \"kept\": " << (kept[j] ? "true" : "false");
        if (found())
          s << ", \"fit\": " << quoted(chosen[j].name)
            << ", \"U_min\": " << number(1e-3 * chosen[j].min_interference())
            << ", \"U_max\": " << number(1e-3 * chosen[j].max_interference())
            << ", \"allowed_min\": " << number(bands[j].low)
            << ", \"allowed_min_by\": " << quoted(bands[j].low_by)
            << ", \"allowed_max\": " << number(bands[j].high)
            << ", \"allowed_max_by\": "
            << quoted(std::isfinite(bands[j].high) ? bands[j].high_by : "");
        s << "}";
      }
    s << "], \"checks\": [";
    for (unsigned int i = 0; i < checks.size(); ++i)
      {
        s << (i ? ", " : "") << "{\"U\": [";
        for (unsigned int j = 0; j < selected.size(); ++j)
          s << (j ? ", " : "") << number(checks[i].U[selected[j]]);
        s << "], \"margin\": " << number(checks[i].margin)
          << ", \"linear_margin\": " << number(checks[i].linear)
          << ", \"governed_by\": " << quoted(checks[i].governed_by) << "}";
      }
    s << "], \"alternatives\": [";
    for (unsigned int r = 0; r < ranked.size(); ++r)
      {
        s << (r ? ", " : "") << "{\"fits\": [";
        for (unsigned int j = 0; j < selected.size(); ++j)
          s << (j ? ", " : "")
            << quoted(candidates[j][ranked[r].choice[j]].name);
        s << "], \"margin\": " << number(ranked[r].margin) << "}";
      }
    s << "], \"notes\": [";
    for (unsigned int i = 0; i < notes.size(); ++i)
      s << (i ? ", " : "") << quoted(notes[i]);
    s << "]}";
    return s.str();
  }
} // namespace coaxfit
