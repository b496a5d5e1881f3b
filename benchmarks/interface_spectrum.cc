// Interface spectrum of the staggered process for one .prm case.
//
// Forms each body's compliance on S (the paper's K_i: nodal force -> u_r,
// the inverse Schur complement on S, CondensedBody),
// solves the generalized eigenproblem K1 x = lambda K2 x and prints what it
// implies for a constant alpha: the double step (Neumann + Dirichlet)
// contracts the error of mode lambda by
//   N(alpha, lambda) = -(alpha sqrt(lambda) - (1 - alpha)/sqrt(lambda))^2,
// (4.17) of the paper, so a constant alpha converges iff |N| < 1 for every
// lambda, and the best one is alpha* = 1 / (1 + sqrt(lambda_min lambda_max)).
//
// Usage: coaxfit-spectrum [--set Section/Name=value]... FILE.prm

#include <deal.II/lac/lapack_full_matrix.h>

#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/base/input_error.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace
{
  using namespace coaxfit;

  /** The parameters named on the command line (file and --set overrides). */
  Parameters
  parse_arguments(int argc, char **argv)
  {
    const std::string usage
      = "usage: coaxfit-spectrum [--set Section/Name=value]... FILE.prm";
    std::vector<std::pair<std::string, std::string>> overrides;
    std::string                                      filename;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--set" && i + 1 < argc)
          {
            const std::string s  = argv[++i];
            const auto        eq = s.find('=');
            if (eq == std::string::npos)
              throw InputError("expected Section/Name=value, got " + s);
            overrides.emplace_back(s.substr(0, eq), s.substr(eq + 1));
          }
        else if (filename.empty() && arg[0] != '-')
          filename = arg;
        else
          throw InputError(usage);
      }
    if (filename.empty())
      throw InputError(usage);
    return read_parameters(filename, overrides);
  }



  /**
   * The eigenvalues of K1 x = lambda K2 x, ascending, for the bodies a run
   * of coaxfit would build (mesh, degree, integration).
   */
  std::vector<double>
  interface_eigenvalues(const Parameters &p)
  {
    const auto shaft = make_body(p, "Shaft");
    const auto hub   = make_body(p, "Hub");
    for (BodyDiscretization *b : {shaft.get(), hub.get()})
      {
        b->setup_system();
        b->assemble_system();
      }
    const unsigned int  n = shaft->n_interface_points();
    BodySolver          shaft_solver(*shaft), hub_solver(*hub);
    const CondensedBody condensed_shaft(shaft_solver),
      condensed_hub(hub_solver);
    LAPACKFullMatrix<double> K1(n, n), K2(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          // inward for the shaft: its compliance is -u_r per unit force
          K1(i, j) = -condensed_shaft.get_compliance()(i, j);
          K2(i, j) = condensed_hub.get_compliance()(i, j);
        }
    std::vector<Vector<double>> vectors(n, Vector<double>(n));
    K1.compute_generalized_eigenvalues_symmetric(K2, vectors);
    std::vector<double> lambda(n);
    for (unsigned int i = 0; i < n; ++i)
      lambda[i] = K1.eigenvalue(i).real();
    std::sort(lambda.begin(), lambda.end());
    return lambda;
  }



  /** max over the modes of |N(alpha, lambda)|, the double step's rate. */
  double
  contraction(const std::vector<double> &lambda, const double alpha)
  {
    double worst = 0.;
    for (const double l : lambda)
      {
        const double s = std::sqrt(l), x = alpha * s - (1. - alpha) / s;
        worst = std::max(worst, x * x);
      }
    return worst;
  }



  /** What the spectrum implies for a constant alpha, on standard output. */
  void
  print_report(const Parameters &p, const std::vector<double> &lambda)
  {
    double lo = 2., hi = -1.;
    for (unsigned int k = 1; k < 10000; ++k)
      if (contraction(lambda, k * 1e-4) < 1.)
        {
          lo = std::min(lo, k * 1e-4);
          hi = std::max(hi, k * 1e-4);
        }
    const double best = 1. / (1. + std::sqrt(lambda.front() * lambda.back()));
    const double own  = contraction(lambda, p.coupling.alpha);

    std::cout << std::setprecision(4) << "case " << p.case_name << ": "
              << lambda.size() << " interface points, FE_Q(" << p.mesh.degree
              << "), refinement " << p.mesh.global_refinements << '\n'
              << "  eigenvalues of K1 K2^-1 in [" << lambda.front() << ", "
              << lambda.back() << "]\n"
              << "  best constant alpha " << best << ", contraction per "
              << "double step " << contraction(lambda, best) << '\n';
    if (hi < lo)
      std::cout << "  no constant alpha converges\n";
    else
      std::cout << "  constant alpha converges for " << lo
                << " <= alpha <= " << hi << '\n';
    std::cout << "  alpha = " << p.coupling.alpha
              << " (Coupling/Alpha): contraction " << own
              << (own < 1. ? "" : " (diverges)") << '\n';
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      const Parameters p = parse_arguments(argc, argv);
      print_report(p, interface_eigenvalues(p));
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "coaxfit-spectrum: error: " << e.what() << std::endl;
      return 1;
    }
}
