#ifndef coaxfit_usage_h
#define coaxfit_usage_h

namespace coaxfit
{
  /**
   * The text of `coaxfit --help`: shared by the launcher, which prints it
   * without loading the program, and the program.
   */
  inline constexpr const char *usage
    = "Usage: coaxfit [--quiet] [--set Section/Name=value]... FILE.prm\n"
      "       coaxfit [options] FILE.prm FILE2.prm ...    several cases\n"
      "       coaxfit [options] --sweep Section/Name=VALUES FILE.prm\n"
      "       coaxfit --print-parameters [STACK.prm]\n"
      "       coaxfit --help\n"
      "\n"
      "Computes the contact of an interference fit between a shaft (or tube)\n"
      "and a hub, two coaxial elastic cylinders, by the principle of\n"
      "alternating continuity (staggered Dirichlet-Neumann coupling).\n"
      "\n"
      "  --set Section/Name=value   override a parameter of FILE.prm, e.g.\n"
      "                             --set Mesh/Global\\ refinements=2\n"
      "                             --set Material/Hub/E=7e4\n"
      "  --quiet                    print only the final report and errors\n"
      "                             (of several cases: only the table)\n"
      "  --sweep Section/Name=v1,v2,...   or   Section/Name=from:to:count\n"
      "                             (v1;v2;... for values with commas,\n"
      "                             v1|v2|... for values with ';': outlines)\n"
      "                             run FILE.prm once for each value; the\n"
      "                             study goes to its Output/Directory with\n"
      "                             _sweep appended: sweep.csv, sweep.png\n"
      "                             and one subdirectory per value\n"
      "  --jobs N                   cases run at once (default: the number\n"
      "                             of processors), each in its own process\n"
      "  --table FILE.csv           the table of several files (default:\n"
      "                             cases.csv beside the first case's\n"
      "                             output directory)\n"
      "  --print-parameters         list every parameter with its default,\n"
      "                             allowed values and documentation (with\n"
      "                             a file of several bodies: that stack's)\n"
      "  --help                     this text\n"
      "\n"
      "Results go to Output/Directory (default output/<FILE's base name>):\n"
      "contact_pressure.csv, convergence.csv, summary.json, parameters.prm\n"
      "(repeats the run), parameters.json, shaft.vtu, hub.vtu,\n"
      "interface.vtp and solution.pvd, replacing that directory as a whole\n"
      "once every file is complete (a failed or interrupted run leaves the\n"
      "earlier results untouched).\n"
      "\n"
      "Several files or a sweep: each case runs as it would alone, into its\n"
      "own directory; a failed case does not stop the others; a table of\n"
      "all of them is printed (and written as CSV) at the end, and the exit\n"
      "code is the gravest of the cases' (3, then 2, then 1).\n"
      "\n"
      "Several bodies (a file with Assembly/Bodies = Shaft, Sleeve, Hub,\n"
      "inside out; doc/several_bodies.md): every joint solved at once;\n"
      "each body a plain ring (Geometry/<body>/...) or drawn as its\n"
      "section (Geometry/<body> section = z, D; ...);\n"
      "summary.json, report.md, contact_pressure_<joint>.csv,\n"
      "interface_<joint>.vtp, <body>.vtu, solution.pvd. Such files run\n"
      "alone, with --sweep or several together (--jobs at a time; with\n"
      "files of two bodies their table is cases_stacks.csv, a row per\n"
      "joint);\n"
      "Design/Mode = select chooses the ISO fits of all joints together.\n"
      "\n"
      "Exit codes: 0 converged; 1 bad input or a run refused for its\n"
      "resources; 2 the coupling did not converge (the state is written,\n"
      "marked \"converged\": false) or diverged (nothing written); 3 internal\n"
      "or system error (out of memory, disk full); 130, 143 interrupted by\n"
      "SIGINT, SIGTERM (earlier results untouched).\n";
} // namespace coaxfit

#endif
