#ifndef coaxfit_plastic_coupling_h
#define coaxfit_plastic_coupling_h

#include <deal.II/lac/vector.h>

#include <coaxfit/solvers/plastic_body.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * How the coupled solve of one load increment ended: converged or not,
   * its coupling steps (or Newton steps of the monolithic solver), the
   * largest number of Newton iterations of one body solve, and in words
   * what failed (which body's Newton solve, or the coupling).
   */
  struct IncrementOutcome
  {
    bool         converged           = false;
    unsigned int steps               = 0;
    unsigned int active_set_rounds   = 0;
    unsigned int max_body_iterations = 0;
    unsigned int body_solves         = 0;
    double       residual            = 0.;
    std::string  failure;
  };

  /**
   * The contact of two bodies that may yield (PlasticBody: the shaft inside
   * the hub, their joint points matching), solved for one load increment
   * from their committed states, for a radial interference given at every
   * joint point.
   *
   * Staggered (the principle of alternating continuity on a nonlinear
   * map): the shaft gets the contact force x (Neumann) and answers with its
   * joint displacement u_1(x); the hub gets u_1 + d (Dirichlet) and answers
   * with its reactions G(x) (or the roles swapped, Settings::
   * neumann_on_hub); interface quasi-Newton IQN-ILS (after a first
   * step relaxed by one half) drives r = G(x) - x to zero. Each body solve
   * is a Newton solve of its own (PlasticBody::solve()); the hub, which
   * yields first in a press fit, is displacement-driven, so that a hub near
   * its limit pressure stays well posed.
   *
   * Monolithic (the reference): Newton's method on the hub's joint
   * displacement u with both bodies displacement-driven, the balance
   * R(u) = F_hub(u) - F_shaft(u - d) = 0 and the Jacobian S_hub + S_shaft
   * of the bodies' consistent tangents condensed onto the joint (the Schur
   * complement of the whole coupled tangent): quadratic convergence.
   *
   * With unilateral contact the points whose force would pull are released
   * (force zero on both sides), those whose gap closes again taken back,
   * until the set stays the same; the staggered process restarts its
   * history when the set changes.
   */
  class PlasticCoupling
  {
  public:
    /** Settings of the coupled solve. */
    struct Settings
    {
      bool monolithic = false;
      /**
       * Staggered: the hub takes the Neumann step and the shaft the
       * Dirichlet one (a shaft that yields and a hub that does not: the
       * body that takes a force must be the one that stays elastic, as a
       * force beyond a body's limit load has no answer).
       */
      bool         neumann_on_hub = false;
      bool         unilateral     = true;
      double       tolerance      = 1e-8; ///< relative force residual
      unsigned int max_steps      = 200;
      unsigned int iqn_columns    = 50;
      double       iqn_filter     = 1e-10;
    };

    PlasticCoupling(PlasticBody &shaft, PlasticBody &hub, const Settings &s);

    /**
     * Solve the increment whose radial interference at each joint point is
     * @p interference (mm), starting from the last increment's force and
     * active set; one line per step to @p progress if given. The bodies
     * hold the trial state afterwards (commit() them, or revert()).
     */
    IncrementOutcome
    solve(const Vector<double> &interference, std::ostream *progress);

    /** The contact force at every joint point (N per radian). */
    const Vector<double> &
    force() const
    {
      return contact_force;
    }

    /** Whether the monolithic solver is in use (else the staggered one). */
    bool
    monolithic() const
    {
      return settings.monolithic;
    }

    /** Which points are in contact. */
    const std::vector<bool> &
    active() const
    {
      return active_points;
    }

    /** The gap u_hub - u_shaft - d at each point (mm; 0 in contact). */
    const Vector<double> &
    gap() const
    {
      return gaps;
    }

    /**
     * Start the next increment from the last one's force and joint
     * displacement extrapolated along the last increment by @p ratio (the
     * next increment over the last), as PlasticBody::extrapolate().
     */
    void
    extrapolate(double ratio);

    /**
     * Scale the committed force and displacement by @p factor (an elastic
     * state at another load level), the unloaded state before it.
     */
    void
    scale_committed(double factor);

    /** Take back the force and active set of the last converged increment. */
    void
    revert();

    /** Keep the force and active set as the converged increment's. */
    void
    commit();

    /**
     * With @p apart, the parts apart in the next solves (the end of a
     * disassembly): every point released and kept released whatever its
     * gap (a hub that never yielded meets the withdrawn shaft at a gap of
     * round-off); without, the active set is updated again.
     */
    void
    set_separated(bool apart);

  private:
    /** The staggered process for a fixed active set. */
    IncrementOutcome
    solve_staggered(const Vector<double> &interference, std::ostream *progress);

    /** Newton's method on the joint displacement for a fixed active set. */
    IncrementOutcome
    solve_monolithic(const Vector<double> &interference,
                     std::ostream         *progress);

    /**
     * Update the active set from the force and gap: true if it changed.
     */
    bool
    update_active_set();

    PlasticBody      &shaft;
    PlasticBody      &hub;
    const Settings    settings;
    Vector<double>    contact_force;
    Vector<double>    hub_displacement; ///< u_r of the hub's joint points
    Vector<double>    gaps;
    std::vector<bool> active_points;
    Vector<double>    committed_force;
    Vector<double>    committed_displacement;
    Vector<double>    previous_force;
    Vector<double>    previous_displacement;
    std::vector<bool> committed_active;
    Vector<double>    committed_gaps;
    bool              separated = false;
    /**
     * The largest norm of a committed contact force: a floor (1e-6 of it)
     * under the scale of the force residual, which has none where the
     * force vanishes (a joint opening everywhere).
     */
    double peak_force = 0.;

    /** The scale of a force residual: @p norm, at least the floor. */
    double
    force_scale(double norm) const
    {
      return std::max(norm, 1e-6 * peak_force);
    }
  };
} // namespace coaxfit

#endif
