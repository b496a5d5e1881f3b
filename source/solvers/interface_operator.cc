#include <coaxfit/solvers/interface_operator.h>

namespace coaxfit
{
  void
  InterfaceOperator::solve_neumann(const Vector<double> &force,
                                   Vector<double>       &u_r)
  {
    Vector<double> force_out;
    solve(std::vector<bool>(force.size(), false),
          Vector<double>(force.size()),
          force,
          u_r,
          force_out);
  }
} // namespace coaxfit
