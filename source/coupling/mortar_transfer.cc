#include <deal.II/base/quadrature_lib.h>

#include <coaxfit/coupling/mortar_transfer.h>
#include <coaxfit/coupling/side_projection.h>

#include <algorithm>
#include <map>

namespace coaxfit
{
  MortarTransfer::MortarTransfer(const InterfaceSide &mortar,
                                 const InterfaceSide &non_mortar,
                                 const bool           detect_matching)
    : n_a(mortar.n_nodes())
    , n_b(non_mortar.n_nodes())
    , is_matching(false)
    , distance(0.)
  {
    const double tolerance
      = 1e-10 * std::max(mortar.length(), non_mortar.length());
    if (detect_matching && find_index_map(mortar, non_mortar, tolerance))
      is_matching = true;
    else
      assemble(mortar, non_mortar, tolerance);
  }



  bool
  MortarTransfer::find_index_map(const InterfaceSide &a,
                                 const InterfaceSide &b,
                                 const double         tolerance)
  {
    if (a.n_nodes() != b.n_nodes() || a.degree() != b.degree())
      return false;
    // Both sides number their nodes from the same end of one curve, or
    // (ends of equal z and r within round-off) possibly from opposite ends.
    for (const bool reversed : {false, true})
      {
        double d = 0.;
        for (unsigned int i = 0; i < n_b && d <= tolerance; ++i)
          d = std::max(
            d, b.points()[i].distance(a.points()[reversed ? n_a - 1 - i : i]));
        if (d <= tolerance)
          {
            distance = d;
            node_of_a.resize(n_b);
            for (unsigned int i = 0; i < n_b; ++i)
              node_of_a[i] = reversed ? n_a - 1 - i : i;
            return true;
          }
      }
    return false;
  }



  void
  MortarTransfer::assemble(const InterfaceSide &a,
                           const InterfaceSide &b,
                           const double         tolerance)
  {
    const unsigned int pa = a.degree(), pb = b.degree();
    const QGauss<1>    mass_quadrature(pb + 1);                // N N r
    const QGauss<1>    coupling_quadrature((pa + pb + 3) / 2); // N N(P) r
    mass = BandedCholesky(n_b, pb);
    std::vector<std::map<unsigned int, double>> rows(n_b);
    std::vector<bool>                           covered(n_b, false);

    for (unsigned int fb = 0; fb < b.n_faces(); ++fb)
      {
        const InterfaceSide::Face &face = b.face(fb);
        const std::vector<double>  t
          = projection_breakpoints(a, face.start, face.end);
        // The pieces that count, and whether A covers all of them.
        std::vector<std::pair<double, double>> pieces;
        bool                                   inside = true;
        for (unsigned int k = 0; k + 1 < t.size(); ++k)
          if ((t[k + 1] - t[k]) * face.length > tolerance)
            {
              const Point<2> middle = face.point((t[k] + t[k + 1]) / 2.);
              inside
                = inside && closest_point(a, middle).overshoot <= tolerance;
              pieces.emplace_back(t[k], t[k + 1]);
            }
        if (!inside)
          continue;

        for (const unsigned int i : face.nodes)
          covered[i] = true;
        // D: the whole face at once (N_i N_j r is one polynomial on it).
        for (unsigned int q = 0; q < mass_quadrature.size(); ++q)
          {
            const double tq = mass_quadrature.point(q)[0];
            const double jxw
              = face.point(tq)[0] * face.length * mass_quadrature.weight(q);
            for (unsigned int i = 0; i <= pb; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                mass.add(face.nodes[i],
                         face.nodes[j],
                         b.shape_value(i, tq) * b.shape_value(j, tq) * jxw);
          }
        // R: piece by piece, the shape functions of A at the projections.
        for (const auto &[t0, t1] : pieces)
          for (unsigned int q = 0; q < coupling_quadrature.size(); ++q)
            {
              const double tq
                = t0 + (t1 - t0) * coupling_quadrature.point(q)[0];
              const Point<2> x   = face.point(tq);
              const double   jxw = x[0] * face.length * (t1 - t0)
                                 * coupling_quadrature.weight(q);
              const SideProjection       y      = closest_point(a, x);
              const InterfaceSide::Face &a_face = a.face(y.face);
              distance = std::max(distance, y.distance);
              for (unsigned int i = 0; i <= pb; ++i)
                {
                  const double value = b.shape_value(i, tq) * jxw;
                  for (unsigned int k = 0; k <= pa; ++k)
                    rows[face.nodes[i]][a_face.nodes[k]]
                      += value * a.shape_value(k, y.t);
                }
            }
      }

    // Uncovered nodes: a unit diagonal in D and a zero row in R.
    for (unsigned int i = 0; i < n_b; ++i)
      if (!covered[i])
        {
          uncovered.push_back(i);
          mass.add(i, i, 1.);
        }
    mass.factorize();

    row_start.assign(1, 0);
    for (const auto &row : rows)
      {
        for (const auto &[column, value] : row)
          {
            columns.push_back(column);
            values.push_back(value);
          }
        row_start.push_back(columns.size());
      }
  }



  void
  MortarTransfer::apply(const Vector<double> &mortar_values,
                        Vector<double>       &non_mortar_values) const
  {
    AssertDimension(mortar_values.size(), n_a);
    non_mortar_values.reinit(n_b);
    if (is_matching)
      {
        for (unsigned int i = 0; i < n_b; ++i)
          non_mortar_values[i] = mortar_values[node_of_a[i]];
        return;
      }
    for (unsigned int i = 0; i < n_b; ++i)
      for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
        non_mortar_values[i] += values[e] * mortar_values[columns[e]];
    mass.solve(non_mortar_values);
  }



  void
  MortarTransfer::apply_transpose(const Vector<double> &non_mortar_forces,
                                  Vector<double>       &mortar_forces) const
  {
    AssertDimension(non_mortar_forces.size(), n_b);
    mortar_forces.reinit(n_a);
    if (is_matching)
      {
        for (unsigned int i = 0; i < n_b; ++i)
          mortar_forces[node_of_a[i]] += non_mortar_forces[i];
        return;
      }
    // M^T = R^T D^{-1} (D symmetric).
    Vector<double> y(non_mortar_forces);
    mass.solve(y);
    for (unsigned int i = 0; i < n_b; ++i)
      for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
        mortar_forces[columns[e]] += values[e] * y[i];
  }



  FullMatrix<double>
  MortarTransfer::matrix() const
  {
    FullMatrix<double> m(n_b, n_a);
    Vector<double>     unit(n_a), column(n_b);
    for (unsigned int k = 0; k < n_a; ++k)
      {
        unit[k] = 1.;
        apply(unit, column);
        for (unsigned int i = 0; i < n_b; ++i)
          m(i, k) = column[i];
        unit[k] = 0.;
      }
    return m;
  }
} // namespace coaxfit
