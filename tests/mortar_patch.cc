// Patch tests of the mortar transfer between the two sides of a joint
// meshed independently (non-matching points), on a cylinder, a cone and a
// flat face, with FE_Q(1), FE_Q(2) and one side of each degree, each side
// in turn the mortar side A.
//
// What the output shows, and why the exact values are what they are:
// - a uniform pressure p = 100 MPa on B, as nodal forces p w_i, carried to
//   A by M^T: the total equals p int r ds (cylinder r = 25, z in [0, 20]:
//   int r ds = 25 * 20 = 500 mm^2; cone r = 20 + z / 10, z in [0, 20]:
//   ds = sqrt(1.01) dz, int r ds = (20 * 20 + 20^2 / 20) sqrt(1.01)
//   = 420 sqrt(1.01); flat face z = 10, r in [10, 30]: int r dr =
//   (30^2 - 10^2) / 2 = 400), and divided by A's lumped weights it gives
//   p at every node (M^T W_B 1 = int_B N_k^A(P) r ds = w_A,k when both
//   sides lie on one line and P is the identity on it);
// - u = 0.01 mm and u = 0.01 + 0.002 s (s: arc length from the end of
//   smaller z, of smaller r on the flat face; on one straight line P keeps
//   s) lie in B's trace space, so the projection reproduces them at B's
//   nodes;
// - F_B . M u_A = M^T F_B . u_A for any fields (here sin and cos of s);
// - max distance: the sides lie on one line, so 0 up to round-off.

#include "mortar_cases.h"

using namespace mortar_cases;

namespace
{
  /** A scene: two sections, their joint and its exact int r ds. */
  struct Scene
  {
    std::string                               name;
    std::function<Point<2>(const Point<2> &)> map_1, map_2;
    std::function<bool(const Point<2> &)>     on_joint;
    std::vector<double>                       x_1, y_1, x_2, y_2;
    double                                    area;
  };

  void
  run(const Scene &scene)
  {
    std::cout << scene.name << '\n';
    for (const auto &[p_1, p_2] :
         std::vector<std::pair<unsigned, unsigned>>{{1, 1}, {2, 2}, {1, 2}})
      {
        const auto one
          = make_body(scene.x_1, scene.y_1, scene.map_1, scene.on_joint, p_1);
        const auto two
          = make_body(scene.x_2, scene.y_2, scene.map_2, scene.on_joint, p_2);
        check_transfer("A = body 2, B = body 1",
                       *two->side,
                       *one->side,
                       scene.area);
        check_transfer("A = body 1, B = body 2",
                       *one->side,
                       *two->side,
                       scene.area);
      }
  }
} // namespace

int
main()
{
  const std::vector<double> uniform_3 = graded_spacing(1., 3, 1., false);
  // Cells along the joint: 7 growing by 1.3 towards the end of smaller z
  // (or r), 5 growing by 1.6 towards the other end.
  const std::vector<double> seven = graded_spacing(1., 7, 1.3, false);
  const std::vector<double> five  = graded_spacing(1., 5, 1.6, true);

  Scene cylinder;
  cylinder.name = "Cylinder: shaft r in [0, 25], hub r in [25, 50], z in [0, "
                  "20]; body 1 the shaft (7 cells along z), body 2 the hub (5)";
  cylinder.map_1
    = [](const Point<2> &x) { return Point<2>(25. * x[0], 20. * x[1]); };
  cylinder.map_2
    = [](const Point<2> &x) { return Point<2>(25. + 25. * x[0], 20. * x[1]); };
  cylinder.on_joint
    = [](const Point<2> &c) { return std::abs(c[0] - 25.) < 1e-9; };
  cylinder.x_1  = uniform_3;
  cylinder.y_1  = seven;
  cylinder.x_2  = uniform_3;
  cylinder.y_2  = five;
  cylinder.area = 500.;
  run(cylinder);

  Scene cone = cylinder;
  cone.name  = "Cone: joint r = 20 + z/10, z in [0, 20]; shaft inside (7 "
               "cells along z), hub outside to r = 40 (5)";
  cone.map_1 = [](const Point<2> &x) {
    const double z = 20. * x[1];
    return Point<2>(x[0] * (20. + 0.1 * z), z);
  };
  cone.map_2 = [](const Point<2> &x) {
    const double z = 20. * x[1], r = 20. + 0.1 * z;
    return Point<2>(r + x[0] * (40. - r), z);
  };
  cone.on_joint = [](const Point<2> &c) {
    return std::abs(c[0] - (20. + 0.1 * c[1])) < 1e-9;
  };
  cone.area = 420. * std::sqrt(1.01);
  run(cone);

  Scene flat;
  flat.name = "Flat face: joint z = 10, r in [10, 30]; body 1 below (7 "
              "cells along r), body 2 above (5)";
  flat.map_1
    = [](const Point<2> &x) { return Point<2>(10. + 20. * x[0], 10. * x[1]); };
  flat.map_2 = [](const Point<2> &x) {
    return Point<2>(10. + 20. * x[0], 10. + 10. * x[1]);
  };
  flat.on_joint = [](const Point<2> &c) { return std::abs(c[1] - 10.) < 1e-9; };
  flat.x_1      = seven;
  flat.y_1      = uniform_3;
  flat.x_2      = five;
  flat.y_2      = uniform_3;
  flat.area     = 400.;
  run(flat);
}
