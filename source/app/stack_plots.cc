#include <coaxfit/app/stack_fit.h>
#include <coaxfit/io/result_writers.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace coaxfit
{
  std::string
  StackFit::write_plots(const std::string &directory) const
  {
    // The pressure axis reaches 1.6 times the largest of the joints'
    // means and estimates: the nodal value at the end of a joint between
    // bodies of different lengths is singular and would flatten the rest.
    double p_top = 0.;
    for (const JointFigures &f : joints_out)
      p_top
        = std::max({p_top, f.p_mean, f.alone_p_mean, f.lame_p, f.lame_alone_p});
    for (const JointFigures &f : joints_assembly)
      p_top = std::max(p_top, f.p_mean);
    p_top          = p_top > 0. ? 1.6 * p_top : 1.;
    bool separated = false;
    for (const JointFigures &f : joints_out)
      separated = separated || f.separated_points > 0;

    std::ostringstream gp;
    gp.precision(10);
    gp << "# coaxfit: gnuplot script of this run's plots; run it here with "
          "'gnuplot plots.gp'\n"
       << "set terminal pngcairo size 960,600 font ',11'\n"
       << "set datafile separator ','\nset grid\n"
       << "\nset output 'contact_pressure.png'\n"
       << (has_loads() ?
             "set title 'Contact pressure of each joint in operation: in "
             "the assembly (points), alone (dashed), plane-stress "
             "estimates (dotted); at assembly, no loads (dash-dot)' font "
             "',10'\n" :
             "set title 'Contact pressure of each joint: in the assembly "
             "(points), alone with the other bodies removed (dashed), "
             "plane-stress estimates (dotted)' font ',10'\n")
       << "set xlabel 'z (mm), "
       << (parameters.sections && !parameters.sections->half_model() ?
             "of the drawing" :
             "from the mid-plane")
       << "'\n"
       << "set ylabel 'contact pressure (MPa)'\nset key outside bottom "
          "center horizontal\n"
       << "set yrange [0:" << p_top << "]\nplot ";
    for (unsigned int k = 0; k < joints_out.size(); ++k)
      {
        const JointFigures &f    = joints_out[k];
        const std::string   csv  = "'contact_pressure_" + f.name + ".csv'";
        const std::string   line = " lc " + std::to_string(k + 1);
        gp << (k > 0 ? ", \\\n     " : "") << csv
           << " skip 1 using 1:2 with linespoints pt 7 ps 0.5 lw 2" << line
           << " title '" << f.name << " (D " << f.diameter << ")', \\\n     "
           << csv << " skip 1 using 1:4 with lines dt 2 lw 2" << line
           << " title '" << f.name << " alone', \\\n     " << f.lame_p
           << " with lines dt 3 lw 1" << line << " notitle, \\\n     "
           << f.lame_alone_p << " with lines dt 3 lw 1" << line << " notitle";
        if (has_loads())
          gp << ", \\\n     " << csv << " skip 1 using 1:5 with lines dt 4 lw 1"
             << line << " title '" << f.name << " at assembly'";
      }
    if (separated)
      for (unsigned int k = 0; k < joints_out.size(); ++k)
        gp << ", \\\n     'contact_pressure_" << joints_out[k].name
           << ".csv' skip 1 using 1:($3 == 0 ? $2 : 1/0) with points pt 6 "
              "ps 1.5 lc rgb 'red' "
           << (k == 0 ? "title 'separated'" : "notitle");
    gp << "\n";

    // The staggered process's residuals (a monolithic run has none).
    bool positive = false;
    for (const auto &[displacement, traction] : history)
      positive = positive || displacement > 0. || traction > 0.;
    // Residuals all exactly zero (nothing to iterate) have no plot.
    const bool staggered = positive;
    if (staggered)
      {
        gp << "\nset output 'convergence.png'\n"
           << "set title 'Coupling over all joints: residuals per step'\n"
           << "set xlabel 'step'\nset ylabel 'relative residual'\n"
           << "set key top right\nset yrange [*:*]\n"
           << "set logscale y\nplot 'convergence.csv' "
           << "skip 1 using 1:($2 > 0 ? $2 : 1/0) with linespoints pt 7 "
              "title 'displacement', \\\n     'convergence.csv' skip 1 using "
              "1:($3 > 0 ? $3 : 1/0) with linespoints pt 5 title 'traction'\n";
      }

    const std::string script = "plots.gp";
    const std::string name   = directory + "/" + script;
    std::ofstream     out    = open_result_file(name);
    out << gp.str();
    close_result_file(out, name);
    std::vector<std::string> pictures = {"contact_pressure.png"};
    if (staggered)
      pictures.push_back("convergence.png");
    const std::string problem = run_gnuplot(directory, script);
    if (!problem.empty())
      {
        // Half-drawn plots are not results.
        for (const std::string &picture : pictures)
          std::remove((directory + "/" + picture).c_str());
        return "plots skipped: " + problem;
      }
    std::string written;
    for (const std::string &picture : pictures)
      {
        check_complete_png(directory + "/" + picture);
        written += picture + ", ";
      }
    return written + "plots (plots.gp redraws them)";
  }
} // namespace coaxfit
