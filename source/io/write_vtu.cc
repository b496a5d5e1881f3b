#include <deal.II/base/exceptions.h>

#include <coaxfit/io/result_writers.h>

#include <fstream>

namespace coaxfit
{
  BodyVtuWriter::BodyVtuWriter(const bool shaft)
    : shaft(shaft)
  {}



  std::string
  BodyVtuWriter::write(const RunResults  &results,
                       const std::string &directory) const
  {
    const std::string         name = file_names()[0];
    const BodyDiscretization &body = shaft ? results.shaft : results.hub;
    const std::string         file = directory + "/" + name;
    const Vector<double>     &field
      = shaft ? results.shaft_field : results.hub_field;
    check_values_for_output(field, file);
    std::ofstream out = open_result_file(file);
    try
      {
        // The shaft is made larger than its mesh by d (radially): drawn
        // in its assembled place by displacement_mm.
        const double oversize = shaft ? results.interface.interference()
                                          / results.parameters.geometry.R1 :
                                        0.;
        body.output_results(field, out, shaft ? 0 : 1, oversize);
      }
    catch (const ExceptionBase &) // deal.II's ExcIO on a failed stream
      {
        out.setstate(std::ios::badbit);
      }
    close_result_file(out, file);
    return name + ": displacement and stresses on "
           + std::to_string(body.n_cells()) + " cells";
  }


  std::vector<std::string>
  BodyVtuWriter::file_names() const
  {
    return {shaft ? "shaft.vtu" : "hub.vtu"};
  }
} // namespace coaxfit
