#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <coaxfit/fe/body_stress.h>

#include <algorithm>
#include <cmath>
#include <functional>
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
          states[q].r       = x[0];
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



  namespace
  {
    /**
     * The cell of @p body that contains @p point and the point's unit-cell
     * coordinates (projected onto the cell); a point outside the mesh by
     * less than @p tolerance of a cell's size (in the unit cell) is taken
     * on the cell it is nearest.
     */
    std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
    cell_around(const BodyDiscretization &body,
                const Point<2>           &point,
                const double              tolerance,
                const std::string        &caller)
    {
      auto found
        = GridTools::find_active_cell_around_point(MappingQ1<2>(),
                                                   body.get_dof_handler(),
                                                   point);
      if (found.first == body.get_dof_handler().end())
        found = GridTools::find_active_cell_around_point(MappingQ1<2>(),
                                                         body.get_dof_handler(),
                                                         point,
                                                         std::vector<bool>(),
                                                         tolerance);
      if (found.first == body.get_dof_handler().end())
        throw std::logic_error(caller
                               + ": the point (r = " + std::to_string(point[0])
                               + ", z = " + std::to_string(point[1])
                               + ") is not in the " + body.name() + "'s mesh");
      return {found.first, GeometryInfo<2>::project_to_unit_cell(found.second)};
    }
  } // namespace



  StressState
  stress_at(const BodyDiscretization &body,
            const Vector<double>     &solution,
            const Point<2>           &point)
  {
    // A point on a slanted surface (a cone's joint) may lie outside by
    // round-off: then the cell within 1e-6 of its size.
    const auto [cell, unit] = cell_around(body, point, 1e-6, "stress_at");
    return stresses_in_cell(body, solution, cell, {unit})[0];
  }



  Tensor<1, 2>
  displacement_at(const BodyDiscretization &body,
                  const Vector<double>     &solution,
                  const Point<2>           &point)
  {
    // A point of a drawn arc (taken as chords) may lie outside the mesh,
    // whose boundary follows the arc with chords of its own: then on the
    // cell within a quarter of its size.
    const auto [cell, unit] = cell_around(body, point, 0.25, "displacement_at");
    FEValues<2> fe_values(MappingQ1<2>(),
                          body.get_dof_handler().get_fe(),
                          Quadrature<2>(std::vector<Point<2>>{unit}),
                          update_values);
    fe_values.reinit(cell);
    std::vector<Vector<double>> values(1, Vector<double>(2));
    fe_values.get_function_values(solution, values);
    Tensor<1, 2> u;
    u[0] = values[0][0];
    u[1] = values[0][1];
    return u;
  }



  std::vector<StressState>
  stresses_along_radius(const BodyDiscretization &body,
                        const Vector<double>     &solution,
                        const double              r)
  {
    const double tolerance
      = 1e-10 * std::max(body.geometry().r_outer, body.geometry().length);
    return stresses_on_faces(
      body,
      solution,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const unsigned int                         f) {
        return std::abs(cell->face(f)->vertex(0)[0] - r) <= tolerance
               && std::abs(cell->face(f)->vertex(1)[0] - r) <= tolerance;
      });
  }



  std::vector<StressState>
  stresses_along_boundary(const BodyDiscretization &body,
                          const Vector<double>     &solution,
                          const types::boundary_id  id)
  {
    return stresses_on_faces(
      body,
      solution,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const unsigned int                         f) {
        return cell->face(f)->at_boundary()
               && cell->face(f)->boundary_id() == id;
      });
  }



  std::vector<StressState>
  stresses_on_faces(
    const BodyDiscretization                &body,
    const Vector<double>                    &solution,
    const std::function<bool(const DoFHandler<2>::active_cell_iterator &,
                             unsigned int)> &on_surface)
  {
    const double tolerance
      = 1e-10 * std::max(body.geometry().r_outer, body.geometry().length);
    const unsigned int degree = body.get_dof_handler().get_fe().degree;
    // Sum and count of the values at each point (shared vertices: two
    // cells), by z and then r.
    struct Sum
    {
      StressState  state;
      unsigned int count = 0;
    };
    std::map<double, std::vector<Sum>> by_z;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      for (const unsigned int f : GeometryInfo<2>::face_indices())
        {
          if (!on_surface(cell, f))
            continue;
          // The face's points on the unit cell: x = f (faces 0, 1) or
          // y = f - 2 (faces 2, 3).
          std::vector<Point<2>> unit_points;
          for (unsigned int i = 0; i <= degree; ++i)
            unit_points.push_back(f < 2 ? Point<2>(f, double(i) / degree) :
                                          Point<2>(double(i) / degree, f - 2));
          for (const StressState &s :
               stresses_in_cell(body, solution, cell, unit_points))
            {
              // Merge points that differ by round-off only.
              auto it = by_z.lower_bound(s.z - tolerance);
              if (it == by_z.end() || it->first > s.z + tolerance)
                it = by_z.emplace(s.z, std::vector<Sum>()).first;
              auto point = std::find_if(it->second.begin(),
                                        it->second.end(),
                                        [&](const Sum &sum) {
                                          return std::abs(sum.state.r - s.r)
                                                 <= tolerance;
                                        });
              if (point == it->second.end())
                {
                  it->second.push_back(Sum());
                  point          = it->second.end() - 1;
                  point->state.r = s.r;
                }
              for (unsigned int c = 0; c < 4; ++c)
                point->state.sigma[c] += s.sigma[c];
              ++point->count;
            }
        }
    std::vector<StressState> states;
    for (auto &[z, sums] : by_z)
      {
        std::sort(sums.begin(), sums.end(), [](const Sum &a, const Sum &b) {
          return a.state.r < b.state.r;
        });
        for (const Sum &sum : sums)
          {
            StressState s = sum.state;
            s.z           = z;
            for (double &c : s.sigma)
              c /= sum.count;
            states.push_back(s);
          }
      }
    return states;
  }
} // namespace coaxfit
