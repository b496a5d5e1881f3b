#include <deal.II/base/numbers.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/gmsh_session.h>
#include <coaxfit/fe/gmsh_transfer.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_mesh.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <gmsh.h>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    std::string
    where(const Point<2> &p)
    {
      return "(z = " + number(p[1], 6) + ", D = " + number(2. * p[0], 6) + ")";
    }

    /** A place on the outline: its arc length from the start of edge 0. */
    struct Place
    {
      unsigned int edge;      ///< index into SectionOutline::edges()
      double       t;         ///< fraction of that edge
      double       arclength; ///< mm from the start of edge 0
    };

    /** A piece of an outline edge between two consecutive vertices. */
    struct Piece
    {
      unsigned int       edge;
      double             t0, t1;
      types::boundary_id boundary_id;
      bool               single = false; ///< exactly one cell
    };

    Place
    locate(const SectionOutline &outline,
           const Point<2>       &p,
           const double          tol,
           const std::string    &what)
    {
      const auto &edges    = outline.edges();
      double      best     = std::numeric_limits<double>::max();
      Place       place    = {0, 0., 0.};
      double      position = 0.;
      for (unsigned int k = 0; k < edges.size(); ++k)
        {
          double       distance = 0.;
          const double t        = edges[k].parameter_of(p, &distance);
          if (distance < best)
            {
              best  = distance;
              place = {k, t, position + t * edges[k].length()};
            }
          position += edges[k].length();
        }
      if (best > tol)
        throw InputError("parameter " + outline.entry() + ": " + what + " "
                         + where(p) + " does not lie on the outline (it is "
                         + number(best, 6) + " mm away)");
      return place;
    }

    /** The forward interval [from, from + length] of a tagged segment. */
    struct Interval
    {
      double             from, length;
      types::boundary_id boundary_id;
      bool               fixed; ///< one cell between its vertices
    };
  } // namespace



  TaggedSegment
  TaggedSegment::from_drawing(const double             z_start,
                              const double             diameter_start,
                              const double             z_end,
                              const double             diameter_end,
                              const types::boundary_id boundary_id)
  {
    return {Point<2>(diameter_start / 2., z_start),
            Point<2>(diameter_end / 2., z_end),
            boundary_id};
  }



  bool
  make_section_mesh(Triangulation<2>          &triangulation,
                    const SectionOutline      &outline,
                    const SectionBoundary     &boundary,
                    const SectionMeshSettings &settings)
  {
    const std::string &entry     = outline.entry();
    const auto        &edges     = outline.edges();
    const double       perimeter = outline.perimeter();
    const double       tol       = 1e-6 * outline.extent();

    // The settings.
    const double h0 = settings.cell_size, q = settings.grading_ratio;
    const double h_max
      = settings.max_cell_size > 0. ? settings.max_cell_size : 8. * h0;
    if (!(h0 > 0.) || !std::isfinite(h0))
      throw InputError("parameter " + entry + ": cell size " + number(h0, 6)
                       + " mm; it must be > 0");
    if (!(q >= 1.) || !(q <= 10.))
      throw InputError("parameter " + entry + ": grading ratio " + number(q, 6)
                       + "; it must lie in [1, 10]");
    if (!(h_max >= h0) || !std::isfinite(h_max))
      throw InputError("parameter " + entry + ": largest cell size "
                       + number(h_max, 6) + " mm is below the cell size "
                       + number(h0, 6) + " mm");
    if (perimeter / h0 > 1e5)
      throw InputError("parameter " + entry + ": cell size " + number(h0, 6)
                       + " mm gives more than 100000 cells along the outline ("
                       + number(perimeter, 6) + " mm long); use a larger one");
    if (!boundary.edge_ids.empty() && boundary.edge_ids.size() != edges.size())
      throw std::logic_error(
        "make_section_mesh: " + std::to_string(boundary.edge_ids.size())
        + " edge ids for " + std::to_string(edges.size()) + " edges");

    // Where the edges are split: the ends of the tagged segments.
    std::vector<std::vector<double>> splits(edges.size());
    std::vector<Interval>            intervals;
    std::vector<Point<2>>            sources = settings.refinement_points;
    for (const TaggedSegment &segment : boundary.segments)
      {
        const Place a
          = locate(outline, segment.start, tol, "tagged segment start");
        const Place b = locate(outline, segment.end, tol, "tagged segment end");
        double      forward = b.arclength - a.arclength;
        if (forward < 0.)
          forward += perimeter;
        if (std::min(forward, perimeter - forward) <= tol)
          throw InputError("parameter " + entry + ": a tagged segment from "
                           + where(segment.start) + " to " + where(segment.end)
                           + " has no length");
        const bool fixed = !segment.vertices.empty();
        if (forward <= perimeter / 2.)
          intervals.push_back(
            {a.arclength, forward, segment.boundary_id, fixed});
        else
          intervals.push_back(
            {b.arclength, perimeter - forward, segment.boundary_id, fixed});
        for (const Point<2> &v : segment.vertices)
          {
            const Place p = locate(outline, v, tol, "tagged segment vertex");
            splits[p.edge].push_back(p.t);
          }
        for (const Place &p : {a, b})
          {
            splits[p.edge].push_back(p.t);
            if (segment.refine_ends)
              sources.push_back(edges[p.edge].point_at(p.t));
          }
      }
    // Stresses concentrate at re-entrant corners and their fillets.
    std::vector<unsigned int> reentrant_arcs;
    for (unsigned int i = 0; i < outline.corners().size(); ++i)
      if (outline.is_reentrant(i) && outline.corners()[i].fillet_radius == 0.)
        sources.push_back(outline.corner_point(i));
    for (unsigned int k = 0; k < edges.size(); ++k)
      if (edges[k].is_arc() && edges[k].sweep < 0.)
        reentrant_arcs.push_back(k);

    // The pieces between consecutive vertices, each with its boundary id.
    std::vector<Piece> pieces;
    {
      double position = 0.;
      for (unsigned int k = 0; k < edges.size(); ++k)
        {
          const double        length = edges[k].length();
          std::vector<double> t      = {0., 1.};
          for (const double s : splits[k])
            if (s * length > tol && (1. - s) * length > tol)
              t.push_back(s);
          std::sort(t.begin(), t.end());
          t.erase(std::unique(t.begin(),
                              t.end(),
                              [&](const double x, const double y) {
                                return (y - x) * length <= tol;
                              }),
                  t.end());
          for (unsigned int i = 0; i + 1 < t.size(); ++i)
            {
              Piece piece = {k, t[i], t[i + 1], SectionId::free};
              if (!boundary.edge_ids.empty())
                piece.boundary_id = boundary.edge_ids[k];
              else if (!edges[k].is_arc() && edges[k].start[0] <= tol
                       && edges[k].end[0] <= tol)
                piece.boundary_id = BoundaryId::axis;
              const double middle = position + 0.5 * (t[i] + t[i + 1]) * length;
              for (const Interval &in : intervals)
                {
                  double offset = middle - in.from;
                  if (offset < 0.)
                    offset += perimeter;
                  if (offset < in.length)
                    {
                      piece.boundary_id = in.boundary_id;
                      piece.single      = in.fixed;
                    }
                }
              pieces.push_back(piece);
            }
          position += length;
        }
    }

    // The size of the cells at a point (mm).
    const auto size_at = [&](const Point<2> &p) {
      double h = sources.empty() && reentrant_arcs.empty() ? h0 : h_max;
      for (const Point<2> &s : sources)
        h = std::min(h, h0 + (q - 1.) * p.distance(s));
      for (const unsigned int k : reentrant_arcs)
        {
          double distance = 0.;
          edges[k].parameter_of(p, &distance);
          h = std::min(h, h0 + (q - 1.) * distance);
        }
      return std::min(h, h_max);
    };

    std::map<int, CurveTag>                    curves;
    std::map<types::manifold_id, Point<2>>     arc_centres;
    std::map<unsigned int, types::manifold_id> arc_manifold;
    for (unsigned int k = 0; k < edges.size(); ++k)
      if (edges[k].is_arc())
        {
          const types::manifold_id id
            = SectionId::first_arc + arc_centres.size();
          arc_manifold[k] = id;
          arc_centres[id] = edges[k].centre;
        }

    bool             full_quad = false;
    std::vector<int> piece_curves; // the gmsh curve of each piece
    // Curve tag: largest cell on an arc (read by the size callback, which
    // gmsh calls until the mesh is complete).
    std::map<int, double> arc_cap;
    run_gmsh_session("parameter " + entry, [&]() {
      // The model, meshed with the recombination @p algorithm (from scratch:
      // clearing a mesh loses the transfinite curves in gmsh 4.11).
      // extra_piece (if a piece index) gets extra_nodes nodes, uniformly.
      const auto mesh_with = [&](const int          algorithm,
                                 const unsigned int extra_piece,
                                 const int          extra_nodes) {
        curves.clear();
        piece_curves.clear();
        gmsh::model::add("section");
        // One gmsh point per vertex of the outline, shared by its two pieces.
        std::vector<int> first_point(pieces.size());
        for (unsigned int i = 0; i < pieces.size(); ++i)
          {
            const Point<2> p = edges[pieces[i].edge].point_at(pieces[i].t0);
            first_point[i]   = gmsh::model::geo::addPoint(p[0], p[1], 0.);
          }
        arc_cap.clear();
        std::vector<int> single_curves; // one cell each
        std::vector<int> loop;
        for (unsigned int i = 0; i < pieces.size(); ++i)
          {
            const OutlineEdge &edge = edges[pieces[i].edge];
            const int          a    = first_point[i],
                      b             = first_point[(i + 1) % pieces.size()];
            int      curve;
            CurveTag tag;
            tag.boundary_id = pieces[i].boundary_id;
            if (edge.is_arc())
              {
                const int centre = gmsh::model::geo::addPoint(edge.centre[0],
                                                              edge.centre[1],
                                                              0.);
                curve            = gmsh::model::geo::addCircleArc(a, centre, b);
                tag.manifold_id  = arc_manifold[pieces[i].edge];
                // At least 6 cells per quarter circle.
                arc_cap[curve] = edge.radius * numbers::PI / 12.;
              }
            else
              curve = gmsh::model::geo::addLine(a, b);
            curves[curve] = tag;
            loop.push_back(curve);
            piece_curves.push_back(curve);
            if (i == extra_piece)
              gmsh::model::geo::mesh::setTransfiniteCurve(curve, extra_nodes);
            if (pieces[i].single)
              single_curves.push_back(curve);
          }
        const int wire = gmsh::model::geo::addCurveLoop(loop);
        gmsh::model::geo::addPlaneSurface({wire});
        for (const int curve : single_curves)
          gmsh::model::geo::mesh::setTransfiniteCurve(curve, 2);
        gmsh::model::geo::synchronize();

        gmsh::model::mesh::setSizeCallback([&](const int    dim,
                                               const int    tag,
                                               const double x,
                                               const double y,
                                               const double) {
          double h = size_at(Point<2>(x, y));
          if (dim == 1 && arc_cap.count(tag) > 0)
            h = std::min(h, arc_cap[tag]);
          return h;
        });
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::option::setNumber("Mesh.Algorithm", 6); // frontal-Delaunay
        gmsh::option::setNumber("Mesh.RecombineAll", 1);
        gmsh::option::setNumber("Mesh.RecombinationAlgorithm", algorithm);
        gmsh::model::mesh::generate(1);
        check_gmsh_error("parameter " + entry);
      };
      const bool has_fixed
        = std::any_of(pieces.begin(), pieces.end(), [](const Piece &p) {
            return p.single;
          });
      // Blossom recombines all triangles only if the number of boundary
      // cells is even: if it is odd, the coarsest piece that is not fixed
      // gets one cell more (uniform on that piece). True if the mesh is
      // all quadrilaterals.
      const unsigned int none    = numbers::invalid_unsigned_int;
      const auto         attempt = [&]() {
        mesh_with(settings.full_quad && !has_fixed ? 3 : 1, none, 0);
        if (!settings.full_quad || has_fixed)
          {
            std::size_t  total = 0, best_cells = 0;
            unsigned int best      = none;
            double       best_size = 0.;
            for (unsigned int i = 0; i < pieces.size(); ++i)
              {
                std::vector<int>                      types;
                std::vector<std::vector<std::size_t>> tags, nodes;
                gmsh::model::mesh::getElements(
                  types, tags, nodes, 1, piece_curves[i]);
                const std::size_t cells = tags.empty() ? 0 : tags[0].size();
                total += cells;
                const OutlineEdge &edge = edges[pieces[i].edge];
                const double       size
                  = (pieces[i].t1 - pieces[i].t0) * edge.length() / cells;
                if (!pieces[i].single && !edge.is_arc() && size > best_size)
                  {
                    best       = i;
                    best_cells = cells;
                    best_size  = size;
                  }
              }
            if (total % 2 == 1 && best != none)
              {
                gmsh::model::remove();
                mesh_with(1, best, static_cast<int>(best_cells) + 2);
              }
          }
        gmsh::model::mesh::generate(2);
        check_gmsh_error("parameter " + entry);
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
        return std::all_of(types.begin(), types.end(), [](const int t) {
          return t == 3;
        });
      };
      // With fixed pieces, full quadrilaterals come from splitting every
      // cell of the mixed mesh (gmsh's subdivision: each boundary cell at
      // its middle, so that two bodies split alike still match); without,
      // from the full-quad variant of Blossom.
      const bool quadrilaterals = attempt();
      full_quad                 = settings.full_quad || !quadrilaterals;
      if (full_quad && has_fixed)
        {
          gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
          gmsh::model::mesh::refine();
          check_gmsh_error("parameter " + entry);
        }
      else if (full_quad && !settings.full_quad)
        {
          gmsh::model::remove();
          mesh_with(3, none, 0);
          gmsh::model::mesh::generate(2);
          check_gmsh_error("parameter " + entry);
        }
      transfer_gmsh_mesh(triangulation,
                         curves,
                         arc_centres,
                         SectionId::free,
                         "parameter " + entry);
    });
    triangulation.refine_global(settings.global_refinements);
    return full_quad;
  }
} // namespace coaxfit
