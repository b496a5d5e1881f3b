#ifndef coaxfit_section_outline_h
#define coaxfit_section_outline_h

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * One corner of a section outline as the user writes it: the axial
   * position z and the diameter D (mm, drawing coordinates) and, when the
   * corner is rounded, the fillet radius R (mm; 0: a sharp corner).
   */
  struct OutlineCorner
  {
    double z             = 0.; ///< axial position (mm)
    double diameter      = 0.; ///< diameter (mm), >= 0
    double fillet_radius = 0.; ///< 0: sharp; > 0: rounded with this radius
  };

  /**
   * One edge of the boundary of a section in (r, z) coordinates (x = r,
   * y = z, mm): a straight segment or a circular arc of less than a half
   * turn, from start to end along the counter-clockwise boundary.
   */
  struct OutlineEdge
  {
    Point<2> start; ///< (r, z), mm
    Point<2> end;   ///< (r, z), mm

    /** For an arc its radius (> 0); 0 for a straight segment. */
    double radius = 0.;
    /** For an arc its centre; unused for a straight segment. */
    Point<2> centre;
    /**
     * For an arc the signed angle swept from start to end (radians,
     * positive counter-clockwise: a convex corner; negative: a re-entrant
     * one); 0 for a straight segment.
     */
    double sweep = 0.;
    /**
     * A straight edge: the index i of the side of the polygon (from corner
     * i to corner i + 1) it lies on; an arc: the index of the corner it
     * rounds. Indices refer to SectionOutline::corners().
     */
    unsigned int origin = 0;

    /** Whether the edge is a circular arc. */
    bool
    is_arc() const
    {
      return radius > 0.;
    }

    /** The length of the edge (mm). */
    double
    length() const;

    /** The point at the fraction @p t in [0, 1] of the edge's length. */
    Point<2>
    point_at(double t) const;

    /**
     * The fraction t in [0, 1] of the edge's length at which the point
     * closest to @p p lies, and in @p distance (if given) how far @p p is
     * from the edge (mm).
     */
    double
    parameter_of(const Point<2> &p, double *distance = nullptr) const;
  };

  /**
   * The (r, z) section of an axisymmetric body given as a closed polygon in
   * drawing coordinates, as in a parameter entry such as
   * `Geometry/Hub section`:
   *
   *     z, D; z, D; z, D, R; ...; z, D
   *
   * Each point is an axial position z and a diameter D (mm); the edges
   * between consecutive points are straight. A third number R rounds that
   * corner with a fillet of radius R (mm): an arc tangent to both edges,
   * which replaces the corner (on a convex corner it removes material, on a
   * re-entrant one it adds material).
   *
   * <h3>Rules (checked by the constructor, which throws InputError)</h3>
   * - The polygon is closed explicitly: its last point repeats its first
   *   (z and D; a fillet radius may be written on either or on both, then
   *   equal). An outline whose last point differs from its first is
   *   refused as open: a forgotten point must not silently close the
   *   section with an unintended edge.
   * - At least three distinct points; D >= 0 (D = 0 lies on the axis);
   *   no two consecutive points equal (an edge of zero length).
   * - No self-intersection: two edges that are not neighbours do not meet
   *   or touch, and neighbouring edges do not fold back onto each other.
   * - A fillet has R > 0, lies at a corner off the axis (D > 0) where the
   *   outline turns (not on a straight line), and its tangent points stay
   *   within the two edges of its corner; two fillets on one edge do not
   *   overlap (their tangent points may meet). The rounded outline does not
   *   intersect itself either.
   *
   * Either orientation is accepted; the corners are stored counter-clockwise
   * in (r, z) (x = r = D / 2, y = z), which makes the section lie to the
   * left of each edge.
   */
  class SectionOutline
  {
  public:
    /**
     * Parse and check the outline @p text of the parameter entry @p entry
     * (e.g. "Geometry/Hub section", used in the messages). Points are
     * separated by ';', the numbers of a point by ','; blanks are ignored
     * and one trailing ';' is allowed.
     *
     * @throws InputError with one line that names @p entry, what is wrong
     * and what is allowed.
     */
    static SectionOutline
    parse(const std::string &text, const std::string &entry);

    /**
     * Check the closed polygon @p points (its last point repeating its
     * first) as parse() does and build the outline.
     */
    SectionOutline(const std::vector<OutlineCorner> &points,
                   const std::string                &entry);

    /** The name of the parameter entry the outline came from. */
    const std::string &
    entry() const;

    /**
     * The distinct corners, counter-clockwise in (r, z), each once (the
     * closing point is not repeated).
     */
    const std::vector<OutlineCorner> &
    corners() const;

    /** Corner @p i as an (r, z) point (mm). */
    Point<2>
    corner_point(unsigned int i) const;

    /**
     * Whether corner @p i is re-entrant (the section's interior angle there
     * exceeds 180 degrees), where stresses concentrate.
     */
    bool
    is_reentrant(unsigned int i) const;

    /**
     * The boundary, counter-clockwise, as straight edges and fillet arcs:
     * for corner i with a fillet, the arc comes between the straight edges
     * of sides i - 1 and i. A side whose two fillets' tangent points meet
     * has no straight edge.
     */
    const std::vector<OutlineEdge> &
    edges() const;

    /** The area of the section (mm^2), arcs included exactly. */
    double
    area() const;

    /**
     * The volume of the body of revolution, 2 pi times the integral of r
     * over the section (Pappus), arcs included exactly (mm^3).
     */
    double
    volume() const;

    /** The length of the boundary (mm), arcs included. */
    double
    perimeter() const;

    /** The largest distance between two corners (mm): the outline's size. */
    double
    extent() const;

  private:
    std::string                entry_name;
    std::vector<OutlineCorner> corner_list;
    std::vector<OutlineEdge>   edge_list;
  };
} // namespace coaxfit

#endif
