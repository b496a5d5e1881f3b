// Helpers of the mortar transfer tests: two bodies meshed independently
// (structured meshes of the unit square mapped onto their (r, z) sections,
// graded differently), their joint tagged by a predicate on the face
// centre, and the checks that a transfer between the two sides must pass.

#ifndef coaxfit_tests_mortar_cases_h
#define coaxfit_tests_mortar_cases_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <coaxfit/coupling/interface_pressure.h>
#include <coaxfit/coupling/interface_side.h>
#include <coaxfit/coupling/mortar_transfer.h>
#include <coaxfit/fe/mesh.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace mortar_cases
{
  using namespace coaxfit;

  /** A meshed body, its DoFs of FE_Q(degree)^2 and its joint. */
  struct Body
  {
    Triangulation<2>               triangulation;
    std::unique_ptr<FESystem<2>>   fe;
    std::unique_ptr<DoFHandler<2>> dof_handler;
    std::unique_ptr<InterfaceSide> side;
  };

  /**
   * Mesh the unit square with the cell sizes @p x_steps, @p y_steps (each
   * summing to 1), map it by @p map onto the body's section, tag the
   * boundary faces whose centre satisfies @p on_joint with
   * BoundaryId::joint and collect the joint with FE_Q(@p degree)^2.
   */
  inline std::unique_ptr<Body>
  make_body(const std::vector<double>                       &x_steps,
            const std::vector<double>                       &y_steps,
            const std::function<Point<2>(const Point<2> &)> &map,
            const std::function<bool(const Point<2> &)>     &on_joint,
            const unsigned int                               degree)
  {
    auto body = std::make_unique<Body>();
    GridGenerator::subdivided_hyper_rectangle(body->triangulation,
                                              {x_steps, y_steps},
                                              Point<2>(0., 0.),
                                              Point<2>(1., 1.));
    GridTools::transform(map, body->triangulation);
    for (const auto &face : body->triangulation.active_face_iterators())
      if (face->at_boundary() && on_joint(face->center()))
        face->set_boundary_id(BoundaryId::joint);
    body->fe          = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 2);
    body->dof_handler = std::make_unique<DoFHandler<2>>(body->triangulation);
    body->dof_handler->distribute_dofs(*body->fe);
    body->side
      = std::make_unique<InterfaceSide>(*body->dof_handler, BoundaryId::joint);
    return body;
  }

  /** "ok" if @p error is below @p bound, "WRONG" otherwise. */
  inline std::string
  verdict(const double error, const double bound = 1e-12)
  {
    return std::abs(error) < bound ? "ok" : "WRONG";
  }

  /** An error for the output: one digit, or 0. */
  inline std::string
  figure(const double error)
  {
    std::ostringstream text;
    if (error == 0.)
      text << "0";
    else
      text << std::scientific << std::setprecision(0) << error;
    return text.str();
  }

  /**
   * The checks of a transfer from @p a (mortar) to @p b (non-mortar) of
   * sides on one curve whose exact r-weighted size is @p exact_area:
   * a uniform pressure on B, turned into nodal forces and carried to A by
   * M^T, comes back as the same total force and the same pressure at every
   * node of A; a constant and a field linear in the arc length go from A to
   * B exactly; and F_B . M u_A = M^T F_B . u_A for fields of no particular
   * form.
   */
  inline void
  check_transfer(const std::string   &label,
                 const InterfaceSide &a,
                 const InterfaceSide &b,
                 const double         exact_area)
  {
    const MortarTransfer transfer(a, b);
    std::cout << "  " << label << ": A " << a.n_nodes() << " nodes FE_Q("
              << a.degree() << "), B " << b.n_nodes() << " nodes FE_Q("
              << b.degree() << "), matching "
              << (transfer.matching() ? "yes" : "no") << ", uncovered "
              << transfer.uncovered_nodes().size() << ", max distance "
              << figure(transfer.max_distance()) << '\n';

    // Uniform pressure on B -> nodal forces -> A.
    const double   p   = 100.;
    Vector<double> f_b = uniform_pressure_force(b, p), f_a;
    transfer.apply_transpose(f_b, f_a);
    double total = 0.;
    for (const double f : f_a)
      total += f;
    const double total_error
      = std::abs(total - p * exact_area) / (p * exact_area);
    std::cout << "    total force on A " << std::setprecision(10) << total
              << "  exact p int r ds " << p * exact_area << "  rel. error "
              << figure(total_error) << ' ' << verdict(total_error) << '\n';
    const Vector<double> pressure       = nodal_pressure(a, f_a);
    double               pressure_error = 0.;
    for (const double q : pressure)
      pressure_error = std::max(pressure_error, std::abs(q - p) / p);
    std::cout << "    pressure on A from the lumped weights: max rel. error "
              << figure(pressure_error) << ' ' << verdict(pressure_error)
              << ", mean " << mean_pressure(a, f_a) << '\n';

    // Constant and linear-in-s displacements A -> B.
    Vector<double> u_a(a.n_nodes()), u_b;
    double         constant_error = 0., linear_error = 0.;
    for (unsigned int k = 0; k < a.n_nodes(); ++k)
      u_a[k] = 0.01;
    transfer.apply(u_a, u_b);
    for (unsigned int i = 0; i < b.n_nodes(); ++i)
      constant_error = std::max(constant_error, std::abs(u_b[i] - 0.01));
    for (unsigned int k = 0; k < a.n_nodes(); ++k)
      u_a[k] = 0.01 + 0.002 * a.arc_length()[k];
    transfer.apply(u_a, u_b);
    for (unsigned int i = 0; i < b.n_nodes(); ++i)
      linear_error
        = std::max(linear_error,
                   std::abs(u_b[i] - (0.01 + 0.002 * b.arc_length()[i])));
    std::cout << "    u = 0.01 mm: max error on B " << figure(constant_error)
              << ' ' << verdict(constant_error, 1e-14)
              << "; u = 0.01 + 0.002 s: max error " << figure(linear_error)
              << ' ' << verdict(linear_error, 1e-14) << '\n';

    // Virtual work for fields of no particular form.
    Vector<double> g_b(b.n_nodes()), g_a;
    for (unsigned int i = 0; i < b.n_nodes(); ++i)
      g_b[i] = b.weights()[i] * (1. + std::sin(0.7 * b.arc_length()[i]));
    for (unsigned int k = 0; k < a.n_nodes(); ++k)
      u_a[k] = std::cos(0.3 * a.arc_length()[k]) * 1e-3;
    transfer.apply(u_a, u_b);
    transfer.apply_transpose(g_b, g_a);
    const double work_b = g_b * u_b, work_a = g_a * u_a;
    const double work_error = std::abs(work_b - work_a) / std::abs(work_b);
    std::cout
      << "    virtual work F_B . M u_A = M^T F_B . u_A: rel. difference "
      << figure(work_error) << ' ' << verdict(work_error) << '\n';
  }
} // namespace mortar_cases

#endif
