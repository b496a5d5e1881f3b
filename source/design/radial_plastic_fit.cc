#include <coaxfit/base/input_error.h>
#include <coaxfit/design/radial_plastic_fit.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace coaxfit
{
  namespace
  {
    /** Stress and tangent of a point in the principal axes (r, t, z). */
    struct PointResponse
    {
      std::array<double, 3>                sigma;
      std::array<std::array<double, 3>, 3> D;
      std::array<double, 4>                state; ///< e_p (r, t, z), a
    };

    /** Radial return from @p old for the total strain @p e. */
    PointResponse
    respond(const Material              &m,
            const std::array<double, 3> &e,
            const std::array<double, 4> &old)
    {
      const double K  = m.E / (3. * (1. - 2. * m.nu));
      const double mu = m.E / (2. * (1. + m.nu));
      const double H  = m.hardening_modulus;
      double       elastic[3], dev[3];
      for (unsigned int i = 0; i < 3; ++i)
        elastic[i] = e[i] - old[i];
      const double vol  = elastic[0] + elastic[1] + elastic[2];
      double       norm = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        {
          dev[i] = 2. * mu * (elastic[i] - vol / 3.);
          norm += dev[i] * dev[i];
        }
      norm = std::sqrt(norm);
      PointResponse out;
      out.state          = old;
      double       theta = 1., theta_bar = 0.;
      double       n[3]  = {0., 0., 0.};
      const double limit = std::sqrt(2. / 3.) * (m.yield_strength + H * old[3]);
      if (m.plastic && norm > limit)
        {
          const double dl = (norm - limit) / (2. * mu + 2. * H / 3.);
          for (unsigned int i = 0; i < 3; ++i)
            {
              n[i] = dev[i] / norm;
              out.state[i] += dl * n[i];
            }
          out.state[3] += std::sqrt(2. / 3.) * dl;
          theta     = 1. - 2. * mu * dl / norm;
          theta_bar = 1. / (1. + H / (3. * mu)) - (1. - theta);
        }
      for (unsigned int i = 0; i < 3; ++i)
        {
          out.sigma[i] = K * vol + theta * dev[i];
          for (unsigned int j = 0; j < 3; ++j)
            out.D[i][j] = K + 2. * mu * theta * ((i == j ? 1. : 0.) - 1. / 3.)
                          - 2. * mu * theta_bar * n[i] * n[j];
        }
      return out;
    }

    /**
     * The plane-stress response: e_z at the point found from sigma_zz = 0
     * (Newton from @p e_z), the tangent condensed onto (r, t).
     */
    PointResponse
    respond_plane_stress(const Material              &m,
                         const double                 e_r,
                         const double                 e_t,
                         double                      &e_z,
                         const std::array<double, 4> &old)
    {
      PointResponse out;
      for (unsigned int k = 0; k < 60; ++k)
        {
          out = respond(m, {{e_r, e_t, e_z}}, old);
          if (std::abs(out.sigma[2])
              <= 1e-13 * m.E * (std::abs(e_r) + std::abs(e_t)))
            break;
          e_z -= out.sigma[2] / out.D[2][2];
        }
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          out.D[i][j] -= out.D[i][2] * out.D[2][j] / out.D[2][2];
      return out;
    }

    /** Solve the symmetric tridiagonal system (d, o) x = b in place. */
    void
    solve_tridiagonal(std::vector<double>  d,
                      std::vector<double>  o,
                      std::vector<double> &b)
    {
      const std::size_t n = d.size();
      for (std::size_t i = 1; i < n; ++i)
        {
          const double f = o[i - 1] / d[i - 1];
          d[i] -= f * o[i - 1];
          b[i] -= f * b[i - 1];
        }
      b[n - 1] /= d[n - 1];
      for (std::size_t i = n - 1; i-- > 0;)
        b[i] = (b[i] - o[i] * b[i + 1]) / d[i];
    }
  } // namespace



  RadialPlasticFit::RadialPlasticFit(const Ring        &shaft,
                                     const Ring        &hub,
                                     const State        state,
                                     const unsigned int elements)
    : state(state)
  {
    const Ring rings[2] = {shaft, hub};
    for (unsigned int b = 0; b < 2; ++b)
      {
        Body &body = bodies[b];
        body.ring  = rings[b];
        body.nodes.resize(elements + 1);
        for (unsigned int i = 0; i <= elements; ++i)
          body.nodes[i]
            = rings[b].r_inner
              + (rings[b].r_outer - rings[b].r_inner) * i / elements;
        body.plastic.assign(2 * elements, {{0., 0., 0., 0.}});
        body.trial = body.plastic;
        body.u.assign(elements + 1, 0.);
        body.point_e_z.assign(2 * elements, 0.);
      }
  }



  double
  RadialPlasticFit::pressure_for(Body        &body,
                                 const bool   joint_at_outer,
                                 const double u_joint) const
  {
    const std::size_t n_nodes = body.nodes.size();
    const std::size_t joint   = joint_at_outer ? n_nodes - 1 : 0;
    const bool        solid   = body.ring.r_inner == 0.;
    const double      g       = 1. / std::sqrt(3.);
    const Material   &m       = body.ring.material;
    // Start from the last field plus the change of the joint's
    // displacement spread as the elastic shape of a ring would (decaying
    // like 1 / r away from a bore, like r into a solid shaft): a
    // disturbance at the joint node alone would strain its first element
    // far beyond yield.
    {
      const double change = u_joint - body.u[joint];
      const double r_j    = body.nodes[joint];
      for (std::size_t i = 0; i < n_nodes; ++i)
        body.u[i]
          += change
             * (joint_at_outer ? body.nodes[i] / r_j : r_j / body.nodes[i]);
    }
    body.u[joint] = u_joint;
    if (solid)
      body.u[0] = 0.;

    std::vector<double> f(n_nodes), d(n_nodes), o(n_nodes - 1), k_ue(n_nodes);
    double              f_z = 0., k_zz = 0.;
    std::vector<double> point_e_z = body.point_e_z;
    // Backtracking: a step that raises the residual is halved.
    std::vector<double> last_u, last_step;
    double              last_e_z = 0., last_de_z = 0., last_norm = 0.;
    double              damping = 1.;
    for (unsigned int iteration = 0; iteration < 100; ++iteration)
      {
        std::fill(f.begin(), f.end(), 0.);
        std::fill(d.begin(), d.end(), 0.);
        std::fill(o.begin(), o.end(), 0.);
        std::fill(k_ue.begin(), k_ue.end(), 0.);
        f_z  = 0.;
        k_zz = 0.;
        for (std::size_t e = 0; e + 1 < n_nodes; ++e)
          {
            const double h = body.nodes[e + 1] - body.nodes[e];
            for (unsigned int q = 0; q < 2; ++q)
              {
                const double xi    = 0.5 + (q == 0 ? -g : g) / 2.;
                const double r     = body.nodes[e] + xi * h;
                const double w     = 0.5 * h * r;
                const double N[2]  = {1. - xi, xi};
                const double dN[2] = {-1. / h, 1. / h};
                const double e_r   = (body.u[e + 1] - body.u[e]) / h;
                const double e_t
                  = (N[0] * body.u[e] + N[1] * body.u[e + 1]) / r;
                const std::size_t   point = 2 * e + q;
                const PointResponse p
                  = state == State::plane_stress ?
                      respond_plane_stress(
                        m, e_r, e_t, point_e_z[point], body.plastic[point]) :
                      respond(m, {{e_r, e_t, body.e_z}}, body.plastic[point]);
                body.trial[point] = p.state;
                double B[2][2]; // [node][r or t]
                for (unsigned int a = 0; a < 2; ++a)
                  {
                    B[a][0] = dN[a];
                    B[a][1] = N[a] / r;
                    f[e + a]
                      += (p.sigma[0] * B[a][0] + p.sigma[1] * B[a][1]) * w;
                  }
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int c = 0; c < 2; ++c)
                    {
                      double k = 0.;
                      for (unsigned int i = 0; i < 2; ++i)
                        for (unsigned int j = 0; j < 2; ++j)
                          k += B[a][i] * p.D[i][j] * B[c][j];
                      k *= w;
                      if (a == c)
                        d[e + a] += k;
                      else if (a == 0)
                        o[e] += k;
                    }
                if (state == State::generalized_plane_strain)
                  {
                    f_z += p.sigma[2] * w;
                    k_zz += p.D[2][2] * w;
                    for (unsigned int a = 0; a < 2; ++a)
                      k_ue[e + a]
                        += (B[a][0] * p.D[0][2] + B[a][1] * p.D[1][2]) * w;
                  }
              }
          }
        // Fixed nodes: the joint (prescribed) and the axis of a solid body.
        const double        reaction = f[joint];
        std::vector<double> residual(n_nodes);
        // The forces of the problem: the reaction, or the force a strain
        // u / r (at least 1e-9) of the wall would carry elastically.
        double       norm = 0.;
        const double scale
          = std::max(std::abs(reaction),
                     m.E * std::max(std::abs(u_joint), 1e-9 * body.ring.r_outer)
                       * (body.ring.r_outer - body.ring.r_inner));
        for (std::size_t i = 0; i < n_nodes; ++i)
          {
            const bool fixed = i == joint || (solid && i == 0);
            residual[i]      = fixed ? 0. : -f[i];
            norm += residual[i] * residual[i];
          }
        if (state == State::generalized_plane_strain)
          norm += f_z * f_z;
        norm = std::sqrt(norm);
        if (norm <= 1e-11 * scale || norm == 0.)
          {
            body.point_e_z = point_e_z;
            return joint_at_outer ? -reaction / body.nodes[joint] :
                                    reaction / body.nodes[joint];
          }
        if (iteration > 0 && !(norm < last_norm) && damping > 1e-3)
          {
            damping /= 2.;
            for (std::size_t i = 0; i < n_nodes; ++i)
              body.u[i] = last_u[i] + damping * last_step[i];
            body.e_z = last_e_z + damping * last_de_z;
            continue;
          }
        last_norm = norm;
        damping   = 1.;
        last_u    = body.u;
        last_e_z  = body.e_z;
        for (std::size_t i = 0; i < n_nodes; ++i)
          if (i == joint || (solid && i == 0))
            {
              d[i] = 1.;
              if (i > 0)
                o[i - 1] = 0.;
              if (i + 1 < n_nodes)
                o[i] = 0.;
              k_ue[i] = 0.;
            }
        std::vector<double> x = residual;
        solve_tridiagonal(d, o, x);
        if (state == State::generalized_plane_strain)
          {
            std::vector<double> y = k_ue;
            solve_tridiagonal(d, o, y);
            double kx = 0., ky = 0.;
            for (std::size_t i = 0; i < n_nodes; ++i)
              {
                kx += k_ue[i] * x[i];
                ky += k_ue[i] * y[i];
              }
            last_de_z = (-f_z - kx) / (k_zz - ky);
            for (std::size_t i = 0; i < n_nodes; ++i)
              x[i] -= y[i] * last_de_z;
            body.e_z += last_de_z;
          }
        for (std::size_t i = 0; i < n_nodes; ++i)
          body.u[i] += x[i];
        last_step = x;
      }
    throw SolverError("the radial elastic-plastic model of the ring "
                      + std::to_string(body.ring.r_inner) + " < r < "
                      + std::to_string(body.ring.r_outer)
                      + " mm did not converge in 100 Newton iterations");
  }



  RadialPlasticFit::Result
  RadialPlasticFit::solve(const double d, const unsigned int increments)
  {
    Result result;
    double U = 0.;
    for (unsigned int k = 1; k <= increments; ++k)
      {
        const double d_k = d * k / increments;
        // g(U) = p_hub(U) - p_shaft(U - d_k) grows with U. The last
        // increment's U (the hub as before, the shaft pressed further) and
        // that U plus the increment of d (the shaft as before, the hub
        // further) bracket the root (Illinois' regula falsi).
        auto g = [&](const double u) {
          return pressure_for(bodies[1], false, u)
                 - pressure_for(bodies[0], true, u - d_k);
        };
        double lo = U, hi = U + d / increments;
        double g_lo = g(lo), g_hi = g(hi);
        int    side = 0;
        for (unsigned int it = 0; it < 200; ++it)
          {
            U                  = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
            const double v     = g(U);
            const double scale = std::max(std::abs(g_lo), std::abs(g_hi));
            if (std::abs(v) <= 1e-13 * scale || hi - lo <= 1e-15 * d)
              break;
            if ((v > 0.) == (g_hi > 0.))
              {
                hi = U, g_hi = v;
                if (side == 1)
                  g_lo *= 0.5;
                side = 1;
              }
            else
              {
                lo = U, g_lo = v;
                if (side == -1)
                  g_hi *= 0.5;
                side = -1;
              }
          }
        // Evaluate at the root last, so that the trial states are its own.
        result.pressure = pressure_for(bodies[1], false, U);
        pressure_for(bodies[0], true, U - d_k);
        for (Body &body : bodies)
          body.plastic = body.trial;
      }
    result.hub_u      = U;
    result.shaft_u    = U - d;
    result.increments = increments;
    for (unsigned int b = 0; b < 2; ++b)
      {
        const Body       &body = bodies[b];
        const std::size_t n    = body.plastic.size();
        const double joint     = b == 0 ? body.ring.r_outer : body.ring.r_inner;
        double       border    = joint;
        // The plastic zone grows from the joint: its border is the last
        // plastic Gauss point from the joint on, halfway to the next.
        const double g       = 1. / std::sqrt(3.);
        auto         point_r = [&](const std::size_t point) {
          const std::size_t e  = point / 2;
          const double      xi = 0.5 + (point % 2 == 0 ? -g : g) / 2.;
          return body.nodes[e] + xi * (body.nodes[e + 1] - body.nodes[e]);
        };
        if (b == 1)
          {
            std::size_t i = 0;
            while (i < n && body.plastic[i][3] > 0.)
              ++i;
            if (i == n)
              border = body.ring.r_outer, result.fully_plastic[b] = true;
            else if (i > 0)
              border = 0.5 * (point_r(i - 1) + point_r(i));
          }
        else
          {
            std::size_t i = n;
            while (i > 0 && body.plastic[i - 1][3] > 0.)
              --i;
            if (i == 0)
              border = body.ring.r_inner, result.fully_plastic[b] = true;
            else if (i < n)
              border = 0.5 * (point_r(i - 1) + point_r(i));
          }
        result.plastic_diameter[b] = 2. * border;
      }
    return result;
  }



  double
  elastic_plastic_hub_pressure(const double yield_strength,
                               const double joint_diameter,
                               const double outer_diameter,
                               const double plastic_diameter)
  {
    const double q = plastic_diameter / outer_diameter;
    return 2. * yield_strength / std::sqrt(3.)
           * (std::log(plastic_diameter / joint_diameter) + 0.5 * (1. - q * q));
  }
} // namespace coaxfit
