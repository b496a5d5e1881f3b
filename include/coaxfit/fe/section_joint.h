#ifndef coaxfit_section_joint_h
#define coaxfit_section_joint_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <coaxfit/fe/section_outline.h>

#include <optional>
#include <string>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * One straight piece of the joint between two sections: the part of the
   * boundary where both sections lie on the same line with opposite sides,
   * from start to end in (r, z) (mm; along the inner section's
   * counter-clockwise direction), and the inner section's outward unit
   * normal there (pointing into the outer section: +r on a cylinder, a
   * slanted direction on a cone, +-z on a face against a shoulder).
   */
  struct JointPiece
  {
    Point<2>     start;
    Point<2>     end;
    Tensor<1, 2> normal;

    /** Length of the piece (mm). */
    double
    length() const
    {
      return (end - start).norm();
    }
  };

  /**
   * Where the sections @p inner and @p outer meet, both drawn at their
   * nominal size (the interference is not drawn: Fit gives it): every
   * overlap of a straight edge of one with a straight edge of the other
   * that lies on the same line, the two sections on opposite sides, longer
   * than the tolerance. A fillet arc is never part of a joint. The
   * tolerance is 1e-6 of the larger section's extent (drawing precision).
   *
   * @throws InputError naming both entries if the sections do not meet
   * (no joint), or if they overlap: a corner of one lies inside the other
   * farther than the tolerance from its boundary, or two edges cross. The
   * messages say how far (mm) and where (z, D in drawing coordinates).
   */
  std::vector<JointPiece>
  find_joint(const SectionOutline &inner, const SectionOutline &outer);

  /**
   * A face across the axis where two sections also touch, beside their
   * joint (a hub's end face on a shaft's shoulder, a shaft's end face on a
   * step of the bore), in the drawing's coordinates.
   */
  struct ShoulderFace
  {
    double z;              ///< its axial position (mm)
    double diameter_inner; ///< where the touching part begins (mm)
    double diameter_outer; ///< and ends (mm)
  };

  /**
   * Take the faces across the axis (pieces of constant z within @p tol)
   * out of @p pieces and return them.
   */
  std::vector<JointPiece>
  faces_across_axis(std::vector<JointPiece> &pieces, double tol);

  /**
   * The face across the axis @p faces (from faces_across_axis()) beside a
   * joint from @p z_lo to @p z_hi (drawing z, mm), or none if @p faces is
   * empty. With a frictionless joint and no axial load nothing pushes the
   * bodies against each other along the axis: the face's pressures are
   * non-negative with a vanishing axial resultant, so they vanish and the
   * face is modelled free.
   * @throws InputError starting with @p both (the entries at fault) if the
   * faces lie at more than one axial position (a body held between two
   * faces: the axial force would depend on strains a face contact must
   * take) or inside the joint's axial range.
   */
  std::optional<ShoulderFace>
  shoulder_beside(const std::vector<JointPiece> &faces,
                  double                         z_lo,
                  double                         z_hi,
                  double                         tol,
                  const std::string             &both);

  /**
   * Refuse sections @p inner and @p outer that overlap (find_joint()'s
   * first check, also for bodies that need not meet): a corner of one
   * inside the other farther than the tolerance from its boundary, or two
   * straight edges that cross.
   * @throws InputError naming both entries, how far and where.
   */
  void
  check_apart(const SectionOutline &inner, const SectionOutline &outer);

  /**
   * The radii (mm) at which the boundary of @p outline crosses the plane
   * z = @p z, arcs as 32 chords; a vertex at z counts once (each straight
   * piece half open).
   */
  std::vector<double>
  radii_at(const SectionOutline &outline, double z);

  /**
   * The outer diameter of @p hub averaged over the axial extent [@p z_start,
   * @p z_end] of a joint (mm): at each z the largest diameter of the
   * section there, its mean over z. DIN 7190's plain-cylinder estimate of a
   * hub that is not a plain cylinder takes it as D_aA (a gear hub of boss
   * D 80 over a joint z -25..25 with a rim D 180 over z -15..15: (20 x 80
   * + 30 x 180) / 50 = 140 mm). Exact for straight edges; a fillet arc
   * counts as 32 chords.
   */
  double
  mean_outer_diameter(const SectionOutline &hub, double z_start, double z_end);
} // namespace coaxfit

#endif
