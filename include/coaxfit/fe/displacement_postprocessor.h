#ifndef coaxfit_displacement_postprocessor_h
#define coaxfit_displacement_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The displacement that draws a body in its assembled place when ParaView
   * warps the mesh by it (Warp By Vector): u + oversize r e_r (mm).
   *
   * Both bodies are meshed at the joint radius R_F, but the shaft is made
   * larger than that by the radial interference d: its unassembled shape is
   * the mesh scaled radially by 1 + d / R_F. Its elastic displacement u is
   * measured from that shape, so warping the mesh by u alone draws a false
   * gap of d along the whole joint. Adding oversize r e_r with
   * oversize = d / R_F (0 for the hub) moves the shaft's surface to
   * R_F + d + u_1 = R_F + u_2 where the bodies touch: the warped bodies meet
   * at the joint and open only where they separate. The axis (r = 0) does
   * not move. A ring in the middle of a stack is drawn larger at its outer
   * joint only: oversize r + offset, zero at its bore (offset =
   * -oversize r_inner).
   */
  class AssembledDisplacement : public DataPostprocessorVector<2>
  {
  public:
    /**
     * @p name of the output vector, @p oversize = d / R_F (or 0), the
     * radial @p offset (mm) added everywhere.
     */
    AssembledDisplacement(const std::string &name,
                          double             oversize,
                          double             offset = 0.);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

  private:
    const double oversize;
    const double offset;
  };
} // namespace coaxfit

#endif
