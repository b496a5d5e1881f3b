#include <coaxfit/io/result_writers.h>

#include <fstream>

namespace coaxfit
{
  std::string
  ParametersWriter::write(const RunResults  &results,
                          const std::string &directory) const
  {
    const std::vector<std::string> names = file_names();
    for (const auto &[name, text] :
         {std::pair<std::string, const std::string &>{
            names[0], results.parameters.used_prm},
          {names[1], results.parameters.used_json}})
      {
        std::ofstream out = open_result_file(directory + "/" + name);
        out << text;
        close_result_file(out, directory + "/" + name);
      }
    return "parameters.prm, parameters.json: the parameters of this run "
           "(repeat it with coaxfit "
           + results.parameters.output_directory() + "/parameters.prm)";
  }


  std::vector<std::string>
  ParametersWriter::file_names() const
  {
    return {"parameters.prm", "parameters.json"};
  }
} // namespace coaxfit
