#ifndef coaxfit_stress_postprocessor_h
#define coaxfit_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <coaxfit/parameters.h>

namespace coaxfit
{
  /**
   * Computes the axisymmetric stresses sigma_rr, sigma_zz, sigma_tt (hoop),
   * sigma_rz and the von Mises stress (MPa) from the displacement (u_r, u_z)
   * for DataOut, under the names ParaView users expect.
   */
  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    explicit StressPostprocessor(const Material &material);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Material material;
  };
} // namespace coaxfit

#endif
