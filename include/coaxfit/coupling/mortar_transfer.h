#ifndef coaxfit_mortar_transfer_h
#define coaxfit_mortar_transfer_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <coaxfit/coupling/banded_cholesky.h>
#include <coaxfit/coupling/interface_side.h>

#include <cstddef>
#include <vector>

namespace coaxfit
{
  /**
   * The transfer of nodal data between the two sides of a joint whose
   * meshes need not match: from the mortar side A to the non-mortar side B
   * for displacements, from B back to A for forces. Either side of a joint
   * may be A; the transfer is built from the two InterfaceSide objects and
   * keeps no reference to them.
   *
   * <h3>Displacements: a weighted L2 projection</h3>
   * A scalar nodal field u_A on A (a normal displacement, say) goes to B as
   * u_B = M u_A, the projection onto B's trace space with the axisymmetric
   * weight r:
   * @f[ \int_B N^B_i N^B_j r\,ds\; u_{B,j}
   *     = \int_B N^B_i (u_A \circ P)\, r\,ds, \qquad M = D^{-1} R, @f]
   * P mapping a point of B to its closest point on A (closest_point(): the
   * projection along A's normal). Both integrals are taken on B's faces by
   * Gauss quadrature; each face is cut where P changes the face of A it
   * lands on (projection_breakpoints()), so that the integrand is a
   * polynomial on each piece and the quadrature (QGauss((p_A + p_B + 3)/2)
   * on the pieces, QGauss(p_B + 1) for D) is exact. A field of A whose
   * composition with P lies in B's trace space (a constant; a field linear
   * in s where both sides lie on one straight line) arrives exactly.
   *
   * D is the r-weighted mass matrix of B's trace, banded along the curve
   * (bandwidth p_B) and factorized once (BandedCholesky); R is stored in
   * compressed rows. M itself, the product D^{-1} R, is a full matrix and
   * is formed only on request (matrix()).
   *
   * <h3>Forces: the transpose</h3>
   * Nodal forces F_B on B (F_i = int p N_i r ds) go to A as F_A = M^T F_B.
   * The total force is conserved (sum_k F_A,k = sum_i F_B,i, since each
   * active row of M sums to one) and so is virtual work (F_B . M u_A =
   * M^T F_B . u_A), to round-off. A uniform pressure on B comes out as the
   * same uniform pressure on A (F_A,k = p w_A,k) wherever both sides lie on
   * the same curve.
   *
   * <h3>Partial overlap</h3>
   * Only B's faces that A covers entirely (every point of them projects
   * onto A, within 1e-10 of the joint size) take part. A node of B on none
   * of them, in particular every node whose own projection falls beyond an
   * end of A (a hub shorter than the shaft's joint), gets a zero row of M:
   * it receives u_B = 0 and its force is not transferred (the total
   * conserved is that of the covered nodes). Such nodes are listed by
   * uncovered_nodes(): the caller treats them as free (no contact). A face
   * of B that A covers only in part is left out whole, so the sides should
   * end at the same point; nodes of A that B does not cover get zero
   * columns (no force).
   *
   * <h3>Matching sides</h3>
   * When both sides have the same degree and number of nodes and every node
   * of B coincides with a node of A within 1e-10 of the joint size (the
   * longer side's length), the transfer is the exact index map (the
   * identity when both are numbered alike) and matching() is true.
   */
  class MortarTransfer
  {
  public:
    /**
     * Build the transfer from @p mortar (A) to @p non_mortar (B). With
     * @p detect_matching false the projection is built even for matching
     * sides (it is then the identity up to round-off).
     */
    MortarTransfer(const InterfaceSide &mortar,
                   const InterfaceSide &non_mortar,
                   bool                 detect_matching = true);

    /** Number of nodes of the mortar side A (columns of M). */
    unsigned int
    n_mortar_nodes() const
    {
      return n_a;
    }

    /** Number of nodes of the non-mortar side B (rows of M). */
    unsigned int
    n_non_mortar_nodes() const
    {
      return n_b;
    }

    /** Whether the sides match and the transfer is an index map. */
    bool
    matching() const
    {
      return is_matching;
    }

    /**
     * For matching sides: the node of A that coincides with each node of
     * B; empty otherwise.
     */
    const std::vector<unsigned int> &
    index_map() const
    {
      return node_of_a;
    }

    /** The nodes of B with a zero row of M (not covered by A), ascending. */
    const std::vector<unsigned int> &
    uncovered_nodes() const
    {
      return uncovered;
    }

    /**
     * The largest distance (mm) between a point of B's covered faces used
     * in the integrals (or a node, for matching sides) and its projection
     * on A: 0 for sides on one curve, the chord's sagitta for two
     * polylines approximating one arc.
     */
    double
    max_distance() const
    {
      return distance;
    }

    /** u_B = M u_A. */
    void
    apply(const Vector<double> &mortar_values,
          Vector<double>       &non_mortar_values) const;

    /** F_A = M^T F_B. */
    void
    apply_transpose(const Vector<double> &non_mortar_forces,
                    Vector<double>       &mortar_forces) const;

    /** The full matrix M (n_B x n_A), for checks on small interfaces. */
    FullMatrix<double>
    matrix() const;

  private:
    unsigned int              n_a;
    unsigned int              n_b;
    bool                      is_matching;
    std::vector<unsigned int> node_of_a;
    std::vector<unsigned int> uncovered;
    double                    distance;

    /** R in compressed rows: row i's entries at [row_start[i], row_start[i+1]).
     */
    std::vector<std::size_t>  row_start;
    std::vector<unsigned int> columns;
    std::vector<double>       values;

    /** The factorized mass matrix D of B (identity on uncovered nodes). */
    BandedCholesky mass;

    /** Try the index map; true if the sides match. */
    bool
    find_index_map(const InterfaceSide &a,
                   const InterfaceSide &b,
                   double               tolerance);

    /** Assemble D and R for non-matching sides. */
    void
    assemble(const InterfaceSide &a, const InterfaceSide &b, double tolerance);
  };
} // namespace coaxfit

#endif
