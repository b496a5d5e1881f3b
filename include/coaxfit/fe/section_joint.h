#ifndef coaxfit_section_joint_h
#define coaxfit_section_joint_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <coaxfit/fe/section_outline.h>

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
} // namespace coaxfit

#endif
