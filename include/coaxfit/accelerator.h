#ifndef coaxfit_accelerator_h
#define coaxfit_accelerator_h

#include <deal.II/lac/vector.h>

#include <coaxfit/parameters.h>

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
   * restart() when the set of contact points changes: the map is then a
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

  private:
    const unsigned int          max_columns;
    const double                filter;
    std::vector<Vector<double>> residuals; ///< r_k, oldest first
    std::vector<Vector<double>> outputs;   ///< G(x_k), oldest first
  };

  /** The accelerator selected in @p parameters. */
  std::unique_ptr<Accelerator>
  make_accelerator(const CouplingParameters &parameters);
} // namespace coaxfit

#endif
