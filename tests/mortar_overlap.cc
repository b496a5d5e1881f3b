// The mortar transfer on matching sides and on sides that overlap only in
// part (a hub shorter than the shaft's joint).
//
// Matching: shaft r in [0, 25] and hub r in [25, 50], z in [0, 20], both
// with the same 7 graded cells along z. The transfer detects it
// (matching yes) and is the index map, M = I exactly; built as a projection
// all the same (detection off) it is I up to round-off, both trace spaces
// being the same.
//
// Partial overlap: the shaft's joint is r = 25, z in [0, 20]; the hub's
// z in [0, 12].
// - B = shaft, A = hub: the shaft's nodes beyond z = 12 are uncovered,
//   with zero rows. Shaft in 10 cells of 2 mm (a node at z = 12): FE_Q(1)
//   z = 14, 16, 18, 20 (4), FE_Q(2) z = 13, 14, ..., 20 (8). Shaft in 7
//   cells growing by 1.3 (nodes at z = 0, 1.137, 2.616, 4.539, 7.038,
//   10.286, 14.510, 20): the face [10.286, 14.510] is covered only in part
//   and left out, so FE_Q(1) leaves z = 14.510, 20 (2) and FE_Q(2) also
//   the midpoints 12.398, 17.255 (4). A uniform pressure p = 100 MPa on
//   the covered faces of the shaft (its consistent nodal forces) reaches
//   the hub as p at every node, total p * 25 * 12 = 30000, when the ends
//   meet at a node. With the hub's end inside a shaft face, only the
//   forces of the covered nodes go across: their total, p * 25 * 10.286
//   = 25715.69927 (10.286 = 20 (1.3^5 - 1) / (1.3^7 - 1)), arrives whole,
//   but the hub's nodes beyond z = 10.286 get no force (the pressure's
//   error there is 1, all of it). u = 0.01 + 0.002 z arrives exactly at
//   the covered nodes and as 0 at the uncovered ones.
// - B = hub, A = shaft: the hub is covered whole (no uncovered node); a
//   uniform pressure on the hub gives the total 30000 on the shaft, p at
//   its nodes below z = 12 and no force at its nodes beyond the hub's end
//   face (the nodes of faces that do not reach down to z = 12).

#include <deal.II/base/quadrature_lib.h>

#include "mortar_cases.h"

using namespace mortar_cases;

namespace
{
  const std::vector<double> uniform_3 = graded_spacing(1., 3, 1., false);

  std::unique_ptr<Body>
  cylinder(const double               r0,
           const double               r1,
           const double               length,
           const std::vector<double> &steps,
           const unsigned int         degree)
  {
    return make_body(
      uniform_3,
      steps,
      [=](const Point<2> &x) {
        return Point<2>(r0 + (r1 - r0) * x[0], length * x[1]);
      },
      [](const Point<2> &c) { return std::abs(c[0] - 25.) < 1e-9; },
      degree);
  }

