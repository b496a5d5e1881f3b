#ifndef coaxfit_section_scene_h
#define coaxfit_section_scene_h

#include <deal.II/grid/tria.h>

#include <coaxfit/fe/section_joint.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/fe/section_outline.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * A scene of two bodies drawn as sections (`Geometry/Shaft section`,
   * `Geometry/Hub section`): both outlines checked, where they meet (the
   * joint), the plane about which the scene is symmetric, and the
   * sections the model meshes.
   *
   * This version models scenes whose joint is one straight piece: a
   * cylinder or a cone (a taper fit). A scene
   * symmetric about a plane z = z_m is modelled as its half z >= z_m of
   * each section, shifted so that the plane is z = 0 of the model (u_z = 0
   * there, as the plain cylinders have it), the joint from z = 0 to its
   * half length. Any other scene (a hub flush with the shaft end, a
   * shoulder beside the hub) is modelled whole in the drawing's
   * coordinates, each body's axial rigid motion fixed at its joint node
   * nearest the joint's middle (BodyDiscretization). A cone passes axial
   * force: the hub is pushed on along the axis towards the cone's larger
   * diameter (Fit/Push-on distance), so its flat end face on the other
   * side is held (BoundaryId::held, u_z = 0), and the shaft is held at its
   * flat end face on the side the hub is pushed towards. Beside a
   * cylindrical joint the sections may also touch on one face across the
   * axis (a hub against a shoulder: shoulder_face()). A joint of several
   * pieces is refused with one line naming both entries; see
   * doc/real_parts.md for what comes next.
   *
   * Both bodies are meshed by gmsh with the same vertices on the joint
   * (joint_vertices(): graded towards its ends from the cell size, a
   * vertex at the middle of a whole joint), so that their joint nodes
   * coincide and the coupling takes the exact index map.
   */
  class SectionScene
  {
  public:
    /**
     * Parse, check and place the outlines @p shaft_text and @p hub_text.
     * Either may instead name a gmsh file (is_section_file_name(), a path
     * the caller has resolved): its mesh is read once (read_section_file())
     * and its boundary is the outline the joint is found from
     * (outline_of_mesh()). A scene with a file is modelled whole, its
     * joint nodes are its own (the file's mesh is not changed), the file's
     * physical curve `joint` must be the joint the sections make, faces on
     * r = 0 are the axis, and on a cone the held face is tagged in it.
     * @throws InputError naming the entry (or both) at fault.
     */
    SectionScene(const std::string &shaft_text, const std::string &hub_text);

    /** Whether the shaft's (@p shaft) or the hub's section is a gmsh file. */
    bool
    from_file(const bool shaft) const
    {
      return (shaft ? shaft_file : hub_file) != nullptr;
    }

    /** Whether either section is a gmsh file. */
    bool
    has_file() const
    {
      return from_file(true) || from_file(false);
    }

    /**
     * The boundary ids of the named physical curves of a gmsh file section
     * (empty for an outline).
     */
    std::map<std::string, types::boundary_id>
    face_names(bool shaft) const;

    /**
     * Whether the shaft (@p shaft: its bore) or the hub (its largest
     * diameter) has faces that carry Operation/Shaft bore pressure or Hub
     * outer pressure: an outline's straight edges there, a gmsh file's
     * unnamed faces there.
     */
    bool
    has_pressure_surface(bool shaft) const;

    /**
     * Whether the named face @p name of a gmsh file section (@p shaft's)
     * is still a free face of its mesh (not taken into the joint, as a
     * fillet over which contact may spread is).
     */
    bool
    has_free_named_face(bool shaft, const std::string &name) const;

    /**
     * The axial force (N, + along z) on the shaft (@p shaft) or the hub of
     * uniform pressures @p pressures (MPa) on its named faces: minus the
     * integral of p n_z 2 pi r over them, exact for the straight faces of
     * the gmsh file's mesh (and for arcs: n_z ds = -+dr, whatever the
     * curve). @p scale receives the sum of |p| 2 pi r over the same faces,
     * the size against which the resultant is zero.
     */
    double
    axial_face_force(
      bool                                               shaft,
      const std::vector<std::pair<std::string, double>> &pressures,
      double                                            &scale) const;

    /**
     * Whether a face named @p name of the shaft's (@p shaft) or the hub's
     * gmsh file lies in part on shoulder_face() (where the sections touch
     * beside the joint; a face of the file's mesh that overlaps the
     * touching ring by more than the drawing tolerance).
     */
    bool
    named_face_on_shoulder(bool shaft, const std::string &name) const;

    /**
     * The gmsh file's mesh of the shaft (@p shaft) or of the hub as read
     * (before Mesh/Global refinements), or nullptr for an outline: what
     * the memory estimate of a run counts (cells, joint faces).
     */
    const Triangulation<2> *
    file_mesh(const bool shaft) const
    {
      return from_file(shaft) ? &(shaft ? shaft_file : hub_file)->mesh :
                                nullptr;
    }

    /** The outline as drawn of the shaft (@p shaft) or of the hub. */
    const SectionOutline &
    drawn(bool shaft) const
    {
      return shaft ? *shaft_drawn : *hub_drawn;
    }

    /**
     * The modelled section of the shaft or the hub: the half z >= 0 of the
     * model, or the drawn one of a whole model.
     */
    const SectionOutline &
    modelled(bool shaft) const
    {
      return shaft ? *shaft_half : *hub_half;
    }

    /** Whether the model is the half of a symmetric scene. */
    bool
    half_model() const
    {
      return half;
    }

    /**
     * Model z of the joint's ends (mm): 0 and l_F / 2 for the half model,
     * the drawing's z for a whole one.
     */
    double
    joint_start() const
    {
      return half ? 0. : z_start;
    }
    double
    joint_end() const
    {
      return half ? half_length : z_start + 2. * half_length;
    }

    /** Joint radius R_F (mm): a cone's mean radius. */
    double
    joint_radius() const
    {
      return radius;
    }

    /**
     * An end of the joint where one section's edge is rounded (a fillet
     * that begins at the joint's end, tangent to it): contact may spread
     * onto the fillet, over the other section's straight surface.
     */
    struct RoundedEnd
    {
      bool     shaft;   ///< whose edge is rounded
      Point<2> tangent; ///< the joint's end (model r, z)
      Point<2> far;     ///< the other end of the fillet's arc
      double   radius;  ///< of the fillet (mm)
    };

    /** The rounded ends of the joint (none: sharp or chamfered ends). */
    const std::vector<RoundedEnd> &
    rounded_ends() const
    {
      return rounded;
    }

    /**
     * The part of a body's boundary tagged BoundaryId::joint, the joint
     * and where contact may spread: over each rounded end the fillet's arc
     * (@p shaft's own fillet) or the straight surface under it (the other
     * body's), to where the arc ends.
     */
    TaggedSegment
    contact_segment(bool shaft) const;

    /** A face across the axis beside the joint (section_joint.h). */
    using ShoulderFace = coaxfit::ShoulderFace;

    /**
     * The face beside the joint where the sections touch, if any. With a
     * frictionless cylindrical joint and no axial load, nothing pushes the
     * bodies against each other along the axis: the face's contact
     * pressures are non-negative and their axial resultant must vanish,
     * so they vanish everywhere, and the face is modelled as free. Each
     * body's axial rigid motion is fixed at its joint node nearest the
     * face (axial_pin_z()), so the two stay together there.
     */
    const std::optional<ShoulderFace> &
    shoulder_face() const
    {
      return shoulder;
    }

    /**
     * Model z (mm) of the joint node at which a whole model's bodies are
     * held axially (BodyDiscretization::set_axial_pin_z()): the joint's
     * end at a shoulder face, otherwise the joint's middle.
     */
    double
    axial_pin_z() const;

    /** Whether the joint is a cone (a taper fit). */
    bool
    conical() const
    {
      return cone;
    }

    /** The joint's radius at model z @p z (mm; linear on a cone). */
    double
    joint_radius_at(double z) const;

    /**
     * The taper C = (D_large - D_small) / l_F of a conical joint (0 on a
     * cylinder): 0.1 for a taper 1:10.
     */
    double
    taper() const
    {
      return 2. * std::abs(r_end - r_start) / joint_length();
    }

    /**
     * The direction along the axis (+1 or -1) in which the hub is pushed
     * onto a cone: towards its larger diameter.
     */
    double
    push_direction() const
    {
      return r_end >= r_start ? 1. : -1.;
    }

    /** Joint length l_F (mm), the whole joint. */
    double
    joint_length() const
    {
      return 2. * half_length;
    }

    /**
     * Drawing z of the model's z = 0: the symmetry plane z_m of a half
     * model, 0 for a whole one (a drawing z is model z + drawing_offset()).
     */
    double
    drawing_offset() const
    {
      return z_m;
    }

    /**
     * The hub's outer diameter averaged over the joint (mm): D_aA of the
     * plain-cylinder estimate (DIN 7190 column).
     */
    double
    hub_outer_diameter() const
    {
      return hub_mean_outer;
    }

    /**
     * The shaft's bore diameter for the plain-cylinder estimate (mm): 0 if
     * the shaft's section reaches the axis, else its smallest diameter.
     */
    double
    shaft_bore_diameter() const
    {
      return shaft_bore;
    }

    /**
     * The largest radius of the hub's section on the plane of symmetry,
     * or on the plane through the middle of a whole joint (mm): where its
     * outer surface crosses it (the rim of a gear hub), the point of the
     * FE's "hub outer surface" figures.
     */
    double
    hub_outer_radius_at_plane() const;

    /** Axial extent of the shaft's section (mm). */
    double
    shaft_length() const
    {
      return shaft_extent;
    }

    /**
     * The joint's vertices in the model between its ends (r = R_F,
     * ascending): the first cell at each end of the joint has size
     * @p cell_size, sizes grow by @p grading_ratio towards the middle up
     * to @p max_cell_size, each half of the joint filled exactly (a whole
     * joint has a vertex at its middle).
     */
    std::vector<Point<2>>
    joint_vertices(double cell_size,
                   double grading_ratio,
                   double max_cell_size) const;

    /**
     * Mesh both modelled sections into @p shaft and @p hub (empty): the
     * joint tagged BoundaryId::joint with the same vertices in both, the
     * plane z = 0 BoundaryId::symmetry, r = 0 BoundaryId::axis, every other
     * face SectionId::free. @p settings.refinement_points are ignored: the
     * ends of the joint and re-entrant corners are refined.
     */
    void
    make_meshes(Triangulation<2>          &shaft,
                Triangulation<2>          &hub,
                const SectionMeshSettings &settings) const;

    /**
     * Mesh both modelled sections each on its own: the joint tagged but
     * its vertices chosen by gmsh from each body's @p shaft_settings or
     * @p hub_settings (cell size at the joint's ends), so that the joint
     * nodes need not coincide. A section from a gmsh file is its file's
     * mesh as tagged by the constructor.
     */
    void
    make_own_meshes(Triangulation<2>          &shaft,
                    Triangulation<2>          &hub,
                    const SectionMeshSettings &shaft_settings,
                    const SectionMeshSettings &hub_settings) const;

    /** Both base meshes of a run, the shaft's first. */
    using MeshPair = std::array<Triangulation<2>, 2>;

    /**
     * Both base meshes for @p settings (before Mesh/Global refinements):
     * make_meshes() with @p shared_nodes, else make_own_meshes() with the
     * hub's cell size @p hub_cell_size (0: that of @p settings). Meshed
     * once per settings and kept: a run's coarse twin, the cases of a
     * study and the states of a selection mesh the same sections alike,
     * and gmsh is deterministic.
     */
    std::shared_ptr<const MeshPair>
    base_meshes(const SectionMeshSettings &settings,
                bool                       shared_nodes,
                double                     hub_cell_size) const;

  private:
    /**
     * The boundary of the mesh of @p outline: the joint @p joint, for a
     * half model the plane of symmetry, for a cone the held end face of the
     * body (@p shaft or the hub).
     */
    SectionBoundary
    boundary(const SectionOutline &outline,
             const TaggedSegment  &joint,
             bool                  shaft) const;

    /** The joint as a tagged segment from its start to its end. */
    TaggedSegment
    joint_segment() const;

    /** A section read from a gmsh file: its mesh as tagged for the run. */
    struct FileSection
    {
      std::string                               path;
      Triangulation<2>                          mesh;
      std::map<std::string, types::boundary_id> names;
    };

    /**
     * Read the gmsh file @p path of entry @p entry into a FileSection and
     * return it with its boundary as an outline in @p outline.
     */
    static std::shared_ptr<FileSection>
    read_file(const std::string               &path,
              const std::string               &entry,
              std::unique_ptr<SectionOutline> &outline);

    /**
     * Check that the file's physical curve `joint` is the joint found
     * (its faces on the joint's line, covering it), tag its faces on
     * r = 0 as the axis and, on a cone, its held face (@p shaft: the
     * shaft's file); refuse a circle arc that begins at an end of the joint.
     */
    void
    tag_file_mesh(FileSection &file, bool shaft, double tol) const;

    /**
     * Tag the faces of @p mesh (the shaft's, @p shaft, or the hub's) that
     * carry the plain pressures of operation: the shaft's untagged faces
     * at its bore diameter (a hollow shaft) BoundaryId::bore, the hub's at
     * its largest diameter BoundaryId::outer.
     */
    void
    tag_surfaces(Triangulation<2> &mesh, bool shaft) const;

    std::shared_ptr<FileSection> shaft_file, hub_file;

    /**
     * Find the rounded ends of the joint (a fillet of one modelled section
     * beginning at an end of the joint); @p tol the drawing tolerance.
     */
    void
    find_rounded_ends(double tol);

    /**
     * The radius at which a pressure of operation acts on a section: the
     * shaft's bore (0: solid) or the hub's largest.
     */
    double
    pressure_radius(bool shaft) const;

    /** The boundary id of the face @p name of a gmsh file's section. */
    std::optional<types::boundary_id>
    named_id(bool shaft, const std::string &name) const;

    /**
     * Accept the faces across the axis @p faces where the sections touch
     * beside the joint from @p z_lo to @p z_hi (shoulder_face()), or refuse
     * them: beside a cone, at more than one axial position (the body held
     * between two faces), or inside the joint's axial range.
     */
    void
    check_shoulder(const std::vector<JointPiece> &faces,
                   double                         z_lo,
                   double                         z_hi,
                   double                         tol);

    std::unique_ptr<SectionOutline> shaft_drawn, hub_drawn;
    std::unique_ptr<SectionOutline> shaft_half, hub_half;
    double                          radius  = 0.;
    double                          r_start = 0.; ///< at joint_start
    double                          r_end   = 0.; ///< at joint_end
    bool                            cone    = false;
    std::vector<RoundedEnd>         rounded;
    std::optional<ShoulderFace>     shoulder;
    double                          half_length    = 0.;
    double                          z_m            = 0.;
    double                          z_start        = 0.; ///< drawing
    bool                            half           = true;
    double                          hub_mean_outer = 0.;
    double                          shaft_bore     = 0.;
    double                          shaft_extent   = 0.;

    /** The meshes of base_meshes(), by the settings that decide them. */
    mutable std::mutex mesh_mutex;
    mutable std::map<std::tuple<bool, double, double, double, double>,
                     std::shared_ptr<const MeshPair>>
      mesh_cache;
  };
} // namespace coaxfit

#endif
