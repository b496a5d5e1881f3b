#ifndef coaxfit_contact_interface_h
#define coaxfit_contact_interface_h

#include <deal.II/lac/vector.h>

#include <coaxfit/fe/body_discretization.h>

#include <vector>

namespace coaxfit
{
  /**
   * The size of the z range @p z for relative tolerances (mm):
   * max(|z_0|, |z_n|, z_n - z_0), 1 if empty (a whole model's z may end at
   * 0, a half model's starts there).
   */
  double
  z_range_scale(const std::vector<double> &z);

  /**
   * Whether the interface points of @p a and @p b coincide: as many, each
   * z within 1e-9 of z_range_scale() of @p a's.
   */
  bool
  matching_points(const BodyDiscretization &a, const BodyDiscretization &b);

  /**
   * The contact surface S as both bodies see it, and its algebra: the
   * ordered points shared by the shaft D1 and the hub D2 (their meshes match
   * on S, so point i of one body is point i of the other), the interference
   * d, the lumped weights w_i = int_S N_i r dz that turn a nodal force into
   * a pressure, the gap u2 - u1 - d and the residuals of the coupling.
   *
   * Vectors over the points are nodal contact forces (compression positive,
   * F_i = int_S p N_i r dz) or radial displacements u1 (shaft), u2 (hub).
   *
   * Loads of operation: each body's own answer to its loads with a free
   * contact surface moves S by u1_load, u2_load. The bodies are linear, so
   * the coupling solves for the contact answer alone (u1, u2: the
   * displacements caused by the contact force) with the pointwise
   * interference d_i = d + u1_load_i - u2_load_i; the total displacement is
   * the sum. d_i <= 0 is a clearance at that point.
   */
  class ContactInterface
  {
  public:
    /**
     * Collect the interface of two assembled bodies. Throws if their
     * interface points do not coincide.
     */
    ContactInterface(const BodyDiscretization &shaft,
                     const BodyDiscretization &hub,
                     double                    interference);

    /**
     * With the displacements @p u1_load, @p u2_load of S under the loads of
     * operation (each body's own, free contact surface).
     */
    ContactInterface(const BodyDiscretization &shaft,
                     const BodyDiscretization &hub,
                     double                    interference,
                     const Vector<double>     &u1_load,
                     const Vector<double>     &u2_load);

    /**
     * The interface on the joint points of @p side alone (the sides do not
     * match: the other side's displacements @p u1_load or @p u2_load have
     * been brought to these points by the mortar transfer).
     */
    ContactInterface(const BodyDiscretization &side,
                     double                    interference,
                     const Vector<double>     &u1_load,
                     const Vector<double>     &u2_load);

    unsigned int
    n_points() const
    {
      return z_coordinates.size();
    }

    /** Axial coordinate of each point (mm), increasing from 0. */
    const std::vector<double> &
    z() const
    {
      return z_coordinates;
    }

    /** Lumped weights w_i = int_S N_i r dz (mm^2), all positive. */
    const Vector<double> &
    weights() const
    {
      return lumped_weights;
    }

    /** Radial interference d (mm) of the drawing and the fit. */
    double
    interference() const
    {
      return d;
    }

    /**
     * The interference at point i under the loads of operation,
     * d_i = d + u1_load_i - u2_load_i (mm).
     */
    double
    interference(const unsigned int i) const
    {
      return d_load[i];
    }

    /**
     * The gap @p gap (mm, >= 0) the drawing leaves at each point: where one
     * section's rounded edge rises from the other's straight surface (0 on
     * the joint itself). It is taken from the interference of each point,
     * d_i = d + u1_load_i - u2_load_i - gap_i, so that contact spreads onto
     * the edge where the deformation closes it; the convergence scale stays
     * that of the interference.
     */
    void
    set_shape_gap(const Vector<double> &gap);

    /** The gap of the drawing at each point (empty: none). */
    const Vector<double> &
    drawing_gap() const
    {
      return shape_gap;
    }

    /** The two sides of the joint: the inner body (D1), the outer (D2). */
    enum class Side
    {
      inner,
      outer
    };

    /** u_r of S under the loads of operation alone, of the side @p side. */
    const Vector<double> &
    load_displacement(const Side side) const
    {
      return side == Side::inner ? u1_load : u2_load;
    }

    /**
     * The displacement that relative residuals are measured against:
     * max(|d|, max_i |d_i|) (mm), at least 1e-12 of the joint radius.
     */
    double
    displacement_scale() const
    {
      return scale;
    }

    /**
     * The gap g = u2 - u1 - d_i at every point for the contact answers
     * u1, u2 (mm; negative: penetration).
     */
    Vector<double>
    gap(const Vector<double> &u1, const Vector<double> &u2) const;

    /**
     * Relative displacement residual max_i r_i / displacement_scale():
     * r_i = |g_i| at points in
     * @p contact, the penetration -g_i at separated points (they may open;
     * left out if not @p with_penetration: the residual of the problem
     * with these flags, which an update of the flags cannot wait for).
     * NaN if not finite.
     */
    double
    relative_gap_residual(const Vector<double>    &u1,
                          const Vector<double>    &u2,
                          const std::vector<bool> &contact,
                          bool with_penetration = true) const;

    /** Nodal (lumped) pressure F_i / w_i (MPa). */
    Vector<double>
    pressure(const Vector<double> &force) const;

    /** max_i |F_i| / w_i (MPa). */
    double
    max_pressure(const Vector<double> &force) const;

    /** max_i |F2_i - F1_i| / w_i (MPa): the traction mismatch. */
    double
    max_pressure_difference(const Vector<double> &force1,
                            const Vector<double> &force2) const;

    /** max(0, max_i -F_i / w_i) (MPa): the largest tensile pressure. */
    double
    max_tension(const Vector<double> &force) const;

    /**
     * Mean contact pressure over S (MPa): total force over int_S r dz. It is
     * the same for the consistent and the lumped pressure.
     */
    double
    mean_pressure(const Vector<double> &force) const;

  private:
    double              d;
    std::vector<double> z_coordinates;
    Vector<double>      lumped_weights;
    Vector<double>      u1_load, u2_load, d_load;
    Vector<double>      shape_gap; ///< set_shape_gap(); empty: none
    double              scale;
  };
} // namespace coaxfit

#endif
