// Scenes symmetric about a plane z = z_m are modelled as their half: the
// plane found (mirror_plane) and the half outlines (half_outline), whose
// area and Pappus volume must be half the whole's (exact figures in
// tests/section_outline.cc): (a) the plain hub D 50-100, z -20..20, on a
// shaft z -40..40: plane z 0, half area 500; (b) the gear hub of "Real
// parts" on a shaft z -100..100: plane z 0, half area 810; (c) the flush
// pulley (shaft z 0..150, hub z 0..40): no plane, modelled whole; (d) the
// plain hub with its outer corners rounded (R 3): half area (982 + 4.5 pi)
// / 2 = 498.069; (e) a hub z -2..2 whose two R 2 fillets meet on the plane
// (their tangent points at z = 0): symmetric, but its half would cut the
// arcs, so the scene is modelled whole.
#include <coaxfit/fe/section_symmetry.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
  using namespace coaxfit;

  void
  show(const std::string &label,
       const std::string &shaft_text,
       const std::string &hub_text)
  {
    const SectionOutline shaft
      = SectionOutline::parse(shaft_text, "Geometry/Shaft section");
    const SectionOutline hub
      = SectionOutline::parse(hub_text, "Geometry/Hub section");
    std::cout << label << ": ";
    const std::optional<double> plane = mirror_plane({&shaft, &hub});
    if (!plane)
      {
        std::cout << "not symmetric: modelled whole\n";
        return;
      }
    std::cout << "symmetric about z = " << *plane;
    for (const SectionOutline *s : {&shaft, &hub})
      {
        const std::optional<SectionOutline> half = half_outline(*s, *plane);
        if (!half)
          {
            std::cout << "; " << s->entry() << ": no half (modelled whole)";
            continue;
          }
        std::cout << std::setprecision(6) << "; " << s->entry()
                  << " half: area " << half->area() << " of " << s->area()
                  << " (ratio "
                  << std::round(1e9 * half->area() / s->area()) / 1e9
                  << "), volume ratio "
                  << std::round(1e9 * half->volume() / s->volume()) / 1e9;
      }
    std::cout << '\n';
  }
} // namespace



int
main()
{
  show("(a) plain",
       "-40, 0; 40, 0; 40, 50; -40, 50; -40, 0",
       "-20, 50; 20, 50; 20, 100; -20, 100; -20, 50");
  show("(b) gear hub",
       "-100, 0; 100, 0; 100, 50; -100, 50; -100, 0",
       "-25, 50; 25, 50; 25, 80; 6, 80; 6, 150; 15, 150; 15, 180; -15, 180; "
       "-15, 150; -6, 150; -6, 80; -25, 80; -25, 50");
  show("(c) flush pulley",
       "0, 0; 150, 0; 150, 50; 0, 50; 0, 0",
       "0, 50; 40, 50; 40, 100; 0, 100; 0, 50");
  show("(d) rounded hub",
       "-40, 0; 40, 0; 40, 50; -40, 50; -40, 0",
       "-20, 50; 20, 50; 20, 100, 3; -20, 100, 3; -20, 50");
  show("(e) short rounded hub",
       "-40, 0; 40, 0; 40, 50; -40, 50; -40, 0",
       "-2, 50; 2, 50; 2, 100, 2; -2, 100, 2; -2, 50");
}
