#ifndef coaxfit_contact_interface_h
#define coaxfit_contact_interface_h

#include <deal.II/lac/vector.h>

#include <coaxfit/body_discretization.h>

#include <vector>

namespace coaxfit
{
  /**
   * The contact surface S as both bodies see it, and its algebra: the
   * ordered points shared by the shaft D1 and the hub D2 (their meshes match
   * on S, so point i of one body is point i of the other), the interference
   * d, the lumped weights w_i = int_S N_i r dz that turn a nodal force into
   * a pressure, the gap u2 - u1 - d and the residuals of the coupling.
   *
   * Vectors over the points are nodal contact forces (compression positive,
   * F_i = int_S p N_i r dz) or radial displacements u1 (shaft), u2 (hub).
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

    /** Radial interference d (mm). */
    double
    interference() const
    {
      return d;
    }

    /** The gap g = u2 - u1 - d at every point (mm; negative: penetration). */
    Vector<double>
    gap(const Vector<double> &u1, const Vector<double> &u2) const;

    /**
     * Relative displacement residual max_i r_i / d: r_i = |g_i| at points in
     * @p contact, the penetration -g_i at separated points (they may open).
     * NaN if not finite.
     */
    double
    relative_gap_residual(const Vector<double>    &u1,
                          const Vector<double>    &u2,
                          const std::vector<bool> &contact) const;

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
  };
} // namespace coaxfit

#endif
