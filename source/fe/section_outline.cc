#include <deal.II/base/numbers.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_outline.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /**
     * @p text for a one-line message: control characters (a line break in
     * the entry) written as \n, \t or \xHH.
     */
    std::string
    printable(const std::string &text)
    {
      std::string out;
      for (const char c : text)
        {
          const unsigned char u = static_cast<unsigned char>(c);
          if (c == '\n')
            out += "\\n";
          else if (c == '\t')
            out += "\\t";
          else if (u < 32 || u == 127)
            {
              const char *digits = "0123456789abcdef";
              out += "\\x";
              out += digits[u / 16];
              out += digits[u % 16];
            }
          else
            out += c;
        }
      return out;
    }



    constexpr double pi = numbers::PI;

    std::string
    trim(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\r\n");
      if (first == std::string::npos)
        return "";
      const auto last = text.find_last_not_of(" \t\r\n");
      return text.substr(first, last - first + 1);
    }

    std::vector<std::string>
    split(const std::string &text, const char separator)
    {
      std::vector<std::string> parts;
      std::string::size_type   begin = 0;
      while (true)
        {
          const auto end = text.find(separator, begin);
          parts.push_back(trim(text.substr(begin, end - begin)));
          if (end == std::string::npos)
            return parts;
          begin = end + 1;
        }
    }

    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /** The point of segment [a, b] closest to @p p. */
    Point<2>
    closest_on_segment(const Point<2> &p, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      const double       l2 = ab * ab;
      if (l2 == 0.)
        return a;
      const double t = std::clamp(((p - a) * ab) / l2, 0., 1.);
      return a + t * ab;
    }

    double
    segment_distance(const Point<2> &a,
                     const Point<2> &b,
                     const Point<2> &c,
                     const Point<2> &d)
    {
      const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
      const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
      if (((o1 < 0. && o2 > 0.) || (o1 > 0. && o2 < 0.))
          && ((o3 < 0. && o4 > 0.) || (o3 > 0. && o4 < 0.)))
        return 0.; // a proper crossing
      return std::min({a.distance(closest_on_segment(a, c, d)),
                       b.distance(closest_on_segment(b, c, d)),
                       c.distance(closest_on_segment(c, a, b)),
                       d.distance(closest_on_segment(d, a, b))});
    }

    /** Whether the direction from an arc's centre to @p p lies in the arc. */
    bool
    within_sweep(const OutlineEdge &arc, const Point<2> &p)
    {
      const Tensor<1, 2> a = arc.start - arc.centre, b = arc.end - arc.centre,
                         v = p - arc.centre;
      const double s       = arc.sweep > 0. ? 1. : -1.;
      // Arcs sweep less than a half turn.
      return s * cross(a, v) >= 0. && s * cross(v, b) >= 0.;
    }

    double
    distance_to_edge(const Point<2> &p, const OutlineEdge &edge)
    {
      double distance = 0.;
      edge.parameter_of(p, &distance);
      return distance;
    }

    /** The points where the circle of @p arc meets the line through a, b. */
    std::vector<Point<2>>
    circle_line_points(const OutlineEdge &arc,
                       const Point<2>    &a,
                       const Point<2>    &b,
                       const bool         within_segment)
    {
      std::vector<Point<2>> points;
      const Tensor<1, 2>    d = b - a, f = a - arc.centre;
      const double          qa = d * d, qb = 2. * (f * d),
                   qc   = f * f - arc.radius * arc.radius;
      const double disc = qb * qb - 4. * qa * qc;
      if (qa == 0. || disc < 0.)
        return points;
      for (const double sign : {-1., 1.})
        {
          const double t = (-qb + sign * std::sqrt(disc)) / (2. * qa);
          if (!within_segment || (t >= 0. && t <= 1.))
            points.push_back(a + t * d);
        }
      return points;
    }

    /** The shortest distance between two edges of an outline. */
    double
    edge_distance(const OutlineEdge &e, const OutlineEdge &f)
    {
      if (!e.is_arc() && !f.is_arc())
        return segment_distance(e.start, e.end, f.start, f.end);
      if (!e.is_arc())
        return edge_distance(f, e);
      double distance = std::min({distance_to_edge(e.start, f),
                                  distance_to_edge(e.end, f),
                                  distance_to_edge(f.start, e),
                                  distance_to_edge(f.end, e)});
      if (!f.is_arc())
        {
          for (const Point<2> &p : circle_line_points(e, f.start, f.end, true))
            if (within_sweep(e, p))
              return 0.;
          // Closest approach of the segment's interior to the circle.
          const Point<2> q = closest_on_segment(e.centre, f.start, f.end);
          if (within_sweep(e, q))
            distance
              = std::min(distance, std::abs(q.distance(e.centre) - e.radius));
          return distance;
        }
      // Two arcs: where the circles cross, and along the line of centres.
      const double dc = e.centre.distance(f.centre);
      if (dc > 0.)
        {
          const double a
            = (dc * dc + e.radius * e.radius - f.radius * f.radius) / (2. * dc);
          const double h2 = e.radius * e.radius - a * a;
          if (h2 >= 0.)
            {
              const Tensor<1, 2> u = (f.centre - e.centre) / dc;
              const Tensor<1, 2> n({-u[1], u[0]});
              for (const double sign : {-1., 1.})
                {
                  const Point<2> p
                    = e.centre + a * u + sign * std::sqrt(h2) * n;
                  if (within_sweep(e, p) && within_sweep(f, p))
                    return 0.;
                }
            }
          const Tensor<1, 2> u = (f.centre - e.centre) / dc;
          for (const double se : {-1., 1.})
            for (const double sf : {-1., 1.})
              {
                const Point<2> p = e.centre + se * e.radius * u;
                const Point<2> q = f.centre + sf * f.radius * u;
                if (within_sweep(e, p) && within_sweep(f, q))
                  distance = std::min(distance, p.distance(q));
              }
        }
      return distance;
    }

    /** ∫ r^2/2 dz along the edge: its share of ∫ r dA (Green). */
    double
    first_moment(const OutlineEdge &e)
    {
      if (!e.is_arc())
        {
          const double r0 = e.start[0], r1 = e.end[0];
          return 0.5 * (e.end[1] - e.start[1]) * (r0 * r0 + r0 * r1 + r1 * r1)
                 / 3.;
        }
      // r = c + R cos(phi), dz = R cos(phi) dphi.
      const double c = e.centre[0], R = e.radius;
      const double phi0 = std::atan2(e.start[1] - e.centre[1], e.start[0] - c);
      const auto   primitive = [&](const double phi) {
        const double s = std::sin(phi);
        return c * c * s + c * R * (phi + std::sin(2. * phi) / 2.)
               + R * R * (s - s * s * s / 3.);
      };
      return 0.5 * R * (primitive(phi0 + e.sweep) - primitive(phi0));
    }

    /** ∫ (r dz - z dr) / 2 along the edge: its share of the area (Green). */
    double
    area_share(const OutlineEdge &e)
    {
      if (!e.is_arc())
        return 0.5 * (e.start[0] * e.end[1] - e.end[0] * e.start[1]);
      const double cr = e.centre[0], cz = e.centre[1], R = e.radius;
      const double phi0 = std::atan2(e.start[1] - cz, e.start[0] - cr),
                   phi1 = phi0 + e.sweep;
      return 0.5
             * (R
                  * (cr * (std::sin(phi1) - std::sin(phi0))
                     - cz * (std::cos(phi1) - std::cos(phi0)))
                + R * R * e.sweep);
    }
  } // namespace



  double
  OutlineEdge::length() const
  {
    return is_arc() ? radius * std::abs(sweep) : start.distance(end);
  }



  Point<2>
  OutlineEdge::point_at(const double t) const
  {
    if (!is_arc())
      return start + t * (end - start);
    const double phi
      = std::atan2(start[1] - centre[1], start[0] - centre[0]) + t * sweep;
    return centre + radius * Point<2>(std::cos(phi), std::sin(phi));
  }



  double
  OutlineEdge::parameter_of(const Point<2> &p, double *distance) const
  {
    double t = 0.;
    if (!is_arc())
      {
        const Tensor<1, 2> d  = end - start;
        const double       l2 = d * d;
        t = l2 > 0. ? std::clamp(((p - start) * d) / l2, 0., 1.) : 0.;
      }
    else if (p.distance(centre) > 0.)
      {
        // The angle from the start, in the direction of the sweep.
        const Tensor<1, 2> a = start - centre, v = p - centre;
        double angle = std::atan2(cross(a, v), a * v); // in (-pi, pi]
        if (sweep < 0.)
          angle = -angle;
        const double span = std::abs(sweep);
        if (angle >= 0. && angle <= span)
          t = angle / span;
        else // outside the arc: the nearer end
          t = p.distance(start) <= p.distance(end) ? 0. : 1.;
      }
    if (distance != nullptr)
      *distance = p.distance(point_at(t));
    return t;
  }



  SectionOutline
  SectionOutline::parse(const std::string &text, const std::string &entry)
  {
    const std::string form = " (write each point as 'z, D' or 'z, D, R', "
                             "mm, separated by ';')";
    std::vector<std::string> points = split(text, ';');
    if (points.size() > 1 && points.back().empty())
      points.pop_back(); // one trailing ';'
    if (points.size() == 1 && points[0].empty())
      throw InputError("parameter " + entry
                       + ": the outline is empty; give a closed polygon 'z, D; "
                         "z, D; ...' whose last point repeats its first");

    std::vector<OutlineCorner> corners;
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const std::string where = "parameter " + entry + ": point "
                                  + std::to_string(i + 1) + " '"
                                  + printable(points[i]) + "'";
        const std::vector<std::string> numbers = split(points[i], ',');
        if (numbers.size() < 2 || numbers.size() > 3)
          throw InputError(where + " has " + std::to_string(numbers.size())
                           + (numbers.size() == 1 ? " number" : " numbers")
                           + form);
        double values[3] = {0., 0., 0.};
        for (unsigned int k = 0; k < numbers.size(); ++k)
          {
            const char *begin = numbers[k].c_str();
            char       *end   = nullptr;
            values[k]         = std::strtod(begin, &end);
            // A plain decimal number (no hexadecimal, inf or nan).
            const bool decimal = numbers[k].find_first_not_of("0123456789.eE+-")
                                 == std::string::npos;
            if (numbers[k].empty() || !decimal || *end != '\0'
                || !std::isfinite(values[k]))
              throw InputError(where + ": '" + printable(numbers[k])
                               + "' is not a finite decimal number" + form);
          }
        OutlineCorner corner;
        corner.z        = values[0];
        corner.diameter = values[1];
        if (numbers.size() == 3)
          {
            if (!(values[2] > 0.))
              throw InputError(where
                               + ": fillet radius R = " + number(values[2], 6)
                               + " mm; a fillet needs R > 0 (write 'z, D' for "
                                 "a sharp corner)");
            corner.fillet_radius = values[2];
          }
        corners.push_back(corner);
      }
    return SectionOutline(corners, entry);
  }



  SectionOutline::SectionOutline(const std::vector<OutlineCorner> &points,
                                 const std::string                &entry)
    : entry_name(entry)
  {
    const std::string head     = "parameter " + entry + ": ";
    const auto        describe = [](const OutlineCorner &c) {
      return "(z = " + number(c.z, 6) + ", D = " + number(c.diameter, 6) + ")";
    };

    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const std::string where
          = head + "point " + std::to_string(i + 1) + " " + describe(points[i]);
        if (!std::isfinite(points[i].z) || !std::isfinite(points[i].diameter)
            || !std::isfinite(points[i].fillet_radius))
          throw InputError(where + " is not finite");
        if (points[i].diameter < 0.)
          throw InputError(where
                           + ": a negative diameter; D >= 0 mm (0 on "
                             "the axis)");
        if (points[i].fillet_radius < 0.)
          throw InputError(where + ": fillet radius R = "
                           + number(points[i].fillet_radius, 6)
                           + " mm; a fillet needs R > 0");
      }

    // The size of the outline sets the tolerance of every comparison.
    double zmin = std::numeric_limits<double>::max(), zmax = -zmin, dmax = 0.;
    for (const OutlineCorner &c : points)
      {
        zmin = std::min(zmin, c.z);
        zmax = std::max(zmax, c.z);
        dmax = std::max(dmax, c.diameter);
      }
    const double size = points.empty() ? 0. : std::hypot(zmax - zmin, dmax);
    const double tol  = 1e-9 * size;
    const auto   same = [tol](const OutlineCorner &a, const OutlineCorner &b) {
      return std::abs(a.z - b.z) <= tol
             && std::abs(a.diameter - b.diameter) <= tol;
    };

    if (points.size() < 2 || !same(points.front(), points.back()))
      throw InputError(
        head + "the outline is open: its last point "
        + (points.empty() ? std::string("(none)") : describe(points.back()))
        + " must repeat its first "
        + (points.empty() ? std::string("(none)") : describe(points.front()))
        + " to close the polygon");

    std::vector<OutlineCorner> raw(points.begin(), points.end() - 1);
    {
      const double r_first = raw.front().fillet_radius,
                   r_last  = points.back().fillet_radius;
      if (r_first > 0. && r_last > 0. && r_first != r_last)
        throw InputError(
          head + "the first and the closing point " + describe(raw.front())
          + " give different fillet radii (" + number(r_first, 6) + " and "
          + number(r_last, 6) + " mm); write it on one of them");
      raw.front().fillet_radius = std::max(r_first, r_last);
    }
    const unsigned int n = raw.size();

    // Zero-length edges, then the count of distinct points.
    for (unsigned int i = 0; i + 1 < points.size(); ++i)
      if (same(points[i], points[i + 1]))
        throw InputError(
          head + "points " + std::to_string(i + 1) + " and "
          + std::to_string(i + 2) + " are equal " + describe(points[i])
          + ": an edge of zero length; every edge must be longer "
            "than 0 mm");
    {
      unsigned int distinct = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          bool seen = false;
          for (unsigned int k = 0; k < i; ++k)
            seen = seen || same(raw[i], raw[k]);
          distinct += seen ? 0 : 1;
        }
      if (distinct < 3)
        throw InputError(head + "only " + std::to_string(distinct)
                         + " distinct points; a section needs at least 3 "
                           "(and the last point repeating the first)");
    }
    // User numbering (1-based) of each stored corner, for the messages.
    std::vector<unsigned int> label(n);
    for (unsigned int i = 0; i < n; ++i)
      label[i] = i + 1;

    // Counter-clockwise in (r, z): a positive signed area.
    double signed_area = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        const OutlineCorner &a = raw[i], &b = raw[(i + 1) % n];
        signed_area += 0.5 * (a.diameter / 2. * b.z - b.diameter / 2. * a.z);
      }
    if (signed_area < 0.)
      {
        // Reverse, keeping corner 0 first.
        std::reverse(raw.begin() + 1, raw.end());
        std::reverse(label.begin() + 1, label.end());
      }
    corner_list = raw;

    const auto point_name = [&](const unsigned int i) {
      return "point " + std::to_string(label[i]) + " " + describe(raw[i]);
    };
    const auto side_name = [&](const unsigned int i) {
      const unsigned int a = std::min(label[i], label[(i + 1) % n]),
                         b = std::max(label[i], label[(i + 1) % n]);
      return "the edge from point " + std::to_string(a) + " to point "
             + std::to_string(b);
    };

    // The polygon: sides that are not neighbours never meet, and
    // neighbours do not fold back onto each other.
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> prev = corner_point((i + n - 1) % n),
                       here = corner_point(i), next = corner_point((i + 1) % n);
        const Tensor<1, 2> d1 = (here - prev) / here.distance(prev),
                           d2 = (next - here) / next.distance(here);
        if (std::abs(cross(d1, d2)) <= 1e-12 && d1 * d2 < 0.)
          throw InputError(head + "the outline folds back on itself at "
                           + point_name(i)
                           + ": the edges before and after it overlap; a "
                             "section must not intersect itself");
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 2; j < n; ++j)
        if (!(i == 0 && j == n - 1)
            && segment_distance(corner_point(i),
                                corner_point((i + 1) % n),
                                corner_point(j),
                                corner_point((j + 1) % n))
                 <= tol)
          throw InputError(head + "the outline intersects itself: "
                           + side_name(i) + " meets " + side_name(j)
                           + "; a section must be a simple polygon");

    // The fillets: tangent length t = R tan(theta / 2) at a turn by theta.
    std::vector<double> tangent(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      if (raw[i].fillet_radius > 0.)
        {
          const Point<2> prev   = corner_point((i + n - 1) % n),
                         here   = corner_point(i),
                         next   = corner_point((i + 1) % n);
          const Tensor<1, 2> d1 = (here - prev) / here.distance(prev),
                             d2 = (next - here) / next.distance(here);
          if (here[0] <= tol)
            throw InputError(head + "a fillet (R = "
                             + number(raw[i].fillet_radius, 6) + " mm) at "
                             + point_name(i)
                             + " on the axis; fillets are allowed only at "
                               "points with D > 0");
          const double theta = std::atan2(std::abs(cross(d1, d2)), d1 * d2);
          if (theta <= 1e-9)
            throw InputError(head + "a fillet (R = "
                             + number(raw[i].fillet_radius, 6) + " mm) at "
                             + point_name(i)
                             + ", where the outline runs straight on; fillets "
                               "are allowed only at corners");
          tangent[i] = raw[i].fillet_radius * std::tan(theta / 2.);
        }
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int j      = (i + 1) % n;
        const double       length = corner_point(i).distance(corner_point(j));
        if (tangent[i] + tangent[j] <= length * (1. + 1e-12))
          continue;
        if (tangent[i] > 0. && tangent[j] > 0.
            && std::max(tangent[i], tangent[j]) <= length)
          throw InputError(head + "the fillets at " + point_name(i) + " and "
                           + point_name(j) + " overlap on their common edge ("
                           + number(length, 6) + " mm long): they take "
                           + number(tangent[i], 6) + " + "
                           + number(tangent[j], 6)
                           + " mm of it; the sum must not exceed its length");
        const unsigned int k = tangent[i] > length ? i : j;
        const unsigned int o = (k == i) ? j : i;
        throw InputError(
          head + "the fillet R = " + number(raw[k].fillet_radius, 6) + " mm at "
          + point_name(k) + " is too large for " + side_name(i) + " ("
          + number(length, 6) + " mm): its tangent point lies "
          + number(tangent[k], 6) + " mm from the corner; allowed R <= "
          + number(std::max(0.,
                            raw[k].fillet_radius * (length - tangent[o])
                              / tangent[k]),
                   6)
          + " mm");
      }

    // The edges, counter-clockwise: arc at corner i, then side i.
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> prev = corner_point((i + n - 1) % n),
                       here = corner_point(i), next = corner_point((i + 1) % n);
        const Tensor<1, 2> d1 = (here - prev) / here.distance(prev),
                           d2 = (next - here) / next.distance(here);
        if (tangent[i] > 0.)
          {
            OutlineEdge arc;
            arc.origin              = i;
            arc.radius              = raw[i].fillet_radius;
            arc.start               = here - tangent[i] * d1;
            arc.end                 = here + tangent[i] * d2;
            const double       turn = cross(d1, d2) > 0. ? 1. : -1.;
            const Tensor<1, 2> n1   = turn * Tensor<1, 2>({-d1[1], d1[0]});
            arc.centre              = arc.start + arc.radius * n1;
            arc.sweep = turn * std::atan2(std::abs(cross(d1, d2)), d1 * d2);
            edge_list.push_back(arc);
          }
        const unsigned int j = (i + 1) % n;
        OutlineEdge        side;
        side.origin = i;
        side.start  = here + tangent[i] * d2;
        side.end    = next - tangent[j] * d2;
        if (side.start.distance(side.end) > tol)
          edge_list.push_back(side);
      }

    // The rounded outline must not intersect itself either.
    const unsigned int m = edge_list.size();
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int b = a + 2; b < m; ++b)
        if (!(a == 0 && b == m - 1)
            && (edge_list[a].is_arc() || edge_list[b].is_arc())
            && edge_distance(edge_list[a], edge_list[b]) <= tol)
          {
            const OutlineEdge &arc
              = edge_list[a].is_arc() ? edge_list[a] : edge_list[b];
            throw InputError(head + "the fillet R = " + number(arc.radius, 6)
                             + " mm at " + point_name(arc.origin)
                             + " makes the outline intersect itself; use a "
                               "smaller radius");
          }
  }



  const std::string &
  SectionOutline::entry() const
  {
    return entry_name;
  }



  const std::vector<OutlineCorner> &
  SectionOutline::corners() const
  {
    return corner_list;
  }



  Point<2>
  SectionOutline::corner_point(const unsigned int i) const
  {
    return Point<2>(corner_list[i].diameter / 2., corner_list[i].z);
  }



  bool
  SectionOutline::is_reentrant(const unsigned int i) const
  {
    const unsigned int n = corner_list.size();
    const Point<2> prev = corner_point((i + n - 1) % n), here = corner_point(i),
                   next = corner_point((i + 1) % n);
    // Counter-clockwise: a right turn is a re-entrant corner.
    return cross(here - prev, next - here)
           < -1e-12 * here.distance(prev) * next.distance(here);
  }



  const std::vector<OutlineEdge> &
  SectionOutline::edges() const
  {
    return edge_list;
  }



  double
  SectionOutline::area() const
  {
    double sum = 0.;
    for (const OutlineEdge &e : edge_list)
      sum += area_share(e);
    return sum;
  }



  double
  SectionOutline::volume() const
  {
    double sum = 0.;
    for (const OutlineEdge &e : edge_list)
      sum += first_moment(e);
    return 2. * pi * sum;
  }



  double
  SectionOutline::perimeter() const
  {
    double sum = 0.;
    for (const OutlineEdge &e : edge_list)
      sum += e.length();
    return sum;
  }



  double
  SectionOutline::extent() const
  {
    double largest = 0.;
    for (unsigned int i = 0; i < corner_list.size(); ++i)
      for (unsigned int j = i + 1; j < corner_list.size(); ++j)
        largest = std::max(largest, corner_point(i).distance(corner_point(j)));
    return largest;
  }
} // namespace coaxfit
