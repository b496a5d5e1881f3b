#ifndef coaxfit_parameters_h
#define coaxfit_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * Isotropic linear elastic material: Young's modulus in MPa and Poisson's
   * ratio, with the Lame constants derived from them.
   */
  struct Material
  {
    double E  = 2.0e5;
    double nu = 0.33;

    /** First Lame constant lambda (MPa). */
    double
    lambda() const
    {
      return E * nu / ((1. + nu) * (1. - 2. * nu));
    }

    /** Shear modulus mu (MPa). */
    double
    mu() const
    {
      return E / (2. * (1. + nu));
    }

    /**
     * The same mu without lambda (nu = 0): the deviatoric-like part of a
     * selective reduced integration, whose lambda part is added separately.
     */
    Material
    without_lambda() const
    {
      return {2. * mu(), 0.};
    }
  };

  /**
   * Every knob of a coaxfit run. The values are read from a `.prm` file by
   * a ParameterHandler (declare_parameters() documents each entry with its
   * unit and allowed range), overridden by `--set Section/Name=value` on the
   * command line, and checked by validate() before any work is done.
   *
   * Lengths are in mm, moduli in MPa. L1 and L2 are *half* lengths measured
   * from the common mid-plane z = 0, as in the paper's table: each cylinder
   * is 2 L long and only the half z >= 0 is modelled.
   */
  struct Parameters
  {
    /** @name Geometry (mm) */
    /** @{ */
    double R0 = 0.;   ///< inner radius of the shaft (0: solid shaft)
    double R1 = 100.; ///< nominal contact radius
    double R2 = 200.; ///< outer radius of the hub
    double L1 = 200.; ///< half length of the shaft
    double L2 = 100.; ///< half length of the hub
    double d  = 0.25; ///< radial interference
    /** @} */

    Material shaft; ///< material of D1 (shaft or tube)
    Material hub;   ///< material of D2 (hub)

    /** @name Mesh */
    /** @{ */
    unsigned int axial_cells        = 12;
    unsigned int radial_cells       = 10;
    double       grading_ratio      = 1.4;
    unsigned int global_refinements = 0;
    unsigned int degree             = 2;
    /** Selective reduced integration of the volumetric (lambda) part. */
    bool reduced_volumetric_integration = false;
    /** @} */

    /** Solver/Method: staggered (the paper's) or monolithic (reference). */
    std::string solver_method = "staggered";

    /** @name Coupling */
    /** @{ */
    double       alpha            = 0.8;
    std::string  alpha_controller = "iqn-ils";
    double       tolerance        = 1e-8;
    unsigned int max_steps        = 200;
    double       beta = 0.; ///< pointwise controller, (4.22); 0: automatic
    double       aitken_omega       = 1.0;    ///< first Aitken relaxation
    unsigned int iqn_columns        = 50;     ///< IQN-ILS history length
    double       iqn_filter         = 1e-10;  ///< IQN-ILS QR filter
    std::string  interface_operator = "auto"; ///< auto, full or condensed
    /** @} */

    /** Unilateral contact: the surfaces may separate (Contact/Unilateral). */
    bool unilateral = true;
    /** Contact/Active set update: auto, every step or when converged. */
    std::string active_set_update = "auto";
    /** Contact/Active set tolerance: inner convergence before an update. */
    double active_set_tolerance = 1e-4;

    /** @name Output */
    /** @{ */
    std::string output_directory; ///< resolved: never empty after parsing
    bool        write_vtu    = true;
    bool        print_timing = true;
    /** @} */

    /** Name of the case: the parameter file's base name. */
    std::string case_name = "default";

    /** Declare all entries, with documentation, in @p prm. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the values from a ParameterHandler that has been parsed. */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Check every value and the relations between them (0 <= R0 < R1 < R2,
     * positive lengths, E > 0, -1 < nu < 0.5, ...). Throws InputError with a
     * one-line message naming the parameter, its value and the allowed range.
     */
    void
    validate() const;

    /** Contact length min(L1, L2) in mm. */
    double
    contact_length() const
    {
      return std::min(L1, L2);
    }
  };

  /**
   * Read @p filename, apply the command line @p overrides (pairs of a
   * `Section/Subsection/Name` path and a value) and validate. Every problem
   * is reported as an InputError with a one-line message.
   */
  Parameters
  read_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides);

  /** Print every parameter with its default, pattern and documentation. */
  void
  print_parameters(std::ostream &out);
} // namespace coaxfit

#endif
