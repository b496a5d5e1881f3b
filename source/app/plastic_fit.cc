#include <coaxfit/app/plastic_fit.h>
#include <coaxfit/base/blas_threads.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/design/compound_cylinders.h>
#include <coaxfit/io/result_writers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace coaxfit
{
  PlasticFit::PlasticFit(const Parameters &parameters,
                         std::ostream     &out,
                         const bool        verbose)
    : parameters(parameters)
    , out(out)
    , verbose(verbose)
    , scene(parameters)
  {}



  void
  PlasticFit::check_scope() const
  {
    const std::string why
      = "Material/Shaft or Material/Hub has Plasticity = von Mises: "
        "elastic-plastic fits are computed for two plain cylinders in "
        "this version; ";
    if (parameters.sections)
      throw InputError("parameter Geometry/Shaft section or Hub section: " + why
                       + "give the plain cylinders (empty sections)");
    (void)scene;
    if (parameters.mesh.reduced_volumetric_integration())
      throw InputError("parameter Mesh/Volumetric integration = reduced: " + why
                       + "elastic-plastic bodies are integrated with the "
                         "full Gauss rule, allowed is full");
    if (parameters.design.mode == DesignMode::select)
      throw InputError("parameter Design/Mode = select: " + why
                       + "the fit selection stays elastic, allowed is "
                         "Design/Mode = check");
    if (parameters.fit.fit_case == FitCase::all)
      throw InputError("parameter Fit/Case = all: " + why
                       + "allowed are min, mean and max");
    if (parameters.mesh.degree < 1)
      throw InputError("parameter Mesh/Degree: at least 1");
  }



  void
  PlasticFit::setup_system()
  {
    const auto start = std::chrono::steady_clock::now();
    // The bodies' systems are small and solved one after the other: BLAS
    // threads inside UMFPACK only wait for each other.
    set_blas_threads(1);
    for (Body &body : scene.bodies)
      body.discretization->setup_system();
    for (Body &body : scene.bodies)
      body.discretization->assemble_system();
    scene.connect_joint();
    if (scene.has_transfer())
      throw InputError("parameter Mesh/Joint nodes = own: elastic-plastic "
                       "fits need matching joint nodes, allowed is "
                       "Mesh/Joint nodes = shared");
    for (const Body &body : scene.bodies)
      {
        bodies.push_back(std::make_unique<PlasticBody>(*body.discretization,
                                                       parameters.load_path));
        bodies.back()->setup_system();
      }
    PlasticCoupling::Settings settings;
    settings.monolithic = parameters.solver.method == SolverMethod::monolithic;
    // The staggered process gives the force to a body that stays elastic:
    // a force beyond a yielding body's limit load has no answer.
    settings.neumann_on_hub
      = parameters.shaft.plastic && !parameters.hub.plastic;
    if (!settings.monolithic && parameters.shaft.plastic
        && parameters.hub.plastic)
      {
        settings.monolithic = true;
        method_note = "both bodies may yield: the staggered process needs "
                      "one that stays elastic for its Neumann step, so the "
                      "monolithic solver is used";
      }
    settings.unilateral  = parameters.contact.unilateral;
    settings.tolerance   = parameters.coupling.tolerance;
    settings.max_steps   = parameters.coupling.max_steps;
    settings.iqn_columns = parameters.coupling.iqn_columns;
    settings.iqn_filter  = parameters.coupling.iqn_filter;
    coupling
      = std::make_unique<PlasticCoupling>(*bodies[0], *bodies[1], settings);
    time_setup
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  }



  Vector<double>
  PlasticFit::interference(const double fraction) const
  {
    const unsigned int n = scene.bodies[1].discretization->n_interface_points();
    Vector<double>     d(n);
    d = fraction * scene.joint().radial_interference;
    return d;
  }



  double
  PlasticFit::mean_pressure() const
  {
    // The normal force over the joint's area: sum F_i = int p r dz.
    const BodyDiscretization &hub    = *scene.bodies[1].discretization;
    const auto               &z      = hub.interface_z();
    const double              length = z.back() - z.front();
    const double              radius = hub.interface_points()[0][0];
    double                    sum    = 0.;
    for (unsigned int i = 0; i < coupling->force().size(); ++i)
      sum += coupling->force()[i];
    return sum / (radius * length);
  }



  double
  PlasticFit::elastic_limit_fraction()
  {
    const unsigned int steps_before = total_steps;
    const double       ratio
      = elastic_yield_ratio(0., "the elastic solve of the fit");
    elastic_steps    = total_steps - steps_before;
    elastic_fraction = ratio > 0. ? 1. / ratio : 1e300;
    if (elastic_fraction < 1.)
      {
        // Linear up to the first yield: the state there is the elastic one
        // scaled (with unilateral contact too, as long as its contact
        // points stay: scaling keeps the signs of forces and gaps).
        for (auto &body : bodies)
          body->scale_committed(elastic_fraction);
        coupling->scale_committed(elastic_fraction);
        reached = elastic_fraction;
      }
    else
      reached = 1.;
    return elastic_fraction;
  }



  double
  PlasticFit::elastic_yield_ratio(const double       load_factor,
                                  const std::string &what)
  {
    for (auto &body : bodies)
      {
        body->set_elastic_only(true);
        body->set_load_factor(load_factor);
      }
    const IncrementOutcome outcome = coupling->solve(interference(1.), nullptr);
    for (auto &body : bodies)
      {
        body->set_elastic_only(false);
        body->set_load_factor(0.);
      }
    total_steps += outcome.steps;
    body_solves += outcome.body_solves;
    if (!outcome.converged)
      throw SolverError(what + " did not converge: " + outcome.failure);
    for (auto &body : bodies)
      body->commit();
    coupling->commit();
    double ratio = 0.;
    for (const auto &body : bodies)
      ratio = std::max(ratio, body->max_yield_ratio());
    return ratio;
  }



  double
  PlasticFit::operation_yield_ratio()
  {
    // The elastic state at the full interference with the loads of
    // operation: along the straight path from the state of assembly to it
    // the von Mises stress (convex in the stresses) is largest at an end.
    return elastic_yield_ratio(1., "the elastic solve of the fit in operation");
  }



  bool
  PlasticFit::follow(StageResult &stage,
                     const double fraction_start,
                     const double load_start,
                     double       t)
  {
    using Stage          = LoadPathParameters::Stage;
    const double U       = 2. * scene.joint().radial_interference;
    const double nominal = (1. - t) / parameters.load_path.increments;
    const auto   at      = [&](const double s, double &fraction, double &load) {
      fraction = fraction_start + s * (stage.fraction - fraction_start);
      load     = load_start + s * (stage.load_factor - load_start);
    };
    double step = nominal;
    // Joining from the elastic limit: the scaled elastic state lies on the
    // path, so the first increment is extrapolated from it; a later stage
    // starts from the state the one before left.
    double            last_step = stage.kind == Stage::joining ? t : 0.;
    unsigned int      halvings  = 0;
    const std::string name      = to_string(stage.kind);
    // The smallest increment tried: Load path/Max bisections halvings of
    // the nominal one. A bound on the size, not on the halvings in a row:
    // near a limit load the halved increments converge, the doubled ones
    // after them fail, and the path would creep towards the limit forever.
    const double smallest
      = nominal
        * std::ldexp(1.,
                     -static_cast<int>(parameters.load_path.max_bisections));
    if (stage.kind == Stage::joining && t >= 1.)
      // Joining stayed elastic: the elastic solve is its one increment.
      increments.push_back({0, 1., 0., elastic_steps, 1, 0, mean_pressure()});
    while (t < 1.)
      {
        // The last increment ends at the stage's end exactly (sums of
        // fractions fall short of 1 by round-off).
        const double next = t + step > 1. - 1e-9 * nominal ? 1. : t + step;
        const double size = next - t;
        double       fraction, load;
        at(next, fraction, load);
        const double ratio = last_step > 0. ? size / last_step : 0.;
        for (auto &body : bodies)
          {
            body->set_load_factor(load);
            body->extrapolate(ratio);
          }
        coupling->extrapolate(ratio);
        // The end of a disassembly: the shaft withdrawn, the parts apart.
        coupling->set_separated(stage.kind == Stage::disassembly && next == 1.);
        const IncrementOutcome outcome
          = coupling->solve(interference(fraction), nullptr);
        total_steps += outcome.steps;
        body_solves += outcome.body_solves;
        if (!outcome.converged)
          {
            for (auto &body : bodies)
              body->revert();
            coupling->revert();
            ++total_halvings;
            ++halvings;
            if (size / 2. < smallest * (1. - 1e-9))
              {
                double f0, l0;
                at(t, f0, l0);
                std::ostringstream text;
                text << std::setprecision(9) << "the " << name
                     << " increment from ";
                if (stage.kind == Stage::joining
                    || stage.kind == Stage::disassembly)
                  text << f0 * U << " to " << fraction * U
                       << " mm of the interference U";
                else
                  text << "load factor " << l0 << " to " << load
                       << " of the loads of operation";
                text << std::setprecision(3) << " (increment "
                     << increments.size() + 1 << " of the load path, "
                     << size / nominal << " x the stage's nominal "
                     << "increment, the smallest Load path/Max bisections = "
                     << parameters.load_path.max_bisections
                     << " allows) failed: " << outcome.failure;
                // A body plastic through its wall carries no more load.
                for (unsigned int b = 0; b < 2; ++b)
                  if (body_figures(b).fully_plastic)
                    text << "; the " << scene.bodies[b].discretization->name()
                         << " is plastic through its wall: the load may pass "
                            "the limit load it can carry";
                failure = text.str();
                return false;
              }
            step = size / 2.;
            continue;
          }
        for (auto &body : bodies)
          body->commit();
        coupling->commit();
        t         = next;
        last_step = size;
        if (stage.kind == Stage::joining)
          reached = t;
        increments.push_back({static_cast<unsigned int>(stages.size()),
                              fraction,
                              load,
                              outcome.steps,
                              outcome.max_body_iterations,
                              halvings,
                              mean_pressure()});
        if (verbose)
          out << "  " << std::setw(11) << std::left << name << std::right
              << " increment " << std::setw(3) << increments.size() << ": U "
              << std::fixed << std::setprecision(5) << fraction * U
              << " mm, load factor " << std::setprecision(3) << load << ", "
              << outcome.steps
              << " steps, Newton <= " << outcome.max_body_iterations
              << ", mean p " << std::setprecision(2)
              << increments.back().mean_pressure << " MPa" << std::defaultfloat
              << '\n';
        // After a halved increment the next ones grow back to the nominal
        // size, never beyond: the load path is the same whichever method
        // solves it (the staggered and monolithic answers then agree to
        // the coupling tolerance, not to the path's own error).
        step     = std::min(nominal, 2. * size);
        halvings = 0;
      }
    return true;
  }



  bool
  PlasticFit::solve()
  {
    using Stage         = LoadPathParameters::Stage;
    const auto start    = std::chrono::steady_clock::now();
    double     fraction = 0., load = 0.;
    completed = true;
    for (const Stage kind : stage_list)
      {
        StageResult stage;
        stage.kind = kind;
        // A disassembly takes the interference away (a clearance has none
        // to take: the parts are only pulled apart).
        stage.fraction    = kind == Stage::disassembly
                             && scene.joint().radial_interference > 0. ?
                              0. :
                              1.;
        stage.load_factor = kind == Stage::operation ? 1. :
                            kind == Stage::unloading ? 0. :
                                                       load;
        const double t    = kind == Stage::joining ? reached : 0.;
        stage.completed   = follow(stage, fraction, load, t);
        capture(stage);
        stages.push_back(std::move(stage));
        if (!stages.back().completed)
          {
            completed = false;
            break;
          }
        fraction = stages.back().fraction;
        load     = stages.back().load_factor;
      }
    time_solve
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    return completed;
  }



  PlasticFit::BodyFigures
  PlasticFit::body_figures(const unsigned int b) const
  {
    const PlasticBody                       &body   = *bodies[b];
    const BodyDiscretization                &disc   = body.discretization();
    const auto                              &state  = body.committed_states();
    const auto                              &point  = body.quadrature_points();
    const std::vector<Axisymmetric::Vector4> stress = body.committed_stresses();
    BodyFigures                              f;
    f.name          = disc.name();
    f.plastic_model = disc.material().plastic;
    f.r_min         = 1e300;
    // Layers of quadrature points at the same z (the meshes of plain
    // cylinders are structured): a layer that yields all through is a
    // section plastic through its whole wall.
    struct LayerPoint
    {
      double r;
      bool   plastic;
      double yield_ratio; ///< von Mises over the yield stress
      bool
      operator<(const LayerPoint &other) const
      {
        return r < other.r;
      }
    };
    const PlasticMaterial                     material(disc.material());
    std::map<double, std::vector<LayerPoint>> layers;
    for (unsigned int i = 0; i < state.size(); ++i)
      {
        const bool plastic = state[i].equivalent_plastic_strain > 0.;
        f.max_von_mises
          = std::max(f.max_von_mises, Axisymmetric::von_mises(stress[i]));
        f.max_equivalent_plastic_strain
          = std::max(f.max_equivalent_plastic_strain,
                     state[i].equivalent_plastic_strain);
        if (plastic)
          {
            f.yields = true;
            f.r_min  = std::min(f.r_min, point[i][0]);
            f.r_max  = std::max(f.r_max, point[i][0]);
            f.z_max  = std::max(f.z_max, point[i][1]);
          }
        layers[std::round(point[i][1] * 1e9) / 1e9].push_back(
          {point[i][0],
           plastic,
           f.plastic_model ?
             Axisymmetric::von_mises(stress[i])
               / material.yield_stress(state[i].equivalent_plastic_strain) :
             0.});
      }
    if (!f.yields)
      f.r_min = f.r_max = 0.;
    for (auto &[z, layer] : layers)
      {
        bool all = true;
        for (const auto &p : layer)
          all = all && p.plastic;
        f.fully_plastic = f.fully_plastic || all;
      }
    // The plastic zone at the mid-plane (the layer of smallest z), from the
    // joint into the wall: its border where the yield ratio of the elastic
    // points, extrapolated linearly from the first two of them, reaches 1
    // (kept between the last plastic point and the first elastic one).
    auto &mid = layers.begin()->second;
    std::sort(mid.begin(), mid.end());
    const bool   outer = b == 1; // the hub yields from its bore outwards
    const double joint = outer ?
                           scene.bodies[1].discretization->geometry().r_inner :
                           scene.bodies[0].discretization->geometry().r_outer;
    const double far   = outer ?
                           scene.bodies[1].discretization->geometry().r_outer :
                           scene.bodies[0].discretization->geometry().r_inner;
    if (!outer)
      std::reverse(mid.begin(), mid.end());
    std::size_t k = 0;
    while (k < mid.size() && mid[k].plastic)
      ++k;
    double border = k == 0 ? joint : far;
    // A zone that does not touch the joint (a shaft yielding about its
    // axis): its border towards the joint.
    if (k == 0)
      for (std::size_t i = mid.size(); i-- > 0;)
        if (mid[i].plastic)
          {
            border = mid[i].r;
            break;
          }
    if (k > 0 && k < mid.size())
      {
        const LayerPoint &a = mid[k], &c = mid[k - 1];
        border = 0.5 * (a.r + c.r);
        if (k + 1 < mid.size() && mid[k + 1].yield_ratio < a.yield_ratio)
          {
            const LayerPoint &n = mid[k + 1];
            const double      r = a.r
                             - (1. - a.yield_ratio) * (n.r - a.r)
                                 / (a.yield_ratio - n.yield_ratio);
            border = std::clamp(r, std::min(a.r, c.r), std::max(a.r, c.r));
          }
      }
    f.plastic_diameter_mid = 2. * border;
    // The share of the wall's points at the mid-plane that yield.
    std::size_t plastic_points = 0;
    for (const LayerPoint &p : mid)
      plastic_points += p.plastic ? 1 : 0;
    f.utilisation = k > 0 ? (border - joint) / (far - joint) :
                            static_cast<double>(plastic_points) / mid.size();
    return f;
  }



  void
  PlasticFit::capture(StageResult &stage) const
  {
    const BodyDiscretization &shaft = *scene.bodies[0].discretization;
    const BodyDiscretization &hub   = *scene.bodies[1].discretization;
    const Vector<double>     &F     = coupling->force();
    const auto               &z     = hub.interface_z();
    // The state reached (a stage that failed: its last converged one).
    stage.load_factor = bodies[0]->committed_load_factor();
    if (!increments.empty() && increments.back().stage == stages.size())
      stage.fraction = increments.back().fraction;
    else if (!stage.completed)
      stage.fraction = stages.empty() ? reached : stages.back().fraction;
    stage.pressure.reinit(F.size());
    for (unsigned int i = 0; i < F.size(); ++i)
      stage.pressure[i] = F[i] / hub.interface_weights()[i];
    const Vector<double> &p = stage.pressure;
    stage.p_mid             = p[0];
    stage.p_mean            = mean_pressure();
    stage.p_min             = *std::min_element(p.begin(), p.end());
    stage.p_max             = p[0];
    stage.z_of_max          = z[0];
    for (unsigned int i = 0; i < F.size(); ++i)
      if (p[i] > stage.p_max)
        stage.p_max = p[i], stage.z_of_max = z[i];
    stage.separated_points = 0;
    for (const bool a : coupling->active())
      stage.separated_points += a ? 0 : 1;
    stage.figures.clear();
    for (unsigned int b = 0; b < 2; ++b)
      {
        stage.figures.push_back(body_figures(b));
        // The plastic zone never shrinks (a point that yielded keeps its
        // plastic strain); its border between the last plastic and the
        // first elastic point is placed by the yield ratios, which only
        // mean it while the zone grows: a stage that unloads keeps the
        // border of the stage before.
        BodyFigures &now = stage.figures.back();
        if (!stages.empty())
          {
            const BodyFigures &before = stages.back().figures[b];
            if (before.yields && before.utilisation > now.utilisation)
              {
                now.plastic_diameter_mid = before.plastic_diameter_mid;
                now.utilisation          = before.utilisation;
              }
          }
      }
    // Torque capacity: friction on the normal force pi D_F l_F p_mean.
    const double DF       = 2. * parameters.geometry.R1;
    const double length   = 2. * (z.back() - z.front());
    stage.normal_force    = stage.p_mean * M_PI * DF * length;
    stage.torque_capacity = parameters.design.friction_coefficient
                            * stage.normal_force * DF / 2. / 1000.;
    // With K_A and the required axial force, as the elastic code (0
    // without a required load).
    const double safety = slip_safety(stage);
    stage.slip_safety   = std::isnan(safety) ? 0. : safety;

    const Vector<double> u1
      = shaft.interface_radial_values(bodies[0]->solution());
    const Vector<double> u2
      = hub.interface_radial_values(bodies[1]->solution());
    stage.shaft_diameter_change = 2. * u1[0];
    stage.hub_bore_change       = 2. * u2[0];
    std::ostringstream csv;
    csv << "z_mm,pressure_MPa,u_r_shaft_mm,u_r_hub_mm,gap_mm,status\n"
        << std::setprecision(12);
    for (unsigned int i = 0; i < p.size(); ++i)
      csv << z[i] << ',' << p[i] << ',' << u1[i] << ',' << u2[i] << ','
          << coupling->gap()[i] << ','
          << (coupling->active()[i] ? "contact" : "separated") << '\n';
    stage.contact_csv = csv.str();
    if (parameters.output.write_vtu)
      for (unsigned int b = 0; b < 2; ++b)
        {
          check_values_for_output(bodies[b]->solution(),
                                  scene.bodies[b].discretization->name() + " ("
                                    + to_string(stage.kind) + ")");
          std::ostringstream vtu;
          // After disassembly the shaft is drawn at its own size, apart.
          const double oversize
            = stage.kind == LoadPathParameters::Stage::disassembly ?
                0. :
                scene.oversize(b);
          bodies[b]->output_results(vtu, b, oversize);
          stage.vtu[b] = vtu.str();
        }
  }



  const PlasticFit::StageResult &
  PlasticFit::least_torque_stage() const
  {
    const StageResult *least = &stages.front();
    for (const StageResult &stage : stages)
      if (stage.kind != LoadPathParameters::Stage::disassembly
          && stage.torque_capacity < least->torque_capacity)
        least = &stage;
    return *least;
  }



  void
  PlasticFit::postprocess()
  {
    const StageResult        &joined = stages.front();
    const GeometryParameters &g      = parameters.geometry;
    const double              DF = 2. * g.R1, DaA = 2. * g.R2;
    if (parameters.hub.plastic)
      {
        din_estimate = elastic_plastic_hub_pressure(
          parameters.hub.yield_strength,
          DF,
          DaA,
          std::max(DF, std::min(DaA, joined.figures[1].plastic_diameter_mid)));
        din_limit = elastic_plastic_hub_pressure(parameters.hub.yield_strength,
                                                 DF,
                                                 DaA,
                                                 DaA);
      }
    // The plane-stress radial model of the same rings (the thin-disc
    // state DIN 7190's elastic formulas assume too).
    RadialPlasticFit model({g.R0, g.R1, parameters.shaft},
                           {g.R1, g.R2, parameters.hub},
                           RadialPlasticFit::State::plane_stress,
                           400);
    try
      {
        // A clearance has no pressure to model.
        radial_valid = g.d > 0.;
        if (radial_valid)
          radial = model.solve(g.d, 100);
      }
    catch (const SolverError &)
      {
        // A side estimate: its failure (a wall of a few hundredths of a
        // millimetre) is reported as missing, never as the run's.
        radial_valid = false;
      }
    // The elastic plane-stress pressure (Lame) for comparison.
    elastic_lame
      = CompoundCylinders(
          {{2. * g.R0, 2. * g.R1, parameters.shaft.E, parameters.shaft.nu},
           {2. * g.R1, 2. * g.R2, parameters.hub.E, parameters.hub.nu}},
          {2. * g.d},
          0.,
          0.,
          false)
          .pressure(0);
  }
} // namespace coaxfit
