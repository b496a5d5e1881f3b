#include <coaxfit/base/input_error.h>
#include <coaxfit/coupling/contact_interface.h>
#include <coaxfit/coupling/interface_side.h>
#include <coaxfit/coupling/scene.h>
#include <coaxfit/fe/section_scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

namespace coaxfit
{
  namespace
  {
    /** Throw if @p name is not a body of the parameter files. */
    bool
    is_shaft(const std::string &name)
    {
      if (name != "Shaft" && name != "Hub")
        throw std::logic_error("no body named '" + name + "'");
      return name == "Shaft";
    }

    /**
     * Whether between every two neighbouring points of @p b along the
     * joint (ends included) lies a node of @p a: the mortar side @p a is
     * then at least as fine as @p b everywhere.
     */
    bool
    nodes_interlace(
      const InterfaceSide                         &a,
      const InterfaceSide                         &b,
      const std::function<bool(const Point<2> &)> &counts
      = [](const Point<2> &) { return true; })
    {
      const std::vector<Point<2>> &pa = a.points();
      std::vector<Point<2>>        pb;
      for (const Point<2> &p : b.points())
        if (counts(p))
          pb.push_back(p);
      if (pb.empty())
        return true;
      const Tensor<1, 2> along     = (pa.back() - pa.front()) / a.length();
      const auto         positions = [&](const std::vector<Point<2>> &points) {
        std::vector<double> t;
        for (const Point<2> &p : points)
          t.push_back((p - pa.front()) * along);
        std::sort(t.begin(), t.end());
        return t;
      };
      const std::vector<double> ta = positions(pa), tb = positions(pb);
      const double              tol = 1e-9 * a.length();
      for (unsigned int i = 0; i + 1 < tb.size(); ++i)
        {
          const auto next = std::lower_bound(ta.begin(), ta.end(), tb[i] - tol);
          if (next == ta.end() || *next > tb[i + 1] + tol)
            return false;
        }
      return true;
    }
  } // namespace



  Body::Body(std::unique_ptr<BodyDiscretization> discretization)
    : discretization(std::move(discretization))
  {}



  Vector<double>
  Body::answer_to(const BodyLoad &load) const
  {
    return solver->solve_load_field(discretization->assemble_load_vector(load));
  }



  const JointSides &
  Scene::joint() const
  {
    if (joints.size() != 1)
      throw std::logic_error("a scene of " + std::to_string(joints.size())
                             + " joints where one was expected");
    return joints[0];
  }



  std::string
  Body::key_of(const std::string &name)
  {
    std::string key = name;
    for (char &c : key)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return key;
  }



  BodyGeometry
  body_geometry(const Parameters &parameters, const std::string &name)
  {
    const GeometryParameters &geometry = parameters.geometry;
    BodyGeometry              g;
    g.contact_length     = geometry.contact_length();
    g.axial_cells        = parameters.mesh.axial_cells;
    g.radial_cells       = parameters.mesh.radial_cells;
    g.grading_ratio      = parameters.mesh.grading_ratio;
    g.global_refinements = parameters.mesh.global_refinements;
    if (is_shaft(name))
      {
        g.r_inner                 = geometry.R0;
        g.r_outer                 = geometry.R1;
        g.length                  = geometry.L1;
        g.contact_at_outer_radius = true;
      }
    else
      {
        g.r_inner                 = geometry.R1;
        g.r_outer                 = geometry.R2;
        g.length                  = geometry.L2;
        g.contact_at_outer_radius = false;
      }
    return g;
  }



  BodyLoad
  body_load(const Parameters &parameters, const std::string &name)
  {
    const OperationParameters &o     = parameters.operation;
    const bool                 shaft = is_shaft(name);
    const Material            &m = shaft ? parameters.shaft : parameters.hub;
    BodyLoad                   load;
    load.thermal_strain
      = m.thermal_expansion
        * ((shaft ? o.shaft_temperature() : o.hub_temperature())
           - o.assembly_temperature);
    load.omega_squared = o.omega() * o.omega();
    if (shaft)
      load.inner_pressure = o.shaft_bore_pressure;
    else
      load.outer_pressure = o.hub_outer_pressure;
    if (parameters.sections)
      {
        const auto names = parameters.sections->face_names(shaft);
        for (const auto &[name, p] : o.face_pressures())
          if (names.count(name) != 0)
            load.face_pressures[names.at(name)] = p;
      }
    return load;
  }



  std::unique_ptr<BodyDiscretization>
  make_body(const Parameters &parameters, const std::string &name)
  {
    return std::make_unique<BodyDiscretization>(
      name,
      body_geometry(parameters, name),
      is_shaft(name) ? parameters.shaft : parameters.hub,
      parameters.mesh.degree,
      parameters.mesh.reduced_volumetric_integration(),
      body_load(parameters, name));
  }



  std::vector<std::string>
  Scene::body_names(const Parameters &)
  {
    return {"Shaft", "Hub"};
  }



  std::vector<std::string>
  Scene::body_keys(const Parameters &parameters)
  {
    std::vector<std::string> keys;
    for (const std::string &name : body_names(parameters))
      keys.push_back(Body::key_of(name));
    return keys;
  }



  SectionMeshSettings
  section_mesh_settings(const Parameters &parameters)
  {
    SectionMeshSettings settings;
    const double        l_F = 2. * parameters.geometry.contact_length();
    settings.cell_size
      = parameters.mesh.cell_size > 0. ? parameters.mesh.cell_size : 0.01 * l_F;
    settings.grading_ratio      = parameters.mesh.grading_ratio;
    settings.global_refinements = 0; // each body refines its copy
    return settings;
  }



