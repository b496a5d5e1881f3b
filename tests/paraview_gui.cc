// The ParaView GUI route of tools/paraview/view.py, as a user takes it:
// `COAXFIT_OUTPUT=DIR paraview --script=tools/paraview/view.py`, here under
// a virtual display (Xvfb, 1600 x 1000) and photographed with xwd.
// - variant 14 (coarse, its tube separates at the ends of the hub) is run,
//   and files stand in for the pictures of an earlier pvpython run of
//   view.py in their default place (DIR_views/; test paraview_view draws
//   the real ones);
// - the GUI then shows the views placed in a layout (before, they were
//   never placed and an empty render view showed): the part coloured by
//   von Mises (strongly coloured pixels, ParaView's own widgets are grey)
//   and the chart of contact pressure and gap (pixels of the series
//   colours that view.py sets: pressure navy 0,0,153, gap green 0,170,0;
//   no other item of the GUI has them);
// - the GUI writes nothing unless asked: the files there keep their bytes
//   and times, and no file is added (before, the GUI replaced the pictures
//   with black ones).
// view.py creates the file named by COAXFIT_VIEW_READY once its views are
// in place; every wait is bounded. The GUI's own messages stay in gui.log.
// Without paraview, xvfb-run, xwd or /usr/bin/python3 with numpy
// the test fails (it does not skip).

#include "run_executable.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace
{
  const std::string source_dir = COAXFIT_SOURCE_DIR;

  /** Checksum, size and modification time of each file in @p directory. */
  std::map<std::string, std::string>
  fingerprints(const std::string &directory)
  {
    std::map<std::string, std::string> found;
    if (!std::filesystem::is_directory(directory))
      return found;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      {
        const std::string name = entry.path().filename().string();
        found[name]            = coaxfit_test::run_command(
                        "cksum < '" + entry.path().string()
                        + "'; stat -c %Y.%y '" + entry.path().string() + "'")
                        .message;
      }
    return found;
  }

  /**
   * Start the GUI on the result directory "separating" under a virtual
   * display (nothing else asked of view.py), wait until view.py
   * signals that its views are in place, take @p shots screenshots 2 s
   * apart (shot1.xwd, ...), end the GUI. A virtual X server that is not
   * ready in time aborts the GUI at its start: up to 3 tries. Returns
   * whether the views were in place and whether the GUI still ran then.
   */
  std::pair<bool, bool>
  run_gui(const unsigned int shots)
  {
    const std::string ready = std::filesystem::absolute("gui.ready").string();
    bool              was_ready = false, running = false;
    for (unsigned int attempt = 0; attempt < 3 && !was_ready; ++attempt)
      {
        std::filesystem::remove(ready);
        for (unsigned int k = 1; k <= shots; ++k)
          std::filesystem::remove("shot" + std::to_string(k) + ".xwd");
        const coaxfit_test::RunResult gui = coaxfit_test::run_command(
          "COAXFIT_OUTPUT=separating COAXFIT_VIEW_READY=" + ready
          + " timeout 150 xvfb-run -a -s '-screen 0 1600x1000x24' sh -c '"
            "paraview --dr --script="
          + source_dir + "/tools/paraview/view.py"
          + " > gui.log 2>&1 & pid=$!; i=0; "
            "while [ ! -e "
          + ready
          + " ] && [ $i -lt 180 ] && kill -0 $pid 2>/dev/null; "
            "do sleep 0.5; i=$((i+1)); done; "
            "[ -e "
          + ready
          + " ] && echo ready; "
            "k=0; while [ $k -lt "
          + std::to_string(shots)
          + " ]; do k=$((k+1)); sleep 2; "
            "timeout 20 xwd -root -silent -display \"$DISPLAY\" > shot$k.xwd; "
            "done; "
            "kill -0 $pid 2>/dev/null && echo running; "
            "kill $pid 2>/dev/null; wait $pid 2>/dev/null; true' 2>/dev/null");
        was_ready = gui.message.find("ready") != std::string::npos;
        running   = gui.message.find("running") != std::string::npos;
      }
    return {was_ready, running};
  }


  /**
   * The counts of tests/xwd_pixels.py for the screenshot @p shot; with
   * @p png also the screenshot as SHOT.png (to look at when a check fails).
   */
  std::map<std::string, double>
  pixels(const std::string &shot, const bool png = false)
  {
    const coaxfit_test::RunResult r = coaxfit_test::run_command(
      "timeout 60 /usr/bin/python3 " + source_dir + "/tests/xwd_pixels.py "
      + shot + (png ? " --png " + shot + ".png" : std::string())
      + " --colour pressure=0,0,153 --colour gap=0,170,0 2>/dev/null");
    std::map<std::string, double> values;
    std::istringstream            lines(r.message);
    std::string                   key;
    while (lines >> key)
      {
        if (key == "colour")
          lines >> key;
        double value = 0;
        lines >> value;
        values[key] = value;
        if (key == "size")
          lines >> values["height"];
      }
    return values;
  }
} // namespace


