#include <coaxfit/result_writers.h>

#include <fstream>

namespace coaxfit
{
  std::string
  ParametersWriter::write(const RunResults  &results,
                          const std::string &directory) const
  {
    for (const auto &[name, text] :
         {std::pair<std::string, const std::string &>{
            "parameters.prm", results.parameters.used_prm},
          {"parameters.json", results.parameters.used_json}})
      {
        std::ofstream out = open_result_file(directory + "/" + name);
        out << text;
        close_result_file(out, directory + "/" + name);
      }
    return "parameters.prm, parameters.json: the parameters of this run "
           "(repeat it with coaxfit "
           + directory + "/parameters.prm)";
  }
} // namespace coaxfit
