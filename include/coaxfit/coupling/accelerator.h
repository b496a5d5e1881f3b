#ifndef coaxfit_accelerator_h
#define coaxfit_accelerator_h

#include <deal.II/lac/vector.h>

#include <coaxfit/parameters/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Acceleration of a fixed-point iteration x_{k+1} = G(x_k), behind one
   * interface. For the staggered process x is the nodal contact force
   * applied in a Neumann step and G(x) the blend F1 + alpha (F2 - F1) of the
   * reactions of the Dirichlet step that follows; the accelerator sees only
   * the pairs (x_k, G(x_k)) and returns the next x. The coupling calls
   * restart(), forget_points() or keep_model() when the set of contact
   * points changes (Coupling/Active set change): the map is then a
   * different one.
   */
  class Accelerator
  {
  public:
    virtual ~Accelerator() = default;

    /** Name as selected by Coupling/Accelerator. */
    virtual std::string
    name() const = 0;

    /**
     * Given the iterate @p x and its image @p g = G(x), overwrite @p g with
     * the next iterate.
     */
    virtual void
    accelerate(const Vector<double> &x, Vector<double> &g)
      = 0;

    /** Forget the history (the map changed). */
    virtual void
    restart()
      = 0;

    /**
     * The map changed at the points flagged in @p changed only: forget what
     * the history says about them and keep the rest.
     */
    virtual void
    forget_points(const std::vector<bool> &changed)
      = 0;

    /**
     * The map changed at the points flagged in @p changed: start a new
     * history but keep what the old one learned about the map as a prior
     * (where the accelerator has such a model; else restart()).
     */
    virtual void
    keep_model(const std::vector<bool> &changed)
    {
      (void)changed;
      restart();
    }

    /**
     * A model of the inverse Jacobian J (n x n row-major, the step being
     * x_{k+1} = G(x_k) + J r_k) known before any history, kept through
     * restart(); an empty @p prior removes it. Accelerators without such a
     * model ignore it.
     */
    virtual void
    set_prior(std::vector<double> prior)
    {
      (void)prior;
    }
  };

  /** The plain iteration x_{k+1} = G(x_k). */
  class NoAcceleration : public Accelerator
  {
  public:
    std::string
    name() const override;

    void
    accelerate(const Vector<double> &x, Vector<double> &g) override;

    void
    restart() override;

    void
    forget_points(const std::vector<bool> &changed) override;
  };

  /**
   * Dynamic (Aitken / Irons-Tuck) relaxation:
   * x_{k+1} = x_k + omega_k r_k, r_k = G(x_k) - x_k,
   * omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2.
   */
  class AitkenAcceleration : public Accelerator
  {
  public:
    explicit AitkenAcceleration(double initial_omega);

    std::string
    name() const override;

    void
    accelerate(const Vector<double> &x, Vector<double> &g) override;

    void
    restart() override;

    /** Zeroes the changed entries of the last residual, keeps omega. */
    void
    forget_points(const std::vector<bool> &changed) override;

  private:
    const double   initial_omega;
    double         omega;
    Vector<double> last_residual;
  };

  /**
   * Interface quasi-Newton with inverse Jacobian from a least-squares model
   * (IQN-ILS, Degroote et al. 2009): with the differences V of the residuals
   * r = G(x) - x and W of the outputs G(x) of the previous iterations,
   * c = argmin |V c + r_k| and x_{k+1} = G(x_k) + W c. Nearly dependent
   * columns of V are dropped by a QR filter (relative threshold), the
   * history is capped.
   */
  class IQNILSAcceleration : public Accelerator
  {
  public:
    IQNILSAcceleration(unsigned int max_columns, double filter);

    std::string
    name() const override;

    void
    accelerate(const Vector<double> &x, Vector<double> &g) override;

    void
    restart() override;

    /**
     * Zeroes the rows of the changed points in every stored residual and
     * output: the least-squares model then fits the unchanged points only
     * and leaves the changed ones to the plain step.
     */
    void
    forget_points(const std::vector<bool> &changed) override;

    /**
     * The inverse Jacobian model J = J_prior - (W + J_prior V)(V^T V)^-1 V^T
     * of the current history becomes the prior of the next (rows and
     * columns of the changed points zeroed), and the history restarts.
     * With a prior the step is x_{k+1} = G(x_k) + W c + J_prior (r_k + V c)
     * (IQN-IMVJ, Lindner et al. 2015); without one it is IQN-ILS.
     */
    void
    keep_model(const std::vector<bool> &changed) override;

    /** The prior of every model from now on (IQN-IMVJ with that prior). */
    void
    set_prior(std::vector<double> prior) override;

  private:
    /**
     * The filtered least-squares model of the history: the kept difference
     * columns V (as Q R) and W, and with a prior J_prior V. Empty if the
     * history has no usable column.
     */
    struct Model
    {
      std::vector<Vector<double>>      q;       ///< orthonormal Q of V
      std::vector<std::vector<double>> R;       ///< R[j][k], column j
      std::vector<Vector<double>>      v;       ///< the kept columns of V
      std::vector<Vector<double>>      w;       ///< the matching ones of W
      std::vector<Vector<double>>      prior_v; ///< J_prior v_j
    };

    /** Factor the current history (modified Gram-Schmidt, QR filter). */
    Model
    factor() const;

    /** Add J @p r, the step of @p model for the residual @p r, to @p out. */
    void
    add_model_step(const Model          &model,
                   const Vector<double> &r,
                   Vector<double>       &out) const;

    /** Add J_prior @p x to @p out. */
    void
    multiply_prior(const Vector<double> &x, Vector<double> &out) const;

    const unsigned int          max_columns;
    const double                filter;
    std::vector<double>         prior; ///< J_prior, n x n row-major or empty
    std::vector<double>         base_prior; ///< the prior restart() returns to
    std::vector<Vector<double>> residuals;  ///< r_k, oldest first
    std::vector<Vector<double>> outputs;    ///< G(x_k), oldest first
  };

  /** The accelerator selected in @p parameters. */
  std::unique_ptr<Accelerator>
  make_accelerator(const CouplingParameters &parameters);
} // namespace coaxfit

#endif
