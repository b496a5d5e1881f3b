#include <coaxfit/result_writers.h>

#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace coaxfit
{
  std::ofstream
  open_result_file(const std::string &filename)
  {
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error("cannot write '" + filename + "'");
    out << std::setprecision(15);
    return out;
  }



  void
  close_result_file(std::ofstream &out, const std::string &filename)
  {
    out.close();
    if (!out)
      throw std::runtime_error("writing '" + filename + "' failed");
  }



  std::vector<std::unique_ptr<ResultWriter>>
  make_result_writers(const OutputParameters &output)
  {
    std::vector<std::unique_ptr<ResultWriter>> writers;
    writers.push_back(std::make_unique<ContactPressureWriter>());
    writers.push_back(std::make_unique<ConvergenceWriter>());
    writers.push_back(std::make_unique<ParametersWriter>());
    if (output.write_vtu)
      {
        writers.push_back(std::make_unique<BodyVtuWriter>(true));
        writers.push_back(std::make_unique<BodyVtuWriter>(false));
        writers.push_back(std::make_unique<InterfaceVtpWriter>());
        writers.push_back(std::make_unique<PvdWriter>());
      }
    return writers;
  }
} // namespace coaxfit
