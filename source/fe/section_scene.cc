#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_file.h>
#include <coaxfit/fe/section_joint.h>
#include <coaxfit/fe/section_placement.h>
#include <coaxfit/fe/section_scene.h>
#include <coaxfit/fe/section_symmetry.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  namespace
  {
    const std::string shaft_entry = "Geometry/Shaft section";
    const std::string hub_entry   = "Geometry/Hub section";
    const std::string both
      = "parameters " + shaft_entry + " and " + hub_entry + ": ";

    /**
     * Whether @p mesh has a boundary face with id @p id for which
     * @p accept (the face) holds.
     */
    template <typename Predicate>
    bool
    any_boundary_face(const Triangulation<2>  &mesh,
                      const types::boundary_id id,
                      const Predicate         &accept)
    {
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id && accept(face))
            return true;
      return false;
    }
  } // namespace



  double
  SectionScene::pressure_radius(const bool shaft) const
  {
    if (shaft)
      return 0.5 * shaft_bore;
    double r = 0.;
    for (const OutlineCorner &c : drawn(false).corners())
      r = std::max(r, 0.5 * c.diameter);
    return r;
  }



  std::optional<types::boundary_id>
  SectionScene::named_id(const bool shaft, const std::string &name) const
  {
    if (!from_file(shaft))
      return std::nullopt;
    const auto &names = (shaft ? shaft_file : hub_file)->names;
    const auto  id    = names.find(name);
    if (id == names.end())
      return std::nullopt;
    return id->second;
  }



  std::shared_ptr<SectionScene::FileSection>
  SectionScene::read_file(const std::string               &path,
                          const std::string               &entry,
                          std::unique_ptr<SectionOutline> &outline)
  {
    auto file   = std::make_shared<FileSection>();
    file->path  = path;
    file->names = read_section_file(file->mesh, path, entry);
    outline     = std::make_unique<SectionOutline>(
      outline_of_mesh(file->mesh, entry, path));
    return file;
  }



  SectionScene::SectionScene(const std::string &shaft_text,
                             const std::string &hub_text)
  {
    for (const bool shaft : {true, false})
      {
        const std::string &text  = shaft ? shaft_text : hub_text;
        const std::string &entry = shaft ? shaft_entry : hub_entry;
        std::unique_ptr<SectionOutline> &outline
          = shaft ? shaft_drawn : hub_drawn;
        if (is_section_file_name(text))
          (shaft ? shaft_file : hub_file)
            = read_file(trimmed(text), entry, outline);
        else
          outline = std::make_unique<SectionOutline>(
            SectionOutline::parse(text, entry));
      }
    const double tol
      = 1e-6 * std::max(shaft_drawn->extent(), hub_drawn->extent());
    std::vector<JointPiece> pieces
      = merged(find_joint(*shaft_drawn, *hub_drawn), tol);
    // Sections that meet within the drawing tolerance: corners on the
    // joint's cylinder or cone moved onto it exactly, so that both meshes
    // have it.
    if (pieces.size() == 1)
      {
        Point<2> a = pieces[0].start, b = pieces[0].end;
        if (std::abs(a[0] - b[0]) <= tol)
          b[0] = a[0];
        shaft_drawn
          = std::make_unique<SectionOutline>(snapped(*shaft_drawn, a, b, tol));
        hub_drawn
          = std::make_unique<SectionOutline>(snapped(*hub_drawn, a, b, tol));
        pieces = merged(find_joint(*shaft_drawn, *hub_drawn), tol);
      }
    // Faces across the axis (a hub's end face on a shaft's shoulder, a
    // shaft's end face on a step of the bore): with a frictionless joint
    // and no axial load they carry no force (below), so they are set
    // aside and the joint is what remains.
    const std::vector<JointPiece> faces = faces_across_axis(pieces, tol);
    if (pieces.size() != 1)
      throw InputError(
        both + "the sections meet in " + std::to_string(pieces.size())
        + " pieces along the axis; this version models a joint that is one "
          "cylinder or one cone, beside which a face across the axis may "
          "touch (two seats beside a relief groove in the bore are modelled "
          "for the bodies written as a stack: Assembly/Bodies = Shaft, Hub)");
    const JointPiece &joint = pieces.front();
    // A cone up to 30 degrees from the axis (tapers are 1:50 to 1:5, 0.6 to
    // 5.7 degrees); steeper joints are faces more than cones.
    if (std::abs(joint.normal[0]) < std::cos(numbers::PI / 6.))
      throw InputError(
        both + "the joint from z = " + number(joint.start[1], 6) + ", D = "
        + number(2. * joint.start[0], 6) + " to z = " + number(joint.end[1], 6)
        + ", D = " + number(2. * joint.end[0], 6) + " is inclined "
        + number(std::acos(std::min(1., std::abs(joint.normal[0]))) * 180.
                   / numbers::PI,
                 3)
        + " degrees to the axis; allowed: a cylinder or a cone up to 30 "
          "degrees (a face against a shoulder is not modelled yet)");
    if (joint.normal[0] < 0.)
      throw InputError(both
                       + "the shaft's section lies outside the hub's at "
                         "the joint; the shaft must be the inner body");
    cone              = std::abs(joint.start[0] - joint.end[0]) > tol;
    const double z_lo = std::min(joint.start[1], joint.end[1]);
    const double z_hi = std::max(joint.start[1], joint.end[1]);
    if (!faces.empty())
      check_shoulder(faces, z_lo, z_hi, tol);
    r_start = joint.start[1] <= joint.end[1] ? joint.start[0] : joint.end[0];
    r_end   = joint.start[1] <= joint.end[1] ? joint.end[0] : joint.start[0];
    radius  = 0.5 * (r_start + r_end);
    half_length       = 0.5 * (z_hi - z_lo);
    hub_mean_outer    = mean_outer_diameter(*hub_drawn, z_lo, z_hi);
    const auto [a, b] = axial_range(*shaft_drawn);
    shaft_extent      = b - a;
    shaft_bore        = shaft_drawn->corners().front().diameter;
    for (const OutlineCorner &c : shaft_drawn->corners())
      shaft_bore = std::min(shaft_bore, c.diameter);

    z_start = z_lo;
    // Symmetric about the joint's middle: the half; anything else whole
    // (and a gmsh file's mesh is not cut).
    const std::optional<double> plane
      = mirror_plane({shaft_drawn.get(), hub_drawn.get()});
    std::optional<SectionOutline> shaft_part, hub_part;
    if (plane && !has_file() && std::abs(*plane - 0.5 * (z_lo + z_hi)) <= tol)
      {
        shaft_part = half_outline(*shaft_drawn, *plane);
        hub_part   = half_outline(*hub_drawn, *plane);
      }
    half = shaft_part && hub_part;
    if (half)
      {
        z_m = *plane;
        shaft_half
          = std::make_unique<SectionOutline>(shifted(*shaft_part, -z_m));
        hub_half = std::make_unique<SectionOutline>(shifted(*hub_part, -z_m));
      }
    else
      {
        z_m        = 0.;
        shaft_half = std::make_unique<SectionOutline>(*shaft_drawn);
        hub_half   = std::make_unique<SectionOutline>(*hub_drawn);
      }
    find_rounded_ends(tol);
    for (const bool shaft : {true, false})
      if (from_file(shaft))
        tag_file_mesh(*(shaft ? shaft_file : hub_file), shaft, tol);
  }



  void
  SectionScene::tag_surfaces(Triangulation<2> &mesh, const bool shaft) const
  {
    const double r = pressure_radius(shaft);
    if (r <= 0.)
      return; // a solid shaft has no bore
    tag_free_faces_at_radius(mesh,
                             r,
                             drawn(shaft).extent(),
                             shaft ? BoundaryId::bore : BoundaryId::outer);
  }



  bool
  SectionScene::has_pressure_surface(const bool shaft) const
  {
    if (from_file(shaft))
      return any_boundary_face((shaft ? shaft_file : hub_file)->mesh,
                               shaft ? BoundaryId::bore : BoundaryId::outer,
                               [](const auto &) { return true; });
    const SectionOutline &outline = drawn(shaft);
    const double          r       = pressure_radius(shaft);
    const double          tol     = 1e-9 * outline.extent();
    for (const OutlineEdge &edge : outline.edges())
      if (!edge.is_arc() && std::abs(edge.start[0] - r) <= tol
          && std::abs(edge.end[0] - r) <= tol
          && edge.start.distance(edge.end) > tol)
        return r > 0.;
    return false;
  }



  bool
  SectionScene::has_free_named_face(const bool         shaft,
                                    const std::string &name) const
  {
    const auto id = named_id(shaft, name);
    return id
           && any_boundary_face((shaft ? shaft_file : hub_file)->mesh,
                                *id,
                                [](const auto &) { return true; });
  }



  double
  SectionScene::axial_face_force(
    const bool                                         shaft,
    const std::vector<std::pair<std::string, double>> &pressures,
    double                                            &scale) const
  {
    scale = 0.;
    if (!from_file(shaft))
      return 0.;
    const FileSection &file = *(shaft ? shaft_file : hub_file);
    std::map<types::boundary_id, double> by_id;
    for (const auto &[name, p] : pressures)
      if (const auto id = named_id(shaft, name))
        by_id[*id] = p;
    double force = 0.;
    for (const auto &cell : file.mesh.active_cell_iterators())
      for (unsigned int f = 0; f < GeometryInfo<2>::faces_per_cell; ++f)
        if (cell->face(f)->at_boundary())
          if (const auto p = by_id.find(cell->face(f)->boundary_id());
              p != by_id.end())
            {
              const Point<2> a = cell->face(f)->vertex(0),
                             b = cell->face(f)->vertex(1);
              // 2 pi r_mid |ab|; n_z |ab| = -+dr, exact for any curve.
              const double ring   = numbers::PI * (a[0] + b[0]);
              const double length = a.distance(b);
              force -= p->second * ring * length * outward_normal(cell, f)[1];
              scale += std::abs(p->second) * ring * length;
            }
    return force;
  }



  bool
  SectionScene::named_face_on_shoulder(const bool         shaft,
                                       const std::string &name) const
  {
    const auto id = named_id(shaft, name);
    if (!shoulder || !id)
      return false;
    const double tol = 1e-6 * drawn(shaft).extent();
    const double r0  = 0.5 * shoulder->diameter_inner,
                 r1  = 0.5 * shoulder->diameter_outer;
    return any_boundary_face(
      (shaft ? shaft_file : hub_file)->mesh, *id, [&](const auto &face) {
        const Point<2> a = face->vertex(0), b = face->vertex(1);
        return std::abs(a[1] - shoulder->z) <= tol
               && std::abs(b[1] - shoulder->z) <= tol
               && std::min(r1, std::max(a[0], b[0]))
                      - std::max(r0, std::min(a[0], b[0]))
                    > tol;
      });
  }



  std::map<std::string, types::boundary_id>
  SectionScene::face_names(const bool shaft) const
  {
    return from_file(shaft) ? (shaft ? shaft_file : hub_file)->names :
                              std::map<std::string, types::boundary_id>();
  }



  void
  SectionScene::tag_file_mesh(FileSection &file,
                              const bool   shaft,
                              const double tol) const
  {
    const SectionOutline &outline = drawn(shaft);
    const std::string     context
      = "parameter " + outline.entry() + " = '" + file.path + "'";
    // The straight surface that can touch: the joint, and under the other
    // section's rounded edge the straight surface as far as its fillet
    // reaches; this section's own rounded edges are arcs beyond the joint.
    bool rounded_here = false;
    for (const RoundedEnd &r : rounded)
      rounded_here = rounded_here || r.shaft == shaft;
    const TaggedSegment line
      = rounded_here ? joint_segment() : contact_segment(shaft);
    const Point<2> a = line.start, b = line.end;
    const auto     on_fillet = [&](const Point<2> &p) {
      for (const RoundedEnd &r : rounded)
        if (r.shaft == shaft && p[0] >= std::min(r.tangent[0], r.far[0]) - tol
            && p[0] <= std::max(r.tangent[0], r.far[0]) + tol
            && p[1] >= std::min(r.tangent[1], r.far[1]) - tol
            && p[1] <= std::max(r.tangent[1], r.far[1]) + tol)
          return true;
      return false;
    };
    const Tensor<1, 2> along    = (b - a) / (b - a).norm();
    const auto         on_joint = [&](const Point<2> &p) {
      const Tensor<1, 2> d = p - a;
      return std::abs(along[0] * d[1] - along[1] * d[0]) <= tol
             && d * along >= -tol && d * along <= (b - a).norm() + tol;
    };
    const auto where = [](const Point<2> &p) {
      return "(r = " + number(p[0], 6) + ", z = " + number(p[1], 6) + ")";
    };
    const std::string joint_text
      = "the joint the sections make, from " + where(a) + " to " + where(b);
    // On a cone the held face, as the outline gives it (checked there).
    std::vector<TaggedSegment> held;
    if (cone)
      for (const TaggedSegment &segment :
           boundary(outline, joint_segment(), shaft).segments)
        if (segment.boundary_id == BoundaryId::held)
          held.push_back(segment);
    const auto on_segment = [&](const TaggedSegment &s, const Point<2> &p) {
      const Tensor<1, 2> t = (s.end - s.start) / (s.end - s.start).norm();
      const Tensor<1, 2> d = p - s.start;
      return std::abs(t[0] * d[1] - t[1] * d[0]) <= tol && d * t >= -tol
             && d * t <= (s.end - s.start).norm() + tol;
    };

    double covered = 0.;
    for (const auto &cell : file.mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> p = face->vertex(0), q = face->vertex(1);
            // A rounded edge of this section at the joint: its arc's faces
            // are where contact may spread.
            if (face->manifold_id() != numbers::flat_manifold_id && on_fillet(p)
                && on_fillet(q))
              {
                face->set_boundary_id(BoundaryId::joint);
                continue;
              }
            if (face->boundary_id() == BoundaryId::joint)
              {
                if (!on_joint(p) || !on_joint(q))
                  throw InputError(
                    context + ": its physical curve 'joint' has a face from "
                    + where(p) + " to " + where(q) + " off " + joint_text
                    + "; 'joint' must be the surface that meets the other "
                      "body and no more");
                covered += p.distance(q);
                continue;
              }
            if (on_joint(p) && on_joint(q))
              {
                // Under the other section's rounded edge the surface goes on
                // beyond the joint: contact may spread onto it.
                if (!rounded_here && !rounded.empty())
                  {
                    face->set_boundary_id(BoundaryId::joint);
                    covered += p.distance(q);
                    continue;
                  }
                throw InputError(context + ": a face from " + where(p) + " to "
                                 + where(q) + " lies on " + joint_text
                                 + " but not in the physical curve 'joint'");
              }
            if (p[0] <= tol && q[0] <= tol)
              face->set_boundary_id(BoundaryId::axis);
            for (const TaggedSegment &s : held)
              if (on_segment(s, p) && on_segment(s, q))
                face->set_boundary_id(BoundaryId::held);
          }
    tag_surfaces(file.mesh, shaft);
    if (std::abs(covered - (b - a).norm()) > 1e3 * tol)
      throw InputError(context + ": its physical curve 'joint' covers "
                       + number(covered, 6) + " mm of " + joint_text + " ("
                       + number((b - a).norm(), 6)
                       + " mm); it must cover all of it");
  }



  void
  SectionScene::check_shoulder(const std::vector<JointPiece> &faces,
                               const double                   z_lo,
                               const double                   z_hi,
                               const double                   tol)
  {
    const double z = faces.front().start[1];
    if (cone)
      throw InputError(both
                       + "the sections also touch on the face across "
                         "the axis at z = "
                       + number(z, 6)
                       + " beside a cone; a hub pushed onto a taper against "
                         "a shoulder is not modelled (the push-on distance "
                         "would press the face); allowed: a face beside a "
                         "cylindrical joint");
    shoulder = shoulder_beside(faces, z_lo, z_hi, tol, both);
  }



  double
  SectionScene::axial_pin_z() const
  {
    if (shoulder)
      return std::clamp(shoulder->z - z_m, joint_start(), joint_end());
    return 0.5 * (joint_start() + joint_end());
  }



  void
  SectionScene::find_rounded_ends(const double tol)
  {
    // A fillet of one section that begins at an end of the joint (its
    // tangent point): contact may spread onto it, over the other section's
    // straight surface, which must go on beyond the joint's end as far as
    // the fillet reaches.
    std::vector<Point<2>> ends{Point<2>(r_end, joint_end())};
    if (!half)
      ends.insert(ends.begin(), Point<2>(r_start, joint_start()));
    for (const bool is_shaft : {true, false})
      for (const OutlineEdge &edge : modelled(is_shaft).edges())
        for (const Point<2> &end : ends)
          {
            if (!edge.is_arc()
                || std::min(edge.start.distance(end), edge.end.distance(end))
                     > tol)
              continue;
            const SectionOutline &outline = modelled(is_shaft);
            const Point<2>        far
              = edge.start.distance(end) <= tol ? edge.end : edge.start;
            const std::string where
              = "the end of the joint (z = " + number(end[1] + z_m, 6)
                + ", D = " + number(2. * end[0], 6) + ")";
            if (cone)
              throw InputError("parameter " + outline.entry()
                               + ": a fillet begins at " + where
                               + " of a taper; rounded edges are modelled "
                                 "on cylindrical joints only");
            // The other section's straight surface r = R beyond the end.
            const SectionOutline                  &other = modelled(!is_shaft);
            std::vector<std::pair<double, double>> covered;
            for (const OutlineEdge &e : other.edges())
              if (!e.is_arc() && std::abs(e.start[0] - radius) <= tol
                  && std::abs(e.end[0] - radius) <= tol)
                covered.emplace_back(std::min(e.start[1], e.end[1]),
                                     std::max(e.start[1], e.end[1]));
            std::sort(covered.begin(), covered.end());
            const double lo = std::min(end[1], far[1]),
                         hi = std::max(end[1], far[1]);
            double reach    = lo;
            for (const auto &[a, b] : covered)
              if (a <= reach + tol)
                reach = std::max(reach, b);
            if (reach < hi - tol)
              throw InputError(
                "parameters " + outline.entry() + " and " + other.entry()
                + ": the fillet (R " + number(edge.radius, 6)
                + ") that begins at " + where
                + " reaches z = " + number(far[1] + z_m, 6) + ", but "
                + other.entry().substr(other.entry().find('/') + 1)
                + " does not go on straight at D = " + number(2. * radius, 6)
                + " that far, so contact could not spread onto it; allowed: "
                  "a rounded edge over a straight surface of the other "
                  "section (or a sharp or chamfered edge)");
            for (const RoundedEnd &r : rounded)
              if (std::abs(r.tangent[1] - end[1]) <= tol)
                throw InputError(both + "both sections are rounded at " + where
                                 + "; allowed: one rounded edge over a "
                                   "straight surface of the other section");
            rounded.push_back({is_shaft, end, far, edge.radius});
          }
  }



  TaggedSegment
  SectionScene::contact_segment(const bool shaft) const
  {
    TaggedSegment segment = joint_segment();
    for (const RoundedEnd &r : rounded)
      {
        const Point<2> p
          = r.shaft == shaft ? r.far : Point<2>(radius, r.far[1]);
        if (r.tangent[1] < 0.5 * (joint_start() + joint_end()))
          segment.start = p;
        else
          segment.end = p;
      }
    return segment;
  }



  double
  SectionScene::hub_outer_radius_at_plane() const
  {
    if (!half)
      {
        const double z = z_start + half_length, dz = 1e-6 * half_length;
        return std::max(radius,
                        0.5 * mean_outer_diameter(*hub_drawn, z - dz, z + dz));
      }
    double r = radius;
    for (const OutlineCorner &c : hub_half->corners())
      if (std::abs(c.z) <= 1e-9 * hub_half->extent())
        r = std::max(r, 0.5 * c.diameter);
    return r;
  }



  std::vector<Point<2>>
  SectionScene::joint_vertices(const double cell_size,
                               const double grading_ratio,
                               const double max_cell_size) const
  {
    const std::vector<double> from_middle
      = joint_offsets(half_length, cell_size, grading_ratio, max_cell_size);
    const double          middle = joint_start() + (half ? 0. : half_length);
    std::vector<Point<2>> vertices;
    if (!half)
      {
        for (const double x : from_middle)
          vertices.emplace_back(joint_radius_at(middle - x), middle - x);
        vertices.emplace_back(radius, middle);
      }
    for (auto x = from_middle.rbegin(); x != from_middle.rend(); ++x)
      vertices.emplace_back(joint_radius_at(middle + *x), middle + *x);
    return vertices;
  }



  double
  SectionScene::joint_radius_at(const double z) const
  {
    if (!cone)
      return radius;
    const double t = (z - joint_start()) / (joint_end() - joint_start());
    return r_start + t * (r_end - r_start);
  }



  TaggedSegment
  SectionScene::joint_segment() const
  {
    return TaggedSegment{Point<2>(r_start, joint_start()),
                         Point<2>(r_end, joint_end()),
                         BoundaryId::joint};
  }



  void
  SectionScene::make_meshes(Triangulation<2>          &shaft,
                            Triangulation<2>          &hub,
                            const SectionMeshSettings &settings) const
  {
    if (has_file())
      throw InputError("parameter Mesh/Joint nodes = shared is not possible "
                       "with a gmsh file as a section (its mesh keeps its own "
                       "joint nodes); allowed: own");
    const Point<2> end  = joint_segment().end;
    const double  h_max = settings.max_cell_size > 0. ? settings.max_cell_size :
                                                        8. * settings.cell_size;
    TaggedSegment joint = joint_segment();
    joint.vertices
      = joint_vertices(settings.cell_size, settings.grading_ratio, h_max);
    // A corner of either outline inside the joint (on a straight line)
    // is a vertex of its mesh: it must be one of both.
    {
      std::vector<double> z;
      for (const Point<2> &v : joint.vertices)
        z.push_back(v[1]);
      z = with_corners(
        z,
        {&modelled(true), &modelled(false)},
        [this](const double zi) { return joint_radius_at(zi); },
        joint_start(),
        joint_end());
      joint.vertices.clear();
      for (const double zi : z)
        joint.vertices.emplace_back(joint_radius_at(zi), zi);
    }
    // The middle of a half model's joint is no end.
    joint.refine_ends = !half;

    SectionMeshSettings local = settings;
    local.refinement_points.clear();
    if (half)
      local.refinement_points.push_back(end);
    const auto mesh_both = [&](const bool full_quad) {
      shaft.clear();
      hub.clear();
      local.full_quad = full_quad;
      const bool a    = make_section_mesh(shaft,
                                       modelled(true),
                                       boundary(modelled(true), joint, true),
                                       local);
      const bool b    = make_section_mesh(hub,
                                       modelled(false),
                                       boundary(modelled(false), joint, false),
                                       local);
      return a == b;
    };
    if (!mesh_both(settings.full_quad))
      mesh_both(true);
    tag_surfaces(shaft, true);
    tag_surfaces(hub, false);
  }



  SectionBoundary
  SectionScene::boundary(const SectionOutline &outline,
                         const TaggedSegment  &joint,
                         const bool            shaft) const
  {
    SectionBoundary result;
    result.segments.push_back(joint);
    if (half)
      for (const TaggedSegment &plane : symmetry_segments(outline))
        result.segments.push_back(plane);
    if (!cone)
      return result;
    const double tol = 1e-9 * outline.extent();
    // A cone: the shaft held at its end face on the side the hub is pushed
    // towards, the hub at its end face on the other side (where the press
    // pushes it).
    const double direction = shaft ? push_direction() : -push_direction();
    double       z_face    = outline.corners().front().z;
    for (const OutlineCorner &c : outline.corners())
      z_face = direction > 0. ? std::max(z_face, c.z) : std::min(z_face, c.z);
    bool   found = false;
    double held = 0., r_min = outline.corners().front().diameter, r_max = 0.;
    for (const OutlineCorner &c : outline.corners())
      {
        r_min = std::min(r_min, 0.5 * c.diameter);
        r_max = std::max(r_max, 0.5 * c.diameter);
      }
    for (const OutlineEdge &edge : outline.edges())
      if (!edge.is_arc() && std::abs(edge.start[1] - z_face) <= tol
          && std::abs(edge.end[1] - z_face) <= tol
          && edge.start.distance(edge.end) > tol)
        {
          TaggedSegment face{edge.start, edge.end, BoundaryId::held};
          face.refine_ends = false;
          result.segments.push_back(face);
          found = true;
          held += edge.start.distance(edge.end);
        }
    // A face much smaller than the section is a point support: its give
    // grows without bound under refinement.
    if (found && held < 0.25 * (r_max - r_min))
      throw InputError(
        "parameter " + outline.entry() + ": a taper fit holds the "
        + std::string(shaft ? "shaft" : "hub") + " at its flat face at z = "
        + number(z_face + z_m, 6) + ", which spans " + number(held, 6)
        + " mm of the section's " + number(r_max - r_min, 6)
        + " mm radial extent; allowed: a face of at least a quarter of it "
          "(a smaller one acts as a point support)");
    if (!found)
      throw InputError(
        "parameter " + outline.entry() + ": a taper fit holds the "
        + std::string(shaft ? "shaft at its end face" : "hub at the face")
        + " at z = " + number(z_face + z_m, 6) + " ("
        + (shaft ? "the side the hub is pushed towards" :
                   "where the hub is pushed on")
        + "), but the section has no flat face (an edge of constant z) "
          "there; draw that end flat");
    return result;
  }



  std::shared_ptr<const SectionScene::MeshPair>
  SectionScene::base_meshes(const SectionMeshSettings &settings,
                            const bool                 shared_nodes,
                            const double               hub_cell_size) const
  {
    Assert(settings.refinement_points.empty() && !settings.full_quad
             && settings.global_refinements == 0,
           ExcMessage("base_meshes() keys its meshes by the cell sizes, the "
                      "grading and the joint nodes only"));
    const auto                  key = std::make_tuple(shared_nodes,
                                     settings.cell_size,
                                     settings.grading_ratio,
                                     settings.max_cell_size,
                                     shared_nodes ? 0. : hub_cell_size);
    std::lock_guard<std::mutex> lock(mesh_mutex);
    if (const auto known = mesh_cache.find(key); known != mesh_cache.end())
      return known->second;
    auto meshes = std::make_shared<MeshPair>();
    if (shared_nodes)
      make_meshes((*meshes)[0], (*meshes)[1], settings);
    else
      {
        SectionMeshSettings hub = settings;
        if (hub_cell_size > 0.)
          hub.cell_size = hub_cell_size;
        make_own_meshes((*meshes)[0], (*meshes)[1], settings, hub);
      }
    mesh_cache.emplace(key, meshes);
    return meshes;
  }



  void
  SectionScene::make_own_meshes(Triangulation<2>          &shaft,
                                Triangulation<2>          &hub,
                                const SectionMeshSettings &shaft_settings,
                                const SectionMeshSettings &hub_settings) const
  {
    const Point<2> end = joint_segment().end;
    // Over a rounded edge the rounded body first: the straight body's joint
    // gets the z of its joint vertices, so that it has a node between every
    // two of the rounded side's points (its values carry the projection
    // onto them).
    std::vector<bool> order = {true, false};
    if (!rounded.empty())
      order = {rounded[0].shaft, !rounded[0].shaft};
    for (const bool is_shaft : order)
      {
        TaggedSegment joint = contact_segment(is_shaft);
        joint.refine_ends   = !half; // the middle of a half model is no end
        if (!rounded.empty() && is_shaft != rounded[0].shaft)
          {
            const double        tol = 1e-9 * modelled(is_shaft).extent();
            std::vector<double> z;
            for (const auto &cell :
                 (is_shaft ? hub : shaft).active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary()
                    && face->boundary_id() == BoundaryId::joint)
                  for (const unsigned int v : {0u, 1u})
                    z.push_back(face->vertex(v)[1]);
            std::sort(z.begin(), z.end());
            z.erase(std::unique(z.begin(),
                                z.end(),
                                [&](const double a, const double b) {
                                  return b - a <= tol;
                                }),
                    z.end());
            const double lo = std::min(joint.start[1], joint.end[1]),
                         hi = std::max(joint.start[1], joint.end[1]);
            std::vector<double> fixed;
            for (const double zi : z)
              if (zi > lo + tol && zi < hi - tol)
                fixed.push_back(zi);
            if (joint.start[1] > joint.end[1])
              std::reverse(fixed.begin(), fixed.end());
            for (const double zi : fixed)
              joint.vertices.emplace_back(radius, zi);
          }
        SectionMeshSettings local = is_shaft ? shaft_settings : hub_settings;
        local.refinement_points.clear();
        if (half)
          local.refinement_points.push_back(end);
        // A rounded edge: the finest cells where contact leaves the joint,
        // an eighth of the cell size at its tangent points (contact spreads
        // onto the fillet by a few hundredths of a mm), as coarse as the
        // cell size makes it elsewhere.
        for (const RoundedEnd &r : rounded)
          local.refinement_points.push_back(r.tangent);
        if (!rounded.empty() && is_shaft == rounded[0].shaft)
          {
            if (local.max_cell_size <= 0.)
              local.max_cell_size = 8. * local.cell_size;
            local.cell_size /= 8.;
          }
        Triangulation<2> &mesh = is_shaft ? shaft : hub;
        mesh.clear();
        if (from_file(is_shaft))
          {
            mesh.copy_triangulation((is_shaft ? shaft_file : hub_file)->mesh);
            continue;
          }
        make_section_mesh(mesh,
                          modelled(is_shaft),
                          boundary(modelled(is_shaft), joint, is_shaft),
                          local);
        tag_surfaces(mesh, is_shaft);
      }
  }
} // namespace coaxfit
