#ifndef coaxfit_fit_design_h
#define coaxfit_fit_design_h

#include <deal.II/lac/vector.h>

#include <coaxfit/design/din7190.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/fe/body_stress.h>
#include <coaxfit/parameters/parameters.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The design figures of a finished run next to DIN 7190's: capacity
   * (torque, axial force, press-in force, safety against slip) from the
   * finite element contact force and from the Lame pressure, and strength
   * (stresses at DIN 7190's check points at the mid-plane, maxima along the
   * hub bore and the shaft surface at least Design/Edge distance away from
   * the singular end of the joint, safety against yield). Units: MPa, N,
   * N m, mm. A figure that cannot be given (no required load, no yield
   * strength) is NaN, written as null.
   *
   * The finite element normal force over the joint is 4 pi sum_i F_i (both
   * halves of the section, the full circumference; F_i are the nodal contact
   * forces per radian of the modelled half), the torque capacity mu R_F
   * times it, the axial capacity mu times it.
   */
  class FitDesign
  {
  public:
    static constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

    /**
     * tan, cos and sin of the half angle beta of a cone of taper C = 2
     * tan(beta) (@p taper; 0: a cylinder, {0, 1, 0}).
     */
    static std::array<double, 3>
    cone_half_angle(double taper);

    /**
     * Friction on a cone of taper C = 2 tan(beta) (@p taper) with the normal
     * force @p N (N) and the friction coefficient @p mu, the hub held along
     * the axis by friction alone (Coulomb: the friction force in the
     * cone's surface at most mu N; a nut holding the hub would leave more).
     * The cone pushes the hub off with N sin(beta), so friction along the
     * generatrix must already carry (N sin(beta) + F) / cos(beta) of an
     * axial pull F, and the circumferential force 2 M / D_F of a torque M
     * adds to it as a vector.
     *
     * The pull (N) the cone holds alone: N (mu cos(beta) - sin(beta)), 0
     * where that is negative (not self-locking).
     */
    static double
    cone_pull_off_capacity(double N, double mu, double taper);

    /**
     * The circumferential force (N) the cone of cone_pull_off_capacity()
     * holds alone: N sqrt(mu^2 - tan^2(beta)), 0 if not self-locking.
     */
    static double
    cone_circumferential_capacity(double N, double mu, double taper);

    /**
     * The safety against slip of the cone of cone_pull_off_capacity()
     * under the circumferential force @p circumferential and the axial
     * pull @p pull (N, both times K_A): the factor S on both at which the
     * friction reaches mu N, ((N sin + S pull) / cos)^2 + (S
     * circumferential)^2 = (mu N)^2; 0 if not self-locking, linear in N.
     * On a cylinder it is DIN 7190's mu N over the resultant of the two.
     */
    static double
    cone_slip_safety(double N,
                     double mu,
                     double taper,
                     double circumferential,
                     double pull);

    /** Stresses at one check point: FE at the mid-plane, and DIN 7190. */
    struct CheckPoint
    {
      std::string         name; ///< e.g. "hub bore"
      StressState         fe;
      Din7190::CheckPoint din;
    };

    /** The stress maximum along one surface away from the corner. */
    struct SurfaceMaximum
    {
      std::string name;
      /**
       * The largest von Mises stress at least the edge distance from the
       * end of the joint, and where (z, mm): near the end it follows the
       * singular corner field, and so the edge distance and the mesh.
       */
      double von_mises = 0., z = 0.;
      /**
       * The largest von Mises stress over the middle half of the joint
       * (|z| up to a quarter of the joint length), and where: away from
       * the ends, it converges under refinement.
       */
      double interior = 0., interior_z = 0.;
      double corner = 0.; ///< von Mises at the corner (singular)
      /** The corner value one refinement coarser (NaN: not computed). */
      double corner_coarser = std::numeric_limits<double>::quiet_NaN();
    };

    FitDesign(const Parameters         &parameters,
              const BodyDiscretization &shaft,
              const Vector<double>     &shaft_field,
              const BodyDiscretization &hub,
              const Vector<double>     &hub_field,
              const Vector<double>     &contact_force);

    /** Normal force over the whole joint (N), FE. */
    double normal_force;
    /**
     * Mean FE pressure over the nominal joint area pi D_F l_F (MPa), on a
     * cone over its surface pi D_F l_F / cos(beta).
     */
    double mean_pressure;
    /**
     * A taper fit's cone (half angle beta): cos and sin of beta (1 and 0 on
     * a cylinder). On a cone the capacities take the normal force N over
     * the cone's surface: torque mu N R_F, axial force against pulling off
     * N (mu cos - sin) (0 if not self-locking), press-in (push-on) force
     * N (sin + mu_e cos).
     */
    double cone_cos = 1., cone_sin = 0.;
    /** A cone's push-on force without friction, N sin(beta) (N; 0). */
    double push_on_force = 0., push_on_force_din = 0.;
    double pressure_din;
    double torque_capacity, torque_capacity_din;           ///< N m
    double axial_force_capacity, axial_force_capacity_din; ///< N
    double press_in_force, press_in_force_din;             ///< N
    double safety_slip, safety_slip_din;
    double safety_yield_shaft, safety_yield_shaft_din;
    double safety_yield_hub, safety_yield_hub_din;
    /**
     * The strength figures behind the FE yield safeties (MPa): the largest
     * von Mises stress of the body at its mid-plane check points and over
     * the middle half of the joint surface, away from the singular ends,
     * so that it converges under refinement and does not depend on
     * Design/Edge distance.
     */
    double strength_stress_shaft, strength_stress_hub;
    /**
     * The end of the joint as a notch, assessed on its own: the yield
     * strength over the largest von Mises stress of the body with the
     * joint surface up to Design/Edge distance from the end included (so
     * never above the yield safety; depends on the edge distance and on
     * the mesh; local yielding there is common and not a design criterion
     * of DIN 7190).
     */
    double safety_yield_shaft_edge, safety_yield_hub_edge;
    /**
     * The FE safeties against yield at assembly (room temperature, at
     * rest, no pressures): those above with no loads of operation, else
     * set by the operation analysis.
     */
    double safety_yield_shaft_assembly = unknown;
    double safety_yield_hub_assembly   = unknown;
    double edge_distance; ///< mm, in use

    /**
     * A brittle hub (Material/Hub/Kind): DIN 7190's criterion for brittle
     * materials, the largest hoop (tangential) stress against the tensile
     * strength R_m. FE: the largest hoop stress at the mid-plane check
     * points and along the bore at least the edge distance from the end of
     * the joint; DIN 7190: Lame's at the bore. Its yield safeties are then
     * not given (NaN). NaN for a hub that is not brittle.
     */
    double hoop_stress_max_hub     = unknown;
    double hoop_stress_max_hub_din = unknown;
    double safety_fracture_hub     = unknown;
    double safety_fracture_hub_din = unknown;

    /** hub bore, hub outer surface, shaft surface, shaft bore or axis. */
    std::vector<CheckPoint> check_points;

    /** Along the hub bore and along the shaft surface. */
    std::vector<SurfaceMaximum> surface_maxima;

    /** The stresses along the hub bore and the shaft surface, by z. */
    std::vector<StressState> hub_bore_stresses, shaft_surface_stresses;

    /** Warnings (yield exceeded, slip), one line each. */
    std::vector<std::string>
    warnings(const Parameters &parameters) const;

  private:
    void
    compute_capacity(const Parameters &parameters, const Din7190 &din);

    void
    compute_strength(const Parameters         &parameters,
                     const Din7190            &din,
                     const BodyDiscretization &shaft,
                     const Vector<double>     &shaft_field,
                     const BodyDiscretization &hub,
                     const Vector<double>     &hub_field);
  };
} // namespace coaxfit

#endif
