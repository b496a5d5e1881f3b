#include <coaxfit/fe/lame.h>

#include <cmath>

namespace coaxfit
{
  LameCylinder::LameCylinder(const double    a,
                             const double    b,
                             const Material &material,
                             const double    p_in,
                             const double    p_out)
    : A((p_in * a * a - p_out * b * b) / (b * b - a * a))
    , B((p_in - p_out) * a * a * b * b / (b * b - a * a))
    , material(material)
  {}



  double
  LameCylinder::u_r(const double r) const
  {
    const double nu = material.nu;
    return ((1. - nu) * A * r + (r > 0. ? (1. + nu) * B / r : 0.)) / material.E;
  }



  double
  LameCylinder::u_z(const double z) const
  {
    return -2. * material.nu * A * z / material.E;
  }



  double
  LameCylinder::sigma_rr(const double r) const
  {
    return A - (r > 0. ? B / (r * r) : 0.);
  }



  double
  LameCylinder::sigma_tt(const double r) const
  {
    return A + (r > 0. ? B / (r * r) : 0.);
  }
} // namespace coaxfit

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <coaxfit/fe/axisymmetric.h>
#include <coaxfit/fe/body_discretization.h>

namespace coaxfit
{
  LameErrors
  lame_errors(const BodyDiscretization &body,
              const Vector<double>     &solution,
              const LameCylinder       &exact)
  {
    const auto     &dof_handler = body.get_dof_handler();
    const QGauss<2> quadrature(dof_handler.get_fe().degree + 3);
    FEValues<2>     fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_values | update_gradients
                            | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Scalar u_r(0), u_z(1);
    std::vector<double>       ur(quadrature.size()), uz(quadrature.size());
    std::vector<Tensor<1, 2>> grad_ur(quadrature.size()),
      grad_uz(quadrature.size());

    double e_u = 0, n_u = 0, e_tt = 0, n_tt = 0, e_rr = 0, n_rr = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[u_r].get_function_values(solution, ur);
        fe_values[u_z].get_function_values(solution, uz);
        fe_values[u_r].get_function_gradients(solution, grad_ur);
        fe_values[u_z].get_function_gradients(solution, grad_uz);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<2> x     = fe_values.quadrature_point(q);
            const double   w     = x[0] * fe_values.JxW(q);
            const auto     sigma = Axisymmetric::stress(
              body.material(),
              Axisymmetric::strain(ur[q], grad_ur[q], grad_uz[q], x[0]));
            const double ur_ex = exact.u_r(x[0]), uz_ex = exact.u_z(x[1]);
            e_u += w
                   * ((ur[q] - ur_ex) * (ur[q] - ur_ex)
                      + (uz[q] - uz_ex) * (uz[q] - uz_ex));
            n_u += w * (ur_ex * ur_ex + uz_ex * uz_ex);
            const double tt = exact.sigma_tt(x[0]), rr = exact.sigma_rr(x[0]);
            e_tt += w * (sigma[2] - tt) * (sigma[2] - tt);
            n_tt += w * tt * tt;
            e_rr += w * (sigma[0] - rr) * (sigma[0] - rr);
            n_rr += w * rr * rr;
          }
      }
    return {std::sqrt(e_u / n_u),
            std::sqrt(e_tt / n_tt),
            std::sqrt(e_rr / n_rr)};
  }
} // namespace coaxfit
