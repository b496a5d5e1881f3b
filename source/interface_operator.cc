#include <deal.II/lac/vector.h>

#include <coaxfit/body.h>
#include <coaxfit/interface_operator.h>

namespace coaxfit
{
  void
  InterfaceOperator::solve_neumann(const std::vector<double> &force,
                                   std::vector<double>       &u_r)
  {
    std::vector<double> force_out;
    solve(std::vector<bool>(force.size(), false),
          std::vector<double>(force.size(), 0.),
          force,
          u_r,
          force_out);
  }



  void
  InterfaceOperator::solve_dirichlet(const std::vector<double> &u_r,
                                     std::vector<double>       &force)
  {
    std::vector<double> u_r_out;
    solve(std::vector<bool>(u_r.size(), true),
          u_r,
          std::vector<double>(u_r.size(), 0.),
          u_r_out,
          force);
  }



  CondensedBody::CondensedBody(Body &body)
  {
    body.interface_compliance(compliance);
  }



  void
  CondensedBody::solve(const std::vector<bool>   &prescribed,
                       const std::vector<double> &displacement,
                       const std::vector<double> &force,
                       std::vector<double>       &u_r,
                       std::vector<double>       &force_out)
  {
    const unsigned int        n = compliance.m();
    std::vector<unsigned int> P;
    for (unsigned int i = 0; i < n; ++i)
      if (prescribed[i])
        P.push_back(i);

    force_out.assign(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      if (!prescribed[i])
        force_out[i] = force[i];

    if (!P.empty())
      {
        auto &lu = factorizations[prescribed];
        if (!lu)
          {
            lu = std::make_unique<LAPACKFullMatrix<double>>(P.size(), P.size());
            for (unsigned int a = 0; a < P.size(); ++a)
              for (unsigned int b = 0; b < P.size(); ++b)
                (*lu)(a, b) = compliance[P[a]][P[b]];
            lu->compute_lu_factorization();
            ++factorization_count;
          }
        // C_PP F_P = u_P - C_PQ F_Q
        Vector<double> rhs(P.size());
        for (unsigned int a = 0; a < P.size(); ++a)
          {
            double s = displacement[P[a]];
            for (unsigned int j = 0; j < n; ++j)
              if (!prescribed[j])
                s -= compliance[P[a]][j] * force_out[j];
            rhs[a] = s;
          }
        lu->solve(rhs);
        for (unsigned int a = 0; a < P.size(); ++a)
          force_out[P[a]] = rhs[a];
      }

    u_r.assign(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        u_r[i] += compliance(i, j) * force_out[j];
  }
} // namespace coaxfit
