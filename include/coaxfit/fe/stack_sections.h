#ifndef coaxfit_stack_sections_h
#define coaxfit_stack_sections_h

#include <deal.II/grid/tria.h>

#include <coaxfit/fe/section_joint.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/fe/section_outline.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * A relief beside a joint of a stack: a stretch where the two sections
   * face each other with a clearance instead of touching, a groove
   * between two of the joint's pieces or an end relief beyond its end.
   */
  struct JointRelief
  {
    double from, to; ///< drawing z (mm)
    /**
     * Where it is judged (drawing z, mm): a groove's inner four fifths (its
     * flanks may slope onto the seats), an end relief's half away from
     * the joint (a chamfer or a sloped relief has opened there by half its
     * depth; nearer the joint any slope touches a little, as it does).
     */
    double judged_from, judged_to;
    double clearance; ///< least radial clearance where judged (mm)
    bool   groove;    ///< between two pieces; false: an end relief

    /** "relief groove" or "end relief". */
    std::string
    name() const
    {
      return groove ? "relief groove" : "end relief";
    }
  };



  /**
   * The sections of a stack of bodies some of which are drawn as sections
   * (`Geometry/<body> section`), the others plain rings given as their
   * rectangles: every outline checked, where each body meets the next one
   * out (its joint), the plane about which the whole stack is symmetric,
   * and the half sections the model meshes.
   *
   * This version models stacks whose every joint is a cylinder, beside
   * which a face across the axis may touch (a shoulder): one piece, or
   * several of one diameter (two seats beside a relief groove in a bore;
   * each piece meshed as a joint, the groove free). A
   * stack whose sections are all symmetric about one plane across the
   * axis through the middle of every joint (a gear wheel with a web
   * between its boss and its rim seat, a flanged sleeve, rings of
   * different lengths centred on one plane) is modelled as the half
   * z >= z_m of each section, shifted so that the plane is z = 0 of the
   * model (u_z = 0 there). Any other (an offset web, a boss longer on one
   * side) is modelled whole in the drawing's coordinates, each body's
   * axial rigid motion held at one of its joint nodes
   * (BodyDiscretization): frictionless cylindrical joints pass no axial
   * force, so that reaction is zero.
   *
   * The two bodies of a joint are meshed by gmsh with the same vertices
   * on it (graded towards its end from Mesh/Cell size), so that their
   * joint nodes coincide: the stack's coupling takes the points of a
   * joint as shared, as it does for rings.
   *
   * A body's section may instead be a gmsh file (`.geo` or `.msh`,
   * read_section_file()): its mesh is kept as it is, and the outline of
   * its boundary (outline_of_mesh()) is what its joints are found from.
   * The neighbour of a file's joint is meshed with the file's nodes on
   * it, so the joint's nodes are again shared; the file's mesh must
   * therefore have a node at each end of the joint (a corner of the
   * neighbour's section lying on one of its faces is refused, naming the
   * point to add), and two files that meet must have the same nodes on
   * their joint. The file's physical curve names are not needed (a
   * stack's joints are where the sections meet). A stack with a file is
   * modelled whole.
   */
  class StackSections
  {
  public:
    /**
     * Parse, check and place the outlines @p texts (one per body, inside
     * out) of the entries @p entries (`Geometry/Sleeve section`, or
     * `Geometry/Sleeve` for a ring drawn as its rectangle).
     * @throws InputError naming the entries at fault.
     */
    StackSections(const std::vector<std::string> &entries,
                  const std::vector<std::string> &texts);

    unsigned int
    n_bodies() const
    {
      return drawn.size();
    }

    /** The outline of body @p b as drawn (the interference not drawn). */
    const SectionOutline &
    drawing(unsigned int b) const
    {
      return *drawn[b];
    }

    /**
     * The modelled section of body @p b: its half z >= 0 in the half
     * model, else as drawn.
     */
    const SectionOutline &
    modelled(unsigned int b) const
    {
      return *half[b];
    }

    /** Drawing z of the model's z = 0, the plane of symmetry (mm). */
    double
    drawing_offset() const
    {
      return z_m;
    }

    /** The radius of joint @p k between bodies k and k + 1 (mm). */
    double
    joint_radius(unsigned int k) const
    {
      return radius[k];
    }

    /**
     * The pieces of joint @p k in the model's z (mm), ascending: one
     * cylinder, or several of one diameter (two seats beside a relief
     * groove); a half model's from its plane on.
     */
    const std::vector<std::pair<double, double>> &
    joint_pieces(unsigned int k) const
    {
      return pieces[k];
    }

    /**
     * The reliefs of joint @p k: the grooves between its pieces, and the
     * stretches beyond its ends where both sections go on facing each
     * other less than a tenth of the joint's radius apart (an end relief:
     * a bore widened at its end, a chamfer), in z order. A relief
     * shallower than the joint's radial interference would touch.
     */
    const std::vector<JointRelief> &
    joint_reliefs(unsigned int k) const
    {
      return reliefs[k];
    }

    /**
     * At drawing z @p z beside joint @p k: the inner section's outside and
     * the outer section's bore (mm; the surfaces that face each other
     * across a relief); a negative outside where a section has none there.
     */
    std::pair<double, double>
    relief_radii(unsigned int k, double z) const;

    /** The largest extent of the sections (mm). */
    double
    extent() const
    {
      double e = 0.;
      for (const auto &outline : drawn)
        e = std::max(e, outline->extent());
      return e;
    }

    /**
     * Whether body @p b's modelled section has a straight surface r = @p r
     * that runs on both sides of model z @p z (not a corner there; in a
     * half model a surface from the plane runs on through its mirror).
     */
    bool
    surface_through(unsigned int b, double r, double z) const;

    /**
     * The first relief of joint @p k (joint_reliefs()) that a largest
     * diametral interference @p U (mm) would close: its clearance no more
     * than U / 2, so its bottom would touch, which is not modelled.
     */
    std::optional<JointRelief>
    closing_relief(const unsigned int k, const double U) const
    {
      for (const JointRelief &relief : reliefs[k])
        if (relief.clearance <= U / 2.)
          return relief;
      return std::nullopt;
    }

    /** The pieces of joint @p k in the drawing's z (mm), ascending. */
    const std::vector<std::pair<double, double>> &
    joint_drawn_pieces(unsigned int k) const
    {
      return drawn_pieces[k];
    }

    /** The half length of joint @p k, from end to end (mm). */
    double
    joint_half_length(unsigned int k) const
    {
      return half_length[k];
    }

    /**
     * The face across the axis beside joint @p k where its two sections
     * also touch (a wheel's end face on a shaft's shoulder), in the
     * drawing's coordinates, if any. Its joint is frictionless and nothing
     * loads the bodies along the axis, so the face carries no force and is
     * modelled free (shoulder_beside()).
     */
    const std::optional<ShoulderFace> &
    shoulder_face(unsigned int k) const
    {
      return shoulders[k];
    }

    /**
     * Model z at which a whole model holds body @p b axially: the end of
     * its bore joint at a shoulder face, else of its outer joint at one;
     * none without a shoulder (then the joint's middle).
     */
    std::optional<double>
    axial_pin_z(unsigned int b) const;

    /**
     * Whether the model is the half z >= 0 of a stack symmetric about a
     * plane through every joint's middle (else the sections whole, in the
     * drawing's coordinates).
     */
    bool
    half_model() const
    {
      return half_model_;
    }

    /**
     * Model z of joint @p k's ends and middle (mm): 0, its half length and
     * 0 in the half model.
     */
    double
    joint_start(unsigned int k) const
    {
      return start[k];
    }
    double
    joint_end(unsigned int k) const
    {
      return start[k] + (half_model_ ? 1. : 2.) * half_length[k];
    }
    double
    joint_middle(unsigned int k) const
    {
      return half_model_ ? 0. : start[k] + half_length[k];
    }

    /**
     * The smallest radius of body @p b's section (its bore; 0 if it
     * reaches the axis) and its largest (mm).
     */
    double
    bore_radius(unsigned int b) const;
    double
    outer_radius(unsigned int b) const;

    /**
     * The plain ring DIN 7190's estimate puts in place of body @p b
     * (diameters in mm): from the joint inside it (the innermost body:
     * its bore) to the joint outside it (the outermost: its outer
     * diameter averaged over its joint, mean_outer_diameter()).
     */
    double
    equivalent_inner_diameter(unsigned int b) const;
    double
    equivalent_outer_diameter(unsigned int b) const;

    /** The cells of body @p b's gmsh file, unrefined; 0 for an outline. */
    unsigned int
    file_cells(const unsigned int b) const
    {
      return files[b] ? files[b]->n_active_cells() : 0;
    }

    /** Whether body @p b's section is a gmsh file (its mesh kept). */
    bool
    from_file(const unsigned int b) const
    {
      return files[b] != nullptr;
    }

    /** The axial extent of body @p b's section (mm). */
    double
    length(unsigned int b) const;

    /**
     * Mesh every modelled section: its joints tagged (the inner one
     * BoundaryId::inner_joint of a body in the middle, else
     * BoundaryId::joint) with the same vertices in both bodies of each
     * joint, the plane z = 0 BoundaryId::symmetry, r = 0 BoundaryId::axis,
     * the innermost body's bore BoundaryId::bore and the outermost body's
     * largest diameter BoundaryId::outer (for Operation's pressures),
     * every other face SectionId::free; refined @p
     * settings.global_refinements times.
     */
    std::vector<std::shared_ptr<Triangulation<2>>>
    make_meshes(const SectionMeshSettings &settings) const;

  private:
    std::vector<std::unique_ptr<SectionOutline>> drawn, half;
    std::vector<double>                          radius, half_length;
    std::vector<double>                          outer_mean; ///< per joint
    std::vector<std::optional<ShoulderFace>>     shoulders;  ///< per joint
    std::vector<double>                          start; ///< joints' model z
    /** Per joint: its pieces, (lo, hi) in the drawing's and the model's z. */
    std::vector<std::vector<std::pair<double, double>>> drawn_pieces, pieces;
    std::vector<std::vector<JointRelief>>               reliefs; ///< per joint
    /** Per body: the mesh of its gmsh file, unrefined; null: an outline. */
    std::vector<std::shared_ptr<const Triangulation<2>>> files;
    std::vector<std::string> file_paths; ///< per body, as given (resolved)
    /**
     * Per joint: the z of a file's mesh nodes on it (model z, ascending,
     * both ends included); empty if neither body is a file.
     */
    std::vector<std::vector<double>> file_joint_z;
    double                           z_m         = 0.;
    bool                             half_model_ = true;

    /**
     * The z of the vertices of the mesh of the file of body @p b on joint
     * @p k's pieces (ascending, merged within @p tol).
     * @throws InputError naming the entry @p entry if it has none at an end
     * of a piece, where the neighbour's section has its corner.
     */
    std::vector<double>
    file_nodes_on_joint(unsigned int       b,
                        unsigned int       k,
                        double             tol,
                        const std::string &entry,
                        const std::string &other) const;

    /**
     * The boundary ids of the copy @p mesh of body @p b's file: its joints
     * (BoundaryId::inner_joint or BoundaryId::joint as make_meshes() says),
     * r = 0 the axis, every other face SectionId::free.
     */
    void
    tag_file_mesh(Triangulation<2> &mesh, unsigned int b) const;

    /** Whether model z @p z lies on a piece of joint @p k (within @p tol). */
    bool
    on_piece(unsigned int k, double z, double tol) const;

    /**
     * The vertices of piece @p i of joint @p k between its ends, ascending:
     * a file's nodes there, else graded from the cell size at its ends.
     */
    std::vector<Point<2>>
    joint_vertices(unsigned int               k,
                   unsigned int               i,
                   const SectionMeshSettings &settings) const;
  };
} // namespace coaxfit

#endif
