#ifndef coaxfit_coarse_interface_model_h
#define coaxfit_coarse_interface_model_h

#include <deal.II/lac/vector.h>

#include <coaxfit/contact_interface.h>
#include <coaxfit/interface_operator.h>

#include <array>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The staggered process's fixed-point map on the same case meshed one
   * refinement coarser, as a model of the fine map for the quasi-Newton
   * accelerator (multi-level acceleration: the coarse model's Jacobian is
   * the prior of the fine inverse Jacobian, IQN-IMVJ).
   *
   * The map x -> G(x) of one Neumann and one Dirichlet step is affine in
   * the nodal contact force x; its linear part E (zero interference) is
   * formed on the coarse interface column by column with the coarse
   * bodies' condensed operators, for the fine run's alpha and contact
   * flags. The quasi-Newton step x + (I - E)^-1 r for the residual
   * r = G(x) - x is exact for a linear map; written as
   * G(x) + J r it needs J = (I - E)^-1 - I. The prior is that J on the
   * coarse interface between the transfers of the forces: restriction
   * F_c = P^T F (the work-conjugate of the interpolation P of u_r,
   * piecewise linear in z between coarse points) and prolongation of the
   * coarse pressures F_c / w_c by P to fine forces w P (F_c / w_c). What
   * the coarse mesh cannot represent (short waves, the corner) gets no
   * prior: there the step is the plain one and the least-squares model of
   * the history acts.
   */
  class CoarseInterfaceModel
  {
  public:
    /**
     * The coarse bodies' operators @p coarse_shaft and @p coarse_hub
     * (condensed: a column costs O(n^2)) on the interface @p coarse; the
     * fine run's interface @p fine. Every coarse point must lie on a fine
     * point (a refinement of the coarse mesh). Only the points' positions
     * and weights are taken from the interfaces. @p short_wave_ratio is the
     * ratio shaft / hub of the compliances of short waves, for which both
     * bodies answer as half-spaces: E_hub (1 - nu_shaft^2) /
     * (E_shaft (1 - nu_hub^2)).
     */
    CoarseInterfaceModel(InterfaceOperator      &coarse_shaft,
                         InterfaceOperator      &coarse_hub,
                         const ContactInterface &coarse,
                         const ContactInterface &fine,
                         double                  short_wave_ratio);

    /**
     * The prior J (n x n row-major, n fine points) for the fine map with the
     * weight @p alpha at each fine point and the contact flags
     * @p contact of the fine points.
     */
    std::vector<double>
    inverse_jacobian_prior(const std::vector<double> &alpha,
                           const std::vector<bool>   &contact);

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
    const double         short_wave_ratio;
    /** The fine point at each coarse point. */
    std::vector<unsigned int> coarse_index;
    /**
     * Interpolation P: fine point i takes weight[i][0] of coarse point
     * left[i] and weight[i][1] of coarse point left[i] + 1.
     */
    std::vector<unsigned int>          left;
    std::vector<std::array<double, 2>> interpolation;
  };
} // namespace coaxfit

#endif
