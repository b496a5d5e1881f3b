#ifndef coaxfit_result_writers_h
#define coaxfit_result_writers_h

#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_solver.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/design/fit_design.h>
#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/design/pressure_summary.h>
#include <coaxfit/design/verdict.h>
#include <coaxfit/fe/body_discretization.h>
#include <coaxfit/parameters/parameters.h>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace coaxfit
{
  /** Everything a result writer may read about a finished run. */
  struct RunResults
  {
    const Parameters                  &parameters;
    const Scene                       &scene;
    const std::vector<Vector<double>> &fields; ///< per body of scene
    const ContactInterface            &interface;
    const InterfaceSolver             &solver;
    /** The solver's work for this state (before any further analysis). */
    const SolverStatistics              &statistics;
    const PressureSummary               &pressure;
    const Complementarity               &complementarity;
    const FitDesign                     &design;
    const OperationAnalysis             &operation;
    const std::map<std::string, double> &timing;   ///< wall times (s)
    const std::vector<std::string>      &warnings; ///< one line each
    const Verdict                       &verdict;
  };

  /**
   * Writes one result file of a run into a directory and returns one line
   * for the console that says what it wrote (ASPECT's postprocessors are
   * the model). Adding an output file is one new writer, listed in
   * make_result_writers().
   */
  class ResultWriter
  {
  public:
    virtual ~ResultWriter() = default;

    virtual std::string
    write(const RunResults &results, const std::string &directory) const = 0;

    /** The names of the files write() creates. */
    virtual std::vector<std::string>
    file_names() const = 0;

    /**
     * Whether write() reads what the other writers of the run wrote (it
     * then runs after them; the others run concurrently).
     */
    virtual bool
    needs_the_other_files() const
    {
      return false;
    }
  };

  /** contact_pressure.csv: z, pressure, u_r of both bodies, gap, status. */
  class ContactPressureWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /** convergence.csv: one row per coupling step. */
  class ConvergenceWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /**
   * parameters.prm and parameters.json: the parameters exactly as read
   * (file and --set overrides); `coaxfit DIR/parameters.prm` repeats the
   * run.
   */
  class ParametersWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /** shaft.vtu or hub.vtu: the displacement and stress fields of a body. */
  class BodyVtuWriter : public ResultWriter
  {
  public:
    /**
     * Write the body @p body of the scene into `<key>.vtu`, @p key being
     * its lower-case name.
     */
    BodyVtuWriter(unsigned int body, const std::string &key);

    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;

  private:
    const unsigned int body;
    const std::string  key;
  };

  /**
   * interface.vtp: the contact surface as a polyline in the (r, z) plane
   * with pressure, gap and status (1 contact, 0 separated), for ParaView.
   */
  class InterfaceVtpWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /** solution.pvd: shaft.vtu, hub.vtu and interface.vtp as one collection. */
  class PvdWriter : public ResultWriter
  {
  public:
    /** The blocks: one per body (`<key>.vtu`), then the contact surface. */
    explicit PvdWriter(const std::vector<std::string> &body_keys);

    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;

  private:
    const std::vector<std::string> body_keys;
  };

  /**
   * summary.json: everything a script needs to know about a run, always
   * valid JSON (non-finite numbers are null). Written last, so that it can
   * report the time the other writers took.
   */
  class SummaryWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /**
   * hub_bore_stresses.csv and shaft_surface_stresses.csv: the stresses
   * along the joint radius in each body (z, sigma_rr, sigma_zz, sigma_tt,
   * sigma_rz, von Mises), as the design figures use them.
   */
  class SurfaceStressWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /**
   * contact_pressure.png, surface_stresses.png and convergence.png, drawn
   * by gnuplot (Debian package gnuplot-nox) from the CSV files with the
   * script plots.gp, which stays beside them for redrawing. Without gnuplot,
   * or if it fails, the plots are skipped with a one-line note: never an
   * error of the run.
   */
  class PlotWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;
  };

  /**
   * report.md: the inputs in engineering terms, the design table (FE next
   * to DIN 7190), the warnings and the plots of the run.
   */
  class ReportWriter : public ResultWriter
  {
  public:
    std::string
    write(const RunResults  &results,
          const std::string &directory) const override;

    std::vector<std::string>
    file_names() const override;

    /** It shows the plots that were drawn. */
    bool
    needs_the_other_files() const override
    {
      return true;
    }
  };

  /**
   * Run gnuplot on @p script in @p directory (its output discarded); the
   * empty string on success, otherwise why not.
   */
  std::string
  run_gnuplot(const std::string &directory, const std::string &script);

  /**
   * Throw ResourceError unless @p filename is a complete PNG (gnuplot does
   * not report a failed write: a full disk leaves a truncated file).
   */
  void
  check_complete_png(const std::string &filename);

  /** The writers of the files that @p output asks for, summary.json aside. */
  std::vector<std::unique_ptr<ResultWriter>>
  make_result_writers(const OutputParameters         &output,
                      const std::vector<std::string> &body_keys);

  /**
   * @p text as one CSV field: quoted (its quotes doubled, line breaks as
   * spaces) if it holds a comma, quote or line break.
   */
  std::string
  csv_field(const std::string &text);

  /**
   * Open @p filename for writing with 15 significant digits; throws if it
   * cannot be opened.
   */
  std::ofstream
  open_result_file(const std::string &filename);

  /**
   * Throw (exit 3, one line naming @p filename) unless every entry of
   * @p values is finite and small enough for the single precision (float)
   * arrays of VTK files, |v| < 1e30: a file that ParaView would show as inf
   * or nan is not written.
   */
  void
  check_values_for_output(const Vector<double> &values,
                          const std::string    &filename);

  /** Close @p out and throw if anything written to it was lost. */
  void
  close_result_file(std::ofstream &out, const std::string &filename);

  /**
   * Write @p filename by @p write (a deal.II writer: VTU, PVD) between
   * open_result_file() and close_result_file(): deal.II's ExcIO on a
   * failed stream (a full disk) becomes the same one-line "cannot write"
   * error as that of any other result file.
   */
  void
  write_result_file(const std::string                         &filename,
                    const std::function<void(std::ostream &)> &write);
} // namespace coaxfit

#endif
