#include <deal.II/base/exceptions.h>

#include <coaxfit/io/result_writers.h>

#include <fstream>

namespace coaxfit
{
  BodyVtuWriter::BodyVtuWriter(const unsigned int body, const std::string &key)
    : body(body)
    , key(key)
  {}



  std::string
  BodyVtuWriter::write(const RunResults  &results,
                       const std::string &directory) const
  {
    const std::string         name = file_names()[0];
    const BodyDiscretization &d    = *results.scene.bodies[body].discretization;
    const std::string         file = directory + "/" + name;
    const Vector<double>     &field = results.fields[body];
    check_values_for_output(field, file);
    // The inner body of a joint is made larger than its mesh by d
    // (radially): drawn in its assembled place by displacement_mm.
    write_result_file(file, [&](std::ostream &out) {
      d.output_results(field, out, body, results.scene.oversize(body));
    });
    return name + ": displacement and stresses on "
           + std::to_string(d.n_cells()) + " cells";
  }


  std::vector<std::string>
  BodyVtuWriter::file_names() const
  {
    return {key + ".vtu"};
  }
} // namespace coaxfit
