#include <coaxfit/solvers/condensed_body.h>

namespace coaxfit
{
  CondensedBody::CondensedBody(BodySolver &solver)
    // Every set of contact points may recur: keep all their LUs.
    : factorizations(std::numeric_limits<unsigned int>::max())
  {
    solver.interface_compliance(compliance);
  }



  CondensedBody::CondensedBody(const FullMatrix<double> &compliance)
    : compliance(compliance)
    , factorizations(std::numeric_limits<unsigned int>::max())
  {}



  void
  CondensedBody::solve(const std::vector<bool> &prescribed,
                       const Vector<double>    &displacement,
                       const Vector<double>    &force,
                       Vector<double>          &u_r,
                       Vector<double>          &force_out)
  {
    const unsigned int        n = compliance.m();
    std::vector<unsigned int> P;
    for (unsigned int i = 0; i < n; ++i)
      if (prescribed[i])
        P.push_back(i);

    force_out.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      if (!prescribed[i])
        force_out[i] = force[i];

    if (!P.empty())
      {
        const LAPACKFullMatrix<double> &lu
          = factorizations.get(prescribed, [&]() {
              auto block = std::make_unique<LAPACKFullMatrix<double>>(P.size(),
                                                                      P.size());
              for (unsigned int a = 0; a < P.size(); ++a)
                for (unsigned int b = 0; b < P.size(); ++b)
                  (*block)(a, b) = compliance[P[a]][P[b]];
              block->compute_lu_factorization();
              return block;
            });
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
        lu.solve(rhs);
        for (unsigned int a = 0; a < P.size(); ++a)
          force_out[P[a]] = rhs[a];
      }

    u_r.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        u_r[i] += compliance(i, j) * force_out[j];
  }
} // namespace coaxfit
