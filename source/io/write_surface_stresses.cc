#include <coaxfit/io/result_writers.h>

#include <fstream>

namespace coaxfit
{
  std::string
  SurfaceStressWriter::write(const RunResults  &results,
                             const std::string &directory) const
  {
    const std::vector<std::string> names = file_names();
    for (unsigned int i = 0; i < 2; ++i)
      {
        const std::vector<StressState> &states
          = i == 0 ? results.design.hub_bore_stresses :
                     results.design.shaft_surface_stresses;
        const std::string file = directory + "/" + names[i];
        std::ofstream     out  = open_result_file(file);
        out << "z_mm,sigma_rr_MPa,sigma_zz_MPa,sigma_tt_MPa,sigma_rz_MPa,"
               "von_Mises_MPa\n";
        for (const StressState &s : states)
          out << s.z << ',' << s.sigma[0] << ',' << s.sigma[1] << ','
              << s.sigma[2] << ',' << s.sigma[3] << ',' << s.von_mises()
              << '\n';
        close_result_file(out, file);
      }
    return names[0] + ", " + names[1]
           + ": stresses along the joint radius in each body";
  }



  std::vector<std::string>
  SurfaceStressWriter::file_names() const
  {
    return {"hub_bore_stresses.csv", "shaft_surface_stresses.csv"};
  }
} // namespace coaxfit
