#ifndef coaxfit_interface_side_h
#define coaxfit_interface_side_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace coaxfit
{
  using namespace dealii;

  /**
   * The trace of one body on one tagged part of its boundary (a joint), as
   * a curve in the (r, z) plane: a cylinder, a cone, a flat face, or an arc
   * approximated by the mesh's straight faces.
   *
   * Built from a DoFHandler<2> with FESystem(FE_Q(p)^2) (x = r, y = z, mm)
   * and a boundary id. The faces of that id must form one open chain; the
   * nodes (the support points of the DoFs on those faces) are numbered along
   * it, starting at the end of smaller z (of smaller r if both ends have the
   * same z), so that face f holds the nodes f p, ..., f p + p, and the arc
   * length s grows from 0 at the first node.
   *
   * Geometry is that of the straight faces (MappingQ1): a node inside a face
   * sits where FE_Q(p) puts its support point on the straight segment, and
   * a manifold attached to the triangulation is not followed.
   *
   * On each face the trace of FE_Q(p) is the 1D Lagrange basis of degree p
   * on the face's nodes; shape_value() evaluates it at the face parameter
   * t in [0, 1] (t = 0 at the face's first node along the curve).
   *
   * The lumped weights w_i = int_S N_i r ds (mm^2 per radian; times 2 pi the
   * area that node i carries) turn nodal forces into pressures. They are
   * positive but for a degree-2 end node on the axis r = 0, whose weight is
   * exactly 0.
   */
  class InterfaceSide
  {
  public:
    /**
     * One face of the chain: its nodes along the curve and its straight
     * geometry.
     */
    struct Face
    {
      std::vector<unsigned int> nodes;  ///< p + 1 node indices, in curve order
      Point<2>                  start;  ///< the point of nodes.front()
      Point<2>                  end;    ///< the point of nodes.back()
      Tensor<1, 2>              normal; ///< outward unit normal of the body
      double                    length; ///< |end - start| (mm)

      /** The point at face parameter @p t in [0, 1]. */
      Point<2>
      point(const double t) const
      {
        return start + t * (end - start);
      }
    };

    /**
     * Collect the trace of the DoFs of @p dof_handler on the faces with
     * boundary id @p boundary_id. Throws std::logic_error if the element is
     * not FE_Q(p)^2, if there are no such faces or if they do not form one
     * open chain (a closed loop, two separate pieces, a branch).
     */
    InterfaceSide(const DoFHandler<2> &dof_handler,
                  types::boundary_id   boundary_id);

    /** Number of nodes. */
    unsigned int
    n_nodes() const
    {
      return node_points.size();
    }

    /** Number of faces. */
    unsigned int
    n_faces() const
    {
      return chain.size();
    }

    /** Polynomial degree p of the trace. */
    unsigned int
    degree() const
    {
      return p;
    }

    /** Position (r, z) of every node (mm), in curve order. */
    const std::vector<Point<2>> &
    points() const
    {
      return node_points;
    }

    /**
     * The global DoF indices of node @p i: of its r component (element 0)
     * and of its z component (element 1).
     */
    const std::array<types::global_dof_index, 2> &
    dofs(const unsigned int i) const
    {
      return node_dofs[i];
    }

    /**
     * Outward unit normal at every node: that of its face, the normalized
     * mean of both faces' normals where two faces of different direction
     * meet (exact wherever the curve is straight).
     */
    const std::vector<Tensor<1, 2>> &
    normals() const
    {
      return node_normals;
    }

    /** Arc length s of every node along the curve (mm), from 0. */
    const std::vector<double> &
    arc_length() const
    {
      return node_arc_length;
    }

    /** Length of the curve (mm). */
    double
    length() const
    {
      return node_arc_length.empty() ? 0. : node_arc_length.back();
    }

    /** Lumped weights w_i = int_S N_i r ds (mm^2). */
    const Vector<double> &
    weights() const
    {
      return lumped_weights;
    }

    /** The r-weighted size of S, int_S r ds = sum_i w_i (mm^2). */
    double
    area() const
    {
      return weighted_area;
    }

    /** Face @p f of the chain, in curve order. */
    const Face &
    face(const unsigned int f) const
    {
      return chain[f];
    }

    /**
     * The parameters t in [0, 1] of a face's nodes along it (0, the
     * interior support points of FE_Q(p) in increasing order, 1).
     */
    const std::vector<double> &
    face_node_parameters() const
    {
      return node_parameters;
    }

    /**
     * The trace shape function of the @p j th node of a face (in curve
     * order) at face parameter @p t.
     */
    double
    shape_value(unsigned int j, double t) const;

    /**
     * The values at the nodes of the normal component u . n of the
     * displacement @p solution (a vector over the DoFs of the DoFHandler
     * the side was built from).
     */
    Vector<double>
    normal_component(const Vector<double> &solution) const;

  private:
    unsigned int                                        p;
    std::vector<Point<2>>                               node_points;
    std::vector<std::array<types::global_dof_index, 2>> node_dofs;
    std::vector<Tensor<1, 2>>                           node_normals;
    std::vector<double>                                 node_arc_length;
    Vector<double>                                      lumped_weights;
    double                                              weighted_area;
    std::vector<Face>                                   chain;
    std::vector<double>                                 node_parameters;
  };
} // namespace coaxfit

#endif