  /** Consistent nodal forces of the pressure @p p on the faces below z_max. */
  Vector<double>
  pressure_below(const InterfaceSide &side, const double p, const double z_max)
  {
    Vector<double>  force(side.n_nodes());
    const QGauss<1> quadrature(side.degree() + 1);
    for (unsigned int f = 0; f < side.n_faces(); ++f)
      {
        const InterfaceSide::Face &face = side.face(f);
        if (std::max(face.start[1], face.end[1]) > z_max + 1e-9)
          continue;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double t = quadrature.point(q)[0];
            for (unsigned int j = 0; j < face.nodes.size(); ++j)
              force[face.nodes[j]] += p * side.shape_value(j, t)
                                      * face.point(t)[0] * face.length
                                      * quadrature.weight(q);
          }
      }
    return force;
  }

  void
  matching(const unsigned int degree)
  {
    const std::vector<double> seven = graded_spacing(1., 7, 1.3, false);
    const auto                shaft = cylinder(0., 25., 20., seven, degree);
    const auto                hub   = cylinder(25., 50., 20., seven, degree);
    const MortarTransfer      detected(*hub->side, *shaft->side);
    const MortarTransfer      projected(*hub->side, *shaft->side, false);
    FullMatrix<double>        m = detected.matrix(), n = projected.matrix();
    double                    error_m = 0., error_n = 0.;
    for (unsigned int i = 0; i < m.m(); ++i)
      for (unsigned int k = 0; k < m.n(); ++k)
        {
          error_m = std::max(error_m, std::abs(m(i, k) - (i == k)));
          error_n = std::max(error_n, std::abs(n(i, k) - (i == k)));
        }
    std::cout << "  FE_Q(" << degree << "), " << shaft->side->n_nodes()
              << " nodes: matching " << (detected.matching() ? "yes" : "no")
              << ", max |M - I| " << figure(error_m) << ' '
              << verdict(error_m, 1e-300) << "; as a projection: matching "
              << (projected.matching() ? "yes" : "no") << ", max |M - I| "
              << figure(error_n) << ' ' << verdict(error_n) << '\n';
  }

  void
  partial(const std::string         &label,
          const std::vector<double> &shaft_steps,
          const unsigned int         degree)
  {
    const double p     = 100.;
    const auto   shaft = cylinder(0., 25., 20., shaft_steps, degree);
    const auto   hub
      = cylinder(25., 50., 12., graded_spacing(1., 5, 1.6, true), degree);
    const InterfaceSide &s = *shaft->side, &h = *hub->side;
    std::cout << "  " << label << ", FE_Q(" << degree << "):\n";

    // B = shaft, A = hub.
    {
      const MortarTransfer transfer(h, s);
      std::cout << "    B = shaft (" << s.n_nodes()
                << " nodes): " << transfer.uncovered_nodes().size()
                << " uncovered at z =";
      for (const unsigned int i : transfer.uncovered_nodes())
        std::cout << ' ' << std::setprecision(5) << s.points()[i][1];
      std::cout << '\n';
      Vector<double> f_a;
      transfer.apply_transpose(pressure_below(s, p, 12.), f_a);
      double total = 0., pressure_error = 0.;
      for (unsigned int k = 0; k < h.n_nodes(); ++k)
        {
          total += f_a[k];
          pressure_error = std::max(pressure_error,
                                    std::abs(f_a[k] / h.weights()[k] - p) / p);
        }
      const Vector<double> f_b           = pressure_below(s, p, 12.);
      double               covered_total = 0.;
      for (unsigned int i = 0; i < s.n_nodes(); ++i)
        if (!std::binary_search(transfer.uncovered_nodes().begin(),
                                transfer.uncovered_nodes().end(),
                                i))
          covered_total += f_b[i];
      const double conservation = std::abs(total - covered_total) / total;
      std::cout << "      total on the hub " << std::setprecision(10) << total
                << " = covered shaft total " << covered_total << " (rel. "
                << figure(conservation) << ' ' << verdict(conservation)
                << "); pressure on the hub: max rel. error "
                << figure(pressure_error) << '\n';
      Vector<double> u_a(h.n_nodes()), u_b;
      for (unsigned int k = 0; k < h.n_nodes(); ++k)
        u_a[k] = 0.01 + 0.002 * h.points()[k][1];
      transfer.apply(u_a, u_b);
      double error = 0., uncovered = 0.;
      for (unsigned int i = 0; i < s.n_nodes(); ++i)
        if (std::binary_search(transfer.uncovered_nodes().begin(),
                               transfer.uncovered_nodes().end(),
                               i))
          uncovered = std::max(uncovered, std::abs(u_b[i]));
        else
          error
            = std::max(error,
                       std::abs(u_b[i] - (0.01 + 0.002 * s.points()[i][1])));
      std::cout << "      u = 0.01 + 0.002 z: max error at covered nodes "
                << figure(error) << ' ' << verdict(error, 1e-14)
                << ", max |u| at uncovered " << figure(uncovered) << '\n';
    }

    // B = hub, A = shaft.
    {
      const MortarTransfer transfer(s, h);
      Vector<double>       f_a;
      transfer.apply_transpose(uniform_pressure_force(h, p), f_a);
      double total = 0., pressure_error = 0., beyond = 0.;
      for (unsigned int k = 0; k < s.n_nodes(); ++k)
        {
          total += f_a[k];
          if (s.points()[k][1] < 12. - 1e-9)
            {
              // Nodes whose faces all lie below z = 12.
              bool inside = true;
              for (unsigned int f = 0; f < s.n_faces(); ++f)
                for (const unsigned int j : s.face(f).nodes)
                  if (j == k && s.face(f).end[1] > 12. + 1e-9)
                    inside = false;
              if (inside)
                pressure_error
                  = std::max(pressure_error,
                             std::abs(f_a[k] / s.weights()[k] - p) / p);
            }
          else if (s.points()[k][1] > 12. + 1e-9)
            {
              bool reaches = false;
              for (unsigned int f = 0; f < s.n_faces(); ++f)
                for (const unsigned int j : s.face(f).nodes)
                  if (j == k && s.face(f).start[1] < 12. - 1e-9)
                    reaches = true;
              if (!reaches)
                beyond = std::max(beyond, std::abs(f_a[k]));
            }
        }
      const double total_error = std::abs(total - p * 300.) / (p * 300.);
      std::cout << "    B = hub: " << transfer.uncovered_nodes().size()
                << " uncovered; total on the shaft " << std::setprecision(10)
                << total << " exact 30000 (rel. " << figure(total_error) << ' '
                << verdict(total_error) << "), pressure below z = 12: max rel. "
                << "error " << figure(pressure_error) << ' '
                << verdict(pressure_error) << ", force beyond "
                << figure(beyond) << ' ' << verdict(beyond, 1e-300) << '\n';
    }
  }
} // namespace

int
main()
{
  std::cout << "Matching sides (shaft and hub, 7 graded cells along z):\n";
  matching(1);
  matching(2);

  std::cout << "Partial overlap: shaft joint z in [0, 20], hub z in [0, 12]\n";
  for (const unsigned int degree : {1u, 2u})
    {
      partial("shaft in 10 cells of 2 mm",
              graded_spacing(1., 10, 1., false),
              degree);
      partial("shaft in 7 cells growing by 1.3",
              graded_spacing(1., 7, 1.3, false),
              degree);
    }
}
