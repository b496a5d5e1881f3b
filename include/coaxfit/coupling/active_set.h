#ifndef coaxfit_active_set_h
#define coaxfit_active_set_h

#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The unilateral (frictionless, no adhesion) contact conditions of the
   * paper, (1.2)-(1.3), as a contact / separated flag per interface point,
   * updated inside the staggered process:
   *
   * - force step: a tensile blended nodal force is set to zero (a point
   *   cannot pull), clamp();
   * - after the Neumann solve, a point with zero force and a gap
   *   du = u2 - u1 - d >= 0 satisfies the separation conditions and is
   *   flagged separated; every other point is in contact, update(). In the
   *   next Dirichlet step only the contact points get the blended
   *   displacement, separated points stay traction free in both bodies.
   *
   * That is the Update::every_step mode. With the project's accelerated
   * controllers the set is better kept fixed while the coupling iteration
   * converges the problem with the current set (bilateral at contact
   * points, traction free at separated ones) and then updated like a
   * primal-dual active set method (deal.II step-41): a contact point whose
   * force became tensile separates, a separated point that penetrates
   * closes; Update::when_converged. Both end in the same complementarity
   * conditions.
   *
   * With the pass disabled (bilateral contact) every point stays in contact
   * and nothing is clamped.
   */
  class UnilateralActiveSet
  {
  public:
    /** When the flags are updated. */
    enum class Update
    {
      every_step,    ///< the paper's process
      when_converged ///< primal-dual active set outer loop
    };

    UnilateralActiveSet(unsigned int n_points, bool enabled, Update update);

    Update
    update_mode() const
    {
      return mode;
    }

    bool
    enabled() const
    {
      return is_enabled;
    }

    /**
     * Set tensile (negative) nodal forces to zero (every_step mode only);
     * returns how many.
     */
    unsigned int
    clamp(Vector<double> &force) const;

    /**
     * Flag the points from the state of a Neumann step. Returns true if
     * the set changed.
     */
    bool
    update(const Vector<double> &force, const Vector<double> &gap);

    /**
     * Start from the flags @p flags (a prediction, e.g. of a coarser mesh);
     * ignored if the pass is disabled. Not counted as a change.
     */
    void
    assume(const std::vector<bool> &flags);

    /**
     * Set the flags to @p flags (a solution of the contact problem of a
     * model); ignored if the pass is disabled. Returns true if the set
     * changed, and counts the change.
     */
    bool
    set(const std::vector<bool> &flags);

    /** Contact flag of every point (the Dirichlet step's prescribed set). */
    const std::vector<bool> &
    in_contact() const
    {
      return contact;
    }

    /** Number of separated points. */
    unsigned int
    n_separated() const;

    /** How often update() changed the set. */
    unsigned int
    n_changes() const
    {
      return changes;
    }

    /**
     * Separated zones [z_start, z_end] (mm): runs of separated points, each
     * extended half way to its contact neighbours (to the end of S at the
     * ends).
     */
    std::vector<std::pair<double, double>>
    separated_zones(const std::vector<double> &z, double contact_length) const
    {
      return separated_zones(z, 0., contact_length);
    }

    /**
     * The same for a joint modelled from @p start to @p end (a whole
     * model): a zone at the first point begins at @p start.
     */
    std::vector<std::pair<double, double>>
    separated_zones(const std::vector<double> &z,
                    double                     start,
                    double                     end) const;

  private:
    const bool        is_enabled;
    const Update      mode;
    std::vector<bool> contact;
    unsigned int      changes = 0;
  };
} // namespace coaxfit

#endif
