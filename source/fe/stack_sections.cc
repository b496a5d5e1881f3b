#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_file.h>
#include <coaxfit/fe/section_joint.h>
#include <coaxfit/fe/section_placement.h>
#include <coaxfit/fe/section_symmetry.h>
#include <coaxfit/fe/stack_sections.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace coaxfit
{
  namespace
  {
    /** The lowest and highest z of an outline's corners (mm). */
    std::pair<double, double>
    z_range(const SectionOutline &outline)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const OutlineEdge &e : outline.edges())
        for (const double t : {0., 1.})
          {
            lo = std::min(lo, e.point_at(t)[1]);
            hi = std::max(hi, e.point_at(t)[1]);
          }
      return {lo, hi};
    }
  } // namespace


  StackSections::StackSections(const std::vector<std::string> &entries,
                               const std::vector<std::string> &texts)
  {
    const unsigned int N = texts.size();
    files.resize(N);
    file_paths.resize(N);
    for (unsigned int b = 0; b < N; ++b)
      if (is_section_file_name(texts[b]))
        {
          // A gmsh file: its mesh as it is, its boundary the outline.
          const std::string path = trimmed(texts[b]);
          auto              mesh = std::make_shared<Triangulation<2>>();
          read_section_file(*mesh, path, entries[b], 0, false);
          drawn.push_back(std::make_unique<SectionOutline>(
            outline_of_mesh(*mesh, entries[b], path)));
          files[b]      = mesh;
          file_paths[b] = path;
        }
      else
        drawn.push_back(std::make_unique<SectionOutline>(
          SectionOutline::parse(texts[b], entries[b])));
    const double tol = 1e-6 * extent();

    // Each body meets the next one out on a cylinder: one piece, or
    // several of one diameter (a relief groove between two seats).
    std::vector<double> z_lo(N - 1), z_hi(N - 1);
    drawn_pieces.resize(N - 1);
    for (unsigned int k = 0; k + 1 < N; ++k)
      {
        const std::string both
          = "parameters " + entries[k] + " and " + entries[k + 1] + ": ";
        std::vector<JointPiece> pieces
          = merged(find_joint(*drawn[k], *drawn[k + 1]), tol);
        // A face across the axis beside the joint (a wheel against a
        // shaft's shoulder) is set aside: it carries no force (below).
        std::vector<JointPiece> faces = faces_across_axis(pieces, tol);
        // A piece off the first one's cylinder (a stepped seat).
        const auto off_cylinder = [&](const JointPiece &piece) {
          return std::abs(piece.start[0] - pieces[0].start[0]) > tol
                 || std::abs(piece.end[0] - pieces[0].start[0]) > tol;
        };
        const auto on_one_cylinder = [&]() {
          return !pieces.empty()
                 && std::none_of(pieces.begin(), pieces.end(), off_cylinder);
        };
        // Sections that meet within the drawing tolerance: corners on the
        // joint's cylinder moved onto it exactly, so that both meshes have
        // it (a file's mesh is not moved).
        if (on_one_cylinder())
          {
            double lo = pieces[0].start[1], hi = lo;
            for (const JointPiece &piece : pieces)
              for (const double z : {piece.start[1], piece.end[1]})
                {
                  lo = std::min(lo, z);
                  hi = std::max(hi, z);
                }
            const Point<2> a(pieces[0].start[0], lo), c(pieces[0].start[0], hi);
            for (const unsigned int b : {k, k + 1})
              if (!files[b])
                drawn[b] = std::make_unique<SectionOutline>(
                  snapped(*drawn[b], a, c, tol));
            pieces = merged(find_joint(*drawn[k], *drawn[k + 1]), tol);
            faces  = faces_across_axis(pieces, tol);
          }
        for (const JointPiece &joint : pieces)
          {
            if (std::abs(joint.start[0] - joint.end[0]) > tol)
              throw InputError(
                both + "the joint from z = " + number(joint.start[1], 6)
                + ", D = " + number(2. * joint.start[0], 6)
                + " to z = " + number(joint.end[1], 6)
                + ", D = " + number(2. * joint.end[0], 6)
                + " is not a cylinder; a joint of a stack is a cylinder in "
                  "this version (taper fits are modelled for two bodies)");
            if (joint.normal[0] < 0.)
              throw InputError(both
                               + "the first section lies outside the second "
                                 "at their joint; Assembly/Bodies lists "
                                 "the bodies inside out");
          }
        if (pieces.empty())
          throw InputError(
            both
            + "the sections meet only on a face across the axis; a "
              "joint of a stack needs a cylinder the two bodies share "
              "(drawn at the nominal joint diameter, the interference "
              "given in Fit)");
        if (!on_one_cylinder())
          throw InputError(
            both + "the sections meet on cylinders of "
            + std::to_string(pieces.size())
            + " pieces with different diameters (D = "
            + number(2. * pieces[0].start[0], 6) + " and "
            + number(
              2.
                * std::find_if(pieces.begin(), pieces.end(), off_cylinder)
                    ->start[0],
              6)
            + "); a joint of a stack is one diameter in this version "
              "(a stepped seat is not modelled); allowed: pieces of one "
              "diameter, such as two seats beside a relief groove");
        radius.push_back(pieces[0].start[0]);
        z_lo[k] = std::numeric_limits<double>::infinity();
        z_hi[k] = -z_lo[k];
        for (const JointPiece &piece : pieces)
          {
            const double lo = std::min(piece.start[1], piece.end[1]),
                         hi = std::max(piece.start[1], piece.end[1]);
            drawn_pieces[k].emplace_back(lo, hi);
            z_lo[k] = std::min(z_lo[k], lo);
            z_hi[k] = std::max(z_hi[k], hi);
          }
        std::sort(drawn_pieces[k].begin(), drawn_pieces[k].end());
        // The reliefs: each groove between pieces, and beyond the joint's
        // ends the stretches where both sections go on; each one's least
        // clearance where it is judged (JointRelief): the outer section's
        // bore less the inner section's outside at 201 planes, a plane
        // where either section has no surface left out.
        reliefs.emplace_back();
        const auto relief = [&](const double a,
                                const double b,
                                const double from,
                                const double to,
                                const bool   groove) {
          JointRelief r{
            a, b, from, to, std::numeric_limits<double>::infinity(), groove};
          for (unsigned int s = 0; s <= 200; ++s)
            {
              const auto [outside, bore]
                = relief_radii(k, from + s / 200. * (to - from));
              if (outside >= 0. && std::isfinite(bore))
                r.clearance = std::min(r.clearance, bore - outside);
            }
          // An end relief deeper than a tenth of the joint's radius cannot
          // close (interferences and deformations are of the order of
          // 1e-3 of it): a wheel's rim wider than its hub faces the shaft
          // across tens of millimetres, no relief.
          if (std::isfinite(r.clearance)
              && (groove || r.clearance < 0.1 * radius[k]))
            reliefs[k].push_back(r);
        };
        const auto [in_lo, in_hi]   = z_range(*drawn[k]);
        const auto [out_lo, out_hi] = z_range(*drawn[k + 1]);
        const double below          = std::max(in_lo, out_lo),
                     above          = std::min(in_hi, out_hi);
        // An end relief judged up to the bodies' end (a plane just inside
        // it: on the end face itself the bore has no crossing).
        if (const double L = z_lo[k] - below; L > tol)
          relief(below, z_lo[k], below + 1e-6 * L, below + 0.5 * L, false);
        for (unsigned int i = 0; i + 1 < drawn_pieces[k].size(); ++i)
          {
            const double a = drawn_pieces[k][i].second,
                         b = drawn_pieces[k][i + 1].first;
            relief(a, b, a + 0.1 * (b - a), b - 0.1 * (b - a), true);
          }
        if (const double L = above - z_hi[k]; L > tol)
          relief(z_hi[k], above, z_hi[k] + 0.5 * L, above - 1e-6 * L, false);
        shoulders.push_back(
          shoulder_beside(faces, z_lo[k], z_hi[k], tol, both));
        half_length.push_back(0.5 * (z_hi[k] - z_lo[k]));
        outer_mean.push_back(
          mean_outer_diameter(*drawn[k + 1], z_lo[k], z_hi[k]));
      }

    // Bodies that are not neighbours must not overlap, nor touch: that
    // contact is not modelled.
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = i + 2; j < N; ++j)
        {
          check_apart(*drawn[i], *drawn[j]);
          std::vector<JointPiece> touching;
          try
            {
              touching = find_joint(*drawn[i], *drawn[j]);
            }
          catch (const InputError &)
            {
              // They do not meet: as it should be.
            }
          if (!touching.empty())
            throw InputError(
              "parameters " + entries[i] + " and " + entries[j]
              + ": the sections touch from z = "
              + number(touching[0].start[1], 6)
              + ", D = " + number(2. * touching[0].start[0], 6)
              + " to z = " + number(touching[0].end[1], 6)
              + ", D = " + number(2. * touching[0].end[0], 6)
              + ", but they are not neighbours in Assembly/Bodies, whose "
                "joints alone are modelled; allowed: only neighbours meet");
        }

    // One plane of symmetry through every joint's middle: the half model;
    // anything else is modelled whole.
    std::vector<const SectionOutline *> all;
    for (const auto &outline : drawn)
      all.push_back(outline.get());
    // A file's mesh is not cut: a stack with a file is modelled whole.
    const std::optional<double> plane     = mirror_plane(all);
    bool                        symmetric = plane.has_value();
    for (unsigned int b = 0; b < N; ++b)
      symmetric = symmetric && !files[b];
    for (unsigned int k = 0; k + 1 < N && symmetric; ++k)
      symmetric = std::abs(*plane - 0.5 * (z_lo[k] + z_hi[k])) <= tol;
    for (unsigned int b = 0; b < N && symmetric; ++b)
      {
        std::optional<SectionOutline> part = half_outline(*drawn[b], *plane);
        symmetric                          = part.has_value();
        if (symmetric)
          half.push_back(
            std::make_unique<SectionOutline>(shifted(*part, -*plane)));
      }
    if (symmetric)
      {
        z_m = *plane;
        for (unsigned int k = 0; k + 1 < N; ++k)
          start.push_back(0.);
      }
    else
      {
        half.clear();
        for (unsigned int b = 0; b < N; ++b)
          half.push_back(std::make_unique<SectionOutline>(*drawn[b]));
        z_m   = 0.;
        start = z_lo;
      }
    half_model_ = symmetric;

    // The joints' pieces in the model's z: a half model's from the plane
    // on (a piece across it from z = 0, one beyond it whole).
    pieces.assign(N - 1, {});
    for (unsigned int k = 0; k + 1 < N; ++k)
      for (auto [lo, hi] : drawn_pieces[k])
        {
          lo -= z_m;
          hi -= z_m;
          if (half_model_)
            {
              if (hi <= tol)
                continue;
              lo = lo <= tol ? 0. : lo;
            }
          pieces[k].emplace_back(lo, hi);
        }

    // A file's nodes on its joints: its neighbour is meshed with them.
    file_joint_z.assign(N - 1, {});
    for (unsigned int k = 0; k + 1 < N; ++k)
      for (const unsigned int b : {k, k + 1})
        if (files[b])
          {
            const unsigned int  other = b == k ? k + 1 : k;
            std::vector<double> z
              = file_nodes_on_joint(b, k, tol, entries[b], entries[other]);
            if (file_joint_z[k].empty())
              file_joint_z[k] = z;
            else
              {
                bool same = z.size() == file_joint_z[k].size();
                for (unsigned int i = 0; same && i < z.size(); ++i)
                  same
                    = std::abs(z[i] - file_joint_z[k][i]) <= 1e-10 * extent();
                if (!same)
                  throw InputError(
                    "parameters " + entries[k] + " and " + entries[k + 1]
                    + ": both are gmsh files, with "
                    + std::to_string(file_joint_z[k].size()) + " and "
                    + std::to_string(z.size())
                    + " nodes on their joint from z = " + number(z_lo[k], 6)
                    + " to " + number(z_hi[k], 6)
                    + " that are not the same; a stack's joint shares its "
                      "nodes: give both files the same points on it, or "
                      "draw one of them as an outline");
              }
          }
  }



  std::vector<double>
  StackSections::file_nodes_on_joint(const unsigned int b,
                                     const unsigned int k,
                                     const double       tol,
                                     const std::string &entry,
                                     const std::string &other) const
  {
    const double        R = radius[k];
    std::vector<double> z;
    for (const auto &cell : files[b]->active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && std::abs(face->vertex(0)[0] - R) <= tol
            && std::abs(face->vertex(1)[0] - R) <= tol)
          for (const unsigned int v : {0u, 1u})
            if (on_piece(k, face->vertex(v)[1], tol))
              z.push_back(face->vertex(v)[1]);
    std::sort(z.begin(), z.end());
    std::vector<double> unique;
    for (const double zi : z)
      if (unique.empty() || zi - unique.back() > tol)
        unique.push_back(zi);
    std::vector<double> ends;
    for (const auto &[lo, hi] : pieces[k])
      ends.insert(ends.end(), {lo, hi});
    for (const double end : ends)
      {
        const auto near
          = std::find_if(unique.begin(), unique.end(), [&](const double zi) {
              return std::abs(zi - end) <= tol;
            });
        if (near == unique.end())
          throw InputError(
            "parameter " + entry + " = '" + file_paths[b]
            + "': its mesh has no node at z = " + number(end, 6)
            + ", D = " + number(2. * R, 6) + ", where its joint with " + other
            + " ends (a corner of that section lies on a face of this "
              "mesh); a stack's joint shares its nodes, so add a point "
              "there to the file, or make the sections end together");
        // The neighbour's corner: the same point to the coupling's
        // precision, or refused (a corner 1e-6 mm off the node would
        // leave the two meshes' joint points apart).
        const double close = 1e-10 * extent();
        if (std::abs(*near - end) > close)
          throw InputError(
            "parameter " + entry + " = '" + file_paths[b]
            + "': its mesh's node at z = " + number(*near, 12) + " is "
            + number(std::abs(*near - end), 3) + " mm from z = "
            + number(end, 12) + ", where its joint with " + other
            + " ends; a stack's joint shares its nodes, so they must "
              "coincide (within "
            + number(close, 3) + " mm): move the point or the corner");
        *near = end;
      }
    return unique;
  }



  void
  StackSections::tag_file_mesh(Triangulation<2>  &mesh,
                               const unsigned int b) const
  {
    const double       tol = 1e-6 * extent();
    const unsigned int N   = n_bodies();
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2>     p = face->vertex(0), q = face->vertex(1);
            types::boundary_id id
              = p[0] <= tol && q[0] <= tol ? BoundaryId::axis : SectionId::free;
            for (const unsigned int k : {b - 1, b})
              if (k < N - 1 // b - 1 wraps round for b = 0
                  && std::abs(p[0] - radius[k]) <= tol
                  && std::abs(q[0] - radius[k]) <= tol && on_piece(k, p[1], tol)
                  && on_piece(k, q[1], tol)
                  && on_piece(k, 0.5 * (p[1] + q[1]), tol))
                id = k + 1 == b && b + 1 < N ? BoundaryId::inner_joint :
                                               BoundaryId::joint;
            face->set_boundary_id(id);
          }
  }



  std::optional<double>
  StackSections::axial_pin_z(const unsigned int b) const
  {
    for (const unsigned int k : {b - 1, b})
      if (k < shoulders.size() && shoulders[k]) // b - 1 wraps round for 0
        return std::clamp(shoulders[k]->z - z_m, joint_start(k), joint_end(k));
    return std::nullopt;
  }



  double
  StackSections::bore_radius(const unsigned int b) const
  {
    double r = half[b]->corners().front().diameter;
    for (const OutlineCorner &c : half[b]->corners())
      r = std::min(r, c.diameter);
    return 0.5 * r;
  }



  double
  StackSections::outer_radius(const unsigned int b) const
  {
    double r = 0.;
    for (const OutlineCorner &c : half[b]->corners())
      r = std::max(r, c.diameter);
    return 0.5 * r;
  }



  double
  StackSections::equivalent_inner_diameter(const unsigned int b) const
  {
    return b == 0 ? 2. * bore_radius(0) : 2. * radius[b - 1];
  }



  double
  StackSections::equivalent_outer_diameter(const unsigned int b) const
  {
    return b + 1 < n_bodies() ? 2. * radius[b] : outer_mean.back();
  }



  double
  StackSections::length(const unsigned int b) const
  {
    const auto [lo, hi] = axial_range(*drawn[b]);
    return hi - lo;
  }



  std::pair<double, double>
  StackSections::relief_radii(const unsigned int k, const double z) const
  {
    // The inner section lies inside the outer one at every plane: its
    // outermost surface faces the outer section's innermost one above it.
    const double tol     = 1e-6 * extent();
    double       outside = -1.;
    for (const double r : radii_at(*drawn[k], z))
      outside = std::max(outside, r);
    double bore = std::numeric_limits<double>::infinity();
    for (const double r : radii_at(*drawn[k + 1], z))
      if (r >= outside - tol)
        bore = std::min(bore, r);
    return {outside, bore};
  }



  bool
  StackSections::surface_through(const unsigned int b,
                                 const double       r,
                                 const double       z) const
  {
    // The straight stretches at r, neighbours joined (a point drawn on a
    // straight surface splits it into two edges).
    const double                           tol = 1e-9 * extent();
    std::vector<std::pair<double, double>> runs;
    for (const OutlineEdge &e : half[b]->edges())
      if (!e.is_arc() && std::abs(e.start[0] - r) <= tol
          && std::abs(e.end[0] - r) <= tol)
        runs.emplace_back(std::min(e.start[1], e.end[1]),
                          std::max(e.start[1], e.end[1]));
    std::sort(runs.begin(), runs.end());
    // Whether the surface from lo to hi runs on both sides of z (in a
    // half model one from the plane runs on through its mirror).
    const auto through = [&](const double lo, const double hi) {
      const bool from_plane = half_model_ && std::abs(lo) <= tol;
      return (z > lo + tol || (from_plane && std::abs(z) <= tol))
             && z < hi - tol;
    };
    for (unsigned int i = 0; i < runs.size();)
      {
        const double lo = runs[i].first;
        double       hi = runs[i].second;
        for (++i; i < runs.size() && runs[i].first <= hi + tol; ++i)
          hi = std::max(hi, runs[i].second);
        if (through(lo, hi))
          return true;
      }
    return false;
  }



  bool
  StackSections::on_piece(const unsigned int k,
                          const double       z,
                          const double       tol) const
  {
    for (const auto &[lo, hi] : pieces[k])
      if (z >= lo - tol && z <= hi + tol)
        return true;
    return false;
  }



  std::vector<Point<2>>
  StackSections::joint_vertices(const unsigned int         k,
                                const unsigned int         i,
                                const SectionMeshSettings &settings) const
  {
    const auto [lo, hi]   = pieces[k][i];
    const double        R = radius[k];
    std::vector<double> z;
    if (!file_joint_z[k].empty())
      {
        // A file's nodes on the piece.
        const double tol = 1e-9 * (hi - lo);
        for (const double zi : file_joint_z[k])
          if (zi >= lo - tol && zi <= hi + tol)
            z.push_back(zi);
      }
    else
      {
        const double h_max = settings.max_cell_size > 0. ?
                               settings.max_cell_size :
                               8. * settings.cell_size;
        // A piece from a half model's plane: graded towards its end; any
        // other graded from both ends, a vertex at its middle.
        const bool                from_plane = half_model_ && lo == 0.;
        const double              middle = from_plane ? 0. : 0.5 * (lo + hi);
        const std::vector<double> from_middle
          = joint_offsets(from_plane ? hi : 0.5 * (hi - lo),
                          settings.cell_size,
                          settings.grading_ratio,
                          h_max);
        if (!from_plane)
          {
            for (const double x : from_middle)
              z.push_back(middle - x);
            z.push_back(middle);
          }
        for (auto x = from_middle.rbegin(); x != from_middle.rend(); ++x)
          z.push_back(middle + *x);
        z = with_corners(
          z,
          {half[k].get(), half[k + 1].get()},
          [R](const double) { return R; },
          lo,
          hi);
      }
    std::vector<Point<2>> vertices;
    for (const double zi : z)
      vertices.emplace_back(R, zi);
    return vertices;
  }



  std::vector<std::shared_ptr<Triangulation<2>>>
  StackSections::make_meshes(const SectionMeshSettings &settings) const
  {
    const unsigned int                      N = n_bodies();
    std::vector<std::vector<TaggedSegment>> joints(N - 1);
    for (unsigned int k = 0; k + 1 < N; ++k)
      for (unsigned int i = 0; i < pieces[k].size(); ++i)
        {
          TaggedSegment joint{Point<2>(radius[k], pieces[k][i].first),
                              Point<2>(radius[k], pieces[k][i].second),
                              BoundaryId::joint};
          joint.vertices = joint_vertices(k, i, settings);
          // A half model's plane is no end.
          joint.refine_ends = !(half_model_ && pieces[k][i].first == 0.);
          joints[k].push_back(joint);
        }
    std::vector<std::shared_ptr<Triangulation<2>>> meshes(N);
    // Every outline's cells split, or none: the joints' vertices must
    // match (then a file's mesh is refined once more, which splits its
    // faces as gmsh does).
    unsigned int n_outlines = 0;
    for (unsigned int b = 0; b < N; ++b)
      n_outlines += !files[b];
    unsigned int split    = 0;
    const auto   mesh_all = [&](const bool full_quad) {
      split = 0;
      for (unsigned int b = 0; b < N; ++b)
        {
          if (files[b])
            continue;
          SectionBoundary boundary;
          if (b > 0)
            for (TaggedSegment piece : joints[b - 1])
              {
                if (b + 1 < N)
                  piece.boundary_id = BoundaryId::inner_joint;
                boundary.segments.push_back(piece);
              }
          if (b + 1 < N)
            boundary.segments.insert(boundary.segments.end(),
                                     joints[b].begin(),
                                     joints[b].end());
          const SectionOutline &outline = *half[b];
          if (half_model_)
            for (const TaggedSegment &plane : symmetry_segments(outline))
              boundary.segments.push_back(plane);
          SectionMeshSettings local = settings;
          local.refinement_points.clear();
          for (const unsigned int k : {b - 1, b})
            if (k < joints.size()) // b - 1 wraps round for b = 0
              for (const TaggedSegment &piece : joints[k])
                {
                  local.refinement_points.push_back(piece.end);
                  if (piece.refine_ends)
                    local.refinement_points.push_back(piece.start);
                }
          local.full_quad = full_quad;
          meshes[b]       = std::make_shared<Triangulation<2>>();
          split += make_section_mesh(*meshes[b], outline, boundary, local);
        }
      return split == 0 || split == n_outlines;
    };
    if (!mesh_all(settings.full_quad))
      mesh_all(true);
    for (unsigned int b = 0; b < N; ++b)
      if (files[b])
        {
          meshes[b] = std::make_shared<Triangulation<2>>();
          meshes[b]->copy_triangulation(*files[b]);
          tag_file_mesh(*meshes[b], b);
          meshes[b]->refine_global(settings.global_refinements
                                   + (split > 0 ? 1 : 0));
        }

    // The surfaces Operation's pressures act on: the innermost body's
    // bore, the outermost body's largest diameter.
    for (const unsigned int b : {0u, N - 1})
      {
        const double r = b == 0 ? bore_radius(0) : outer_radius(N - 1);
        if (r > 0.)
          tag_free_faces_at_radius(*meshes[b],
                                   r,
                                   half[b]->extent(),
                                   b == 0 ? BoundaryId::bore :
                                            BoundaryId::outer);
      }
    return meshes;
  }
} // namespace coaxfit
