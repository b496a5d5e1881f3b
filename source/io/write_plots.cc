#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_writers.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>

extern char **environ;

namespace coaxfit
{
  namespace
  {
    /** How long gnuplot may take for the plots of one run. */
    constexpr std::chrono::seconds gnuplot_time_limit(120);

    /** The gnuplot script of the three plots, for the files of a run. */
    std::string
    plot_script(const RunResults &results)
    {
      const FitDesign &d = results.design;
      // The corner value is singular: the axes stop at a multiple of the
      // values away from it, and the plots say so.
      const double p_top = 2.5 * std::max(d.pressure_din, 1e-300);
      double       s_top = 0.;
      for (const auto &m : d.surface_maxima)
        s_top = std::fmax(s_top, 1.6 * m.von_mises);
      // The yield strengths are drawn where they are: the axis reaches them.
      for (const double strength : {results.parameters.hub.yield_strength,
                                    results.parameters.shaft.yield_strength})
        s_top = std::max(s_top, 1.1 * strength);
      if (!(s_top > 0.))
        s_top = 1.;
      const Parameters  &p        = results.parameters;
      const double       z_corner = p.geometry.joint_end();
      std::ostringstream gp;
      gp.precision(10);
      gp << "# coaxfit: gnuplot script of this run's plots; run it here "
            "with 'gnuplot plots.gp'\n"
         << "set terminal pngcairo size 960,600 font ',11'\n"
         << "set datafile separator ','\nset grid\n"
         << "\nset output 'contact_pressure.png'\n"
         << "set title 'Contact pressure along the joint (the value at the "
            "end of the joint is singular; axis clipped)'\n"
         << (p.geometry.whole ? "set xlabel 'z (mm)'\n" :
                                "set xlabel 'z (mm), from the mid-plane'\n")
         << "set ylabel 'contact pressure (MPa)'\nset key top left\n"
         << "set yrange [0:" << p_top << "]\n"
         << "plot 'contact_pressure.csv' skip 1 using 1:2 with linespoints "
            "pt 7 ps 0.5 lw 2 title 'FE (nodal pressure)', \\\n"
         << "     " << d.pressure_din
         << " with lines dt 2 lw 2 title 'DIN 7190 (Lame, equal lengths)'";
      if (results.solver.get_active_set().n_separated() > 0)
        gp << ", \\\n     'contact_pressure.csv' skip 1 using 1:(strcol(6) "
              "eq 'separated' ? 0 : 1/0) with points pt 6 ps 1.5 lc rgb "
              "'red' title 'separated'";
      gp << "\n"
         << "\nset output 'surface_stresses.png'\n"
         << "set title 'Von Mises stress along the joint radius (excluded "
            "within "
         << d.edge_distance << " mm of the end of the joint)'\n"
         << "set ylabel 'von Mises stress (MPa)'\n"
         << "set yrange [0:" << std::max(s_top, 1e-300) << "]\n"
         << "set object 1 rect from " << z_corner - d.edge_distance
         << ", graph 0 to " << z_corner + d.edge_distance
         << ", graph 1 fc rgb '#e8e8e8' fs solid behind\n";
      if (p.geometry.whole) // the other end of a whole joint
        gp << "set object 2 rect from "
           << p.geometry.joint_start() - d.edge_distance << ", graph 0 to "
           << p.geometry.joint_start() + d.edge_distance
           << ", graph 1 fc rgb '#e8e8e8' fs solid behind\n";
      gp << "plot 'hub_bore_stresses.csv' skip 1 using 1:6 with lines lw 2 "
            "title 'hub bore', \\\n"
         << "     'shaft_surface_stresses.csv' skip 1 using 1:6 with lines "
            "lw 2 title 'shaft surface'";
      for (const auto &[name, strength] :
           {std::pair<std::string, double>{"hub", p.hub.yield_strength},
            {"shaft", p.shaft.yield_strength}})
        if (strength > 0.)
          gp << ", \\\n     " << strength << " with lines dt "
             << (name == "hub" ? 2 : 4) << " lw 2 title 'yield strength, "
             << name << "'";
      gp << "\n\nset output 'convergence.png'\n"
         << "unset object 1\n"
         << "set title 'Coupling: relative mismatches per step'\n"
         << "set xlabel 'step'\nset ylabel 'relative mismatch'\n";
      // Mismatches that are all exactly zero (no contact anywhere, nothing
      // to iterate) have no logarithm: drawn on a linear axis.
      bool positive = false;
      for (const CouplingStep &step : results.solver.history())
        positive = positive
                   || (step.neumann ? step.displacement_mismatch :
                                      step.traction_mismatch)
                        > 0.;
      if (!positive)
        {
          gp << "set yrange [-0.1:1]\nset key top right\n"
             << "plot 'convergence.csv' skip 1 using 1:(strcol(2) eq "
                "'neumann' ? $4 : 1/0) with linespoints pt 7 title "
                "'displacement mismatch (exactly 0 in every step)', \\\n"
             << "     'convergence.csv' skip 1 using 1:(strcol(2) eq "
                "'dirichlet' ? $5 : 1/0) with linespoints pt 5 title "
                "'traction mismatch (exactly 0 in every step)'\n";
          return gp.str();
        }
      gp << "set logscale y\nset yrange [*:*]\nset key top right\n"
         << "plot 'convergence.csv' skip 1 using 1:(strcol(2) eq 'neumann' "
            "&& $4 > 0 ? $4 : 1/0) with linespoints pt 7 title 'displacement "
            "|u2 - u1 - d|/d (after Neumann steps)', \\\n"
         << "     'convergence.csv' skip 1 using 1:(strcol(2) eq 'dirichlet' "
            "&& $5 > 0 ? $5 : 1/0) with linespoints pt 5 title 'traction "
            "|p2 - p1|/|p| (after Dirichlet steps)'\n";
      return gp.str();
    }

  } // namespace



