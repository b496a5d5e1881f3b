#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/fe/stress_postprocessor.h>

namespace coaxfit
{
  StressPostprocessor::StressPostprocessor(const Material &material,
                                           const bool      volumetric_component,
                                           const double    thermal_strain)
    : material(material)
    , volumetric_component(volumetric_component)
    , thermal_strain(thermal_strain)
  {}



  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    // Without lambda (nu = 0, same mu) when the volumetric part is given.
    const Material shear_only
      = volumetric_component ? material.without_lambda() : material;
    for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
      {
        Axisymmetric::Vector4 sigma = Axisymmetric::stress(
          shear_only,
          Axisymmetric::mechanical(
            Axisymmetric::strain(inputs.solution_values[q][0],
                                 inputs.solution_gradients[q][0],
                                 inputs.solution_gradients[q][1],
                                 inputs.evaluation_points[q][0]),
            thermal_strain));
        if (volumetric_component)
          for (unsigned int c = 0; c < 3; ++c)
            sigma[c] += inputs.solution_values[q][2];
        for (unsigned int c = 0; c < 4; ++c)
          computed_quantities[q][c] = sigma[c];
        computed_quantities[q][4] = Axisymmetric::von_mises(sigma);
      }
  }



  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"sigma_rr_MPa",
            "sigma_zz_MPa",
            "sigma_tt_MPa",
            "sigma_rz_MPa",
            "von_Mises_MPa"};
  }



  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }
} // namespace coaxfit
