#ifndef coaxfit_stack_coupling_h
#define coaxfit_stack_coupling_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/parameters/stack_parameters.h>
#include <coaxfit/solvers/interface_operator.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * One joint of a stack as the coupling sees it: its inner body k and
   * outer body k + 1, its points (shared by both bodies' meshes: point i
   * of the inner body's outer surface is point i of the outer body's
   * bore), their lumped weights w_i = int N_i r dz, the radial
   * interference d = U / 2 and, with loads of operation, how far the
   * loads alone move the sides apart.
   */
  struct StackJoint
  {
    std::string         name; ///< `<inner>-<outer>`
    std::vector<double> z;    ///< mm, increasing from the mid-plane
    Vector<double>      weights;
    double              interference; ///< radial, mm; negative: clearance
    /**
     * u_outer - u_inner of the two free bodies under their loads of
     * operation alone (thermal strain, rotation, pressures) at each point
     * (mm); empty: no loads. The bodies are linear, so the contact of the
     * loaded bodies is that of the unloaded ones with the interference
     * d - load_shift_i (interference_at()); their fields add the load
     * fields.
     */
    Vector<double> load_shift;
    /**
     * Whether the joint is modelled whole (a stack of sections without a
     * common plane of symmetry); else its half from the mid-plane z = 0.
     */
    bool whole = false;
    /**
     * The pieces the joint bears on (mm, model z, ascending): empty for
     * one piece from the first point to the last; else several of one
     * diameter, the stretches between them (a relief groove) free.
     */
    std::vector<std::pair<double, double>> pieces;

    unsigned int
    n_points() const
    {
      return z.size();
    }

    /** Whether the stretch from point @p i to point i + 1 bears. */
    bool
    bearing(const unsigned int i) const
    {
      if (pieces.empty())
        return true;
      const double m = 0.5 * (z[i] + z[i + 1]);
      for (const auto &[lo, hi] : pieces)
        if (m > lo && m < hi)
          return true;
      return false;
    }

    /**
     * The joint's length l_F (mm): the length it bears on, twice the half
     * model's (a relief groove not counted).
     */
    double
    length() const
    {
      double l = 0.;
      for (unsigned int i = 0; i + 1 < n_points(); ++i)
        l += bearing(i) ? z[i + 1] - z[i] : 0.;
      return whole ? l : 2. * l;
    }

    /** Model z of the joint's middle, from end to end (0 in a half model). */
    double
    centre() const
    {
      return whole ? 0.5 * (z.front() + z.back()) : 0.;
    }

    /**
     * Model z of the joint's mid-plane: its middle (0 in a half model);
     * where that is not inside a piece (in a relief groove, or at a
     * groove's edge), the middle of its longest piece, its main seat.
     */
    double
    middle_z() const
    {
      const double m = centre();
      if (pieces.empty())
        return m;
      const double tol = 1e-9 * (z.back() - z.front());
      for (const auto &[lo, hi] : pieces)
        if ((m > lo + tol || (!whole && lo == 0.)) && m < hi - tol)
          return m;
      // A half model's piece from the plane is half of one.
      const auto full = [&](const std::pair<double, double> &piece) {
        return (!whole && piece.first == 0. ? 2. : 1.)
               * (piece.second - piece.first);
      };
      // Of pieces equally long the last (largest z), as a half model has
      // it.
      auto longest = pieces.begin();
      for (auto piece = pieces.begin(); piece != pieces.end(); ++piece)
        if (full(*piece) >= (1. - 1e-9) * full(*longest))
          longest = piece;
      return longest->first == 0. && !whole ?
               0. :
               0.5 * (longest->first + longest->second);
    }

    /** The point nearest the joint's mid-plane (middle_z()). */
    unsigned int
    middle() const
    {
      const double m    = middle_z();
      unsigned int best = 0;
      for (unsigned int i = 1; i < n_points(); ++i)
        if (std::abs(z[i] - m) < std::abs(z[best] - m))
          best = i;
      return best;
    }

    /** The radial interference left at point @p i under the loads (mm). */
    double
    interference_at(const unsigned int i) const
    {
      return load_shift.size() == 0 ? interference :
                                      interference - load_shift[i];
    }

    /** The largest |interference_at(i)| over the points (mm). */
    double
    largest_interference() const
    {
      double d = 0.;
      for (unsigned int i = 0; i < n_points(); ++i)
        d = std::max(d, std::abs(interference_at(i)));
      return d;
    }
  };

  /**
   * The state of a stack's joints: the nodal contact force of every point
   * of every joint (compression positive, F_i = int p N_i r dz) and
   * whether the point is in contact.
   */
  struct StackState
  {
    std::vector<Vector<double>>    force;   ///< per joint
    std::vector<std::vector<bool>> contact; ///< per joint

    /** The lumped pressure F_i / w_i of joint @p k (MPa). */
    Vector<double>
    pressure(const std::vector<StackJoint> &joints, unsigned int k) const;
  };

  /**
   * The interface points of the bodies of a stack: body b's operator acts
   * on the points of joint b - 1 (its bore, if b > 0) followed by those of
   * joint b (its outer surface, if b is not the last), compression
   * positive, u_r out.
   */
  class StackLayout
  {
  public:
    explicit StackLayout(const std::vector<StackJoint> &joints);

    unsigned int
    n_bodies() const
    {
      return n_joints + 1;
    }

    /** The first point of joint @p k among body @p b's points. */
    unsigned int
    offset(unsigned int b, unsigned int k) const
    {
      return k + 1 == b ? 0 : (b == 0 ? 0 : sizes[b - 1]);
    }

    /** The number of interface points of body @p b. */
    unsigned int
    n_points(unsigned int b) const;

  private:
    unsigned int              n_joints;
    std::vector<unsigned int> sizes; ///< points of each joint
  };

  /**
   * The staggered Dirichlet-Neumann process of two bodies generalised to
   * a stack of N bodies and N - 1 joints.
   *
   * A Neumann step gives every point of a joint its force F (the same on
   * both sides) and returns the two sides' u_r: the mismatch
   * du = u_outer - u_inner - d. The Dirichlet step prescribes the blended
   * position u = u_inner + (1 - alpha) du at the points in contact (the
   * outer body gets u + d), separated points traction free, and returns
   * both sides' reactions p_inner, p_outer; the next force is
   * p_inner + alpha (p_outer - p_inner) (alpha: the outer side's weight,
   * the project's convention, per joint). With Gauss-Seidel ordering each
   * joint's two bodies make a Neumann and a Dirichlet step in turn, inside
   * out, the other surface of a body in the middle loaded by the newest
   * force of its other joint; with Jacobi ordering the visits of all
   * joints run at once (concurrently) from the same forces. The forces of all
   * joints together are the iterate of one fixed point, accelerated by
   * Aitken's relaxation or IQN-ILS. The contact points stay fixed until the
   * process has settled for them (residuals below 1e-4 or the tolerance):
   * then a point whose blended force pulls separates and a separated point
   * that penetrates closes (a primal-dual active set over the staggered
   * solves), and the history restarts.
   *
   * Converged when every joint's displacement mismatch (over the largest
   * interference; a separated point's penetration counts) and traction
   * mismatch (over the largest pressure) are below the tolerance and no
   * contact point changed in the last step.
   */
  class StackCoupling
  {
  public:
    /**
     * The bodies' interface operators @p bodies (in StackLayout's order of
     * points), the joints @p joints, the settings of @p parameters
     * (Coupling, Contact) and the relaxation weight @p alpha of each
     * joint.
     */
    StackCoupling(const std::vector<InterfaceOperator *> &bodies,
                  const std::vector<StackJoint>          &joints,
                  const StackParameters                  &parameters,
                  const std::vector<double>              &alpha);

    /**
     * Run from the paper's zero force; one line per step to @p progress if
     * not null. Returns whether it converged within the step limit; a
     * non-finite residual throws.
     */
    bool
    run(std::ostream *progress);

    const StackState &
    state() const
    {
      return current;
    }

    /** Steps (one Neumann and one Dirichlet visit of every joint). */
    unsigned int
    n_steps() const
    {
      return steps;
    }

    /** Solves of single bodies. */
    unsigned int
    n_body_solves() const
    {
      return body_solves;
    }

    /** The displacement and traction residuals after each step. */
    const std::vector<std::pair<double, double>> &
    history() const
    {
      return residuals;
    }

  private:
    /** What a joint's surfaces are given in a body solve. */
    enum class Data
    {
      force,
      position
    };

    /**
     * The data of body @p b's points for a solve (see solve_body()).
     */
    void
    body_data(unsigned int                       b,
              const std::vector<Data>           &data,
              const std::vector<Vector<double>> &target,
              std::vector<bool>                 &prescribed,
              Vector<double>                    &displacement,
              Vector<double>                    &force) const;

    /**
     * Solve body @p b with the data @p data of each joint (indexed by
     * joint, only its own two used): forces from the current state,
     * positions from @p target (the inner side's; the outer side gets
     * target + d) at the contact points. Returns u_r and the forces
     * (reactions where prescribed) at its points.
     */
    void
    solve_body(unsigned int                       b,
               const std::vector<Data>           &data,
               const std::vector<Vector<double>> &target,
               Vector<double>                    &u_r,
               Vector<double>                    &force);

    /** What a visit of a joint returns. */
    struct Visit
    {
      Vector<double> next;             ///< the blended force
      Vector<double> du;               ///< the Neumann step's mismatch
      Vector<double> p_inner, p_outer; ///< the Dirichlet step's reactions
    };

    /**
     * The Neumann and Dirichlet visit of joint @p k (bodies k, k + 1), the
     * other surfaces of its bodies under the current forces of their
     * joints; it changes no state but its bodies' factorizations (so that
     * the visits of a Jacobi step can run at once).
     */
    Visit
    visit_joint(unsigned int k);

    /** The residuals of joint @p k's mismatches, kept for this step. */
    void
    measure(unsigned int          k,
            const Vector<double> &du,
            const Vector<double> &p_inner,
            const Vector<double> &p_outer);

    /**
     * The displacements of a Neumann step at joint @p k: the mismatch du
     * and the blended Dirichlet position.
     */
    Vector<double>
    dirichlet_target(unsigned int          k,
                     const Vector<double> &u_inner,
                     const Vector<double> &u_outer,
                     Vector<double>       &du) const;

    /**
     * The next force of joint @p k from the reactions of a Dirichlet step
     * (0 at separated points).
     */
    Vector<double>
    blend(unsigned int          k,
          const Vector<double> &p_inner,
          const Vector<double> &p_outer) const;

    std::vector<InterfaceOperator *> bodies;
    /** One lock per body: its operator's factorizations are not shared. */
    std::vector<std::unique_ptr<std::mutex>> body_mutex;
    const std::vector<StackJoint>           &joints;
    StackLayout                              layout;
    const StackParameters                   &parameters;
    std::vector<double>                      alpha;
    StackState                               current;
    double                                   displacement_scale;
    double                                   pressure_scale = 0.;
    double       step_gap = 0., step_set_gap = 0., step_traction = 0.;
    unsigned int steps = 0;
    std::atomic<unsigned int>              body_solves{0};
    std::vector<std::pair<double, double>> residuals;
  };

  /**
   * The contact problem of all joints of a stack at once on the bodies'
   * condensed compliances (the monolithic reference): with C_b body b's
   * compliance on its points (compression positive, u_r out), the gap of
   * joint k is g_k = u_{k+1}(bore) - u_k(outer) - d_k, linear in the forces
   * of joints k - 1, k, k + 1: g = A F - d with A symmetric positive
   * definite. Solved by a primal-dual active set: A_PP F_P = d_P on the
   * points P in contact, F = 0 elsewhere, until no force is tensile and no
   * separated point penetrates.
   */
  StackState
  solve_stack_contact(const std::vector<FullMatrix<double>> &compliances,
                      const std::vector<StackJoint>         &joints,
                      bool                                   unilateral,
                      unsigned int                          &active_set_steps);
} // namespace coaxfit

#endif
