#ifndef coaxfit_design_report_h
#define coaxfit_design_report_h

#include <coaxfit/design/fit_design.h>
#include <coaxfit/parameters/parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /** One line of the design table: a figure by FE and by DIN 7190. */
  struct DesignRow
  {
    std::string label;   ///< with its unit
    double      fe, din; ///< NaN: not given
  };

  /** The rows of the design table of @p design, in reading order. */
  std::vector<DesignRow>
  design_rows(const FitDesign &design);

  /**
   * A figure in @p precision significant digits: "-" for one that is not
   * given (NaN), "infinite" or "-infinite" for an infinite one.
   */
  std::string
  figure_text(double value, int precision);

  /**
   * A design figure as the table and the report print it: 5 significant
   * digits (4 from 1e5 on), "-" for a figure that is not given (NaN).
   */
  std::string
  design_figure(double value);

  /**
   * The corner value of @p m with its refinement trend when known: singular,
   * never a design figure.
   */
  std::string
  corner_text(const FitDesign::SurfaceMaximum &m);

  /** One line saying which interference the run used and where from. */
  std::string
  interference_line(const Parameters &parameters);

  /** Print the design table to @p out (the console report). */
  void
  print_design(std::ostream     &out,
               const Parameters &parameters,
               const FitDesign  &design);
} // namespace coaxfit

#endif
