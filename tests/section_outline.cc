// Section outlines as written in a parameter file ("z, D; ...; z, D" with
// optional fillet radii "z, D, R"): for five outlines, the corners in the
// stored counter-clockwise (r, z) order, the edges (arcs with centre,
// radius and swept angle), and area, Pappus volume and perimeter against
// values worked out by hand (below, in closed form); then a list of bad
// outlines, each with its one-line error.
//
// Exact figures (int r dA in mm^3 per radian, V = 2 pi int r dA):
// (a) plain hub r 25..50, z -20..20: A = 1000, int r dA = 40 (50^2 -
//     25^2) / 2 = 37500, P = 130.
// (b) gear hub: boss r 25..40 x 50, web r 40..75 x 12, rim r 75..90 x 30:
//     A = 750 + 420 + 450 = 1620, int r dA = 24375 + 24150 + 37125 = 85650,
//     P = 50 + 2 (15 + 19 + 35 + 9 + 15) + 30 = 266.
// (c) shaft r 0..25 for z 0..60, r 0..35 for z 60..100, the re-entrant
//     corner (r 25, z 60) filleted with R = 2 (centre r 27, z 58), which
//     adds the square [25, 27] x [58, 60] minus a quarter disc:
//     A = 1500 + 1400 + 4 - pi, int r dA = 18750 + 24500 + (104 - (27 pi -
//     8 / 3)), P = 100 + 25 + 58 + pi + 8 + 40 + 35 = 266 + pi.
// (d) tapered bore, r_i = 25 + z / 40 for z 0..40, outer r 50:
//     A = 1000 - 20 = 980, int r dA = (2500 * 40 - 40 (625 + 650 + 676) /
//     3) / 2 = 110980 / 3, P = sqrt(1601) + 24 + 40 + 25.
// (e) the plain hub with both outer corners rounded, R = 3: each removes
//     R^2 (1 - pi / 4) of area and 436.5 - (47 * 9 pi / 4 + 9) of int r dA:
//     A = 982 + 4.5 pi, int r dA = 36645 + 211.5 pi, P = 118 + 3 pi.

#include <deal.II/base/numbers.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_outline.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
  using namespace coaxfit;

  constexpr double pi = numbers::PI;

  void
  check(const std::string &label, const double value, const double exact)
  {
    const double error = std::abs(value - exact) / std::abs(exact);
    std::cout << "  " << std::left << std::setw(10) << label << std::right
              << std::setprecision(10) << std::setw(16) << value << "  exact "
              << std::setw(16) << exact << "  "
              << (error < 1e-13 ? "ok" : "WRONG") << '\n';
  }

  void
  show(const std::string &title,
       const std::string &text,
       const double       area,
       const double       moment,
       const double       perimeter)
  {
    std::cout << title << ": \"" << text << "\"\n";
    const SectionOutline outline
      = SectionOutline::parse(text, "Geometry/Hub section");
    std::cout << std::setprecision(6) << "  corners (r, z):";
    for (unsigned int i = 0; i < outline.corners().size(); ++i)
      std::cout << " (" << outline.corner_point(i) << ")"
                << (outline.is_reentrant(i) ? "*" : "");
    std::cout << "   (* re-entrant)\n";
    for (const OutlineEdge &e : outline.edges())
      {
        std::cout << "  " << (e.is_arc() ? "arc " : "line") << " (" << e.start
                  << ") -> (" << e.end << ")";
        if (e.is_arc())
          std::cout << " centre (" << e.centre << ") R " << e.radius
                    << " sweep " << e.sweep * 180. / pi << " deg";
        std::cout << '\n';
      }
    check("area", outline.area(), area);
    check("volume", outline.volume(), 2. * pi * moment);
    check("perimeter", outline.perimeter(), perimeter);
  }
} // namespace

int
main()
{
  show("(a) plain hub, written clockwise",
       "-20, 50; 20, 50; 20, 100; -20, 100; -20, 50",
       1000.,
       37500.,
       130.);
  show("(b) gear hub",
       "-25, 50; 25, 50; 25, 80; 6, 80; 6, 150; 15, 150; 15, 180; -15, 180; "
       "-15, 150; -6, 150; -6, 80; -25, 80; -25, 50",
       1620.,
       85650.,
       266.);
  show("(c) shaft with a shoulder, fillet R 2",
       "0, 0; 0, 50; 60, 50, 2; 60, 70; 100, 70; 100, 0; 0, 0",
       2904. - pi,
       43250. + 104. - (27. * pi - 8. / 3.),
       266. + pi);
  show("(d) tapered bore",
       "0, 50; 40, 52; 40, 100; 0, 100; 0, 50;",
       980.,
       110980. / 3.,
       std::sqrt(1601.) + 89.);
  show("(e) plain hub, outer corners R 3",
       "-20,50; 20,50; 20,100,3; -20,100,3; -20,50",
       982. + 4.5 * pi,
       36645. + 211.5 * pi,
       118. + 3. * pi);

  std::cout << "\nbad outlines of Geometry/Hub section:\n";
  const char *bad[] = {
    "",
    " ; ",
    "-20, 50; 20, x; 20, 100; -20, 50",
    "-20, 50; 20; 20, 100; -20, 50",
    "-20, 50; 20, 50, 1, 2; 20, 100; -20, 50",
    "-20, 50; 20, nan; 20, 100; -20, 50",
    "-20, 50; 20, 50; 20, 100; -20, 100",
    "0, 0; 10, 0; 0, 0",
    "-20, 50; 20, -50; 20, 100; -20, 100; -20, 50",
    "-20, 50; 20, 50; 20, 50; 20, 100; -20, 100; -20, 50",
    "0, 50; 20, 100; 20, 50; 0, 100; 0, 50",
    "0, 50; 20, 50; 10, 50; 10, 100; 0, 100; 0, 50",
    "0, 50; 40, 50; 40, 100; 20, 100; 20, 50; 10, 50; 10, 100; 0, 100; 0, 50",
    "-20, 50; 20, 50; 20, 100, 0; -20, 100; -20, 50",
    "-20, 50; 20, 50; 20, 100, -1; -20, 100; -20, 50",
    "-20, 50; 20, 50; 20, 100, 30; -20, 100; -20, 50",
    "-20, 50; 20, 50, 15; 20, 100, 15; -20, 100; -20, 50",
    "0, 0, 2; 0, 50; 60, 50; 60, 0; 0, 0",
    "0, 50; 10, 50, 1; 20, 50; 20, 100; 0, 100; 0, 50",
    "0, 50, 1; 20, 50; 20, 100; 0, 100; 0, 50, 2"};
  for (const char *text : bad)
    {
      std::cout << "  \"" << text << "\"\n    ";
      try
        {
          SectionOutline::parse(text, "Geometry/Hub section");
          std::cout << "accepted (WRONG)\n";
        }
      catch (const InputError &e)
        {
          std::cout << e.what() << '\n';
        }
    }
}
