#include <coaxfit/fe/displacement_postprocessor.h>

namespace coaxfit
{
  AssembledDisplacement::AssembledDisplacement(const std::string &name,
                                               const double       oversize,
                                               const double       offset)
    : DataPostprocessorVector<2>(name, update_values | update_quadrature_points)
    , oversize(oversize)
    , offset(offset)
  {}



  void
  AssembledDisplacement::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
      {
        computed_quantities[q][0] = inputs.solution_values[q][0]
                                    + oversize * inputs.evaluation_points[q][0]
                                    + offset;
        computed_quantities[q][1] = inputs.solution_values[q][1];
      }
  }
} // namespace coaxfit
