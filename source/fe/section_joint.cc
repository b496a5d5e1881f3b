#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_joint.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** "(z, D)" of the (r, z) point @p p, for messages. */
    std::string
    drawing_point(const Point<2> &p)
    {
      std::ostringstream s;
      s << "(z " << p[1] << ", D " << 2. * p[0] << ")";
      return s.str();
    }

    /** 2D cross product a x b. */
    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /**
     * Whether @p p lies inside the polygon of @p outline's straight and arc
     * edges (by the crossings of a ray in +r, arcs taken as their chords
     * plus the segment's bulge test), and its distance to the boundary.
     */
    bool
    inside(const SectionOutline &outline, const Point<2> &p, double &distance)
    {
      distance = std::numeric_limits<double>::max();
      bool in  = false;
      for (const OutlineEdge &e : outline.edges())
        {
          double d = 0.;
          e.parameter_of(p, &d);
          distance = std::min(distance, d);
          // Sample arcs finely enough for the crossing test: the chord of
          // each of 16 parts.
          const unsigned int parts = e.is_arc() ? 16 : 1;
          for (unsigned int k = 0; k < parts; ++k)
            {
              // The ends exactly (point_at(1) may miss the end by
              // round-off, and a vertex must be on one side for both of
              // its edges).
              const Point<2> a
                = k == 0 ? e.start : e.point_at(double(k) / parts);
              const Point<2> b
                = k + 1 == parts ? e.end : e.point_at(double(k + 1) / parts);
              if ((a[1] > p[1]) != (b[1] > p[1]))
                {
                  const double r
                    = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                  if (r > p[0])
                    in = !in;
                }
            }
        }
      return in;
    }

    /**
     * Whether the straight edges @p e and @p f lie on one line within
     * @p tolerance (a cone drawn with rounded coordinates: collinear, not
     * crossing).
     */
    bool
    on_one_line(const OutlineEdge &e,
                const OutlineEdge &f,
                const double       tolerance)
    {
      const Tensor<1, 2> along = (e.end - e.start) / (e.end - e.start).norm();
      return std::abs(cross(along, f.start - e.start)) <= tolerance
             && std::abs(cross(along, f.end - e.start)) <= tolerance;
    }

    [[noreturn]] void
    refuse(const SectionOutline &inner,
           const SectionOutline &outer,
           const std::string    &why)
    {
      throw InputError("parameters " + inner.entry() + " and " + outer.entry()
                       + ": " + why);
    }
  } // namespace



  void
  check_apart(const SectionOutline &inner, const SectionOutline &outer)
  {
    const double tolerance = 1e-6 * std::max(inner.extent(), outer.extent());

    // Overlap: a corner of one inside the other, away from its boundary.
    for (const auto &[a, b] :
         {std::make_pair(&inner, &outer), std::make_pair(&outer, &inner)})
      for (unsigned int i = 0; i < a->corners().size(); ++i)
        {
          double         distance = 0.;
          const Point<2> p        = a->corner_point(i);
          if (inside(*b, p, distance) && distance > tolerance)
            {
              std::ostringstream s;
              s << "the sections overlap: the corner " << drawing_point(p)
                << " of " << a->entry() << " lies " << distance << " mm inside "
                << b->entry()
                << "; allowed: sections that touch (drawn at the nominal "
                   "size; the interference is given in Fit)";
              refuse(inner, outer, s.str());
            }
        }
    // Two straight edges that cross properly.
    for (const OutlineEdge &e : inner.edges())
      for (const OutlineEdge &f : outer.edges())
        {
          if (e.is_arc() || f.is_arc())
            continue;
          const Tensor<1, 2> de = e.end - e.start, df = f.end - f.start;
          const double       le = de.norm(), lf = df.norm();
          const double       denominator = cross(de, df);
          if (on_one_line(e, f, tolerance)
              || std::abs(denominator) <= 1e-12 * le * lf)
            continue;
          const double t = cross(f.start - e.start, df) / denominator;
          const double u = cross(f.start - e.start, de) / denominator;
          if (t * le > tolerance && (1. - t) * le > tolerance
              && u * lf > tolerance && (1. - u) * lf > tolerance)
            refuse(inner,
                   outer,
                   "the sections overlap: their edges cross at "
                     + drawing_point(e.start + t * de)
                     + "; allowed: sections that touch (drawn at the "
                       "nominal size; the interference is given in Fit)");
        }
    // Sections aligned corner on edge overlap with no corner inside: the
    // middle of an edge of one inside the other.
    for (const auto &[a, b] :
         {std::make_pair(&inner, &outer), std::make_pair(&outer, &inner)})
      for (const OutlineEdge &e : a->edges())
        {
          double         distance = 0.;
          const Point<2> p = e.is_arc() ? e.start : 0.5 * (e.start + e.end);
          if (!e.is_arc() && inside(*b, p, distance) && distance > tolerance)
            {
              std::ostringstream s;
              s << "the sections overlap: the point " << drawing_point(p)
                << " of " << a->entry() << "'s outline lies " << distance
                << " mm inside " << b->entry()
                << "; allowed: sections that touch (drawn at the nominal "
                   "size; the interference is given in Fit)";
              refuse(inner, outer, s.str());
            }
        }
  }



  std::vector<JointPiece>
  find_joint(const SectionOutline &inner, const SectionOutline &outer)
  {
    const double tolerance = 1e-6 * std::max(inner.extent(), outer.extent());
    check_apart(inner, outer);

    std::vector<JointPiece> pieces;
    for (const OutlineEdge &e : inner.edges())
      for (const OutlineEdge &f : outer.edges())
        {
          if (e.is_arc() || f.is_arc())
            continue;
          // Crossing edges were refused by check_apart().
          if (!on_one_line(e, f, tolerance))
            continue;
          const Tensor<1, 2> de = e.end - e.start, df = f.end - f.start;
          const double       le = de.norm();
          // Collinear, opposite directions (both counter-clockwise: the
          // sections on opposite sides of the line).
          const Tensor<1, 2> unit = de / le;
          if (de * df >= 0.)
            continue;
          const double s0 = std::max(0., (f.end - e.start) * unit);
          const double s1 = std::min(le, (f.start - e.start) * unit);
          if (s1 - s0 <= tolerance)
            continue;
          JointPiece piece;
          piece.start = e.start + s0 * unit;
          piece.end   = e.start + s1 * unit;
          // Counter-clockwise: the section lies to the left; outward is
          // the direction turned clockwise.
          piece.normal[0] = unit[1];
          piece.normal[1] = -unit[0];
          pieces.push_back(piece);
        }
    if (pieces.empty())
      refuse(inner,
             outer,
             "the sections do not meet: no straight edge of one lies on a "
             "straight edge of the other; allowed: sections that touch "
             "along a line (drawn at the nominal joint diameter, the "
             "interference given in Fit)");
    return pieces;
  }



  std::vector<double>
  radii_at(const SectionOutline &outline, const double z)
  {
    std::vector<double> r;
    for (const OutlineEdge &e : outline.edges())
      {
        const unsigned int parts = e.is_arc() ? 32 : 1;
        for (unsigned int i = 0; i < parts; ++i)
          {
            const Point<2> a = e.point_at(double(i) / parts),
                           b = e.point_at(double(i + 1) / parts);
            if ((a[1] <= z && z < b[1]) || (b[1] <= z && z < a[1]))
              r.push_back(a[0] + (z - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
          }
      }
    return r;
  }



  double
  mean_outer_diameter(const SectionOutline &hub,
                      const double          z_start,
                      const double          z_end)
  {
    // The z where the largest radius may change its edge: every end of a
    // straight piece (arcs as the chords radii_at() takes).
    std::vector<double> breaks{z_start, z_end};
    for (const OutlineEdge &e : hub.edges())
      {
        const unsigned int parts = e.is_arc() ? 32 : 1;
        for (unsigned int k = 0; k < parts; ++k)
          {
            const double z = e.point_at(double(k) / parts)[1];
            if (z > z_start && z < z_end)
              breaks.push_back(z);
          }
      }
    std::sort(breaks.begin(), breaks.end());
    // Between two breaks no piece starts or ends and pieces do not cross:
    // the largest radius is linear there, its midpoint value its mean.
    double integral = 0.;
    for (unsigned int i = 0; i + 1 < breaks.size(); ++i)
      {
        const std::vector<double> r
          = radii_at(hub, 0.5 * (breaks[i] + breaks[i + 1]));
        integral += (r.empty() ? 0. : *std::max_element(r.begin(), r.end()))
                    * (breaks[i + 1] - breaks[i]);
      }
    return 2. * integral / (z_end - z_start);
  }



  std::vector<JointPiece>
  faces_across_axis(std::vector<JointPiece> &pieces, const double tol)
  {
    std::vector<JointPiece> faces;
    for (auto piece = pieces.begin(); piece != pieces.end();)
      if (std::abs(piece->start[1] - piece->end[1]) <= tol)
        {
          faces.push_back(*piece);
          piece = pieces.erase(piece);
        }
      else
        ++piece;
    return faces;
  }



  std::optional<ShoulderFace>
  shoulder_beside(const std::vector<JointPiece> &faces,
                  const double                   z_lo,
                  const double                   z_hi,
                  const double                   tol,
                  const std::string             &both)
  {
    if (faces.empty())
      return std::nullopt;
    const double z = faces.front().start[1];
    double d_in  = 2. * std::min(faces.front().start[0], faces.front().end[0]);
    double d_out = 2. * std::max(faces.front().start[0], faces.front().end[0]);
    for (const JointPiece &face : faces)
      {
        if (std::abs(face.start[1] - z) > tol)
          throw InputError(
            both + "the sections touch on faces across the axis at z = "
            + number(z, 6) + " and z = " + number(face.start[1], 6)
            + ": one body would be held axially between them, and the "
              "axial force that holds it depends on the axial strains, which "
              "a face contact would have to take; allowed: one face beside "
              "the joint (a hub against a shoulder)");
        d_in  = std::min(d_in, 2. * std::min(face.start[0], face.end[0]));
        d_out = std::max(d_out, 2. * std::max(face.start[0], face.end[0]));
      }
    if (z > z_lo + tol && z < z_hi - tol)
      throw InputError(both
                       + "the sections touch on a face across the axis "
                         "at z = "
                       + number(z, 6) + ", inside the joint from z = "
                       + number(z_lo, 6) + " to " + number(z_hi, 6)
                       + "; allowed: a face at or beyond an end of the joint");
    return ShoulderFace{z, d_in, d_out};
  }
} // namespace coaxfit
