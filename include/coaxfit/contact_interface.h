#ifndef coaxfit_contact_interface_h
#define coaxfit_contact_interface_h

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <coaxfit/body.h>

#include <vector>

namespace coaxfit
{
  /**
   * The contact surface S as both bodies see it: the ordered points shared
   * by the shaft D1 and the hub D2 (their meshes match on S, so point i of
   * one body is point i of the other), the interference d, the lumped
   * weights w_i = int_S N_i r dz (row sums of the interface mass matrix)
   * that turn a nodal force into a pressure.
   */
  class ContactInterface
  {
  public:
    /**
     * Collect the interface of two assembled bodies. Throws if their
     * interface points do not coincide.
     */
    ContactInterface(const Body &shaft, const Body &hub, double interference);

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
    const std::vector<double> &
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

    /** Pressure from nodal forces with the lumped weights: F_i / w_i. */
    std::vector<double>
    lumped_pressure(const std::vector<double> &force) const;

    /**
     * Mean contact pressure over S (MPa): total force over int_S r dz. It is
     * the same for the consistent and the lumped pressure.
     */
    double
    mean_pressure(const std::vector<double> &force) const;

  private:
    double              d;
    std::vector<double> z_coordinates;
    std::vector<double> lumped_weights;
  };
} // namespace coaxfit

#endif
