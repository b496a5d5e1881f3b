#include <coaxfit/app/coaxial_fit.h>
#include <coaxfit/app/resources.h>
#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/mesh.h>
#include <coaxfit/fe/section_scene.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <sys/resource.h>

namespace coaxfit
{
  namespace
  {
    /** A field of /proc/self/status or /proc/meminfo in bytes (kB there). */
    double
    proc_field(const std::string &file, const std::string &name)
    {
      std::ifstream in(file);
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind(name + ":", 0) == 0)
          return 1024. * std::stod(line.substr(name.size() + 1));
      return std::numeric_limits<double>::infinity();
    }

    /** A section's gmsh file mesh as read, or nullptr. */
    const Triangulation<2> *
    file_mesh(const Parameters &parameters, const bool shaft)
    {
      return parameters.sections ? parameters.sections->file_mesh(shaft) :
                                   nullptr;
    }

    std::string
    gigabytes(const double bytes)
    {
      std::ostringstream text;
      text << std::fixed << std::setprecision(bytes < 1e10 ? 2 : 0)
           << bytes / 1e9 << " GB";
      return text.str();
    }
  } // namespace



  double
  estimated_memory(const std::size_t n_dofs, const unsigned int degree)
  {
    // Peak resident size of the default case (FE_Q(2)) was 0.19, 0.27,
    // 0.59, 2.01 GB at 12e3, 47e3, 186e3, 741e3 DoFs: 150 MB plus 130 to
    // 165 bytes per n log2 n. Higher degrees couple more DoFs per row.
    const double n        = std::max<double>(n_dofs, 2.);
    const double per_term = 180. * std::max(1., degree / 2.);
    return per_term * n * std::log2(n);
  }



  double
  available_memory()
  {
    // Beyond the matrices and factors: 0.2 GB of resident libraries and
    // buffers; under an address space limit also the threads' stacks and
    // malloc arenas that are reserved but not resident (0.4 GB).
    double available = proc_field("/proc/meminfo", "MemAvailable") - 0.2e9;
    rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        const double used = proc_field("/proc/self/status", "VmSize");
        available         = std::min(available,
                             static_cast<double>(limit.rlim_cur)
                               - (std::isfinite(used) ? used : 0.) - 0.4e9);
      }
    return available;
  }



  double
  estimated_memory_amg(const std::size_t n_dofs, const unsigned int degree)
  {
    // Matrix (deal.II's and Trilinos' copy per set of prescribed points),
    // hierarchy, vectors and mesh: linear in the DoFs. Calibrated in
    // benchmarks (speed_benchmark.py): see benchmarks/README.md.
    return 0.2e9 + 2500. * std::max(1., degree / 2.) * n_dofs;
  }



  namespace
  {
    std::size_t
    run_dofs(const Parameters &parameters)
    {
      const unsigned int degree = parameters.mesh.degree;
      std::size_t        dofs   = 0;
      for (const std::string &name : Scene::body_names(parameters))
        {
          const Triangulation<2> *file = file_mesh(parameters, name == "Shaft");
          // A gmsh file's mesh: its cells, 4 per refinement, with about
          // degree^2 nodes of two components each.
          dofs += file ?
                    static_cast<std::size_t>(
                      2. * degree * degree * file->n_active_cells()
                      * std::pow(4., parameters.mesh.global_refinements)) :
                    predicted_dofs(body_geometry(parameters, name), degree);
        }
      return dofs;
    }

    /**
     * The interface points: the hub's points along its bore (the larger
     * of the two sides' when a section is a gmsh file: the finer side
     * carries the other).
     */
    double
    interface_points(const Parameters &parameters)
    {
      double points = predicted_axial_points(body_geometry(parameters, "Hub"),
                                             parameters.mesh.degree);
      for (const bool shaft : {true, false})
        if (const Triangulation<2> *file = file_mesh(parameters, shaft))
          {
            std::size_t faces = 0;
            for (const auto &face : file->active_face_iterators())
              faces += face->at_boundary()
                       && face->boundary_id() == BoundaryId::joint;
            points
              = std::max(points,
                         faces * parameters.mesh.degree
                             * std::pow(2., parameters.mesh.global_refinements)
                           + 1.);
          }
      return points;
    }
  } // namespace



  double
  estimated_memory_direct(const Parameters &parameters)
  {
    // The interface points are ordered last in each body's factor (the
    // trailing block is the Schur complement on S), so each factor holds
    // a dense block of the order of the interface points, and a body
    // keeps several factors (sets of prescribed points). Measured peak
    // resident size of prm/default.prm with 1 radial cell, grading 1 and
    // 4001, 8001, 12001 interface points: 1.15, 3.50, 7.29 GB, i.e. 48
    // bytes per (interface points)^2 beyond the sparse part; 50 taken.
    const double n_S = interface_points(parameters);
    return estimated_memory(run_dofs(parameters), parameters.mesh.degree)
           + (parameters.solver.method == SolverMethod::monolithic ?
                0. :
                50. * n_S * n_S);
  }



  bool
  use_amg(const Parameters &parameters)
  {
    // Meshes of their own couple through the condensed operator only.
    if (parameters.solver.method == SolverMethod::monolithic
        || (parameters.sections && !parameters.mesh.shared_joint_nodes))
      return false;
    switch (parameters.solver.linear_solver)
      {
        case LinearSolverType::direct:
          return false;
        case LinearSolverType::amg:
          return true;
        default:
          return estimated_memory_direct(parameters) > available_memory();
      }
  }



  void
  check_memory(const Parameters &parameters)
  {
    const unsigned int degree    = parameters.mesh.degree;
    const std::size_t  n_dofs    = run_dofs(parameters);
    const bool         amg       = use_amg(parameters);
    const double       needed    = amg ? estimated_memory_amg(n_dofs, degree) :
                                         estimated_memory_direct(parameters);
    const double       available = available_memory();
    if (needed <= available)
      return;
    const std::string solver
      = parameters.solver.method == SolverMethod::monolithic ?
          "the monolithic solver (sparse direct)" :
          std::string(amg ? "AMG" : "the direct solver")
            + (parameters.solver.linear_solver == LinearSolverType::automatic ?
                 " (chosen by Solver/Linear solver = auto)" :
                 "");
    rlimit     limit;
    const bool limited
      = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    const std::string where
      = available > 0. ? "the " + gigabytes(available) + " available" :
        limited        ? "what the address space limit (ulimit -v, "
                    + gigabytes(static_cast<double>(limit.rlim_cur))
                    + ") leaves beside the program and its libraries: "
                      "nothing" :
                  "the memory available: none";
    throw InputError(
      "parameter Mesh/Global refinements = "
      + std::to_string(parameters.mesh.global_refinements) + ": the run has "
      + std::to_string(n_dofs) + " DoFs and "
      + std::to_string(static_cast<std::size_t>(interface_points(parameters)))
      + " interface points; with " + solver + " it needs about "
      + gigabytes(needed) + " of memory, more than " + where
      + "; use fewer Global refinements or "
      + (parameters.sections ? "a larger Mesh/Cell size (or coarser sizes in "
                               "the gmsh file)" :
                               "Axial/Radial cells")
      + " (the memory of the staggered solver's factors grows with the "
        "square of the interface points)");
  }
} // namespace coaxfit
