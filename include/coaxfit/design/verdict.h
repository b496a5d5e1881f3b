#ifndef coaxfit_verdict_h
#define coaxfit_verdict_h

#include <coaxfit/design/operation_analysis.h>
#include <coaxfit/parameters/parameters.h>

#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * The one verdict of a run: OK, or each criterion the fit fails, with
   * the worst state named. The criteria: the solve converged; the surfaces
   * touch at assembly and in service; the safety against slip reaches
   * Design/Slip safety in both states (with a required torque or axial
   * force); the yield safety of shaft and hub reaches Design/Yield safety
   * at assembly and in service (a brittle hub: the fracture safety reaches
   * Design/Fracture safety); the joint can be assembled by heating the hub
   * (not above its temperature limit) or cooling the shaft (not below
   * liquid nitrogen).
   */
  struct Verdict
  {
    /** The verdict of the run of @p parameters with @p operation. */
    Verdict(const Parameters        &parameters,
            const OperationAnalysis &operation,
            bool                     converged);

    /**
     * The verdict of criteria judged elsewhere (an assembly of several
     * bodies): each of @p failed names one criterion the run fails; none:
     * OK.
     */
    explicit Verdict(std::vector<std::string> failed);

    /**
     * The verdict of a fit selection (Design/Mode = select) that found no
     * fit: the conflict @p conflict (FitSelection::conflict()).
     */
    static Verdict
    no_fit(const std::string &conflict);

    /** Whether every criterion holds. */
    bool
    ok() const
    {
      return failed.empty();
    }

    /** `Verdict: OK` or `Verdict: FAILED: <criterion>; <criterion>`. */
    std::string
    line() const;

    /**
     * `a < b` for a safety @p a below its requirement @p b, with as many
     * significant digits (3 at least) as tell the two apart: a safety just
     * below its requirement is not printed as `1 < 1`.
     */
    static std::string
    below(double a, double b);

    /** One line per failed criterion. */
    std::vector<std::string> failed;

  private:
    Verdict() = default;
  };
} // namespace coaxfit

#endif
