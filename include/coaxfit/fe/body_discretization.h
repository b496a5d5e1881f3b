#ifndef coaxfit_body_discretization_h
#define coaxfit_body_discretization_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/fe/mesh.h>
#include <coaxfit/parameters/parameters.h>

#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The loads of operation that one body carries (all zero in the state of
   * assembly): a uniform thermal eigenstrain alpha (T - T_assembly), the
   * centrifugal body force rho omega^2 r, and pressures on its free
   * cylindrical surfaces (its bore r = r_inner of a hollow body, its outer
   * surface r = r_outer), never on the contact surface S.
   */
  struct BodyLoad
  {
    double thermal_strain = 0.; ///< alpha (T - T_assembly)
    double omega_squared  = 0.; ///< (rad/s)^2
    double inner_pressure = 0.; ///< MPa on the free bore
    double outer_pressure = 0.; ///< MPa on the free outer surface
    /** MPa on the faces of each boundary id (named faces of a section). */
    std::map<types::boundary_id, double> face_pressures;

    /** Whether any entry is not zero. */
    bool
    any() const
    {
      bool faces = false;
      for (const auto &[id, p] : face_pressures)
        faces = faces || p != 0.;
      return thermal_strain != 0. || omega_squared != 0. || inner_pressure != 0.
             || outer_pressure != 0. || faces;
    }
  };

  /**
   * The discretization of one axisymmetric linear elastic cylinder: its
   * Triangulation<2> in the (r, z) half section, FESystem(FE_Q(p)^2) for
   * (u_r, u_z), the r-weighted stiffness matrix with the hoop strain u_r/r,
   * and the homogeneous conditions u_r = 0 on the axis and u_z = 0 on the
   * symmetry plane.
   *
   * Its contact surface S is described by the interface points: the
   * support points of u_r on S, ordered by z and numbered 0..n-1, each with
   * its DoF and its lumped weight w_i = int_S N_i r dz (the row sum of the
   * interface mass matrix, assembled directly as a vector, as step-42's
   * assemble_mass_matrix_diagonal does).
   *
   * The class knows nothing about solving: BodySolver factorizes and solves
   * with its matrix. Fields for output are computed by an explicit call,
   * output_results(), from a solution vector the caller passes.
   */
  class BodyDiscretization
  {
  public:
    /**
     * With @p reduced_volumetric_integration, the lambda part of the
     * stiffness is integrated with the p-point Gauss rule per direction
     * (selective reduced integration against volumetric locking), the
     * 2 mu part with p + 1 points. The body carries @p load (its
     * thermal strain enters the stresses of every field it writes).
     */
    BodyDiscretization(const std::string  &name,
                       const BodyGeometry &geometry,
                       const Material     &material,
                       unsigned int        degree,
                       bool            reduced_volumetric_integration = false,
                       const BodyLoad &load = BodyLoad());

    /**
     * Builds a body's mesh into an empty triangulation, its boundary tagged
     * with the ids of BoundaryId (at least the joint; the axis where the
     * section touches r = 0; the symmetry plane of a half model).
     */
    using MeshBuilder = std::function<void(Triangulation<2> &)>;

    /**
     * Build the mesh with @p builder instead of the plain cylinder of the
     * geometry (make_body_mesh): a section meshed by make_section_mesh or
     * read from a gmsh file. Before setup_system(). The conditions stay
     * those of the ids: u_r = 0 on BoundaryId::axis, u_z = 0 on
     * BoundaryId::symmetry, wherever the mesh has them; a mesh without a
     * symmetry plane gets u_z = 0 at its joint node nearest the joint's
     * middle (axial_pin_dof()).
     */
    void
    set_mesh_builder(const MeshBuilder &builder)
    {
      mesh_builder = builder;
    }

    /**
     * For a mesh without a symmetry plane or a held face: fix the axial
     * rigid motion at the joint node nearest model z @p z instead of the
     * joint's middle (a hub against a shoulder: at the joint's end there).
     */
    void
    set_axial_pin_z(const double z)
    {
      axial_pin_z = z;
    }

    /** The body's name as the parameter file spells it ("Shaft", "Hub"). */
    const std::string &
    name() const
    {
      return body_name;
    }
    /** Build the mesh, distribute DoFs, set constraints and sparsity. */
    void
    setup_system();

    /** Assemble the stiffness matrix and the interface weights. */
    void
    assemble_system();

    /**
     * The load vector of @p load (N per radian, homogeneous constraints
     * applied): the thermal eigenstress C (alpha dT) I against the strains
     * of the shape functions (its lambda part with the reduced rule where
     * the stiffness has it), rho omega^2 r against u_r (Material/Density in
     * kg/m^3, so rho omega^2 r is 1e-12 rho omega^2 r N/mm^3 with r in mm),
     * and the pressures on the free bore and outer surface. Nothing acts on
     * S: the load field of a free interface is the body's own answer.
     */
    Vector<double>
    assemble_load_vector(const BodyLoad &load) const;

    /** The load this body carries. */
    const BodyLoad &
    load() const
    {
      return body_load;
    }

    /**
     * Replace the loads of operation (the matrix does not depend on them;
     * load vectors are assembled from load() when asked for).
     */
    void
    set_load(const BodyLoad &load)
    {
      body_load = load;
    }

    /**
     * Write @p solution as VTU to @p out (the caller owns the file and
     * checks that it was written). Every name carries its unit, which is
     * also attached to the array as its `units` attribute:
     * displacement_mm, the displacement that shows the assembled part when
     * ParaView warps the mesh by it: @p solution plus @p oversize r e_r
     * (the shaft is made larger than the mesh at the joint radius by the
     * radial interference d, so oversize = d / R_F for it and 0 for the
     * hub); elastic_displacement_mm, @p solution itself (what the strains
     * come from); the stresses sigma_rr_MPa, sigma_zz_MPa, sigma_tt_MPa
     * (hoop), sigma_rz_MPa, von_Mises_MPa; with reduced integration
     * volumetric_stress_MPa; and body_id = @p body_id on every cell
     * (0 shaft, 1 hub; inside out in a stack). The radial @p offset (mm)
     * is added to displacement_mm everywhere (a ring in the middle of a
     * stack, drawn larger at its outer joint only).
     */
    void
    output_results(const Vector<double> &solution,
                   std::ostream         &out,
                   unsigned int          body_id  = 0,
                   double                oversize = 0.,
                   double                offset   = 0.) const;

    /**
     * The interface values of a field @p solution solved for the data
     * @p prescribed, @p force (a BodySolver's, or a coupled solve's with every
     * point prescribed): u_r at every point and the contact force
     * (the reaction where prescribed, @p force elsewhere).
     */
    void
    interface_values(const std::vector<bool> &prescribed,
                     const Vector<double>    &force,
                     const Vector<double>    &solution,
                     Vector<double>          &u_r,
                     Vector<double>          &force_out) const;

    /**
     * The interface values of @p field at the interface points: u . n,
     * n = interface_frame() (u_r on a cylinder).
     */
    Vector<double>
    interface_radial_values(const Vector<double> &field) const
    {
      Vector<double> u_r(interface_dofs.size());
      for (unsigned int i = 0; i < interface_dofs.size(); ++i)
        u_r[i] = rotated ? frame[i][0] * field[interface_dofs[i]]
                             + frame[i][1] * field[interface_axial_dofs[i]] :
                           field[interface_dofs[i]];
      return u_r;
    }

    /**
     * The direction of each interface point's value: the joint's unit
     * normal pointing out of the shaft (e_r on a cylinder), the same for
     * both bodies, so that u2 . n = u1 . n + d closes an interference d.
     */
    const std::vector<Tensor<1, 2>> &
    interface_frame() const
    {
      return frame;
    }

    /**
     * Whether the joint is not a cylinder (a cone): then BodySolver solves
     * in the joint's frame, each joint node's (u_r, u_z) DoFs replaced by
     * (u . n, u . t) with n = interface_frame(), t = (-n_z, n_r).
     */
    bool
    rotated_frame() const
    {
      return rotated;
    }

    /**
     * The share of a contact force F_i that acts on the interface DoF of
     * point i: its load is -c_i F_i, and a reaction r there gives
     * F_i = c_i r. The outward normal's n_r (+-1) on a cylinder, +-1 on a
     * cone (its DoF is u . n), the body's side +-1 on a curved joint (a
     * fillet: radial frame).
     */
    const std::vector<double> &
    interface_load_factor() const
    {
      return load_factor;
    }

    /**
     * Whether the joint is curved (it goes on over a fillet): its values
     * are then radial, u_r, and its forces radial too.
     */
    bool
    curved_joint() const
    {
      return curved;
    }

    /** @p v (a vector over the DoFs) into the joint's frame: R^T v. */
    void
    to_interface_frame(Vector<double> &v) const;

    /** @p v from the joint's frame back to (u_r, u_z): R v. */
    void
    from_interface_frame(Vector<double> &v) const;

    /** The stiffness @p K into the joint's frame: R^T K R. */
    void
    to_interface_frame(SparseMatrix<double> &K) const;

    /**
     * The stiffness in the frame the solves use: K on a cylinder, else
     * R^T K R, made into @p storage when it is empty and kept there.
     */
    const SparseMatrix<double> &
    stiffness_in_interface_frame(SparseMatrix<double> &storage) const;
    /** The (r, z) support point of each interface point. */
    const std::vector<Point<2>> &
    interface_points() const
    {
      return points;
    }
    /**
     * The number of interface points on the bore's joint of a ring in a
     * stack (BoundaryId::inner_joint); they come first, those of the
     * outer joint after them. 0 for a body with one joint.
     */
    unsigned int
    n_inner_interface_points() const
    {
      return n_inner_joint_points;
    }

    /** Number of interface points. */
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

    /** Lumped weights w_i = int_S N_i r dz (mm^2) of the interface points. */
    const Vector<double> &
    interface_weights() const
    {
      return weights;
    }

    /**
     * The body's outward unit normal at each interface point, from the
     * faces tagged BoundaryId::joint. Contact forces act along -n; the
     * interface displacement is u . interface_frame() (u_r on a cylinder
     * r = const, where n = +-e_r).
     */
    const std::vector<Tensor<1, 2>> &
    interface_normals() const
    {
      return normals;
    }
    /** The DoF of u_r at each interface point. */
    const std::vector<types::global_dof_index> &
    get_interface_dofs() const
    {
      return interface_dofs;
    }

    /** The DoF of u_z at each interface point (same order). */
    const std::vector<types::global_dof_index> &
    get_interface_axial_dofs() const
    {
      return interface_axial_dofs;
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

    /** Whether the lambda part is integrated with the reduced rule. */
    bool
    reduced_integration() const
    {
      return reduced_volumetric_integration;
    }

    const DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /**
     * The u_z DoF fixed against the axial rigid motion of a body without
     * a symmetry plane (a whole section: its joint node nearest the
     * joint's middle), or numbers::invalid_dof_index.
     */
    types::global_dof_index
    axial_pin_dof() const
    {
      return axial_pin;
    }

    /**
     * The constraints of the axis and the symmetry plane (and the axial
     * pin of a whole section).
     */
    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    const SparsityPattern &
    get_sparsity_pattern() const
    {
      return sparsity_pattern;
    }

    /** The assembled stiffness matrix (homogeneous conditions applied). */
    const SparseMatrix<double> &
    get_stiffness_matrix() const
    {
      return stiffness_matrix;
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

  private:
    /** The interface points: DoFs of u_r on S, ordered by z. */
    void
    collect_interface_points();

    /** The weights w_i = int_S N_i r dz of the interface points. */
    void
    assemble_interface_weights();

    /**
     * With reduced integration: a DoFHandler for the displacement plus the
     * volumetric stress at the reduced points (FE_DGQArbitraryNodes on the
     * p-point Gauss rule), and the field on it.
     */
    void
    volumetric_field(const Vector<double> &solution,
                     DoFHandler<2>        &dof_handler_out,
                     Vector<double>       &field) const;

    const std::string  body_name;
    const BodyGeometry body_geometry;
    const Material     body_material;
    const bool         reduced_volumetric_integration;
    BodyLoad           body_load;
    MeshBuilder        mesh_builder; ///< empty: make_body_mesh

    Triangulation<2>          triangulation;
    const FESystem<2>         fe;
    DoFHandler<2>             dof_handler;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity_pattern;
    SparseMatrix<double>      stiffness_matrix;

    std::vector<types::global_dof_index> interface_dofs;
    unsigned int                         n_inner_joint_points = 0;
    std::vector<types::global_dof_index> interface_axial_dofs;
    std::vector<double>                  interface_z_coordinates;
    std::vector<Point<2>>                points;
    Vector<double>                       weights;
    std::vector<Tensor<1, 2>>            normals;
    std::vector<Tensor<1, 2>>            frame; ///< interface_frame()
    bool                                 rotated = false;
    bool                                 curved  = false;
    std::vector<double>                  load_factor;
    types::global_dof_index              axial_pin = numbers::invalid_dof_index;
    std::optional<double>                axial_pin_z;
  };
} // namespace coaxfit

#endif
