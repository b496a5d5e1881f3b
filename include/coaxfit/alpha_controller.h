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
   * force) and the lumped weights of the interface points.
   */
  struct NeumannState
  {
    unsigned int               step;
    const std::vector<double> &force;                 ///< applied nodal force
    const std::vector<double> &u_shaft;               ///< u_r of D1 on S
    const std::vector<double> &u_hub;                 ///< u_r of D2 on S
    const std::vector<double> &weights;               ///< int_S N_i r dz
    double                     displacement_mismatch; ///< max|u2 - u1 - d| / d
  };

  /**
   * Strategy that steers the staggered process, behind one interface:
   *
   * - the relaxation weight alpha (project convention: alpha weighs the
   *   hub's traction, 1 - alpha its displacement), possibly a different one
   *   per interface point, re-chosen after every Neumann step (update());
   * - an optional acceleration of the traction iteration: the plain process
   *   applies in the next Neumann step the blend x~ = F1 + alpha (F2 - F1)
   *   of the Dirichlet step's reactions; accelerate() may replace it by a
   *   better guess from the history of x (Aitken, IQN-ILS).
   *
   * The coupling calls restart() when the set of contact points changes, so
   * that no history of the old problem is used for the new one.
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
     * Dirichlet step and its traction blend.
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

    /**
     * Given the force @p applied in the last Neumann step and the blend
     * @p next of the reactions of the following Dirichlet step, overwrite
     * @p next with the force for the next Neumann step. The default keeps
     * the blend (the paper's process).
     */
    virtual void
    accelerate(const std::vector<double> &applied, std::vector<double> &next);

    /** Forget the history (the problem changed). */
    virtual void
    restart();
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

  protected:
    double value;
  };

  /**
   * Formula (4.20)-(4.21) of the paper: the bodies treated as Winkler
   * foundations with compliances k_i = u_i / p give the optimal alpha =
   * k2 / (k1 + k2). One global alpha from the energy-weighted compliances
   * of the latest loaded Neumann step, k_i = |sum u_i F| / sum F^2/w,
   * re-estimated after every Neumann step (or frozen after the first
   * estimate); Coupling/Alpha until the first load exists.
   */
  class WinklerAlphaController : public FixedAlphaController
  {
  public:
    /**
     * With @p freeze the first estimate is kept for the rest of the run: an
     * accelerator needs a fixed map x -> G(x) to build its model.
     */
    explicit WinklerAlphaController(double initial_alpha, bool freeze = false);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

  protected:
    /**
     * Whether alpha changed since the last call: a new alpha is a new map
     * x -> G(x), so an accelerator must drop the history it built.
     */
    bool
    alpha_changed();

  private:
    const bool freeze;
    bool       estimated        = false;
    double     alpha_of_history = -1.;
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
  class PointwiseAlphaController : public WinklerAlphaController
  {
  public:
    PointwiseAlphaController(double initial_alpha, double beta);

    std::string
    name() const override;

    void
    update(const NeumannState &state) override;

    double
    alpha(unsigned int i) const override;

    /** The beta in use. */
    double
    current_beta() const
    {
      return beta;
    }

  private:
    double                                 beta;
    const bool                             automatic;
    bool                                   searching;
    double                                 last_mismatch = -1.;
    std::vector<std::pair<double, double>> tried; ///< (beta, contraction)
    std::vector<double>                    values;
  };

  /**
   * Dynamic (Aitken / Irons-Tuck) relaxation of the traction fixed point
   * x -> G(x) (one Neumann and one Dirichlet step with the Winkler alpha):
   * x_{k+1} = x_k + omega_k r_k, r_k = G(x_k) - x_k,
   * omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2.
   */
  class AitkenController : public WinklerAlphaController
  {
  public:
    AitkenController(double initial_alpha, double initial_omega);

    std::string
    name() const override;

    void
    accelerate(const std::vector<double> &applied,
               std::vector<double>       &next) override;

    void
    restart() override;

  private:
    const double        initial_omega;
    double              omega;
    std::vector<double> last_residual;
  };

  /**
   * Interface quasi-Newton with inverse Jacobian from a least-squares model
   * (IQN-ILS, Degroote et al. 2009) on the traction fixed point x -> G(x):
   * with the differences V of the residuals r = G(x) - x and W of the
   * outputs G(x) of the previous iterations, c = argmin |V c + r_k| and
   * x_{k+1} = G(x_k) + W c. Nearly dependent columns of V are dropped by a
   * QR filter (relative threshold), the history is capped and restarted
   * when the active set changes. The Dirichlet blend uses the Winkler alpha.
   */
  class IQNILSController : public WinklerAlphaController
  {
  public:
    IQNILSController(double       initial_alpha,
                     unsigned int max_columns,
                     double       filter);

    std::string
    name() const override;

    void
    accelerate(const std::vector<double> &applied,
               std::vector<double>       &next) override;

    void
    restart() override;

  private:
    const unsigned int               max_columns;
    const double                     filter;
    std::vector<std::vector<double>> residuals; ///< r_k, oldest first
    std::vector<std::vector<double>> outputs;   ///< G(x_k), oldest first
  };

  /** The controller selected in @p parameters. */
  std::unique_ptr<AlphaController>
  make_alpha_controller(const Parameters &parameters);
} // namespace coaxfit

#endif
