#include <coaxfit/result_writers.h>

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
    body.output_results(shaft ? results.shaft_field : results.hub_field,
                        directory + "/" + name);
    return name + ": displacement and stresses on "
           + std::to_string(body.n_cells()) + " cells";
  }


  std::vector<std::string>
  BodyVtuWriter::file_names() const
  {
    return {shaft ? "shaft.vtu" : "hub.vtu"};
  }
} // namespace coaxfit