  std::string
  run_gnuplot(const std::string &directory, const std::string &script)
  {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    // This process ignores SIGXFSZ (a write error instead); gnuplot does
    // not check its writes, so it gets the default: killed at the limit.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGXFSZ);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    const char *argv[] = {"gnuplot", script.c_str(), nullptr};
    pid_t       pid    = 0;
    const int   error  = posix_spawnp(&pid,
                                   "gnuplot",
                                   &actions,
                                   &attributes,
                                   const_cast<char *const *>(argv),
                                   environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (error != 0)
      return error == ENOENT ?
               "gnuplot not found (Debian package gnuplot-nox)" :
               std::string("cannot start gnuplot: ") + std::strerror(error);
    // gnuplot ends with this process (an interrupted run passes its
    // signal on) and within a time limit (a gnuplot that hangs is killed:
    // the plots are skipped, the results are not held up).
    {
      std::lock_guard<std::mutex> lock(Interruption::mutex());
      Interruption::add_child(pid);
    }
    const auto remove_child = [pid]() {
      std::lock_guard<std::mutex> lock(Interruption::mutex());
      Interruption::remove_child(pid);
    };
    const auto start  = std::chrono::steady_clock::now();
    int        status = 0;
    for (;;)
      {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid)
          break;
        if (done < 0 && errno != EINTR)
          {
            remove_child();
            return std::string("waiting for gnuplot: ") + std::strerror(errno);
          }
        if (std::chrono::steady_clock::now() - start > gnuplot_time_limit)
          {
            ::kill(pid, SIGKILL);
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
              ;
            remove_child();
            return "gnuplot did not finish within "
                   + std::to_string(gnuplot_time_limit.count()) + " s";
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    remove_child();
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ)
      throw ResourceError("drawing the plots with gnuplot failed: file size "
                          "limit reached (the earlier results are untouched)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      return "gnuplot failed";
    return "";
  }



  void
  check_complete_png(const std::string &filename)
  {
    // A PNG ends with its IEND chunk: length 0, "IEND", CRC AE 42 60 82.
    const unsigned char end[]
      = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    std::ifstream in(filename, std::ios::binary | std::ios::ate);
    bool          complete = false;
    if (in && in.tellg() >= static_cast<std::streamoff>(sizeof(end)))
      {
        unsigned char tail[sizeof(end)];
        in.seekg(-static_cast<std::streamoff>(sizeof(end)), std::ios::end);
        in.read(reinterpret_cast<char *>(tail), sizeof(tail));
        complete = in && std::equal(tail, tail + sizeof(end), end);
      }
    if (!complete)
      throw ResourceError("writing '"
                          + filename.substr(filename.find_last_of('/') + 1)
                          + "' failed: disk full, quota or file size limit "
                            "reached (the earlier results are untouched)");
  }



  std::string
  PlotWriter::write(const RunResults  &results,
                    const std::string &directory) const
  {
    const std::string script = "plots.gp";
    std::ofstream     out    = open_result_file(directory + "/" + script);
    out << plot_script(results);
    close_result_file(out, directory + "/" + script);
    const std::string problem = run_gnuplot(directory, script);
    if (!problem.empty())
      {
        // Half-drawn plots are not results.
        for (const std::string &name : file_names())
          if (name != script)
            std::remove((directory + "/" + name).c_str());
        return "plots skipped: " + problem;
      }
    for (const std::string &name : file_names())
      if (name != script)
        check_complete_png(directory + "/" + name);
    return "contact_pressure.png, surface_stresses.png, convergence.png: "
           "plots (plots.gp redraws them)";
  }



  std::vector<std::string>
  PlotWriter::file_names() const
  {
    return {"plots.gp",
            "contact_pressure.png",
            "surface_stresses.png",
            "convergence.png"};
  }
} // namespace coaxfit
