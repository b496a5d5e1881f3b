#ifndef coaxfit_scene_h
#define coaxfit_scene_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/mortar_transfer.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/parameters/parameters.h>
#include <coaxfit/solvers/body_solver.h>
#include <coaxfit/solvers/condensed_body.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * One body of a Scene: its discretization (name, section, material, loads
   * of operation, mesh and operator), the solver of its operator and its
   * condensed interface operator once they are made, and its field under
   * its own loads of operation with a free joint surface.
   */
  struct Body
  {
    explicit Body(std::unique_ptr<BodyDiscretization> discretization);

    /** The name as the parameter file spells it ("Shaft", "Hub"). */
    const std::string &
    name() const
    {
      return discretization->name();
    }

    /**
     * The name in lower case, as result files and summary.json keys spell
     * it ("shaft" in shaft.vtu and "n_dofs": {"shaft": ...}).
     */
    std::string
    key() const
    {
      return key_of(name());
    }

    /** @p name in lower case. */
    static std::string
    key_of(const std::string &name);

    /**
     * The body's field under the loads @p load alone (joint surface free),
     * by its solver (after set-up).
     */
    Vector<double>
    answer_to(const BodyLoad &load) const;

    std::unique_ptr<BodyDiscretization> discretization;
    std::unique_ptr<BodySolver>         solver;     ///< after set-up
    std::unique_ptr<CondensedBody>      condensed;  ///< once condensed
    Vector<double>                      load_field; ///< loads alone
  };



  /**
   * Two bodies whose tagged joint surfaces (BoundaryId::joint) touch: the
   * inner one (whose outward normal on the joint points away from the
   * axis) and the outer one, as indices into Scene::bodies, and the
   * interference of the drawing between them: radial on a cylinder, along
   * the joint's normal on a cone (the radial one times cos of the half
   * angle: a hub pushed by a along a taper C overlaps a sin(atan(C/2))).
   */
  struct JointSides
  {
    unsigned int inner;
    unsigned int outer;
    double       interference;        ///< mm, along the joint's normal
    double       radial_interference; ///< mm
  };



  /**
   * The bodies of one run and the joints between them, built from the
   * parameters: everything downstream loops over the bodies and joints or
   * asks a body its name. The parameter files of this version describe
   * two bodies, `Shaft` inside `Hub` (their Material subsections are named
   * so), with one joint on the cylinder of the joint diameter.
   */
  class Scene
  {
  public:
    /** The bodies and joints of @p parameters, not yet set up. */
    explicit Scene(const Parameters &parameters);

    /** The names of the bodies of @p parameters, inside out. */
    static std::vector<std::string>
    body_names(const Parameters &parameters);

    /** The lower-case names of body_names(). */
    static std::vector<std::string>
    body_keys(const Parameters &parameters);

    /**
     * Take the loads of operation and interferences of @p parameters
     * (meshes and operators stay: they do not depend on them).
     */
    void
    set_loads(const Parameters &parameters);

    /**
     * The scene's joint where the code of this version expects exactly
     * one (two bodies); throws std::logic_error otherwise, so that a scene
     * of several joints cannot be taken for one.
     */
    const JointSides &
    joint() const;

    /** The body on the inside of @p joint. */
    const Body &
    inner(const JointSides &joint) const
    {
      return bodies[joint.inner];
    }

    /** The body on the outside of @p joint. */
    const Body &
    outer(const JointSides &joint) const
    {
      return bodies[joint.outer];
    }

    /**
     * How far the body @p body is drawn larger than its mesh at its
     * joint, as a strain: d / R for the inner body of a joint (it is made
     * larger by the radial interference d at the joint radius R), 0 for
     * an outer one. ParaView's warp then shows the assembled parts.
     */
    double
    oversize(unsigned int body) const;

    /**
     * After the bodies are set up: if the joint nodes of the two bodies do
     * not coincide (Mesh/Joint nodes = own), build the mortar transfer
     * from the body with more joint nodes (the mortar side) to the other
     * (whose points carry the coupling's interface data); otherwise
     * none. Throws std::logic_error if a point of the coarser side is not
     * covered by the finer one.
     */
    void
    connect_joint();

    /** Whether the joint's sides are connected by a mortar transfer. */
    bool
    has_transfer() const
    {
      return transfer != nullptr;
    }

    /** The body whose joint points carry the interface data. */
    unsigned int
    point_body() const
    {
      return transfer ? 1 - mortar : 0;
    }

    /**
     * The values @p own at the joint points of body @p body (its u_r, say)
     * at the interface points: M own for the mortar side, else @p own.
     */
    Vector<double>
    joint_values(unsigned int body, const Vector<double> &own) const;

    /**
     * Nodal joint forces @p force at the interface points as forces on
     * the joint points of body @p body: M^T force for the mortar side
     * (total force and virtual work conserved), else @p force.
     */
    Vector<double>
    body_forces(unsigned int body, const Vector<double> &force) const;

    /** The transfer (has_transfer()). */
    const MortarTransfer &
    joint_transfer() const
    {
      return *transfer;
    }

    /** The mortar side of the transfer (has_transfer()). */
    unsigned int
    mortar_body() const
    {
      return mortar;
    }

    std::vector<Body>       bodies; ///< inside out
    std::vector<JointSides> joints; ///< between neighbours, inside out

  private:
    /** The body with a rounded edge at the joint (a section's fillet). */
    std::optional<unsigned int>           rounded_side;
    std::shared_ptr<const MortarTransfer> transfer;
    unsigned int                          mortar = 0;
  };



  /**
   * Geometry and mesh settings of the body named @p name (one of
   * Scene::body_names()) of @p parameters.
   */
  BodyGeometry
  body_geometry(const Parameters &parameters, const std::string &name);

  /**
   * The loads of operation that the body named @p name carries: its
   * thermal strain, the rotation, the pressure on its free surface.
   */
  BodyLoad
  body_load(const Parameters &parameters, const std::string &name);

  /**
   * How the sections of @p parameters are meshed: Mesh/Cell size (0: 1 %
   * of the joint length) at the ends of the joint and at re-entrant
   * corners, Mesh/Grading ratio away from them; no refinement (each body
   * refines its copy by Mesh/Global refinements).
   */
  SectionMeshSettings
  section_mesh_settings(const Parameters &parameters);

  /** The discretization of the body named @p name, not set up. */
  std::unique_ptr<BodyDiscretization>
  make_body(const Parameters &parameters, const std::string &name);
} // namespace coaxfit

#endif
