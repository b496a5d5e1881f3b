#include <coaxfit/coupling/alpha_rule.h>
#include <coaxfit/coupling/block_model_update.h>

#include <algorithm>
#include <limits>

namespace coaxfit
{
  BlockModelUpdate::BlockModelUpdate(const CouplingParameters &parameters,
                                     const ContactInterface   &interface,
                                     UnilateralActiveSet      &active_set)
    : CouplingUpdate(interface, active_set)
    , rule_name(make_alpha_rule(parameters)->name())
    , model(interface.n_points(), parameters.iqn_columns, parameters.iqn_filter)
  {}



  std::string
  BlockModelUpdate::alpha_rule_name() const
  {
    return rule_name;
  }



  std::string
  BlockModelUpdate::accelerator_name() const
  {
    return "ibqn";
  }



  std::string
  BlockModelUpdate::description() const
  {
    return "Accelerator = ibqn";
  }



  std::string
  BlockModelUpdate::failure_advice() const
  {
    return "the models of the bodies' compliances could not recover; try "
           "Coupling/Alpha controller = iqn-ils, or solve this scene with "
           "Solver/Method = monolithic.";
  }



  bool
  BlockModelUpdate::loaded_start() const
  {
    return true;
  }



  void
  BlockModelUpdate::start(bool)
  {
    // The maps F -> u are linear (the displacements of loads of operation
    // are part of the interference): no force, no displacement, an exact
    // sample that makes the model independent of the scale of the first
    // one.
    model.clear_samples();
    const Vector<double> zero(interface.n_points());
    model.add_sample(InterfaceBlockModel::shaft, zero, zero);
    model.add_sample(InterfaceBlockModel::hub, zero, zero);
    if (coarse_model && !model.has_prior())
      {
        model.set_prior(InterfaceBlockModel::shaft,
                        coarse_model->compliance_prior(0));
        model.set_prior(InterfaceBlockModel::hub,
                        coarse_model->compliance_prior(1));
        ++n_priors;
      }
  }



  void
  BlockModelUpdate::sample_neumann(const InterfaceState &state)
  {
    // The model takes the solve as it is (the scaled first step may be a
    // zero force).
    add_samples(state, state.force, state.force);
  }



  NeumannOutcome
  BlockModelUpdate::after_neumann(InterfaceState &state,
                                  unsigned int,
                                  Vector<double> &next_force,
                                  bool           &verified)
  {
    // The flags that made this force are judged by the state below; the
    // model's prediction from it sets those of the next steps.
    const std::vector<bool> made_with = active_set.in_contact();
    state.displacement_mismatch
      = interface.relative_gap_residual(state.u1, state.u2, made_with);
    verified = predict(next_force);
    return {std::numeric_limits<double>::quiet_NaN(),
            static_cast<unsigned int>(
              std::count(made_with.begin(), made_with.end(), false))};
  }



  void
  BlockModelUpdate::dirichlet_data(const InterfaceState &,
                                   Vector<double> &u_inner,
                                   Vector<double> &u_outer)
  {
    // The model's common interface displacement on the contact points.
    u_inner = model_displacement;
    for (unsigned int i = 0; i < u_inner.size(); ++i)
      u_outer[i] = u_inner[i] + interface.interference(i);
  }



  double
  BlockModelUpdate::after_dirichlet(InterfaceState &state,
                                    bool,
                                    const Vector<double> &,
                                    const Vector<double> &,
                                    Vector<double> &f_inner,
                                    Vector<double> &f_outer,
                                    Vector<double> &next_force,
                                    bool           &verified)
  {
    state.traction_mismatch
      = relative_to_pressure(interface.max_pressure_difference(f_inner,
                                                               f_outer),
                             f_inner,
                             f_outer,
                             interface);
    state.force = f_inner;
    state.force.add(0.5, f_outer);
    state.force.add(-0.5, f_inner);
    add_samples(state, f_inner, f_outer);
    // Flags changed by this prediction were not those of the state.
    if (!predict(next_force))
      verified = false;
    return std::numeric_limits<double>::quiet_NaN();
  }



  void
  BlockModelUpdate::add_samples(const InterfaceState &state,
                                const Vector<double> &f_inner,
                                const Vector<double> &f_outer)
  {
    model.add_sample(InterfaceBlockModel::shaft, f_inner, state.u1);
    model.add_sample(InterfaceBlockModel::hub, f_outer, state.u2);
    if (!model.has_prior())
      {
        // No coarse model: Winkler compliances measured in this first step.
        const Vector<double> &w = interface.weights();
        model.set_winkler_prior(InterfaceBlockModel::shaft,
                                -winkler_compliance(state.u1, f_inner, w),
                                w);
        model.set_winkler_prior(InterfaceBlockModel::hub,
                                winkler_compliance(state.u2, f_outer, w),
                                w);
      }
  }



  bool
  BlockModelUpdate::predict(Vector<double> &next_force)
  {
    const unsigned int  n = interface.n_points();
    std::vector<double> d(n);
    for (unsigned int i = 0; i < n; ++i)
      d[i] = interface.interference(i);
    std::vector<bool> contact = active_set.in_contact();
    const bool        settled = model.predict(
      d, active_set.enabled(), contact, next_force, model_displacement);
    return active_set.set(contact) == false && settled;
  }
} // namespace coaxfit
