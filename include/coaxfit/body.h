#ifndef coaxfit_body_h
#define coaxfit_body_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/interface_operator.h>
#include <coaxfit/mesh.h>
#include <coaxfit/parameters.h>
#include <coaxfit/sparse_cholesky.h>

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * One axisymmetric linear elastic cylinder: its Triangulation<2> in the
   * (r, z) half section, FESystem(FE_Q(p)^2) for (u_r, u_z), the r-weighted
   * stiffness matrix with the hoop strain u_r/r, and the homogeneous
   * conditions u_r = 0 on the axis and u_z = 0 on the symmetry plane.
   *
   * The body answers questions about its contact surface S, whose points
   * (the support points of u_r on S, ordered by z) are numbered 0..n-1:
   * given at each point either the radial displacement (Dirichlet,
   * shear-free) or the nodal contact force (Neumann), it solves and returns
   * the displacement and the consistent nodal force at every point. The
   * contact force is compression positive and in the axisymmetric "per
   * radian" form: F_i = int_S p N_i r dz, so F = M p with the interface mass
   * matrix M (weight r). Reactions are rows of K u - f, not differentiated
   * stresses.
   *
   * Each set of prescribed points gives a different matrix (the same
   * pattern, the prescribed rows and columns zeroed): its sparse Cholesky
   * factorization (CHOLMOD) is computed when first needed and cached, so
   * repeated solves with the same set cost two triangular solves. The
   * symbolic analysis is shared by all sets.
   */
  class Body : public InterfaceOperator
  {
  public:
    /**
     * With @p reduced_volumetric_integration, the lambda part of the
     * stiffness is integrated with the p-point Gauss rule per direction
     * (selective reduced integration against volumetric locking), the
     * 2 mu part with p + 1 points.
     */
    Body(const std::string  &name,
         const BodyGeometry &geometry,
         const Material     &material,
         unsigned int        degree,
         bool                reduced_volumetric_integration = false);

    /** Build the mesh, distribute DoFs, set constraints and sparsity. */
    void
    setup_system();

    /** Assemble the stiffness matrix and the interface mass matrix. */
    void
    assemble_system();

    /**
     * Solve with mixed data on S. Point i gets the radial displacement
     * @p displacement[i] if @p prescribed[i], otherwise the nodal contact
     * force @p force[i]. On return @p u_r holds the radial displacement and
     * @p force_out the contact force at every point (the reaction where
     * prescribed, the given force elsewhere).
     */
    void
    solve(const std::vector<bool>   &prescribed,
          const std::vector<double> &displacement,
          const std::vector<double> &force,
          std::vector<double>       &u_r,
          std::vector<double>       &force_out) override;

    /**
     * Compute (or find in the cache) the factorization for the set of
     * prescribed points @p prescribed, so that later solves only substitute.
     */
    void
    factorize(const std::vector<bool> &prescribed)
    {
      factorization(prescribed);
    }

    /**
     * The interface compliance of the free body (no point prescribed):
     * C(i, j) = radial displacement at point i for a unit nodal contact force
     * at point j. Computed with blocked solves of the cached factorization.
     */
    void
    interface_compliance(FullMatrix<double> &compliance);

    /**
     * Write the last solution as VTU: displacement (mm), the stresses
     * sigma_rr, sigma_zz, sigma_tt (hoop), sigma_rz and von Mises (MPa).
     */
    void
    output_results(const std::string &filename) const;

    /** @name Interface description */
    /** @{ */
    unsigned int
    n_interface_points() const
    {
      return interface_dofs.size();
    }

    /** Axial coordinate of each interface point (mm), increasing. */
    const std::vector<double> &
    interface_z() const
    {
      return interface_z_coordinates;
    }

    /**
     * Entries (i, j, M_ij) of the interface mass matrix
     * M_ij = int_S N_i N_j r dz in interface point numbering.
     */
    const std::map<std::pair<unsigned int, unsigned int>, double> &
    interface_mass() const
    {
      return interface_mass_entries;
    }
    /** @} */

    const std::string &
    name() const
    {
      return body_name;
    }

    const BodyGeometry &
    geometry() const
    {
      return body_geometry;
    }

    const Material &
    material() const
    {
      return body_material;
    }

    const DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const Vector<double> &
    get_solution() const
    {
      return solution;
    }

    /** Replace the solution (a solver that owns the system, e.g. the
     * monolithic one, hands its answer back for output). */
    void
    set_solution(const Vector<double> &new_solution)
    {
      solution = new_solution;
    }

    /** The assembled stiffness matrix (homogeneous conditions applied). */
    const SparseMatrix<double> &
    get_stiffness_matrix() const
    {
      return stiffness_matrix;
    }

    /** The DoF of u_r at each interface point. */
    const std::vector<types::global_dof_index> &
    get_interface_dofs() const
    {
      return interface_dofs;
    }

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    unsigned int
    n_cells() const
    {
      return triangulation.n_active_cells();
    }

    /** Number of matrix factorizations so far. */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

    /** Number of solves (each a forward and backward substitution). */
    unsigned int
    n_solves() const
    {
      return solve_count;
    }

    /** Largest number of factorizations kept at once. */
    static constexpr unsigned int max_cached_factorizations = 4;

  private:
    /** The factorization for a set of prescribed points, made if needed. */
    const SparseCholesky::Factor &
    factorization(const std::vector<bool> &prescribed);

    const std::string  body_name;
    const BodyGeometry body_geometry;
    const Material     body_material;
    const bool         reduced_volumetric_integration;

    Triangulation<2>          triangulation;
    const FESystem<2>         fe;
    DoFHandler<2>             dof_handler;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity_pattern;
    SparseMatrix<double>      stiffness_matrix;
    Vector<double>            solution;

    std::vector<types::global_dof_index> interface_dofs;
    std::vector<double>                  interface_z_coordinates;
    std::map<std::pair<unsigned int, unsigned int>, double>
      interface_mass_entries;

    SparseCholesky cholesky;
    bool           analyzed = false;
    std::map<std::vector<bool>, std::unique_ptr<SparseCholesky::Factor>>
                                  factorizations;
    std::deque<std::vector<bool>> factorization_order;
    unsigned int                  factorization_count = 0;
    unsigned int                  solve_count         = 0;
  };
} // namespace coaxfit

#endif
