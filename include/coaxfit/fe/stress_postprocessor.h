#ifndef coaxfit_stress_postprocessor_h
#define coaxfit_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <coaxfit/parameters/parameters.h>

namespace coaxfit
{
  /**
   * Computes the axisymmetric stresses sigma_rr, sigma_zz, sigma_tt (hoop),
   * sigma_rz and the von Mises stress (MPa) from the displacement (u_r, u_z)
   * for DataOut, under the names ParaView users expect.
   *
   * With @p volumetric_component, the field has a third component: the
   * volumetric stress lambda tr(e), interpolated from its values at the
   * reduced quadrature points (selective reduced integration). The stresses
   * then take their volumetric part from it instead of from the strain at
   * the point, whose spurious modes the reduced rule does not see (at
   * nu = 0.4999 they showed as stresses of +-5e4 MPa with FE_Q(1)).
   *
   * A body under a thermal eigenstrain alpha dT = @p thermal_strain is
   * stressed only by the mechanical strain e - alpha dT I.
   */
  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    explicit StressPostprocessor(const Material &material,
                                 bool            volumetric_component = false,
                                 double          thermal_strain       = 0.);

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
    const bool     volumetric_component;
    const double   thermal_strain;
  };
} // namespace coaxfit

#endif
