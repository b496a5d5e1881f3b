#ifndef coaxfit_plastic_body_h
#define coaxfit_plastic_body_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/fe/plastic_material.h>
#include <coaxfit/parameters/parameters.h>

#include <map>
#include <memory>
#include <ostream>
#include <vector>

namespace coaxfit
{
  /**
   * How one Newton solve of a body ended: whether it converged, in how
   * many iterations, the relative residual reached, whether any point
   * yields in the state found and whether its tangent was singular.
   */
  struct NewtonOutcome
  {
    bool         converged  = false;
    unsigned int iterations = 0;
    double       residual   = 0.;
    bool         plastic    = false;
    /** The tangent could not be factorized (no stiffness left). */
    bool singular = false;
  };

  /**
   * One axisymmetric body whose material may yield (von Mises, linear
   * isotropic hardening; PlasticMaterial), solved by Newton's method with
   * the consistent tangent, on the mesh, DoFs, conditions and interface
   * points of its BodyDiscretization (set up): the nonlinear counterpart of
   * BodySolver, with the same data on the contact surface S: the radial
   * displacement at prescribed interface points (shear-free), the nodal
   * contact force F at the others (a load -c_i F_i on the point's DoF, c =
   * BodyDiscretization::interface_load_factor()).
   *
   * Each quadrature point (Gauss, degree + 1 points per direction) keeps the
   * PlasticState of the last committed increment; every solve starts from
   * it (the return is path-independent within an increment), and commit()
   * makes the last solve the new committed state. While no point yields the
   * tangent is the elastic stiffness and its factorization is kept per set
   * of prescribed points.
   */
  class PlasticBody
  {
  public:
    PlasticBody(const BodyDiscretization &body,
                const LoadPathParameters &load_path);

    /** Quadrature, the states, the sparsity pattern (after the body's). */
    void
    setup_system();

    /**
     * Solve for the data @p prescribed, @p displacement (u_r at the
     * prescribed points), @p force (F at the others), starting from the
     * last solve's field; @p u_r and @p force_out get every point's
     * displacement and contact force (reactions F_i = -c_i (f_int - f)_i
     * at the prescribed ones). Never throws for a failed Newton solve: the
     * outcome says so, and the caller cuts its increment.
     */
    NewtonOutcome
    solve(const std::vector<bool> &prescribed,
          const Vector<double>    &displacement,
          const Vector<double>    &force,
          Vector<double>          &u_r,
          Vector<double>          &force_out);

    /**
     * The tangent of the last solve condensed onto its prescribed points:
     * S(i, j) = d F_i / d u_j over the prescribed points i, j (the others
     * keep their forces), in the order of the points. Symmetric positive
     * definite; the elastic interface stiffness while nothing yields.
     */
    FullMatrix<double>
    interface_stiffness();

    /** Make the last solve's state the committed one (end of increment). */
    void
    commit();

    /**
     * Start the next solve from the committed field extrapolated along the
     * last increment: u_n + @p ratio (u_n - u_{n-1}) (@p ratio the next
     * increment over the last). A jump of the joint's displacement alone
     * would strain the joint's cells far beyond yield in the first
     * iterate.
     */
    void
    extrapolate(double ratio);

    /**
     * Whether the body answers elastically whatever its stress (the
     * solve that finds the elastic limit).
     */
    void
    set_elastic_only(const bool elastic)
    {
      elastic_only = elastic;
    }

    /**
     * Scale the committed field by @p factor (an elastic state, no point
     * yielded: the state at another load level) and make the unloaded
     * state the one before it.
     */
    void
    scale_committed(double factor);

    /**
     * The largest ratio of the von Mises stress of the committed state to
     * the yield stress over the quadrature points (0 for a body without
     * plasticity).
     */
    double
    max_yield_ratio() const;

    /**
     * Apply @p factor times the loads of operation of the body
     * (BodyDiscretization::load()) in the solves that follow: the thermal
     * strain factor alpha (T - T_assembly) subtracted from the strain before
     * the return (the yield strength does not change with temperature),
     * the centrifugal force and the pressures on the free surfaces as
     * external forces. 0 in the state of assembly.
     */
    void
    set_load_factor(double factor);

