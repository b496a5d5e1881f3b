#ifndef coaxfit_state_solver_h
#define coaxfit_state_solver_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/design/fit_design.h>
#include <coaxfit/design/pressure_summary.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/parameters/parameters.h>

#include <utility>
#include <vector>

namespace coaxfit
{
  /**
   * A solved state of a fit, as the analyses take it: the contact pressure
   * figures, the design figures, how the solve ended and where the joint
   * is open.
   */
  struct SolvedState
  {
    PressureSummary pressure;
    FitDesign       design;
    bool            converged = false;
    unsigned int    n_steps   = 0;
    /** Separated zones [z_start, z_end] of the half joint (mm). */
    std::vector<std::pair<double, double>> separated_zones;
  };



  /**
   * What the analyses of a run (the operation analysis: a second state,
   * the loosening speed) ask of the program that solves it, behind one
   * interface, so that they call the solve instead of building a program
   * of their own: the run's solved state, the state of other loads on the
   * same scene, and the linear answers of its joint. CoaxialFit implements
   * it.
   */
  class StateSolver
  {
  public:
    virtual ~StateSolver() = default;

    /** The run's own state (after its solve). */
    virtual SolvedState
    solved_state() const = 0;

    /**
     * The state of @p parameters, which differ from the run's only in the
     * loads of operation (same scene and meshes); throws SolverError if
     * the coupling diverges.
     */
    virtual SolvedState
    solve_state(const Parameters &parameters)
      = 0;

    /** The run's joint (its points, weights and interference). */
    virtual const ContactInterface &
    get_interface() const = 0;

    /**
     * How the loads @p loads of the free bodies (one per body) change the
     * interference at each point of the joint (mm).
     */
    virtual Vector<double>
    interference_change(const std::vector<BodyLoad> &loads) = 0;

    /**
     * The nodal contact force for the pointwise radial interference
     * @p interference (mm) and no loads, by the run's own method; throws
     * SolverError if it does not converge.
     */
    virtual Vector<double>
    contact_force_for(const Vector<double> &interference, bool unilateral) = 0;
  };
} // namespace coaxfit

#endif
