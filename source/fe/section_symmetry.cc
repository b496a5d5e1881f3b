#include <coaxfit/fe/section_symmetry.h>

#include <algorithm>
#include <cmath>

namespace coaxfit
{
  std::optional<double>
  mirror_plane(const std::vector<const SectionOutline *> &sections)
  {
    if (sections.empty())
      return std::nullopt;
    double z_low  = sections.front()->corners().front().z;
    double z_high = z_low, extent = 0.;
    for (const OutlineCorner &c : sections.front()->corners())
      {
        z_low  = std::min(z_low, c.z);
        z_high = std::max(z_high, c.z);
      }
    for (const SectionOutline *s : sections)
      extent = std::max(extent, s->extent());
    const double z_m       = 0.5 * (z_low + z_high);
    const double tolerance = 1e-9 * extent;
    for (const SectionOutline *s : sections)
      for (const OutlineCorner &c : s->corners())
        {
          const bool mirrored = std::any_of(
            s->corners().begin(),
            s->corners().end(),
            [&](const OutlineCorner &m) {
              return std::abs(m.z - (2. * z_m - c.z)) <= tolerance
                     && std::abs(m.diameter - c.diameter) <= tolerance
                     && std::abs(m.fillet_radius - c.fillet_radius)
                          <= tolerance;
            });
          if (!mirrored)
            return std::nullopt;
        }
    return z_m;
  }



  std::optional<SectionOutline>
  half_outline(const SectionOutline &outline, const double z_m)
  {
    const std::vector<OutlineCorner> &corners   = outline.corners();
    const double                      tolerance = 1e-9 * outline.extent();
    const unsigned int                n         = corners.size();
    // A fillet within its radius of the plane could be cut: model whole.
    for (const OutlineCorner &c : corners)
      if (c.fillet_radius > 0.
          && std::abs(c.z - z_m) <= c.fillet_radius + tolerance)
        return std::nullopt;
    // Walk the polygon; keep the corners above the plane, and a point on
    // the plane wherever the outline passes from above it to not above or
    // back. One region above the plane passes twice.
    const auto above
      = [&](const OutlineCorner &c) { return c.z - z_m > tolerance; };
    std::vector<OutlineCorner> kept;
    unsigned int               crossings = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const OutlineCorner &a = corners[i], &b = corners[(i + 1) % n];
        if (above(a))
          kept.push_back(a);
        if (above(a) != above(b))
          {
            ++crossings;
            // Where the edge a-b meets the plane (a or b itself if on it).
            const double da = a.z - z_m, db = b.z - z_m;
            const double t = std::abs(da - db) > 0. ? da / (da - db) : 0.;
            kept.push_back(
              {z_m, a.diameter + t * (b.diameter - a.diameter), 0.});
          }
      }
    if (crossings != 2 || kept.size() < 3)
      return std::nullopt;
    kept.push_back(kept.front()); // closed explicitly
    return SectionOutline(kept, outline.entry());
  }
} // namespace coaxfit
