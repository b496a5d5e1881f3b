#ifndef coaxfit_polyline_vtp_h
#define coaxfit_polyline_vtp_h

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace coaxfit
{
  /**
   * A contact surface as ParaView reads it: one polyline in the (r, z)
   * plane (a VTK PolyData file) with point arrays, each with its unit.
   * The interface files of two bodies and of every joint of a stack are
   * written by it, so that tools/paraview/view.py reads both alike.
   */
  struct PolylineVtp
  {
    /** A vector array: (r, z) components per point, in mm. */
    struct VectorArray
    {
      std::string                        name;
      std::vector<std::array<double, 2>> values;
    };

    /** A scalar array; an empty unit writes no units attribute. */
    struct ScalarArray
    {
      std::string         name;
      std::string         unit;
      std::vector<double> values;
    };

    /** The points (r, z) in mm, in the polyline's order. */
    std::vector<std::array<double, 2>> points;
    /**
     * The first point of each polyline after the first (a joint of several
     * pieces: one line per piece, none across a relief groove); empty: one
     * line through all points.
     */
    std::vector<std::size_t> line_starts;
    /** Vector arrays; the first is the one ParaView warps by. */
    std::vector<VectorArray> vectors;
    /** Scalar arrays; the first is the active one. */
    std::vector<ScalarArray> scalars;

    /** The file's XML to @p out, in full precision. */
    void
    write(std::ostream &out) const;
  };
} // namespace coaxfit

#endif
