#ifndef coaxfit_alpha_controller_h
#define coaxfit_alpha_controller_h

#include <coaxfit/parameters.h>
#include <memory>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * What a controller may look at when it chooses alpha: the state of the
   * interface after a Neumann step (both bodies loaded by the same nodal
   * force) and the step number.
   */
  struct NeumannState
  {
    unsigned int               step;
    const std::vector<double> &force;   ///< applied nodal force
    const std::vector<double> &u_shaft; ///< u_r of D1 on S
    const std::vector<double> &u_hub;   ///< u_r of D2 on S
  };

  /**
   * Strategy that chooses the relaxation weight alpha of the staggered
   * process (project convention: alpha weighs the hub's traction, 1 - alpha
   * its displacement). It may give each interface point its own alpha.
   */
  class AlphaController
  {
  public:
    virtual ~AlphaController() = default;

    /** Name as selected by Coupling/Alpha controller. */
    virtual std::string
    name() const = 0;

    /**
     * Called after every Neumann step; sets the alpha used by the next
     * Dirichlet step and the Neumann step that follows it.
     */
    virtual void
    update(const NeumannState &state)
      = 0;

    /** Alpha at interface point @p i. */
    virtual double
    alpha(unsigned int i) const = 0;

    /** One alpha that represents the current choice (for progress output). */
    virtual double
    representative_alpha() const = 0;
  };

  /** The constant alpha of Coupling/Alpha. */
  class FixedAlphaController : public AlphaController
  {
  public:
    explicit FixedAlphaController(double alpha);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

    double
    alpha(unsigned int i) const override;

    double
    representative_alpha() const override;

  private:
    const double value;
  };

  /** The controller selected in @p parameters. */
  std::unique_ptr<AlphaController>
  make_alpha_controller(const Parameters &parameters);
} // namespace coaxfit

#endif