int
main()
{
  for (const std::string tool : {"paraview", "xvfb-run", "xwd"})
    if (coaxfit_test::run_command("command -v " + tool + " >/dev/null")
          .exit_code
        != 0)
      {
        std::cout << tool
                  << " not found: install Debian's paraview, xvfb, xauth and "
                     "x11-apps (.ci/packages)\n";
        return 1;
      }
  if (coaxfit_test::run_command("/usr/bin/python3 -c 'import numpy' "
                                "2>/dev/null")
        .exit_code
      != 0)
    {
      std::cout << "/usr/bin/python3 with numpy not found: install Debian's "
                   "python3-numpy (.ci/packages)\n";
      return 1;
    }

  std::filesystem::remove_all("separating");
  std::filesystem::remove_all("separating_views");
  const coaxfit_test::RunResult run = coaxfit_test::run_coaxfit(
    "separating",
    "--set 'Output/Print timing=false' --set 'Mesh/Global refinements=0' "
      + source_dir + "/prm/variant_14.prm");
  std::cout << "prm/variant_14.prm: exit code " << run.exit_code << '\n';
  if (run.exit_code != 0)
    return 1;

  // Pictures in their default place (DIR_views/), as an earlier pvpython
  // run of view.py leaves them (test paraview_view draws the real ones;
  // here files of the same names, whose bytes and times the GUI must keep).
  std::filesystem::create_directories("separating_views");
  for (const char *name : {"contact_chart.png",
                           "part_3d.png",
                           "section.png",
                           "separation_zoom.png"})
    std::ofstream("separating_views/" + std::string(name))
      << "written before the GUI: " << name << '\n';
  const auto before = fingerprints("separating_views");
  std::cout << "pictures in separating_views: " << before.size() << '\n';

  // The GUI, as a user starts it: nothing asked but the result directory.
  const unsigned int shots        = 2;
  const auto [was_ready, running] = run_gui(shots);
  std::cout << "GUI: views in place (COAXFIT_VIEW_READY) within 90 s: "
            << (was_ready ? "yes" : "NO") << '\n'
            << "GUI: still running at the screenshots: "
            << (running ? "yes" : "NO") << '\n';

  // The first screenshot that shows both counts (the GUI may still be
  // drawing at the first); else the last.
  bool part = false, chart = false;
  for (unsigned int k = 1; k <= shots && !(part && chart); ++k)
    {
      auto values = pixels("shot" + std::to_string(k) + ".xwd");
      if (k == shots
          || (values["saturated"] > 0.015 && values["pressure"] > 200
              && values["gap"] > 100))
        {
          std::cout << "screenshot: " << values["size"] << " x "
                    << values["height"] << '\n';
          part  = values["saturated"] > 0.015;
          chart = values["pressure"] > 200 && values["gap"] > 100;
          if (!(part && chart))
            pixels("shot" + std::to_string(k) + ".xwd", true);
        }
    }
  std::cout << "part shown (strongly coloured pixels above 1.5 % of the "
               "screen): "
            << (part ? "yes" : "NO") << '\n'
            << "chart shown (pressure series above 200 pixels, gap series "
               "above 100): "
            << (chart ? "yes" : "NO") << '\n';

  const auto after = fingerprints("separating_views");
  std::cout << "pictures written before unchanged after the GUI (bytes and "
               "times): "
            << (before == after && !before.empty() ? "yes" : "NO") << '\n';
  return 0;
}
