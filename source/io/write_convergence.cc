#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <fstream>

namespace coaxfit
{
  std::string
  ConvergenceWriter::write(const RunResults  &results,
                           const std::string &directory) const
  {
    const std::string name = file_names()[0];
    std::ofstream     out  = open_result_file(directory + "/" + name);
    out << "step,kind,alpha,displacement_mismatch_relative,"
           "traction_mismatch_relative\n";
    // No alpha (an empty field) where the method has none (ibqn).
    for (const CouplingStep &s : results.solver.history())
      {
        out << s.step << ',' << (s.neumann ? "neumann" : "dirichlet") << ',';
        if (std::isfinite(s.alpha))
          out << s.alpha;
        out << ',' << s.displacement_mismatch << ',' << s.traction_mismatch
            << '\n';
      }
    close_result_file(out, directory + "/" + name);
    return name + ": " + std::to_string(results.solver.history().size())
           + " steps";
  }


  std::vector<std::string>
  ConvergenceWriter::file_names() const
  {
    return {"convergence.csv"};
  }
} // namespace coaxfit
