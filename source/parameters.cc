#include <deal.II/base/exceptions.h>

#include <coaxfit/input_error.h>
#include <coaxfit/parameters.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /**
     * deal.II exceptions carry a multi-line banner; keep the "Additional
     * information" part and fold it into one line.
     */
    std::string
    one_line(const std::exception &exc)
    {
      std::string       text = exc.what();
      const std::string key  = "Additional information:";
      const std::size_t pos  = text.find(key);
      if (pos != std::string::npos)
        text = text.substr(pos + key.size());
      const std::size_t stack = text.find("Stacktrace:");
      if (stack != std::string::npos)
        text = text.substr(0, stack);
      std::string out;
      bool        space = false;
      for (const char c : text)
        {
          if (std::isspace(static_cast<unsigned char>(c)))
            space = !out.empty();
          else
            {
              if (space)
                out += ' ';
              out += c;
              space = false;
            }
        }
      // the banner of an exception without additional information
      while (!out.empty() && (out.back() == '-'))
        out.pop_back();
      return out;
    }

    void
    require(const bool         condition,
            const std::string &name,
            const double       value,
            const std::string &range)
    {
      if (!condition)
        {
          std::ostringstream msg;
          msg.precision(10);
          msg << "parameter " << name << " = " << value
              << " is out of range: allowed is " << range << '.';
          throw InputError(msg.str());
        }
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s.precision(10);
      s << x;
      return s.str();
    }

    std::string
    base_name(const std::string &filename)
    {
      std::string name  = filename;
      const auto  slash = name.find_last_of('/');
      if (slash != std::string::npos)
        name = name.substr(slash + 1);
      const auto dot = name.rfind(".prm");
      if (dot != std::string::npos && dot + 4 == name.size())
        name = name.substr(0, dot);
      return name.empty() ? std::string("default") : name;
    }
  } // namespace



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    const Patterns::Double any_double;
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("R0",
                        "0",
                        any_double,
                        "Inner radius of the shaft D1 in mm; 0 for a solid "
                        "shaft. Allowed: 0 <= R0 < R1.");
      prm.declare_entry(
        "R1",
        "100",
        any_double,
        "Nominal contact radius in mm: outer radius of the "
        "shaft and bore of the hub; both bodies are meshed "
        "at this radius (small strain). Allowed: R0 < R1 < R2.");
      prm.declare_entry(
        "R2",
        "200",
        any_double,
        "Outer radius of the hub D2 in mm. Allowed: R1 < R2 <= 1e4 R1.");
      prm.declare_entry(
        "L1",
        "200",
        any_double,
        "HALF length of the shaft in mm, measured from the "
        "common mid-plane z = 0 (the shaft is 2 L1 long), as "
        "in the paper's table (l1 = L1/R1). Allowed: 1e-4 R1 <= L1 <= 1e4 R1.");
      prm.declare_entry("L2",
                        "100",
                        any_double,
                        "HALF length of the hub in mm, measured from the "
                        "common mid-plane z = 0 (the hub is 2 L2 long). The "
                        "contact surface is r = R1, 0 <= z <= min(L1, L2). "
                        "Allowed: 1e-4 R1 <= L2 <= 1e4 R1.");
      prm.declare_entry("d",
                        "0.25",
                        any_double,
                        "Radial interference in mm: the shaft's radius "
                        "exceeds the bore's by d. The model is linear (small "
                        "strain, both bodies meshed at R1), so d/R1 should "
                        "stay well below 0.01. Allowed: 0 < d <= 0.1 R1.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      for (const std::string body : {"Shaft", "Hub"})
        {
          prm.enter_subsection(body);
          prm.declare_entry("E",
                            "2e5",
                            any_double,
                            "Young's modulus of the "
                              + std::string(body == "Shaft" ? "shaft D1" :
                                                              "hub D2")
                              + " in MPa. Allowed: E > 0.");
          prm.declare_entry("nu",
                            "0.33",
                            any_double,
                            "Poisson's ratio of the "
                              + std::string(body == "Shaft" ? "shaft D1" :
                                                              "hub D2")
                              + " (dimensionless). Allowed: -1 < nu < 0.5.");
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    {
      prm.declare_entry("Axial cells",
                        "12",
                        Patterns::Integer(1, 10000),
                        "Number of cells along the contact length "
                        "0 <= z <= min(L1, L2) before global refinement "
                        "(the paper used 10-12). Cells shrink towards the "
                        "end of contact by the grading ratio; the part of "
                        "the longer body beyond the contact gets cells that "
                        "grow away from it. Allowed: 1 to 10000.");
      prm.declare_entry("Radial cells",
                        "10",
                        Patterns::Integer(1, 10000),
                        "Number of cells across each wall before global "
                        "refinement (the paper used 10), shrinking towards "
                        "the contact surface. Allowed: 1 to 10000.");
      prm.declare_entry("Grading ratio",
                        "1.4",
                        Patterns::Double(1.0, 10.0),
                        "Ratio of the sizes of neighbouring cells "
                        "(geometric progression, the paper used 1.3-1.6); "
                        "1 gives a uniform mesh. Allowed: 1 to 10.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 10),
                        "Number of uniform refinements applied to both "
                        "meshes; 0 is the paper's coarse mesh. Allowed: 0 to "
                        "10.");
      prm.declare_entry("Degree",
                        "2",
                        Patterns::Integer(1, 4),
                        "Polynomial degree p of the FE_Q elements for both "
                        "displacement components. Allowed: 1 to 4.");
      prm.declare_entry("Volumetric integration",
                        "full",
                        Patterns::Selection("full|reduced"),
                        "full: the whole stiffness with the (p+1)-point "
                        "Gauss rule per direction. reduced: selective "
                        "reduced integration, the lambda (volumetric) part "
                        "with the p-point rule, the 2 mu part with p+1; it "
                        "removes volumetric locking of low degrees for nearly "
                        "incompressible materials (nu -> 0.5; see "
                        "benchmarks/stress). The contact pressure comes from "
                        "reactions; the VTU stresses take their volumetric "
                        "part from the reduced points (field "
                        "volumetric_stress), which is accurate for FE_Q(2) "
                        "and up; FE_Q(1) gives one value per cell, off by up "
                        "to a third of p next to the axis at nu = 0.4999.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Method",
                        "staggered",
                        Patterns::Selection("staggered|monolithic"),
                        "staggered: the principle of alternating continuity "
                        "(each body solved on its own, Dirichlet and "
                        "Neumann steps alternating). monolithic: the "
                        "reference, both bodies in one system with the "
                        "contact points tied and a primal-dual active set "
                        "for separation; the Coupling settings are not "
                        "used.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Coupling");
    {
      prm.declare_entry("Alpha",
                        "0.8",
                        any_double,
                        "Relaxation weight alpha (project convention): the "
                        "Neumann step applies p = p1 + alpha (p2 - p1) and "
                        "the Dirichlet step u = u1 + (1 - alpha) (u2 - d - "
                        "u1), with index 1 the shaft and 2 the hub. A stiff "
                        "solid shaft wants alpha near 1, a thin tube near 0. "
                        "Allowed: 0 < alpha < 1.");
      prm.declare_entry("Alpha controller",
                        "iqn-ils",
                        Patterns::Selection(
                          "fixed|winkler|pointwise|aitken|iqn-ils"),
                        "How the staggered process is steered. fixed: the "
                        "constant Coupling/Alpha. winkler: one alpha = "
                        "k2/(k1 + k2) from the bodies' current compliances, "
                        "formulas (4.20)-(4.21), re-estimated after every "
                        "Neumann step. pointwise: an alpha per interface "
                        "point by (4.22) with Coupling/Beta. aitken: "
                        "Winkler alpha plus dynamic (Aitken) relaxation of "
                        "the traction iterate. iqn-ils: Winkler alpha plus "
                        "interface quasi-Newton (inverse least squares) "
                        "acceleration. Coupling/Alpha is the first alpha of "
                        "the adaptive controllers.");
      prm.declare_entry("Interface operator",
                        "auto",
                        Patterns::Selection("auto|full|condensed"),
                        "full: every step solves both bodies (two triangular "
                        "solves each with the cached factorizations, one "
                        "more factorization per body for every new set of "
                        "points in contact). condensed: each body's "
                        "compliance on S is formed once (the inverse of the "
                        "trailing block of the free body's Cholesky factor, "
                        "interface points ordered last), the iteration runs "
                        "on the interface only with dense algebra, and one "
                        "full solve per body gives the final fields. auto: "
                        "condensed up to 2000 interface points (dense "
                        "compliance up to 32 MB per body), full above; "
                        "from 1e5 DoFs on, condensed was 1.6-2.1x faster "
                        "with full contact and 10-16x where the surfaces "
                        "separate (benchmarks/README.md).");
      prm.declare_entry("Beta",
                        "auto",
                        Patterns::Anything(),
                        "beta of the pointwise controller, formula (4.22): "
                        "alpha_i = beta u2/((1 - beta) u1 + beta u2); 0.5 "
                        "gives (4.21). auto: chosen from the contraction of "
                        "the first steps' residuals among 0.5, 0.3 and 0.15 "
                        "or 0.7. Allowed: auto or 0 < beta < 1.");
      prm.declare_entry("Aitken initial omega",
                        "1",
                        any_double,
                        "Relaxation factor of the first Aitken step (1: "
                        "the plain process). Allowed: 0 < omega <= 2.");
      prm.declare_entry("IQN-ILS columns",
                        "50",
                        Patterns::Integer(1, 1000),
                        "Largest number of previous iterations the IQN-ILS "
                        "model keeps. Allowed: 1 to 1000.");
      prm.declare_entry("IQN-ILS filter",
                        "1e-10",
                        any_double,
                        "QR filter of IQN-ILS: a column whose part "
                        "orthogonal to the newer columns is below this "
                        "fraction of its norm is dropped. Allowed: 0 <= "
                        "filter < 1.");
      prm.declare_entry("Tolerance",
                        "1e-8",
                        any_double,
                        "The iteration stops when both the relative "
                        "displacement mismatch max|u2 - u1 - d|/d (after a "
                        "Neumann step) and the relative traction mismatch "
                        "max|p2 - p1|/max|p| (after a Dirichlet step) are "
                        "below this value. Allowed: 1e-14 <= tol < 1.");
      prm.declare_entry("Max steps",
                        "200",
                        Patterns::Integer(1, 100000),
                        "Largest number of coupling steps (each Neumann or "
                        "Dirichlet solve of both bodies is one step). A run "
                        "that reaches it without converging exits with a "
                        "non-zero code. Allowed: 1 to 100000.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    {
      prm.declare_entry("Unilateral",
                        "true",
                        Patterns::Bool(),
                        "true: the contact is unilateral as in the paper "
                        "(1.2)-(1.3): tensile contact forces are set to zero "
                        "and points with a gap >= 0 and no force separate. "
                        "false: bilateral (the surfaces are held together, "
                        "the pressure may become tensile).");
      prm.declare_entry("Active set update",
                        "auto",
                        Patterns::Selection("auto|every step|when converged"),
                        "When the contact / separated flags change. every "
                        "step: the paper's process, tensile forces are set "
                        "to zero in every force step and the flags are set "
                        "after every Neumann step. when converged: the flags "
                        "stay fixed while the coupling converges to the "
                        "Active set tolerance, then tensile contact points "
                        "separate and penetrating separated points close "
                        "(primal-dual active set); accelerators (aitken, "
                        "iqn-ils) need this. auto: every step for the fixed "
                        "controller, when converged otherwise.");
      prm.declare_entry("Active set tolerance",
                        "1e-4",
                        any_double,
                        "In the when-converged mode the flags are updated "
                        "once both relative mismatches are below this value "
                        "(or Coupling/Tolerance if larger). Allowed: "
                        "0 < tol < 1.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Directory for the results (created if missing). "
                        "Empty: output/<base name of the parameter file>, "
                        "relative to the working directory.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write one VTU file per body for the final state "
                        "and a .pvd grouping them (for ParaView).");
      prm.declare_entry("Print timing",
                        "true",
                        Patterns::Bool(),
                        "Print the wall times of the phases at the end of "
                        "the run (they are always in summary.json). Tests "
                        "switch this off to keep their output reproducible.");
    }
    prm.leave_subsection();
  }



  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    R0 = prm.get_double("R0");
    R1 = prm.get_double("R1");
    R2 = prm.get_double("R2");
    L1 = prm.get_double("L1");
    L2 = prm.get_double("L2");
    d  = prm.get_double("d");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    for (const auto &[body, material] :
         {std::pair<std::string, Material *>{"Shaft", &shaft}, {"Hub", &hub}})
      {
        prm.enter_subsection(body);
        material->E  = prm.get_double("E");
        material->nu = prm.get_double("nu");
        prm.leave_subsection();
      }
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    axial_cells        = prm.get_integer("Axial cells");
    radial_cells       = prm.get_integer("Radial cells");
    grading_ratio      = prm.get_double("Grading ratio");
    global_refinements = prm.get_integer("Global refinements");
    degree             = prm.get_integer("Degree");
    reduced_volumetric_integration
      = prm.get("Volumetric integration") == "reduced";
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    solver_method = prm.get("Method");
    prm.leave_subsection();

    prm.enter_subsection("Coupling");
    alpha            = prm.get_double("Alpha");
    alpha_controller = prm.get("Alpha controller");
    tolerance        = prm.get_double("Tolerance");
    max_steps        = prm.get_integer("Max steps");
    {
      const std::string b = prm.get("Beta");
      if (b == "auto")
        beta = 0.;
      else
        {
          std::istringstream in(b);
          if (!(in >> beta) || !(in >> std::ws).eof())
            throw InputError("parameter Coupling/Beta = " + b
                             + " is not a number: allowed is auto or "
                               "0 < beta < 1.");
          if (!(beta > 0. && beta < 1.))
            throw InputError("parameter Coupling/Beta = " + b
                             + " is out of range: allowed is auto or "
                               "0 < beta < 1.");
        }
    }
    interface_operator = prm.get("Interface operator");
    aitken_omega       = prm.get_double("Aitken initial omega");
    iqn_columns        = prm.get_integer("IQN-ILS columns");
    iqn_filter         = prm.get_double("IQN-ILS filter");
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    unilateral           = prm.get_bool("Unilateral");
    active_set_update    = prm.get("Active set update");
    active_set_tolerance = prm.get_double("Active set tolerance");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    write_vtu        = prm.get_bool("Write vtu");
    print_timing     = prm.get_bool("Print timing");
    prm.leave_subsection();
  }



  void
  Parameters::validate() const
  {
    const std::vector<std::pair<std::string, double>> values
      = {{"Geometry/R0", R0},
         {"Geometry/R1", R1},
         {"Geometry/R2", R2},
         {"Geometry/L1", L1},
         {"Geometry/L2", L2},
         {"Geometry/d", d},
         {"Material/Shaft/E", shaft.E},
         {"Material/Shaft/nu", shaft.nu},
         {"Material/Hub/E", hub.E},
         {"Material/Hub/nu", hub.nu},
         {"Mesh/Grading ratio", grading_ratio},
         {"Coupling/Alpha", alpha},
         {"Coupling/Tolerance", tolerance},
         {"Coupling/Aitken initial omega", aitken_omega},
         {"Coupling/IQN-ILS filter", iqn_filter},
         {"Contact/Active set tolerance", active_set_tolerance}};
    for (const auto &[name, value] : values)
      require(std::isfinite(value), name, value, "a finite number");

    require(R0 >= 0., "Geometry/R0", R0, "0 <= R0 < R1");
    require(R1 > R0,
            "Geometry/R1",
            R1,
            "R0 < R1 < R2 (R0 = " + number(R0) + ")");
    require(R2 > R1, "Geometry/R2", R2, "R2 > R1 (R1 = " + number(R1) + ")");
    // Proportions a mesh of 2D cells can represent in double precision.
    require(R2 <= 1e4 * R1, "Geometry/R2", R2, "R1 < R2 <= 1e4 R1");
    require(R1 - R0 >= 1e-6 * R1,
            "Geometry/R0",
            R0,
            "a wall R1 - R0 of at least 1e-6 R1");
    require(L1 > 0. && L1 >= 1e-4 * R1 && L1 <= 1e4 * R1,
            "Geometry/L1",
            L1,
            "1e-4 R1 <= L1 <= 1e4 R1");
    require(L2 > 0. && L2 >= 1e-4 * R1 && L2 <= 1e4 * R1,
            "Geometry/L2",
            L2,
            "1e-4 R1 <= L2 <= 1e4 R1");
    require(d > 0. && d <= 0.1 * R1, "Geometry/d", d, "0 < d <= 0.1 R1");
    require(shaft.E > 0., "Material/Shaft/E", shaft.E, "E > 0");
    require(hub.E > 0., "Material/Hub/E", hub.E, "E > 0");
    require(shaft.nu > -1. && shaft.nu < 0.5,
            "Material/Shaft/nu",
            shaft.nu,
            "-1 < nu < 0.5");
    require(hub.nu > -1. && hub.nu < 0.5,
            "Material/Hub/nu",
            hub.nu,
            "-1 < nu < 0.5");
    require(alpha > 0. && alpha < 1., "Coupling/Alpha", alpha, "0 < alpha < 1");
    require(aitken_omega > 0. && aitken_omega <= 2.,
            "Coupling/Aitken initial omega",
            aitken_omega,
            "0 < omega <= 2");
    require(iqn_filter >= 0. && iqn_filter < 1.,
            "Coupling/IQN-ILS filter",
            iqn_filter,
            "0 <= filter < 1");
    require(active_set_tolerance > 0. && active_set_tolerance < 1.,
            "Contact/Active set tolerance",
            active_set_tolerance,
            "0 < tol < 1");
    require(tolerance >= 1e-14 && tolerance < 1.,
            "Coupling/Tolerance",
            tolerance,
            "1e-14 <= tol < 1");
  }



  Parameters
  read_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot open parameter file '" + filename + "'");
      // A directory opens as a stream on Linux but cannot be read.
      in.peek();
      if (in.bad())
        throw InputError("cannot read parameter file '" + filename + "'");
    }

    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    try
      {
        prm.parse_input(filename, "", false, false);
      }
    catch (const std::exception &exc)
      {
        // deal.II's messages about a line already name the file.
        const std::string message = one_line(exc);
        throw InputError(message.find("of file <") != std::string::npos ?
                           message :
                           "in parameter file '" + filename + "': " + message);
      }

    for (const auto &[path, value] : overrides)
      {
        std::vector<std::string> parts;
        std::size_t              start = 0;
        while (true)
          {
            const std::size_t slash = path.find('/', start);
            parts.push_back(path.substr(start, slash - start));
            if (slash == std::string::npos)
              break;
            start = slash + 1;
          }
        if (parts.size() < 2)
          throw InputError("--set " + path + "=" + value
                           + ": expected Section/Name=value");
        try
          {
            for (std::size_t i = 0; i + 1 < parts.size(); ++i)
              prm.enter_subsection(parts[i]);
            prm.set(parts.back(), value);
            for (std::size_t i = 0; i + 1 < parts.size(); ++i)
              prm.leave_subsection();
          }
        catch (const std::exception &exc)
          {
            throw InputError("--set " + path + "=" + value + ": "
                             + one_line(exc));
          }
      }

    Parameters parameters;
    parameters.parse_parameters(prm);
    parameters.case_name = base_name(filename);
    if (parameters.output_directory.empty())
      parameters.output_directory = "output/" + parameters.case_name;
    parameters.validate();
    return parameters;
  }



  void
  print_parameters(std::ostream &out)
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.print_parameters(out, ParameterHandler::Text);
  }
} // namespace coaxfit
