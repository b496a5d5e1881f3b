#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <coaxfit/fe/body_stress.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace coaxfit
{
  namespace
  {
    /**
     * With selective reduced integration: the volumetric stress lambda tr(e)
     * at the unit-cell points @p unit_points of @p cell, interpolated from
     * its values at the reduced Gauss points (as the VTU output does): the
     * strain at other points carries volumetric modes the reduced rule does
     * not see.
     */
    std::vector<double>
    volumetric_stress(const BodyDiscretization                  &body,
                      const Vector<double>                      &solution,
                      const DoFHandler<2>::active_cell_iterator &cell,
                      const std::vector<Point<2>>               &unit_points)
    {
      const unsigned int            degree = cell->get_fe().degree;
      const FE_DGQArbitraryNodes<2> interpolation{QGauss<1>(degree)};
      const QGauss<2>               reduced(degree);
      FEValues<2>                   fe_values(cell->get_fe(),
                            reduced,
                            update_values | update_gradients
                              | update_quadrature_points);
      fe_values.reinit(cell);
      std::vector<Vector<double>> u(reduced.size(), Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> grad(reduced.size(),
                                                  std::vector<Tensor<1, 2>>(2));
      fe_values.get_function_values(solution, u);
      fe_values.get_function_gradients(solution, grad);
      const std::vector<Point<2>> &nodes
        = interpolation.get_unit_support_points();
      std::vector<double> result(unit_points.size(), 0.);
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          unsigned int q = 0; // the reduced point at node i
          for (unsigned int k = 1; k < reduced.size(); ++k)
            if (reduced.point(k).distance(nodes[i])
                < reduced.point(q).distance(nodes[i]))
              q = k;
          const double value
            = body.material().lambda()
              * Axisymmetric::trace(Axisymmetric::mechanical(
                Axisymmetric::strain(u[q][0],
                                     grad[q][0],
                                     grad[q][1],
                                     fe_values.quadrature_point(q)[0]),
                body.load().thermal_strain));
          for (unsigned int p = 0; p < unit_points.size(); ++p)
            result[p] += value * interpolation.shape_value(i, unit_points[p]);
        }
      return result;
    }

    /** Stress at the unit-cell points @p unit_points of @p cell. */
    std::vector<StressState>
    stresses_in_cell(const BodyDiscretization                  &body,
                     const Vector<double>                      &solution,
                     const DoFHandler<2>::active_cell_iterator &cell,
                     const std::vector<Point<2>>               &unit_points)
    {
      const Quadrature<2> quadrature(unit_points);
      FEValues<2>         fe_values(body.get_dof_handler().get_fe(),
                            quadrature,
                            update_values | update_gradients
                              | update_quadrature_points);
      fe_values.reinit(cell);
      std::vector<Vector<double>> values(unit_points.size(), Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> gradients(
        unit_points.size(), std::vector<Tensor<1, 2>>(2));
      fe_values.get_function_values(solution, values);
      fe_values.get_function_gradients(solution, gradients);
      const bool     reduced = body.reduced_integration();
      const Material material
        = reduced ? body.material().without_lambda() : body.material();
      std::vector<double> volumetric(unit_points.size(), 0.);
      if (reduced)
        volumetric = volumetric_stress(body, solution, cell, unit_points);
      std::vector<StressState> states(unit_points.size());
      for (unsigned int q = 0; q < unit_points.size(); ++q)
        {
          const Point<2> &x = fe_values.quadrature_point(q);
          states[q].z       = x[1];
          states[q].sigma   = Axisymmetric::stress(
            material,
            Axisymmetric::mechanical(Axisymmetric::strain(values[q][0],
                                                          gradients[q][0],
                                                          gradients[q][1],
                                                          std::max(x[0], 0.)),
                                     body.load().thermal_strain));
          for (unsigned int c = 0; c < 3; ++c)
            states[q].sigma[c] += volumetric[q];
        }
      return states;
    }
  } // namespace



  StressState
  stress_at(const BodyDiscretization &body,
            const Vector<double>     &solution,
            const Point<2>           &point)
  {
    const auto found
      = GridTools::find_active_cell_around_point(MappingQ1<2>(),
                                                 body.get_dof_handler(),
                                                 point);
    if (found.first == body.get_dof_handler().end())
      throw std::logic_error("stress_at: the point (r = "
                             + std::to_string(point[0])
                             + ", z = " + std::to_string(point[1])
                             + ") is not in the " + body.name() + "'s mesh");
    const Point<2> unit = GeometryInfo<2>::project_to_unit_cell(found.second);
    return stresses_in_cell(body, solution, found.first, {unit})[0];
  }



  std::vector<StressState>
  stresses_along_radius(const BodyDiscretization &body,
                        const Vector<double>     &solution,
                        const double              r)
  {
    const double tolerance
      = 1e-10 * std::max(body.geometry().r_outer, body.geometry().length);
    const unsigned int degree = body.get_dof_handler().get_fe().degree;
    // Sum and count of the values at each z (shared vertices: two cells).
    std::map<double, std::pair<StressState, unsigned int>> by_z;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      for (const unsigned int f : GeometryInfo<2>::face_indices())
        {
          // Faces 0 and 1 are r = const (x = 0 and x = 1 on the unit cell).
          if (f > 1 || std::abs(cell->face(f)->center()[0] - r) > tolerance)
            continue;
          std::vector<Point<2>> unit_points;
          for (unsigned int i = 0; i <= degree; ++i)
            unit_points.emplace_back(f, double(i) / degree);
          for (const StressState &s :
               stresses_in_cell(body, solution, cell, unit_points))
            {
              // Merge points that differ by round-off only.
              auto it = by_z.lower_bound(s.z - tolerance);
              if (it == by_z.end() || it->first > s.z + tolerance)
                it = by_z.emplace(s.z, std::make_pair(StressState(), 0u)).first;
              for (unsigned int c = 0; c < 4; ++c)
                it->second.first.sigma[c] += s.sigma[c];
              ++it->second.second;
            }
        }
    std::vector<StressState> states;
    for (auto &[z, sum] : by_z)
      {
        StressState s = sum.first;
        s.z           = z;
        for (double &c : s.sigma)
          c /= sum.second;
        states.push_back(s);
      }
    return states;
  }
} // namespace coaxfit
