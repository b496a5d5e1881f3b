#ifndef coaxfit_coarse_interface_model_h
#define coaxfit_coarse_interface_model_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/solvers/interface_operator.h>

#include <array>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The interface compliance of one body for short waves of the pressure,
   * p = p0 cos(k z) -> u = c(k) p: a half-space, c = 2 (1 - nu^2) / (E k),
   * or where its wall behind S is thin, a cylindrical shell of thickness t
   * on radius R, c = 1 / (D k^4 + E t / R^2), D = E t^3 / (12 (1 - nu^2)),
   * whichever is the more compliant (a wall with a free back face answers
   * at least as much as a half-space).
   */
  struct ShortWaveCompliance
  {
    double E;
    double nu;
    double radius; ///< of S
    double wall;   ///< thickness behind S; 0: a solid shaft (half-space)

    /** c(k) for the wave number @p k (1/mm), in mm/MPa. */
    double
    operator()(double k) const;
  };

  /**
   * The same case meshed one refinement coarser, as a model of the fine
   * one (multi-level acceleration): for ibqn the bodies' compliances
   * (compliance_prior()), for iqn-ils the staggered process's fixed-point
   * map, whose Jacobian is the prior of the fine inverse Jacobian
   * (IQN-IMVJ, inverse_jacobian_prior()); and the transfers of the coarse
   * solution the fine run starts from.
   *
   * The map x -> G(x) of one Neumann and one Dirichlet step is affine in
   * the nodal contact force x; its linear part E (zero interference) is
   * formed on the coarse interface column by column with the coarse
   * bodies' condensed operators, for the fine run's alpha and contact
   * flags. The quasi-Newton step x + (I - E)^-1 r for the residual
   * r = G(x) - x is exact for a linear map; written as
   * G(x) + J r it needs J = (I - E)^-1 - I. The prior is that J on the
   * coarse interface between the transfers of the pressures p = F / w:
   * P interpolates coarse pressures with the elements' shape functions
   * (quadratic for FE_Q(2)), Q = (P^T W_f P)^-1 P^T W_f restricts fine ones
   * by weighted least squares. What the coarse mesh cannot represent
   * (short waves, the corner) gets the exact step for two half-spaces or
   * shells (ShortWaveCompliance), and the least-squares model of the
   * history acts there.
   */
  class CoarseInterfaceModel
  {
  public:
    /**
     * The coarse bodies' operators @p coarse_shaft and @p coarse_hub
     * (condensed: a column costs O(n^2)) on the interface @p coarse; the
     * fine run's interface @p fine. Every coarse point must lie on a fine
     * point (a refinement of the coarse mesh). Only the points' positions
     * and weights are taken from the interfaces. @p short_waves gives the
     * compliances of shaft and hub for waves the coarse mesh cannot
     * represent, taken at k = pi / (sqrt(2) h) (h: the spacing of the fine
     * points), the geometric middle of the band between the coarse and the
     * fine points' Nyquist wave numbers.
     * @p degree is that of the elements (the transfer of pressures is
     * their interpolation: quadratic for 2, linear otherwise).
     */
    CoarseInterfaceModel(InterfaceOperator                        &coarse_shaft,
                         InterfaceOperator                        &coarse_hub,
                         const ContactInterface                   &coarse,
                         const ContactInterface                   &fine,
                         const std::array<ShortWaveCompliance, 2> &short_waves,
                         unsigned int                              degree);

    /**
     * The prior J (n x n row-major, n fine points) for the fine map with the
     * weight @p alpha at each fine point and the contact flags
     * @p contact of the fine points.
     */
    std::vector<double>
    inverse_jacobian_prior(const std::vector<double> &alpha,
                           const std::vector<bool>   &contact);

    /**
     * A prior of the fine interface compliance of body @p body (0: shaft,
     * 1: hub; n x n row-major, u = C F in the fine nodal forces F) for the
     * interface block model (Coupling/Accelerator = ibqn): the coarse
     * body's answer to the coarse pressures of F (the weighted
     * least-squares restriction), interpolated to the fine points, plus a
     * half-space compliance for the short waves the coarse mesh cannot
     * represent. Costs one coarse Neumann solve per coarse point.
     */
    std::vector<double>
    compliance_prior(unsigned int body);

    /**
     * The fine nodal forces of the coarse nodal forces @p coarse_force:
     * the coarse pressures interpolated, times the fine weights.
     */
    Vector<double>
    prolongate(const Vector<double> &coarse_force) const;

    /**
     * Fine contact flags from the coarse ones @p coarse_contact: a fine
     * point is separated if the coarse points it is interpolated from are.
     */
    std::vector<bool>
    prolongate(const std::vector<bool> &coarse_contact) const;

    /** Whether every point of @p coarse is a point of @p fine. */
    static bool
    nested(const ContactInterface &coarse, const ContactInterface &fine);

    /** Number of coarse interface points. */
    unsigned int
    n_coarse_points() const
    {
      return coarse_index.size();
    }

  private:
    /**
     * The fine point at each point of @p coarse (both at least two
     * points); empty if some coarse point is not a point of @p fine.
     */
    static std::vector<unsigned int>
    fine_points_at(const ContactInterface &coarse,
                   const ContactInterface &fine);

    /**
     * Q W_f^-1 (coarse points x fine points): the weighted least-squares
     * restriction of fine nodal forces to coarse pressures.
     */
    LAPACKFullMatrix<double>
    force_restriction() const;

    /** Column j of E: the coarse map's answer to a unit force at j. */
    void
    map_column(unsigned int               j,
               const std::vector<double> &alpha,
               const std::vector<bool>   &contact,
               Vector<double>            &column);

    InterfaceOperator &coarse_shaft;
    InterfaceOperator &coarse_hub;
    /** Lumped weights of the coarse and the fine points. */
    const Vector<double> coarse_weights, fine_weights;
    /**
     * Short-wave compliances c(pi / (sqrt(2) h_i)) of shaft (0) and hub (1)
     * at each fine point (h_i: the mean distance to its neighbours), mm/MPa.
     */
    std::array<std::vector<double>, 2> short_wave;
    /** The fine point at each coarse point. */
    std::vector<unsigned int> coarse_index;
    /**
     * Interpolation P: fine point i takes weight[i][0] of coarse point
     * left[i] and weight[i][1] of coarse point left[i] + 1.
     */
    std::vector<unsigned int>          left;
    std::vector<std::array<double, 2>> interpolation;
    /**
     * The transfer P of pressures: row i lists (coarse point, weight) of
     * fine point i (the coarse elements' interpolation). The contact flags
     * use the linear interpolation above.
     */
    std::vector<std::vector<std::pair<unsigned int, double>>> transfer;
  };
} // namespace coaxfit

#endif
