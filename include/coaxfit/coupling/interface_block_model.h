#ifndef coaxfit_interface_block_model_h
#define coaxfit_interface_block_model_h

#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Interface block quasi-Newton model of the contact problem
   * (Coupling/Accelerator = ibqn; IBQN-LS, Vierendeels et al. 2007, with
   * the contact conditions inside the model).
   *
   * Each body b answers nodal contact forces F on S with radial
   * displacements u_b = C_b F (the displacements of loads of operation are
   * part of the interference d): a linear map that does not depend on
   * which points are in contact; the coupling gives the model the exact
   * sample F = 0, u = 0 first. Every solve of a body, Neumann or
   * Dirichlet, with any set of contact points, is a sample (F, u) of that
   * map, so none is ever out of date. The model keeps a compliance
   * B_b = B0_b + (dU - B0_b dF)(dF^T dF)^-1 dF^T for each body, a prior B0_b
   * corrected so that it reproduces every sampled difference dF -> dU
   * (least-change multi-secant update), and predicts the solution of the
   * contact problem
   *   g(F) = u_hub(F) - u_shaft(F) - d >= 0,  F >= 0,  F_i g_i = 0
   * with the two models by a primal-dual active set iteration on the
   * interface (dense, n points). A change of the contact zone is part of
   * the prediction and costs no history.
   */
  class InterfaceBlockModel
  {
  public:
    /** Bodies: 0 the shaft, 1 the hub. */
    static constexpr unsigned int shaft = 0, hub = 1;

    /**
     * A model for @p n_points interface points that keeps at most
     * @p max_samples samples per body; a difference whose part independent
     * of the newer ones is below @p filter times its norm is dropped.
     */
    InterfaceBlockModel(unsigned int n_points,
                        unsigned int max_samples,
                        double       filter);

    /** The prior compliance of @p body (n x n, row-major). */
    void
    set_prior(unsigned int body, std::vector<double> compliance);

    /**
     * The prior of @p body as the diagonal compliance @p k / w_i (a Winkler
     * foundation: u = k p with p = F / w), with the sign of @p k.
     */
    void
    set_winkler_prior(unsigned int          body,
                      double                k,
                      const Vector<double> &weights);

    /** Whether both bodies have a prior. */
    bool
    has_prior() const;

    /** Body @p body answered the nodal forces @p force with @p u. */
    void
    add_sample(unsigned int          body,
               const Vector<double> &force,
               const Vector<double> &u);

    /**
     * The model's solution of the contact problem with the interference
     * @p interference at each point: nodal forces @p force (zero at
     * separated points) and the shaft's displacement @p u_shaft. @p contact
     * holds the flags to start from and returns those of the solution; with
     * @p unilateral false every point stays in contact and forces may be
     * tensile. Returns false if the active set iteration did not settle
     * (the flags and force are then those of its last iterate, clamped).
     */
    bool
    predict(const std::vector<double> &interference,
            bool                       unilateral,
            std::vector<bool>         &contact,
            Vector<double>            &force,
            Vector<double>            &u_shaft) const;

    /**
     * Forget the samples (a new load case: the maps' constant parts
     * change), keep the priors.
     */
    void
    clear_samples()
    {
      samples[shaft].clear();
      samples[hub].clear();
    }

  private:
    /** A body's answer u to the forces F. */
    struct Sample
    {
      Vector<double> force, u;
    };

    /**
     * The current compliance B of @p body (n x n, row-major): the prior
     * corrected to reproduce the sampled differences to the newest sample.
     */
    std::vector<double>
    compliance(unsigned int body) const;

    const unsigned int                 n;
    const unsigned int                 max_samples;
    const double                       filter;
    std::array<std::vector<double>, 2> prior;
    std::array<std::vector<Sample>, 2> samples;
  };
} // namespace coaxfit

#endif
