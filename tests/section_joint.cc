// Where two sections meet (find_joint): for the scenes of "Real parts",
// drawn at their nominal size, the pieces of the joint in drawing
// coordinates (z, D), their lengths and the inner section's outward
// normal, against the geometry by hand:
// (a) plain: shaft D 50, z -40..40; hub D 50-100, z -20..20: the cylinder
//     D 50 for z -20..20 (length 40), normal +r.
// (b) gear hub on a shaft (boss D 50-80 z -25..25, web D 80-150 z -6..6,
//     rim D 150-180 z -15..15; shaft D 50 z -100..100): D 50, z -25..25.
// (c) flush pulley: shaft D 50 z 0..150, hub D 50-100 z 0..40: D 50,
//     z 0..40 (the common end z = 0 is not a joint: both faces are free).
// (d) hub against a shaft shoulder: shaft D 50 for z 0..60 and D 70 for
//     z 60..100, hub D 50-100 for z 20..60: the cylinder D 50 z 20..60
//     (length 40, normal +r) and the shoulder face z = 60, D 50..70
//     (length 10, the shaft's normal -z, towards the hub).
// (e) taper 1:20 on the diameter: shaft cone D 50 at z 0 to D 52 at z 40,
//     hub bore the same cone: length sqrt(40^2 + 1^2) = 40.0125, normal
//     (40, -1) / 40.0125 (outward from the shaft, against z).
// The hubs' outer diameters averaged over the joint (DIN 7190's D_aA of
// the plain-cylinder estimate): (a), (c), (d), (e) 100; (b) the boss D 80
// for 20 of the 50 mm, the rim D 180 for 30: 140.
// Then bad scenes: a hub bore D 52 on the shaft D 50 (no joint), a bore
// D 48 (overlap by 1 mm in the radius), a hub crossing the shaft's end.
#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_joint.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
  using namespace coaxfit;

  void
  show(const std::string &label,
       const std::string &shaft,
       const std::string &hub)
  {
    std::cout << label << ":\n";
    try
      {
        const SectionOutline inner
          = SectionOutline::parse(shaft, "Geometry/Shaft section");
        const SectionOutline outer
          = SectionOutline::parse(hub, "Geometry/Hub section");
        double total = 0.;
        for (const JointPiece &p : find_joint(inner, outer))
          {
            std::cout << std::setprecision(6) << "  from (z " << p.start[1]
                      << ", D " << 2. * p.start[0] << ") to (z " << p.end[1]
                      << ", D " << 2. * p.end[0] << "), length " << p.length()
                      << ", normal (r " << p.normal[0] << ", z " << p.normal[1]
                      << ")\n";
            total += p.length();
          }
        std::cout << "  joint length " << std::setprecision(6) << total
                  << " mm\n";
        const std::vector<JointPiece> joint = find_joint(inner, outer);
        double                        z0 = joint.front().start[1], z1 = z0;
        for (const JointPiece &p : joint)
          for (const double z : {p.start[1], p.end[1]})
            {
              z0 = std::min(z0, z);
              z1 = std::max(z1, z);
            }
        if (z1 > z0)
          std::cout << "  hub outer diameter averaged over z " << z0 << ".."
                    << z1 << ": " << mean_outer_diameter(outer, z0, z1)
                    << " mm\n";
      }
    catch (const InputError &e)
      {
        std::cout << "  error: " << e.what() << '\n';
      }
  }
} // namespace



int
main()
{
  const std::string shaft80 = "-40, 0; 40, 0; 40, 50; -40, 50; -40, 0";
  show("(a) plain", shaft80, "-20, 50; 20, 50; 20, 100; -20, 100; -20, 50");
  show("(b) gear hub on a shaft",
       "-100, 0; 100, 0; 100, 50; -100, 50; -100, 0",
       "-25, 50; 25, 50; 25, 80; 6, 80; 6, 150; 15, 150; 15, 180; -15, 180; "
       "-15, 150; -6, 150; -6, 80; -25, 80; -25, 50");
  show("(c) flush pulley",
       "0, 0; 150, 0; 150, 50; 0, 50; 0, 0",
       "0, 50; 40, 50; 40, 100; 0, 100; 0, 50");
  show("(d) hub against a shaft shoulder",
       "0, 0; 100, 0; 100, 70; 60, 70; 60, 50; 0, 50; 0, 0",
       "20, 50; 60, 50; 60, 100; 20, 100; 20, 50");
  show("(e) taper",
       "0, 0; 40, 0; 40, 52; 0, 50; 0, 0",
       "0, 50; 40, 52; 40, 100; 0, 100; 0, 50");
  show("(f) bore larger than the shaft",
       shaft80,
       "-20, 52; 20, 52; 20, 100; -20, 100; -20, 52");
  show("(g) bore smaller than the shaft",
       shaft80,
       "-20, 48; 20, 48; 20, 100; -20, 100; -20, 48");
  show("(h) hub across the shaft's end face",
       shaft80,
       "30, 40; 50, 40; 50, 100; 30, 100; 30, 40");
}
