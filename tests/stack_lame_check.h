// A stack of rings of equal length whose joints are frictionless, written
// as a parameter file and checked against the compound cylinders (closed
// form): the part the stack tests of sections and of gmsh files share.
#ifndef coaxfit_tests_stack_lame_check_h
#define coaxfit_tests_stack_lame_check_h

#include <coaxfit/design/compound_cylinders.h>

#include "run_summary.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace coaxfit_test
{
  /** One ring of a test stack (mm, MPa). */
  struct LameRing
  {
    std::string name;
    double      d_in, d_out, E, nu;
  };

  /** The rings of a test's @p bodies (name, d_in, d_out, E, nu). */
  template <typename Body>
  std::vector<LameRing>
  rings_of(const std::vector<Body> &bodies)
  {
    std::vector<LameRing> rings;
    for (const Body &b : bodies)
      rings.push_back({b.name, b.d_in, b.d_out, b.E, b.nu});
    return rings;
  }

  /**
   * The entries of a stack of @p rings after its Geometry: Assembly/Bodies,
   * each ring's E and nu, each joint's interference @p U (mm), one global
   * refinement and Coupling/Tolerance 1e-10.
   */
  inline std::string
  lame_stack_entries(const std::vector<LameRing> &rings,
                     const std::vector<double>   &U)
  {
    std::ostringstream s;
    s.precision(12);
    s << "subsection Assembly\n  set Bodies = ";
    for (const LameRing &b : rings)
      s << (&b == &rings[0] ? "" : ", ") << b.name;
    s << "\nend\nsubsection Material\n";
    for (const LameRing &b : rings)
      s << "  subsection " << b.name << "\n    set E = " << b.E
        << "\n    set nu = " << b.nu << "\n  end\n";
    s << "end\nsubsection Fit\n";
    for (unsigned int k = 0; k < U.size(); ++k)
      s << "  subsection " << rings[k].name << '-' << rings[k + 1].name
        << "\n    set Diametral interference = " << U[k] << "\n  end\n";
    s << "end\nsubsection Mesh\n  set Global refinements = 1\nend\n"
         "subsection Coupling\n  set Tolerance = 1e-10\nend\n";
    return s.str();
  }

  /**
   * A parameter file of the test's @p bodies, each a plain ring @p length
   * mm long unless @p section (the body) gives the value of its
   * `Geometry/<body> section`, with interferences @p U
   * (lame_stack_entries()).
   */
  template <typename Body, typename Section>
  std::string
  lame_stack_prm(const std::vector<Body>   &bodies,
                 const std::vector<double> &U,
                 const double               length,
                 const Section             &section)
  {
    std::ostringstream s;
    s.precision(12);
    s << "subsection Geometry\n";
    for (const Body &b : bodies)
      {
        const std::string text = section(b);
        if (!text.empty())
          s << "  set " << b.name << " section = " << text << '\n';
        else
          s << "  subsection " << b.name
            << "\n    set Inner diameter = " << b.d_in
            << "\n    set Outer diameter = " << b.d_out
            << "\n    set Length = " << length << "\n  end\n";
      }
    s << "end\n";
    return s.str() + lame_stack_entries(rings_of(bodies), U);
  }

  /**
   * Run @p prm in the directory @p name and print every joint's pressure
   * (at the mid-plane and its mean) against the compound cylinders of
   * @p rings with interferences @p U, to 1e-5.
   */
  inline void
  check_against_compound_cylinders(const std::string           &name,
                                   const std::string           &prm,
                                   const std::vector<LameRing> &rings,
                                   const std::vector<double>   &U)
  {
    std::filesystem::remove_all(name);
    const RunResult      r = run_coaxfit(name, quiet + prm);
    const nlohmann::json s = read_summary(name);
    std::vector<coaxfit::CompoundCylinders::Ring> closed_form;
    for (const LameRing &b : rings)
      closed_form.push_back({b.d_in, b.d_out, b.E, b.nu});
    const coaxfit::CompoundCylinders exact(closed_form, U, 0., 0.);
    std::cout << name << ": exit " << r.exit_code << ", converged "
              << s["converged"] << ", model "
              << s["mesh"]["model"].get<std::string>() << '\n';
    for (unsigned int k = 0; k < U.size(); ++k)
      {
        const nlohmann::json &j = s["joints"][k];
        const double          p = exact.pressure(k);
        std::cout << "  " << j["name"].get<std::string>() << ": "
                  << std::setprecision(6) << p << " MPa exact: at the "
                  << "mid-plane "
                  << agreement(j["pressure"]["at_mid_plane"], p, 1e-5)
                  << ", mean " << agreement(j["pressure"]["mean"], p, 1e-5)
                  << '\n';
      }
  }
} // namespace coaxfit_test

#endif
