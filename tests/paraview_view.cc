// What a ParaView user sees, checked with ParaView's own reader (pvpython
// from Debian's paraview package, installed by .ci/build):
// - the equal-length Lame case: solution.pvd has the named blocks shaft,
//   hub, contact_surface; every array carries its unit (in its name and as
//   the units attribute); the pressure is Lame's 187.5 MPa, the hub's hoop
//   stress at the bore 312.5 MPa, the solid shaft's sigma_rr = sigma_tt =
//   -187.5 MPa; the bodies warped by displacement_mm meet at the joint
//   (before, the shaft lacked its oversize d and a false gap of d showed);
// - variant 14 (coarse), whose tube separates at its ends: the warped
//   surfaces meet where in contact and open by the gap where separated;
// - tools/paraview/view.py draws its pictures (PNG signature, size, and
//   enough bytes to hold a drawing, not an empty frame): the section, the
//   3D part, the chart of contact pressure and gap along the joint and the
//   close-up of the separated zone; and refuses a field the bodies do not
//   have, naming the ones they have.
// Without pvpython or xvfb-run the test fails (it does not skip).

#include "run_executable.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
  const std::string source_dir = COAXFIT_SOURCE_DIR;


  /** Run coaxfit on @p prm with @p settings into @p directory. */
  bool
  run_case(const std::string &directory,
           const std::string &prm,
           const std::string &settings)
  {
    std::filesystem::remove_all(directory);
    const coaxfit_test::RunResult r
      = coaxfit_test::run_coaxfit(directory,
                                  settings + " " + source_dir + "/" + prm);
    std::cout << prm << ": exit code " << r.exit_code << '\n';
    return r.exit_code == 0;
  }

  /** Print the checks of tests/paraview_check.py on @p directory. */
  void
  check(const std::string &directory, const std::string &kind)
  {
    const coaxfit_test::RunResult r = coaxfit_test::run_command(
      "timeout 300 pvpython " + source_dir + "/tests/paraview_check.py "
      + directory + " " + kind + " 2>&1");
    std::cout << r.message << "paraview_check.py: exit code " << r.exit_code
              << "\n\n";
  }

  /** PNG signature, width and height of @p file; its size in bytes. */
  void
  describe_png(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    unsigned char header[24] = {};
    in.read(reinterpret_cast<char *>(header), sizeof(header));
    const bool signature = in && header[0] == 0x89 && header[1] == 'P'
                           && header[2] == 'N' && header[3] == 'G';
    const auto big_endian = [&](const unsigned int at) {
      return (std::uint32_t(header[at]) << 24)
             | (std::uint32_t(header[at + 1]) << 16)
             | (std::uint32_t(header[at + 2]) << 8) | header[at + 3];
    };
    const auto bytes
      = std::filesystem::exists(file) ? std::filesystem::file_size(file) : 0;
    std::cout << std::filesystem::path(file).filename().string() << ": PNG "
              << (signature ? "yes" : "NO") << ", " << big_endian(16) << " x "
              << big_endian(20)
              << ", more than 20 kB: " << (bytes > 20000 ? "yes" : "NO")
              << '\n';
  }
} // namespace


int
main()
{
  for (const std::string tool : {"pvpython", "xvfb-run"})
    if (coaxfit_test::run_command("command -v " + tool + " >/dev/null")
          .exit_code
        != 0)
      {
        std::cout << tool
                  << " not found: install Debian's paraview, xvfb and xauth "
                     "(.ci/packages)\n";
        return 1;
      }
  const std::string settings = "--set 'Output/Print timing=false'";
  if (run_case("lame", "tests/lame_run.prm", settings))
    check("lame", "LAME");
  if (run_case("separating",
               "prm/variant_14.prm",
               settings + " --set 'Mesh/Global refinements=0'"))
    {
      check("separating", "SEPARATING");
      std::filesystem::remove_all("views");
      // view.py starts its own virtual display when there is none; its
      // log (kept in view.log) shows in the output only if it fails.
      const std::string view
        = "timeout 300 pvpython " + source_dir + "/tools/paraview/view.py ";
      const coaxfit_test::RunResult r = coaxfit_test::run_command(
        view + "separating --png-dir views > view.log 2>&1");
      std::cout << "view.py: exit code " << r.exit_code << '\n';
      if (r.exit_code != 0)
        std::cout << coaxfit_test::run_command("tail -5 view.log").message;
      std::cout << "contact_chart.png written: "
                << (std::filesystem::exists("views/contact_chart.png") ? "yes" :
                                                                         "NO")
                << '\n';
      for (const std::string name : {"section.png",
                                     "part_3d.png",
                                     "contact_chart.png",
                                     "separation_zoom.png"})
        describe_png("views/" + name);

      // A field the bodies do not have: exit code 1, the allowed ones named.
      const coaxfit_test::RunResult wrong = coaxfit_test::run_command(
        view + "separating --field sigma_xx_MPa --no-png 2>&1 >/dev/null");
      std::cout << "view.py --field sigma_xx_MPa: exit code " << wrong.exit_code
                << '\n'
                << wrong.message;
    }
}
