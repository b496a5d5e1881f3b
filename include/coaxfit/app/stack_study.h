#ifndef coaxfit_stack_study_h
#define coaxfit_stack_study_h

#include <coaxfit/app/stack_fit.h>

#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The figures of a stack's run that its studies tabulate (--sweep's
   * sweep.csv, Fit/Case = all's fit_cases.csv): a column per figure of
   * each joint and of each body, named `<joint><suffix>` and
   * `<body><suffix>`; NaN where the run has none (an empty field).
   */
  template <typename Figures>
  struct StackColumn
  {
    const char *suffix;
    double (*value)(const Figures &);
  };

  /** Each joint's columns, in order. */
  inline const std::vector<StackColumn<JointFigures>> &
  stack_joint_columns()
  {
    static const std::vector<StackColumn<JointFigures>> columns
      = {{"_pressure_mid_plane_MPa",
          [](const JointFigures &f) { return f.p_mid; }},
         {"_pressure_mean_MPa", [](const JointFigures &f) { return f.p_mean; }},
         {"_closed", [](const JointFigures &f) { return f.closed ? 1. : 0.; }},
         {"_safety_slip",
          [](const JointFigures &f) {
            return f.slip_judged ? f.slip_safety : std::nan("");
          }},
         {"_press_in_force_N",
          [](const JointFigures &f) { return f.press_in_force; }},
         {"_joining_heat_outer_to_C",
          [](const JointFigures &f) { return f.heat_outer_to; }},
         {"_joining_cool_inner_to_C",
          [](const JointFigures &f) { return f.cool_inner_to; }}};
    return columns;
  }

  /** Each body's columns, in order. */
  inline const std::vector<StackColumn<BodyFigures>> &
  stack_body_columns()
  {
    static const std::vector<StackColumn<BodyFigures>> columns
      = {{"_von_mises_mid_plane_MPa",
          [](const BodyFigures &f) { return f.von_mises_mid_plane; }},
         {"_safety_yield",
          [](const BodyFigures &f) {
            return f.yield_safety > 0. ? f.yield_safety : std::nan("");
          }},
         {"_safety_fracture", [](const BodyFigures &f) {
            return f.fracture_safety > 0. ? f.fracture_safety : std::nan("");
          }}};
    return columns;
  }

  /** The names of the columns of a stack of @p bodies: joints', bodies'. */
  inline std::vector<std::string>
  stack_column_names(const std::vector<std::string> &bodies)
  {
    std::vector<std::string> names;
    for (unsigned int k = 0; k + 1 < bodies.size(); ++k)
      for (const auto &column : stack_joint_columns())
        names.push_back(bodies[k] + "-" + bodies[k + 1] + column.suffix);
    for (const std::string &b : bodies)
      for (const auto &column : stack_body_columns())
        names.push_back(b + column.suffix);
    return names;
  }

  /** The figures of a finished run @p fit in the order of the names. */
  inline std::vector<double>
  stack_column_values(const StackFit &fit)
  {
    std::vector<double> values;
    for (const JointFigures &f : fit.joint_figures())
      for (const auto &column : stack_joint_columns())
        values.push_back(column.value(f));
    for (const BodyFigures &f : fit.body_figures())
      for (const auto &column : stack_body_columns())
        values.push_back(column.value(f));
    return values;
  }

  /**
   * What became of one run of a stack study (a --sweep value, a case of
   * Fit/Case = all), and its figures.
   */
  struct StackStudyRun
  {
    int                      exit_code = 1; ///< as the program's
    bool                     written   = false;
    bool                     no_fits   = false; ///< a selection that found none
    unsigned int             steps     = 0;
    std::string              verdict; ///< OK, FAILED; empty: none
    std::vector<std::string> failed;  ///< the verdict's failed criteria
    std::vector<double>      values;  ///< stack_column_values()
    std::string              error;   ///< why it has no figures, if so
    /** Each joint's nominal U (mm) as run; empty if not read. */
    std::vector<double> U;
    /** Each joint's ISO fit as run (a selection's choice); empty: none. */
    std::vector<std::string> iso_fits;
  };

  /**
   * Run the stack that @p read gives into @p into, a new subdirectory of a
   * staged study (removed again when nothing is written: a diverged
   * process, a refused case), its console lines to @p out if @p verbose.
   * An InputError (reading the case, or the run's own refusal) becomes
   * exit code 1 with its message; any other exception passes.
   */
  StackStudyRun
  run_stack_study_case(const std::function<StackParameters()> &read,
                       const std::string                      &into,
                       bool                                    verbose,
                       std::ostream                           &out);

  /**
   * Write the figures of @p run for @p n columns of a study's CSV table,
   * each after a comma (a run without them, or NaN: an empty field).
   */
  void
  write_study_values(std::ostream        &csv,
                     const StackStudyRun &run,
                     std::size_t          n);

  /**
   * If @p run gave no converged result, say so in one line on the error
   * stream as its own run would: `coaxfit: [error: ]<label>: <error>`
   * (the label left out where the error begins with it).
   */
  void
  say_unconverged(const StackStudyRun &run, const std::string &label);

  /**
   * The exit code of a study of @p runs: 0 if each converged, else the
   * largest of 2 (not converged) and 1 (refused). If none was written,
   * says so to @p out (@p what: "value of the sweep", "case of the
   * study"; the earlier results in @p target untouched) and returns at
   * least 1; @p nothing is then true.
   */
  int
  stack_study_exit_code(const std::vector<StackStudyRun> &runs,
                        const std::string                &what,
                        const std::string                &target,
                        std::ostream                     &out,
                        bool                             &nothing);
} // namespace coaxfit

#endif
