// InterfaceSide: the trace of a body on its tagged joint, ordered along
// the curve. Two listings checked by hand, and the faces that are refused.
//
// Flat face z = 10, r in [10, 30], the body below it, two cells of FE_Q(1):
// nodes r = 10, 20, 30 (s = 0, 10, 20), outward normal +e_z, weights
// w = int N_i r dr of the hat functions: a face [r0, r1] of length h gives
// h (2 r0 + r1) / 6 and h (r0 + 2 r1) / 6, so w = 200/3, 50/3 + 350/3 = 200,
// 400/3 (sum 400 = (30^2 - 10^2) / 2).
//
// Cone r = 20 + z/10, z in [0, 20], the hub outside it, one cell of
// FE_Q(2): nodes at z = 0, 10, 20 (r = 20, 21, 22), s = 0, L/2, L with
// L = 20 sqrt(1.01) = 20.09975124; the outward normal of the hub points to
// smaller r, (-1, 0.1) / sqrt(1.01) = (-0.9950371902, 0.09950371902); the
// quadratic weights are L r0 / 6, L (4/6) (r0 + r1)/2, L r1 / 6 for r
// linear along the face: 66.99917, 281.39652, 73.69909 (sum 21 L =
// 422.0947761).
//
// Refused: a joint in two pieces (4 ends), a closed loop (the whole
// boundary: no end), no face with the id.

#include "mortar_cases.h"

using namespace mortar_cases;

namespace
{
  void
  print_side(const InterfaceSide &side)
  {
    std::cout << "  " << side.n_nodes() << " nodes, " << side.n_faces()
              << " faces, FE_Q(" << side.degree() << "), length "
              << std::setprecision(10) << side.length() << ", int r ds "
              << side.area() << '\n';
    for (unsigned int i = 0; i < side.n_nodes(); ++i)
      std::cout << "    s " << std::setw(12) << side.arc_length()[i] << "  r "
                << std::setw(6) << side.points()[i][0] << "  z " << std::setw(6)
                << side.points()[i][1] << "  n (" << side.normals()[i][0] + 0.
                << ", " << side.normals()[i][1] + 0. << ")  w "
                << side.weights()[i] << '\n';
  }

  void
  refused(const std::string                           &label,
          const std::function<bool(const Point<2> &)> &on_joint)
  {
    try
      {
        make_body(
          {0.5, 0.5},
          {0.25, 0.25, 0.25, 0.25},
          [](const Point<2> &x) { return Point<2>(25. * x[0], 20. * x[1]); },
          on_joint,
          1);
        std::cout << "  " << label << ": ACCEPTED\n";
      }
    catch (const std::exception &e)
      {
        std::cout << "  " << label << ": " << e.what() << '\n';
      }
  }
} // namespace

int
main()
{
  std::cout << "Flat face z = 10, body below, 2 cells FE_Q(1):\n";
  const auto flat = make_body(
    {0.5, 0.5},
    {1.},
    [](const Point<2> &x) { return Point<2>(10. + 20. * x[0], 10. * x[1]); },
    [](const Point<2> &c) { return std::abs(c[1] - 10.) < 1e-9; },
    1);
  print_side(*flat->side);

  std::cout << "Cone r = 20 + z/10, hub outside, 1 cell FE_Q(2):\n";
  const auto cone = make_body(
    {1.},
    {1.},
    [](const Point<2> &x) {
      const double z = 20. * x[1], r = 20. + 0.1 * z;
      return Point<2>(r + x[0] * (40. - r), z);
    },
    [](const Point<2> &c) {
      return std::abs(c[0] - (20. + 0.1 * c[1])) < 1e-9;
    },
    2);
  print_side(*cone->side);

  std::cout << "Refused joints (a shaft r in [0, 25], z in [0, 20]):\n";
  refused("two pieces", [](const Point<2> &c) {
    return std::abs(c[0] - 25.) < 1e-9 && (c[1] < 5. || c[1] > 15.);
  });
  refused("closed loop", [](const Point<2> &) { return true; });
  refused("no face", [](const Point<2> &) { return false; });
}
