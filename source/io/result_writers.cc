#include <deal.II/base/exceptions.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/io/result_writers.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace coaxfit
{
  std::string
  csv_field(const std::string &text)
  {
    if (text.find_first_of(",\"\n") == std::string::npos)
      return text;
    std::string quoted = "\"";
    for (const char ch : text)
      {
        if (ch == '"')
          quoted += '"';
        quoted += (ch == '\n' ? ' ' : ch);
      }
    return quoted + '"';
  }



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
  check_values_for_output(const Vector<double> &values,
                          const std::string    &filename)
  {
    for (const double v : values)
      if (!(std::abs(v) < 1e30))
        throw std::runtime_error(
          "cannot write '" + filename + "': the solution has the value "
          + std::to_string(v)
          + ", not finite or beyond what the file's single-precision "
            "arrays hold");
  }



  void
  close_result_file(std::ofstream &out, const std::string &filename)
  {
    out.close();
    if (!out)
      throw ResourceError("writing '"
                          + std::filesystem::path(filename).filename().string()
                          + "' failed: disk full, quota or file size limit "
                            "reached (the earlier results are untouched)");
  }



  std::vector<std::unique_ptr<ResultWriter>>
  make_result_writers(const OutputParameters         &output,
                      const std::vector<std::string> &body_keys)
  {
    std::vector<std::unique_ptr<ResultWriter>> writers;
    writers.push_back(std::make_unique<ContactPressureWriter>());
    writers.push_back(std::make_unique<ConvergenceWriter>());
    writers.push_back(std::make_unique<ParametersWriter>());
    writers.push_back(std::make_unique<SurfaceStressWriter>());
    if (output.write_vtu)
      {
        for (unsigned int b = 0; b < body_keys.size(); ++b)
          writers.push_back(std::make_unique<BodyVtuWriter>(b, body_keys[b]));
        writers.push_back(std::make_unique<InterfaceVtpWriter>());
        writers.push_back(std::make_unique<PvdWriter>(body_keys));
      }
    if (output.write_plots)
      writers.push_back(std::make_unique<PlotWriter>());
    if (output.write_report) // last: it shows the plots that exist
      writers.push_back(std::make_unique<ReportWriter>());
    return writers;
  }



  void
  write_result_file(const std::string                         &filename,
                    const std::function<void(std::ostream &)> &write)
  {
    std::ofstream out = open_result_file(filename);
    try
      {
        write(out);
      }
    catch (const dealii::ExceptionBase &) // deal.II's ExcIO on a failed stream
      {
        out.setstate(std::ios::badbit);
      }
    close_result_file(out, filename);
  }
} // namespace coaxfit
