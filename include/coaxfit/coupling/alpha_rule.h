#ifndef coaxfit_alpha_rule_h
#define coaxfit_alpha_rule_h

#include <deal.II/lac/vector.h>

#include <coaxfit/parameters/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * What an alpha rule may look at: the state of the interface after a
   * Neumann step (both bodies loaded by the same nodal force).
   */
  struct NeumannState
  {
    const Vector<double> &force;                 ///< applied nodal force
    const Vector<double> &u_shaft;               ///< u_r of D1 on S
    const Vector<double> &u_hub;                 ///< u_r of D2 on S
    double                displacement_mismatch; ///< max|u2 - u1 - d| / d
  };

  /**
   * How the relaxation weight alpha of the staggered process is chosen
   * (project convention: alpha weighs the hub's traction, 1 - alpha its
   * displacement), possibly one per interface point. The coupling calls
   * update() after Neumann steps; an accelerator (Accelerator) acts on the
   * traction iterate independently of the rule.
   */
  class AlphaRule
  {
  public:
    virtual ~AlphaRule() = default;

    /** Name as selected by Coupling/Alpha rule. */
    virtual std::string
    name() const = 0;

    /** Re-choose alpha from the state of a Neumann step. */
    virtual void
    update(const NeumannState &state)
      = 0;

    /** Whether alpha has been estimated from data (not the initial one). */
    virtual bool
    estimated() const = 0;

    /**
     * Replace the initial alpha by @p alpha, the Winkler alpha measured in
     * the first Dirichlet step, before any estimate of the rule's own
     * (the fixed rule keeps the user's alpha).
     */
    virtual void
    seed(double alpha)
      = 0;

    /** Whether seed() changes alpha (all adaptive rules). */
    virtual bool
    adaptive() const = 0;

    /** Alpha at interface point @p i. */
    virtual double
    alpha(unsigned int i) const = 0;

    /** One alpha that represents the current choice (for progress output). */
    virtual double
    representative_alpha() const = 0;
  };

  /** The constant alpha of Coupling/Alpha. */
  class FixedAlpha : public AlphaRule
  {
  public:
    explicit FixedAlpha(double alpha);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

    bool
    estimated() const override;

    /** Keeps Coupling/Alpha: a fixed alpha is the user's choice. */
    void
    seed(double alpha) override;

    bool
    adaptive() const override;

    double
    alpha(unsigned int i) const override;

    double
    representative_alpha() const override;

  protected:
    double value;
  };

  /**
   * Formula (4.20)-(4.21) of the paper: the bodies treated as Winkler
   * foundations with compliances k_i = u_i / p give the optimal alpha =
   * k2 / (k1 + k2). One global alpha from the energy-weighted compliances
   * of the latest loaded Neumann step, k_i = |sum u_i F| / sum F^2/w;
   * Coupling/Alpha until the first load exists.
   */
  class WinklerAlpha : public FixedAlpha
  {
  public:
    explicit WinklerAlpha(double initial_alpha);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

    bool
    estimated() const override;

    void
    seed(double alpha) override;

    bool
    adaptive() const override;

  private:
    bool has_estimate = false;
  };

  /**
   * Formula (4.22): an alpha per point,
   * alpha_i = beta |u2_i| / ((1 - beta) |u1_i| + beta |u2_i|), from the
   * latest loaded Neumann step (beta = 1/2 is (4.21)). Points with no
   * displacement use the global Winkler alpha.
   *
   * With beta = 0 (Coupling/Beta = auto) beta is chosen from the first
   * steps' residuals, as the paper tuned it by hand: the contraction of the
   * displacement mismatch over one double step is measured for beta = 0.5,
   * then 0.3, then 0.15 or 0.7 (towards the better one), and the beta with
   * the smallest contraction is kept for the rest of the run.
   */
  class PointwiseAlpha : public WinklerAlpha
  {
  public:
    PointwiseAlpha(double initial_alpha, double beta);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

    void
    seed(double alpha) override;

    double
    alpha(unsigned int i) const override;

  private:
    /** The automatic choice of beta from the contraction of the mismatch. */
    void
    search_beta(double displacement_mismatch);

    double                                 beta;
    bool                                   searching;
    double                                 last_mismatch = -1.;
    std::vector<std::pair<double, double>> tried; ///< (beta, contraction)
    std::vector<double>                    values;
  };

  /** The rule selected in @p parameters. */
  std::unique_ptr<AlphaRule>
  make_alpha_rule(const CouplingParameters &parameters);
} // namespace coaxfit

#endif
