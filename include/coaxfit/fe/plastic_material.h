#ifndef coaxfit_plastic_material_h
#define coaxfit_plastic_material_h

#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/parameters/parameters.h>

#include <array>

namespace coaxfit
{
  /**
   * The state a quadrature point of an elastic-plastic body carries from
   * one converged increment to the next: its plastic strain (components
   * rr, zz, tt and the tensor shear rz) and its equivalent plastic strain
   * (the hardening variable, int sqrt(2/3 de_p : de_p)).
   */
  struct PlasticState
  {
    Axisymmetric::Vector4 plastic_strain            = {{0., 0., 0., 0.}};
    double                equivalent_plastic_strain = 0.;
  };

  /**
   * Small-strain von Mises plasticity with linear isotropic hardening at one
   * point of an axisymmetric body: the radial return from the elastic trial
   * stress and its consistent (algorithmic) tangent, as step-42 and Simo and
   * Hughes (Computational Inelasticity, 1998, box 3.2) write them.
   *
   * With the trial deviator s of the elastic predictor and
   * f = |s| - sqrt(2/3) (sigma_y + H a), a plastic step (f > 0) gives
   * dl = f / (2 mu + 2 H / 3), the return sigma = sigma_trial - 2 mu dl n
   * (n = s / |s|), a += sqrt(2/3) dl and the tangent
   * C = K 1 (x) 1 + 2 mu theta P_dev - 2 mu theta_bar n (x) n with
   * theta = 1 - 2 mu dl / |s| and theta_bar = 1 / (1 + H / (3 mu)) -
   * (1 - theta).
   *
   * Strains come in as Axisymmetric::strain() gives them (e_rr, e_zz, e_tt
   * and the engineering shear g_rz), stresses go out as (sigma_rr,
   * sigma_zz, sigma_tt, sigma_rz), the tangent maps the one to the other.
   */
  class PlasticMaterial
  {
  public:
    /** From @p material (E, nu, Yield strength, Hardening modulus). */
    explicit PlasticMaterial(const Material &material);

    /** The stress, and whether the point yields, for one strain. */
    struct Response
    {
      Axisymmetric::Vector4                stress;
      std::array<Axisymmetric::Vector4, 4> tangent; ///< d stress / d strain
      PlasticState                         state;   ///< the updated state
      bool                                 plastic = false;
    };

    /**
     * The response to the total strain @p strain from the state @p old of
     * the last converged increment (the path within an increment is
     * radial: the return does not depend on the iterates before).
     */
    Response
    respond(const Axisymmetric::Vector4 &strain, const PlasticState &old) const;

    /** The linear elastic response (a body without plasticity). */
    Response
    respond_elastic(const Axisymmetric::Vector4 &strain) const;

    /** The yield stress at the equivalent plastic strain @p a. */
    double
    yield_stress(const double a) const
    {
      return yield_strength + hardening * a;
    }

  private:
    /** respond(), or without a yield surface unless @p may_yield. */
    Response
    respond_to(const Axisymmetric::Vector4 &strain,
               const PlasticState          &old,
               bool                         may_yield) const;

    const double bulk;
    const double mu;
    const double yield_strength;
    const double hardening;
  };
} // namespace coaxfit

#endif