  namespace
  {
    /**
     * The interference along the joint's normal: the radial one, times
     * cos of the half angle on a cone (C = 2 tan).
     */
    double
    normal_interference(const Parameters &parameters)
    {
      if (!parameters.sections || !parameters.sections->conical())
        return parameters.geometry.d;
      const double tan_half = 0.5 * parameters.sections->taper();
      return parameters.geometry.d / std::sqrt(1. + tan_half * tan_half);
    }
  } // namespace



  Scene::Scene(const Parameters &parameters)
  {
    for (const std::string &name : body_names(parameters))
      bodies.emplace_back(make_body(parameters, name));
    joints.push_back(
      {0, 1, normal_interference(parameters), parameters.geometry.d});
    if (parameters.sections && !parameters.sections->rounded_ends().empty())
      rounded_side = parameters.sections->rounded_ends()[0].shaft ? 0u : 1u;
    if (parameters.sections)
      {
        // Both meshes at once (their joint vertices coincide, or over a
        // rounded edge the straight body's come from the rounded body's),
        // meshed once per settings.
        const std::shared_ptr<const SectionScene::MeshPair> meshes
          = parameters.sections->base_meshes(section_mesh_settings(parameters),
                                             parameters.mesh.shared_joint_nodes,
                                             parameters.mesh.hub_cell_size);
        const unsigned int refinements = parameters.mesh.global_refinements;
        for (unsigned int b = 0; b < 2; ++b)
          {
            bodies[b].discretization->set_mesh_builder(
              [meshes, b, refinements](Triangulation<2> &triangulation) {
                triangulation.copy_triangulation((*meshes)[b]);
                triangulation.refine_global(refinements);
              });
            bodies[b].discretization->set_axial_pin_z(
              parameters.sections->axial_pin_z());
          }
      }
  }



  void
  Scene::set_loads(const Parameters &parameters)
  {
    for (Body &body : bodies)
      body.discretization->set_load(body_load(parameters, body.name()));
    joints[0].radial_interference = parameters.geometry.d;
    joints[0].interference        = normal_interference(parameters);
  }



  double
  Scene::oversize(const unsigned int body) const
  {
    for (const JointSides &joint : joints)
      if (joint.inner == body)
        return joint.radial_interference
               / bodies[body].discretization->geometry().contact_radius();
    return 0.;
  }



  void
  Scene::connect_joint()
  {
    transfer.reset();
    const BodyDiscretization &a = *bodies[0].discretization,
                             &b = *bodies[1].discretization;
    if (matching_points(a, b))
      return;
    const InterfaceSide sides[2]
      = {InterfaceSide(a.get_dof_handler(), BoundaryId::joint),
         InterfaceSide(b.get_dof_handler(), BoundaryId::joint)};
    // The side with more joint nodes is A, unless it is coarser than the
    // other somewhere (graded differently): then B's points there would
    // see fewer of A's nodes than they are, and A's condensed compliance
    // M C_A M^T would be singular. Over a rounded edge the straight side
    // is A (its values reach the fillet's points, the closest points of a
    // curve on a line).
    const unsigned int more = sides[0].n_nodes() >= sides[1].n_nodes() ? 0 : 1;
    if (rounded_side)
      {
        mortar = 1 - *rounded_side;
        // The fillet's points that can touch: a gap of the drawing of at
        // most ten interferences (further up the fillet its points crowd
        // over the straight side's, but stay open).
        const double r_line = sides[mortar].points().front()[0];
        const double reach  = 10. * joints[0].radial_interference;
        if (!nodes_interlace(sides[mortar],
                             sides[1 - mortar],
                             [&](const Point<2> &p) {
                               return std::abs(p[0] - r_line) <= reach;
                             }))
          throw InputError(
            "parameters Mesh/Cell size and Mesh/Hub cell size: with a "
            "rounded edge at the joint the body under it must be at least as "
            "fine along the whole joint as the rounded one ("
            + std::to_string(sides[mortar].n_nodes()) + " against "
            + std::to_string(sides[1 - mortar].n_nodes())
            + " joint nodes); give the body under the edge the smaller cell "
              "size");
      }
    else if (nodes_interlace(sides[more], sides[1 - more]))
      mortar = more;
    else if (nodes_interlace(sides[1 - more], sides[more]))
      mortar = 1 - more;
    else
      throw InputError(
        "parameters Mesh/Cell size, Mesh/Hub cell size and Mesh/Grading "
        "ratio (or a gmsh file's sizes): along the joint each body's mesh is "
        "finer than the other's somewhere ("
        + bodies[0].name() + " " + std::to_string(sides[0].n_nodes())
        + " nodes, " + bodies[1].name() + " "
        + std::to_string(sides[1].n_nodes())
        + "), so neither side's nodes can carry the other's (the coupling "
          "would be singular); allowed: one body at least as fine as the "
          "other along the whole joint, e.g. a smaller cell size or the same "
          "grading for the outline");
    auto m = std::make_shared<MortarTransfer>(sides[mortar], sides[1 - mortar]);
    if (!m->uncovered_nodes().empty())
      throw std::logic_error("the joint of " + bodies[1 - mortar].name()
                             + " has points the " + bodies[mortar].name()
                             + "'s joint does not " + "cover");
    transfer = m;
  }



  Vector<double>
  Scene::joint_values(const unsigned int body, const Vector<double> &own) const
  {
    if (!transfer || body != mortar)
      return own;
    Vector<double> values(transfer->n_non_mortar_nodes());
    transfer->apply(own, values);
    return values;
  }



  Vector<double>
  Scene::body_forces(const unsigned int body, const Vector<double> &force) const
  {
    if (!transfer || body != mortar)
      return force;
    Vector<double> forces(transfer->n_mortar_nodes());
    transfer->apply_transpose(force, forces);
    return forces;
  }
} // namespace coaxfit
