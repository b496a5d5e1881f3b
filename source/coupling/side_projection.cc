#include <coaxfit/coupling/side_projection.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace coaxfit
{
  namespace
  {
    /** Distance of @p x from the segment [a, b]. */
    double
    segment_distance(const Point<2> &x, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> d  = b - a;
      const double       dd = d * d;
      const double t = dd > 0. ? std::clamp(((x - a) * d) / dd, 0., 1.) : 0.;
      return x.distance(a + t * d);
    }
  } // namespace



  SideProjection
  closest_point(const InterfaceSide &side, const Point<2> &x)
  {
    SideProjection best;
    best.distance                     = std::numeric_limits<double>::infinity();
    double             best_unclamped = 0.;
    const unsigned int n              = side.n_faces();
    for (unsigned int f = 0; f < n; ++f)
      {
        const InterfaceSide::Face &face = side.face(f);
        const Tensor<1, 2>         d    = face.end - face.start;
        const double               t    = ((x - face.start) * d) / (d * d);
        const double               tc   = std::clamp(t, 0., 1.);
        const Point<2>             y    = face.point(tc);
        const double               dist = x.distance(y);
        if (dist < best.distance)
          {
            best.face      = f;
            best.t         = tc;
            best.point     = y;
            best.distance  = dist;
            best_unclamped = t;
          }
      }
    const InterfaceSide::Face &face = side.face(best.face);
    if (best.face == 0 && best_unclamped < 0.)
      best.overshoot = -best_unclamped * face.length;
    if (best.face == n - 1 && best_unclamped > 1.)
      best.overshoot = (best_unclamped - 1.) * face.length;
    return best;
  }



  std::vector<double>
  projection_breakpoints(const InterfaceSide &side,
                         const Point<2>      &start,
                         const Point<2>      &end)
  {
    const Tensor<1, 2> d            = end - start;
    const double       length       = d.norm();
    double             longest_face = 0.;
    for (unsigned int f = 0; f < side.n_faces(); ++f)
      longest_face = std::max(longest_face, side.face(f).length);
    const double reach = length + longest_face;

    std::vector<double> t{0., 1.};
    // Where start + t d crosses the line v + lambda n.
    const auto cross = [&](const Point<2> &v, const Tensor<1, 2> &n) {
      if (segment_distance(v, start, end) > reach)
        return;
      const double det = n[0] * d[1] - d[0] * n[1];
      if (std::abs(det) <= 1e-12 * length)
        return; // the segment runs along the normal line
      const Tensor<1, 2> w = v - start;
      const double       s = (n[0] * w[1] - w[0] * n[1]) / det;
      if (s > 0. && s < 1.)
        t.push_back(s);
    };
    for (unsigned int f = 0; f < side.n_faces(); ++f)
      {
        const InterfaceSide::Face &face = side.face(f);
        cross(face.start, face.normal);
        cross(face.end, face.normal);
        if (f > 0 && (side.face(f - 1).normal - face.normal).norm() > 1e-12)
          cross(face.start, side.normals()[face.nodes.front()]);
      }
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(),
                        t.end(),
                        [](const double a, const double b) {
                          return b - a <= 1e-14;
                        }),
            t.end());
    t.back() = 1.;
    return t;
  }
} // namespace coaxfit