    /** The load factor of the committed state. */
    double
    committed_load_factor() const
    {
      return committed_factor;
    }

    /** Go back to the committed state's field (a failed increment). */
    void
    revert();

    /**
     * Start the next solve from @p field (a field of an earlier solve in
     * this increment: a step the body could not follow is taken back).
     */
    void
    set_solution(const Vector<double> &field)
    {
      current = field;
    }

    /** The displacement field of the last solve. */
    const Vector<double> &
    solution() const
    {
      return current;
    }

    /** The body's discretization. */
    const BodyDiscretization &
    discretization() const
    {
      return body;
    }

    /** The committed states, cell by cell, quadrature point by point. */
    const std::vector<PlasticState> &
    committed_states() const
    {
      return committed;
    }

    /** The quadrature points (r, z) in the order of committed_states(). */
    const std::vector<Point<2>> &
    quadrature_points() const
    {
      return points;
    }

    /** Number of quadrature points per cell. */
    unsigned int
    n_q_points() const
    {
      return q_per_cell;
    }

    /**
     * The stress (sigma_rr, sigma_zz, sigma_tt, sigma_rz) at every
     * quadrature point of the committed state and field.
     */
    std::vector<Axisymmetric::Vector4>
    committed_stresses() const;

    /** Newton iterations and factorizations so far. */
    unsigned int
    n_newton_iterations() const
    {
      return newton_iterations;
    }
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

    /**
     * Write the committed state as VTU to @p out: the displacement
     * (displacement_mm, plus @p oversize r e_r as in
     * BodyDiscretization::output_results()), and per cell the mean over its
     * quadrature points of the stresses (sigma_rr_MPa, sigma_zz_MPa,
     * sigma_tt_MPa, sigma_rz_MPa, von_Mises_MPa), the equivalent plastic
     * strain (equivalent_plastic_strain, dimensionless), the share of its
     * points that yield (plastic_fraction) and body_id.
     */
    void
    output_results(std::ostream &out,
                   unsigned int  body_id,
                   double        oversize) const;

  private:
    /**
     * Assemble the tangent and the internal forces of the field current
     * from the committed states (trial states to trial); whether any
     * point yields.
     */
    bool
    assemble_system();

    /** The tangent with the fixed rows and columns of @p fixed eliminated. */
    void
    eliminate(const std::vector<bool> &fixed);

    /**
     * The factorization of the tangent with the points @p prescribed
     * held: the elastic one of that set (kept) unless @p plastic, else
     * that of the last assembly (made if not yet).
     */
    SparseDirectUMFPACK &
    factorization(const std::vector<bool> &prescribed, bool plastic);

    /** The DoFs fixed for @p prescribed (conditions and prescribed points). */
    std::vector<bool>
    fixed_dofs(const std::vector<bool> &prescribed) const;

    const BodyDiscretization &body;
    const LoadPathParameters  load_path;
    const PlasticMaterial     material;
    const bool                may_yield;
    bool                      elastic_only = false;

    SparsityPattern      pattern;
    SparseMatrix<double> tangent;    ///< without conditions
    SparseMatrix<double> eliminated; ///< for the solve
    Vector<double>       internal_force;
    Vector<double>       current;
    Vector<double>       committed_field;
    Vector<double>       previous_committed_field;

    unsigned int              q_per_cell = 0;
    std::vector<Point<2>>     points;
    std::vector<PlasticState> committed;
    std::vector<PlasticState> trial;

    /** The loads of operation without the thermal strain (N per radian). */
    Vector<double> operation_force;
    double         thermal_strain   = 0.;
    double         load_factor      = 0.;
    double         committed_factor = 0.;

    std::vector<bool>   last_prescribed;
    bool                last_plastic = false;
    SparseDirectUMFPACK tangent_factor; ///< of eliminated (plastic)
    bool                tangent_factor_valid = false;
    std::map<std::vector<bool>, std::unique_ptr<SparseDirectUMFPACK>>
                 elastic_factors; ///< per set of prescribed points
    unsigned int newton_iterations   = 0;
    unsigned int factorization_count = 0;
  };
} // namespace coaxfit

#endif
