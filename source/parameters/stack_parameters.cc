#include <coaxfit/base/input_error.h>
#include <coaxfit/fe/section_file.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/operation_entries.h>
#include <coaxfit/parameters/parameter_checks.h>
#include <coaxfit/parameters/parameter_file.h>
#include <coaxfit/parameters/parameter_reading.h>
#include <coaxfit/parameters/stack_parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace coaxfit
{
  namespace
  {
    /** @p text without leading and trailing blanks. */
    std::string
    trim(const std::string &text)
    {
      const std::size_t first = text.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      return text.substr(first, text.find_last_not_of(" \t") + 1 - first);
    }

    /** @p text in lower case. */
    std::string
    lower(std::string text)
    {
      for (char &c : text)
        c = std::tolower(static_cast<unsigned char>(c));
      return text;
    }

    /** The names of a comma separated `Assembly/Bodies`, checked. */
    std::vector<std::string>
    split_bodies(const std::string &list)
    {
      std::vector<std::string> names;
      if (trim(list).empty())
        return names;
      std::istringstream    in(list);
      std::string           name;
      std::set<std::string> seen;
      while (std::getline(in, name, ','))
        {
          name = trim(name);
          bool valid_chars
            = !name.empty()
              && std::isalpha(static_cast<unsigned char>(name[0]));
          for (const char c : name)
            valid_chars
              = valid_chars
                && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
          if (name.size() > 40)
            throw InputError("parameter Assembly/Bodies: the name '"
                             + name.substr(0, 40)
                             + "...' is too long (allowed: at most 40 "
                               "characters; the result files are named "
                               "after the joints)");
          if (!valid_chars)
            throw InputError(
              "parameter Assembly/Bodies: '" + name
              + "' is not a body name (allowed: letters, digits and _, "
                "beginning with a letter; names separated by commas)");
          if (name == "Assembly")
            throw InputError(
              "parameter Assembly/Bodies: the name 'Assembly' is reserved "
              "(Operation/Assembly temperature is the temperature of "
              "assembly, not a body's); allowed: any other name");
          if (!seen.insert(lower(name)).second)
            throw InputError("parameter Assembly/Bodies: the body '" + name
                             + "' is listed twice (each body once, inside "
                               "out; names differing in case only count as "
                               "the same: they name the same files)");
          names.push_back(name);
        }
      if (names.size() < 2 || names.size() > 20)
        throw InputError("parameter Assembly/Bodies = " + trim(list)
                         + ": allowed 2 to 20 bodies, listed inside out");
      return names;
    }

    /** Declare `Assembly/Bodies` with the value @p bodies. */
    void
    declare_bodies_entry(ParameterHandler &prm, const std::string &bodies)
    {
      prm.enter_subsection("Assembly");
      prm.declare_entry(
        "Bodies",
        bodies,
        Patterns::Anything(),
        "The coaxial bodies of the assembly, inside out, separated by "
        "commas (for example Shaft, Sleeve, Hub). Each name is spelled in "
        "its subsections exactly as here: Material/<body>, Geometry/<body> "
        "(Inner diameter, Outer diameter, Length of a plain ring) and the "
        "joint's fit Fit/<inner>-<outer>. Empty: the file describes one "
        "Shaft in one Hub with the entries of Geometry, Fit and Material "
        "of today's files. Allowed: 2 to 20 names of letters, digits and "
        "_, each once.");
      prm.leave_subsection();
    }

    /**
     * Throw an InputError that names what is wrong if @p path enters a
     * subsection of a body or joint that the body list of @p p does not
     * have: its first two parts name the subsection (`Fit/A-C`,
     * `Geometry/X`) when @p is_subsection, else the parts but the last
     * (`Fit/A-C/Diametral interference`). @p where says where it was
     * given.
     */
    void
    check_subsection(const StackParameters &p,
                     const std::string     &path,
                     const bool             is_subsection,
                     const std::string     &where)
    {
      const std::vector<std::string> parts = split_path(path);
      if (parts.size() < (is_subsection ? 2 : 3))
        return;
      const std::string &section = parts[0], &name = parts[1];
      std::string        bodies, joints;
      for (unsigned int b = 0; b < p.bodies.size(); ++b)
        {
          bodies += (b > 0 ? ", " : "") + p.bodies[b];
          if (b + 1 < p.bodies.size())
            joints += (b > 0 ? ", " : "") + p.joint_name(b);
        }
      if (section == "Fit")
        {
          for (unsigned int k = 0; k < p.n_joints(); ++k)
            if (name == p.joint_name(k))
              return;
          throw InputError(where + ": the joint fit Fit/" + name
                           + " names no joint (the joints are the neighbours "
                             "of Assembly/Bodies, inside out: "
                           + joints + ")");
        }
      if (section == "Geometry" || section == "Material")
        {
          if (std::find(p.bodies.begin(), p.bodies.end(), name)
              == p.bodies.end())
            throw InputError(where + ": " + section + "/" + name
                             + " names no body of Assembly/Bodies (" + bodies
                             + ")");
        }
    }

    /**
     * The parameter text @p text (ParameterHandler's short format) without
     * the entries @p entries (`Fit.A-B.Diametral interference`): an entry
     * the file did not give (a joint with an ISO fit has no interference)
     * is not written, so that the text repeats the run.
     */
    std::string
    without_entries(const std::string           &text,
                    const std::set<std::string> &entries)
    {
      std::istringstream       lines(text);
      std::string              line, result;
      std::vector<std::string> path;
      while (std::getline(lines, line))
        {
          const std::string t = trim(line);
          if (t.rfind("subsection ", 0) == 0)
            path.push_back(trim(t.substr(11)));
          else if (t == "end" && !path.empty())
            path.pop_back();
          else if (t.rfind("set ", 0) == 0)
            {
              std::string entry;
              for (const std::string &section : path)
                entry += section + ".";
              entry += trim(t.substr(4, t.find('=') - 4));
              if (entries.count(entry) > 0)
                continue;
            }
          result += line + '\n';
        }
      return result;
    }

    /**
     * Throw an InputError that lists the entries of `Operation` for the
     * bodies of @p p if @p entry is not one of them; @p where says where
     * it was given.
     */
    void
    check_operation_entry(const StackParameters &p,
                          const std::string     &entry,
                          const std::string     &where)
    {
      std::vector<std::string> allowed = {"Assembly temperature"};
      for (const std::string &b : p.bodies)
        allowed.push_back(b + " temperature");
      allowed.push_back("Speed");
      allowed.push_back(p.bodies.front() + " bore pressure");
      allowed.push_back(p.bodies.back() + " outer pressure");
      allowed.push_back("Joining clearance");
      if (std::find(allowed.begin(), allowed.end(), entry) != allowed.end())
        return;
      std::string list;
      for (const std::string &a : allowed)
        list += (list.empty() ? "" : ", ") + a;
      throw InputError(where + ": Operation/" + entry
                       + " is no entry of a stack of these bodies (allowed: "
                       + list + ")");
    }

    /**
     * The joints of @p p in the order they are made, from Assembly/Order:
     * `inside out`, `outside in` (runs of white space count as one), or
     * every joint named once. @p normal receives the order as the results
     * name it: the keyword, or the joints separated by `, `.
     */
    std::vector<unsigned int>
    joining_order(const StackParameters &p, std::string &normal)
    {
      const unsigned int        n = p.n_joints();
      std::vector<unsigned int> order;
      std::string               text;
      for (const char c : trim(p.order_text))
        if (!std::isspace(static_cast<unsigned char>(c)))
          text += c;
        else if (!text.empty() && text.back() != ' ')
          text += ' ';
      if (text == "inside out" || text == "outside in")
        {
          for (unsigned int k = 0; k < n; ++k)
            order.push_back(text == "inside out" ? k : n - 1 - k);
          normal = text;
          return order;
        }
      std::string joints;
      for (unsigned int k = 0; k < n; ++k)
        joints += (k > 0 ? ", " : "") + p.joint_name(k);
      const std::string entry = "parameter Assembly/Order = '" + text + "'";
      const std::string allowed
        = " (allowed: inside out, outside in, or each of the joints " + joints
          + " once, in the order they are made, separated by commas)";
      if (text.empty() || text.back() == ',')
        throw InputError(entry + ": an empty item" + allowed);
      std::istringstream in(text);
      std::string        name;
      while (std::getline(in, name, ','))
        {
          name = trim(name);
          if (name.empty())
            throw InputError(entry + ": an empty item" + allowed);
          unsigned int known = n;
          for (unsigned int k = 0; k < n; ++k)
            if (p.joint_name(k) == name)
              known = k;
          if (known == n)
            throw InputError(entry + ": '" + name
                             + "' is not a joint of Assembly/Bodies" + allowed);
          if (std::find(order.begin(), order.end(), known) != order.end())
            throw InputError(entry + " names the joint " + name + " twice"
                             + allowed);
          order.push_back(known);
        }
      for (unsigned int k = 0; k < n; ++k)
        if (std::find(order.begin(), order.end(), k) == order.end())
          throw InputError(entry + " does not name the joint " + p.joint_name(k)
                           + allowed);
      normal.clear();
      for (const unsigned int k : order)
        normal += (normal.empty() ? "" : ", ") + p.joint_name(k);
      return order;
    }
  } // namespace



  bool
  StackParameters::declares(const std::string &path) const
  {
    // The entries of a copy (add_parameter binds them to its members).
    StackParameters  copy = *this;
    ParameterHandler prm;
    copy.declare_parameters(prm);
    return declares_entry(prm, path);
  }



  std::pair<unsigned int, unsigned int>
  StackParameters::joined_parts(const unsigned int k) const
  {
    // Joint k is made after the joints before it in joining_order.
    const auto at   = std::find(joining_order.begin(), joining_order.end(), k);
    const auto made = [&](const unsigned int j) {
      return std::find(joining_order.begin(), at, j) != at;
    };
    unsigned int first = k, last = k + 1;
    while (first > 0 && made(first - 1))
      --first;
    while (last + 1 < bodies.size() && made(last))
      ++last;
    return {first, last};
  }



  void
  RingDrawing::declare_parameters(ParameterHandler  &prm,
                                  const std::string &name)
  {
    const bool required = true;
    prm.add_parameter("Inner diameter",
                      inner_diameter,
                      "Bore diameter of " + name
                        + " in mm; 0: solid (the innermost body only). "
                          "Each body's inner diameter is the outer "
                          "diameter of the body inside it (the "
                          "interference is given in Fit). Allowed: 0 to "
                          "1e6.",
                      Patterns::Double(0., 1e6),
                      required);
    prm.add_parameter("Outer diameter",
                      outer_diameter,
                      "Outer diameter of " + name
                        + " in mm. Allowed: above the inner diameter, up "
                          "to 1e6.",
                      Patterns::Double(0., 1e6),
                      required);
    prm.add_parameter("Length",
                      length,
                      "Full length of " + name
                        + " in mm, centred on the common mid-plane (a "
                          "joint is as long as the shorter of its two "
                          "bodies). Allowed: above 0, up to 1e6.",
                      Patterns::Double(0., 1e6),
                      required);
  }



  void
  JointFit::declare_parameters(ParameterHandler &prm, const std::string &what)
  {
    const bool required = true;
    prm.add_parameter("Diametral interference",
                      diametral_interference,
                      "Diametral interference U of " + what
                        + " in mm: the inner body's outer diameter less "
                          "the outer body's bore. Negative: a clearance "
                          "(contact may be lost). Allowed: |U| <= 1 % of "
                          "the joint diameter (the linear range).",
                      Patterns::Double(-1e4, 1e4),
                      required);
    prm.add_parameter("ISO fit",
                      iso_fit,
                      "ISO 286 fit of " + what
                        + " (hole/shaft, e.g. H7/s6) instead of the "
                          "Diametral interference: its interference at "
                          "the joint diameter, the smallest, mean or "
                          "largest by Fit/Case. Empty: none.",
                      Patterns::Anything());
    prm.add_parameter("Inner roughness Rz",
                      inner_roughness,
                      "Mean roughness depth Rz in micrometres of the inner "
                      "body's seat at "
                        + what
                        + ". DIN 7190 takes the smoothing loss 0.8 "
                          "(Rz_inner + Rz_outer) off the interference: the "
                          "joint is solved with U_w = U - 0.8 (Rz_inner + "
                          "Rz_outer). 0: Fit's value (itself 0 by "
                          "default). Allowed: 0 to 1000.",
                      Patterns::Double(0., 1000.));
    prm.add_parameter("Outer roughness Rz",
                      outer_roughness,
                      "Mean roughness depth Rz in micrometres of the outer "
                      "body's bore at "
                        + what
                        + " (see Inner roughness Rz). 0: Fit's value. "
                          "Allowed: 0 to 1000.",
                      Patterns::Double(0., 1000.));
    prm.add_parameter(
      "Friction coefficient",
      friction_text,
      "Friction coefficient nu_r of " + what
        + " against slip, for the torque capacity T = nu_r p_mean pi D^2 l / "
          "2 and the axial force capacity nu_r p_mean pi D l (DIN 7190-1); "
          "the joint itself is frictionless in the model. auto: DIN "
          "7190-1's value for the pairing of the two bodies' Material Names "
          "and Design/Joining (steel on steel 0.14 shrunk, 0.20 degreased, "
          "0.12 by pressure oil; steel on cast iron 0.10; on light alloys "
          "0.10; on copper alloys 0.17; a body without a Name taken as "
          "steel; pairings without steel have no value). "
        + (what.compare(0, 9, "the joint") == 0 ?
             "0: Fit's value. " :
             "0: not given (no torque figures). ")
        + "Allowed: auto, 0 or a number from 1e-6 to 1.",
      Patterns::Anything());
    // Fit's own value has a default; a joint's 0 takes Fit's.
    const bool joint_entry = press_in_friction_coefficient == 0.;
    prm.add_parameter(
      "Press-in friction coefficient",
      press_in_friction_coefficient,
      "Coefficient of sliding friction while " + what
        + " is pressed lengthwise (DIN 7190's nu_e), for its press-in force "
          "F = nu_e p_mean pi D l, p_mean the joint's pressure in the "
          "part-assembly present when it is pressed (Assembly/Order), at the "
          "interference in use (the largest with Case = max)."
        + (joint_entry ? " 0: Fit's value. Allowed: 0 to 1." :
                         " Allowed: 1e-6 to 1."),
      Patterns::Double(joint_entry ? 0. : 1e-6, 1.));
  }



  bool
  StackOperation::has_loads() const
  {
    for (const double T : temperature)
      if (T != assembly_temperature)
        return true;
    return speed > 0. || bore_pressure > 0. || outer_pressure > 0.;
  }



  std::string
  StackOperation::describe(const std::vector<std::string> &bodies) const
  {
    std::vector<std::string> parts;
    std::string              heated;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (temperature_of(b) != assembly_temperature)
        heated += (heated.empty() ? "" : ", ") + bodies[b] + " "
                  + number(temperature_of(b)) + " C";
    if (!heated.empty())
      parts.push_back(heated + " (assembly " + number(assembly_temperature)
                      + " C)");
    if (speed > 0.)
      parts.push_back(number(speed) + " 1/min");
    if (bore_pressure > 0.)
      parts.push_back(bodies.front() + " bore pressure " + number(bore_pressure)
                      + " MPa");
    if (outer_pressure > 0.)
      parts.push_back(bodies.back() + " outer pressure "
                      + number(outer_pressure) + " MPa");
    std::string text;
    for (const std::string &part : parts)
      text += (text.empty() ? "" : ", ") + part;
    return text.empty() ? "none" : text;
  }



  void
  StackParameters::declare_parameters(ParameterHandler &prm)
  {
    std::string list;
    for (const std::string &b : bodies)
      list += (list.empty() ? "" : ", ") + b;
    declare_bodies_entry(prm, list);
    prm.enter_subsection("Assembly");
    prm.add_parameter(
      "Report surfaces",
      report_surfaces,
      "Surfaces whose radial displacement after joining is reported (mean, "
      "min, max and the change of diameter): `<body> bore` or `<body> "
      "outer`, separated by commas, e.g. `Bushing bore` for the running "
      "clearance of a pressed-in bushing. Empty: none.",
      Patterns::List(Patterns::Anything()));
    prm.add_parameter(
      "Order",
      order_text,
      "The order in which the joints are made, for each joint's press-in "
      "force (the pressure of the part-assembly present when it is "
      "pressed): inside out (each body pressed onto the bodies inside it: "
      "a sleeve onto its shaft, then the hub onto both), outside in (a "
      "bushing pressed into its housing, then the shaft into the bushing), "
      "or every joint named once in the order it is made, separated by "
      "commas (for example Sleeve-Hub, Shaft-Sleeve).",
      Patterns::Anything());
    prm.leave_subsection();

    prm.enter_subsection("Geometry");
    section_text.resize(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        prm.enter_subsection(bodies[b]);
        rings[b].declare_parameters(prm, bodies[b]);
        prm.leave_subsection();
        prm.add_parameter(
          bodies[b] + " section",
          section_text[b],
          "The section of " + bodies[b]
            + " as drawn, instead of the plain ring Geometry/" + bodies[b]
            + ": a closed outline of points z, D (mm; a third number a "
              "fillet radius) separated by ';', the last repeating the "
              "first, in the drawing's coordinates shared by every body "
              "(a gear wheel with its web, a flanged sleeve); or a gmsh "
              "file (.geo or .msh, x the radius and y the axial position in "
              "mm; relative to this file), whose mesh is used as it is and "
              "whose neighbours are meshed with its nodes on their joints. "
              "Its joints with its neighbours are found where the sections "
              "meet, each a cylinder (one piece, or several of one diameter "
              "beside relief grooves). A stack symmetric about one plane "
              "through the middle of every joint is modelled as its half, "
              "any other (and one with a file) whole. Empty: the plain "
              "ring.",
          Patterns::Anything());
      }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        prm.enter_subsection(bodies[b]);
        materials[b].declare_parameters(prm, bodies[b]);
        prm.leave_subsection();
      }
    prm.leave_subsection();

    prm.enter_subsection("Fit");
    prm.add_parameter("Case",
                      fit_case,
                      "Which interference of the joints' ISO fits the run "
                      "takes (every joint that does not give its own Case "
                      "the same): min, mean or max; all: one run of each "
                      "corner of the joints' bands (every joint at its "
                      "smallest or largest interference, each in turn) and "
                      "of their means, into subdirectories named by the "
                      "cases (min, mean, max, min-max, ...), with one table "
                      "and one verdict (with Design/Mode = select: the "
                      "fits chosen in the case of the means). Joints given "
                      "a Diametral interference take it.",
                      Patterns::Selection("min|mean|max|all"));
    default_fit.press_in_friction_coefficient = 0.08;
    default_fit.declare_parameters(prm,
                                   "every joint that does not give its own "
                                   "(Fit/<inner>-<outer>)");
    for (unsigned int k = 0; k < n_joints(); ++k)
      {
        prm.enter_subsection(joint_name(k));
        joint_entries[k].declare_parameters(prm, "the joint " + joint_name(k));
        prm.add_parameter("Case",
                          joint_cases[k],
                          "Which interference of this joint's ISO fit the "
                          "run takes: min, mean or max; empty: Fit/Case's "
                          "(a Fit/Case = all study varies only the joints "
                          "without their own).",
                          Patterns::Anything());
        prm.leave_subsection();
      }
    prm.leave_subsection();

    prm.enter_subsection("Operation");
    operation.temperature_text.resize(bodies.size());
    prm.add_parameter("Assembly temperature",
                      operation.assembly_temperature,
                      "Temperature in degrees C at which the bodies are "
                      "joined and their interferences measured (the state "
                      "of assembly). Allowed: -273.15 < T <= 1000.",
                      Patterns::Double(absolute_zero, hottest_temperature));
    for (unsigned int b = 0; b < bodies.size(); ++b)
      prm.add_parameter(bodies[b] + " temperature",
                        operation.temperature_text[b],
                        "Uniform temperature of " + bodies[b]
                          + " in operation, in degrees C: it expands by "
                            "Material/"
                          + bodies[b]
                          + "/Thermal expansion times the difference to the "
                            "assembly temperature (a thermal eigenstrain). "
                            "Empty: the assembly temperature. Allowed: "
                            "-273.15 < T <= 1000.",
                        Patterns::Anything());
    prm.add_parameter("Speed",
                      operation.speed,
                      "Rotational speed of the whole stack in operation, in "
                      "1/min: the centrifugal body force rho omega^2 r of "
                      "every body (Material/<body>/Density). 0: at rest. "
                      "Allowed: 0 to 1e7.",
                      Patterns::Double(0., 1e7));
    prm.add_parameter(bodies.front() + " bore pressure",
                      operation.bore_pressure,
                      "Pressure in MPa on the bore of the innermost body "
                      "("
                        + bodies.front()
                        + ", hollow) in operation, e.g. a hydraulic "
                          "cylinder's. Allowed: 0 to 1e4; a solid body "
                          "takes none.",
                      Patterns::Double(0., 1e4));
    prm.add_parameter(bodies.back() + " outer pressure",
                      operation.outer_pressure,
                      "Pressure in MPa on the outer surface of the "
                      "outermost body ("
                        + bodies.back() + ") in operation. Allowed: 0 to 1e4.",
                      Patterns::Double(0., 1e4));
    prm.add_parameter(
      "Joining clearance",
      operation.joining_clearance_text,
      "Diametral clearance in mm each joint needs while it is joined "
      "(DIN 7190's joining clearance), for the joining temperatures: the "
      "outer body of each joint heated, or the inner one cooled, until "
      "the joint's largest interference plus this clearance is gone. "
      "auto: 0.001 D at each joint, DIN 7190's guide value. Allowed: auto "
      "or 0 <= clearance <= 0.1 D of every joint.",
      Patterns::Anything());
    prm.leave_subsection();

    prm.enter_subsection("Design");
    prm.add_parameter(
      "Required torque",
      required_torque,
      "Torque in N m that the assembly passes from the innermost to the "
      "outermost body, through every joint: each joint's safety against "
      "slip is its torque capacity (with its Friction coefficient) over "
      "it (with Required axial force: DIN 7190's resultant). 0: none. "
      "Allowed: 0 to 1e9.",
      Patterns::Double(0., 1e9));
    prm.add_parameter(
      "Required axial force",
      required_axial_force,
      "Axial force in N that the assembly passes from the innermost to the "
      "outermost body, through every joint (a helical gear's thrust): each "
      "joint's safety against slip is its friction force mu p pi D l over "
      "the resultant of this and the circumferential force 2 M / D of "
      "Required torque (DIN 7190). 0: none. Allowed: 0 to 1e9.",
      Patterns::Double(0., 1e9));
    prm.add_parameter(
      "Application factor",
      application_factor,
      "Application (service) factor K_A of the loads: every joint must "
      "carry K_A times Required torque and Required axial force (the safety "
      "against slip is taken against those). 1: the loads as given; shocks "
      "ask more (DIN 3990: 1.25 to 2.25). Dimensionless. Allowed: 1 to 10.",
      Patterns::Double(1., 10.));
    prm.add_parameter(
      "Joining",
      joining_text,
      "How the joints are made, for the friction coefficients given as "
      "auto (DIN 7190-1): shrink (the outer part heated or the inner "
      "cooled, surfaces as machined), shrink degreased, pressure oil, "
      "pressure oil degreased, press (pressed in lengthwise: the oiled "
      "pressure oil value). Allowed: "
        + joining_method_names() + " ('|' separates them).",
      Patterns::Selection(joining_method_names()));
    prm.add_parameter(
      "Slip safety",
      slip_safety,
      "The safety against slip every joint must have, for "
      "the verdict (with a Required torque or axial "
      "force): a joint fails where its torque capacity "
      "over the required torque (the resultant of both "
      "loads times K_A) falls below this. 1: no joint may slip. Allowed: 1 "
      "to 100.",
      Patterns::Double(1., 100.));
    prm.add_parameter("Yield safety",
                      yield_safety,
                      "The safety against yield (yield strength over the "
                      "largest von Mises stress on its surfaces at the "
                      "mid-plane) every body of metal or polymer with a "
                      "yield strength must have, for the verdict. 1: no "
                      "body may yield. Allowed: 1 to 100.",
                      Patterns::Double(1., 100.));
    prm.add_parameter("Fracture safety",
                      fracture_safety,
                      "The safety against fracture (tensile strength over "
                      "the largest hoop tension on its surfaces at the "
                      "mid-plane) every brittle body (Material/<body>/Kind, "
                      "e.g. grey cast iron) with a tensile strength must "
                      "have, for the verdict. Allowed: 1 to 100.",
                      Patterns::Double(1., 100.));
    prm.add_parameter(
      "Running clearance",
      running_clearance,
      "Diametral clearance in mm that every joint given a clearance "
      "(Diametral interference < 0: a running fit, such as a bushing's "
      "shaft) must keep at each of its points, at assembly and with the "
      "loads of Operation, for the verdict and a selection (the bushing's "
      "bore closes as it is pressed in). 0: not judged. Allowed: 0 to 10.",
      Patterns::Double(0., 10.));
    prm.add_parameter(
      "Mode",
      design_mode,
      "check: the fits given (Fit) are checked. select: the ISO 286 fits "
      "of the joints of Selected joints are chosen together, so that "
      "every joint carries the Required torque and axial force with the "
      "Slip safety and "
      "every body bears its stresses with the Yield (brittle: Fracture) "
      "safety at every corner of the fits' bands, at assembly and with the "
      "loads of Operation; the first combination (preferred fits, widest "
      "bands) is checked by FE at the corners and then run at Fit/Case. "
      "The fit entries of a selected joint are not used. Allowed: check, "
      "select.",
      Patterns::Selection("check|select"));
    prm.add_parameter(
      "Selected joints",
      selected_text,
      "With Mode = select: the joints whose ISO fits are chosen, named "
      "<inner>-<outer> and separated by commas; the others keep their fit "
      "entries. all: every joint except one given a clearance "
      "(Diametral interference <= 0: a running fit, e.g. a bushing's "
      "shaft). Allowed: all, or joints of Assembly/Bodies.",
      Patterns::Anything());
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    prm.add_parameter("Axial cells",
                      mesh.axial_cells,
                      "Number of cells along the half length of every "
                      "body before global refinement, shrinking towards "
                      "the end by the grading ratio. Allowed: 1 to 10000.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Radial cells",
                      mesh.radial_cells,
                      "Number of cells across each body's wall before "
                      "global refinement (graded towards the joint of the "
                      "innermost and outermost body, equal in a body with "
                      "two joints). Allowed: 1 to 10000.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Grading ratio",
                      mesh.grading_ratio,
                      "Ratio of neighbouring cell sizes. Allowed: 1 to 10.",
                      Patterns::Double(1., 10.));
    prm.add_parameter("Cell size",
                      mesh.cell_size,
                      "Sections only (Geometry/<body> section): the size "
                      "of the cells at the ends of the joints and at "
                      "re-entrant corners in mm before global refinement; "
                      "away from them cells grow by Mesh/Grading ratio per "
                      "cell up to 8 times this size. The two bodies of a "
                      "joint get the same vertices on it. 0: the shortest "
                      "joint's l_F / 100. Mesh/Axial cells and Radial cells "
                      "apply to plain rings only. Allowed: 0, or l_F / 1000 "
                      "to l_F / 4 of the shortest joint (l_F here from end "
                      "to end of a joint of several pieces).",
                      Patterns::Double(0.));
    prm.add_parameter("Global refinements",
                      mesh.global_refinements,
                      "Uniform refinements of every body's mesh. Allowed: "
                      "0 to 12.",
                      Patterns::Integer(0, 12));
    prm.add_parameter("Degree",
                      mesh.degree,
                      "Polynomial degree of the FE_Q elements. Allowed: 1 "
                      "to 4.",
                      Patterns::Integer(1, 4));
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    // The selections are declared as entries and read back by name.
    prm.declare_entry(
      "Method",
      method == SolverMethod::monolithic ? "monolithic" : "staggered",
      Patterns::Selection("staggered|monolithic"),
      "staggered: the alternating Dirichlet-Neumann process over all joints "
      "(Coupling/Ordering). monolithic: all bodies in one linear system on "
      "their full finite element operators, every joint point in contact "
      "tied, a primal-dual active set (the reference, independent of the "
      "condensation the staggered process works on; one sparse "
      "factorization of all bodies per active set).");
    prm.leave_subsection();
    prm.enter_subsection("Coupling");
    prm.declare_entry(
      "Ordering",
      ordering == StackOrdering::jacobi ? "jacobi" : "gauss-seidel",
      Patterns::Selection("gauss-seidel|jacobi"),
      "How a step of the staggered process visits the joints. "
      "gauss-seidel: joint by joint, inside out, each Neumann and "
      "Dirichlet step of a joint's two bodies with the newest forces of "
      "the neighbouring joints. jacobi: the visits of all joints at once "
      "(concurrently, as many threads as cores) from the same forces.");
    prm.declare_entry(
      "Accelerator",
      accelerator == StackAccelerator::none   ? "none" :
      accelerator == StackAccelerator::aitken ? "aitken" :
                                                "iqn-ils",
      Patterns::Selection("none|aitken|iqn-ils"),
      "Acceleration of the fixed point over the forces of all joints "
      "together: none, aitken (dynamic relaxation) or iqn-ils (interface "
      "quasi-Newton, inverse least squares). The history restarts when a "
      "contact point opens or closes.");
    prm.add_parameter("Alpha",
                      alpha,
                      "Relaxation weight alpha of every joint (the outer "
                      "body's traction weight, as for two bodies). 0: "
                      "each joint's Winkler alpha k_o / (k_i + k_o) from "
                      "the mean diagonal compliances of its two sides. "
                      "Allowed: 0 <= alpha < 1.",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Tolerance",
                      tolerance,
                      "Relative residual at which the process stops: the "
                      "displacement mismatch over the largest "
                      "interference and the traction mismatch over the "
                      "largest pressure, at every joint. Allowed: 1e-14 "
                      "to 0.1.",
                      Patterns::Double(1e-14, 0.1));
    prm.add_parameter("Max steps",
                      max_steps,
                      "Largest number of steps. Allowed: 1 to 100000.",
                      Patterns::Integer(1, 100000));
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    prm.add_parameter("Unilateral",
                      unilateral,
                      "true: the surfaces of a joint may separate (no "
                      "tension); false: every joint stays closed (bonded "
                      "radially).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.add_parameter("Directory",
                      directory,
                      "Directory for the results (created if missing). "
                      "Empty: output/<base name of the parameter file>.",
                      Patterns::Anything());
    prm.add_parameter("Write vtu",
                      write_vtu,
                      "Write one VTU file per body, an interface file "
                      "per joint and solution.pvd grouping them (for "
                      "ParaView).");
    prm.add_parameter("Write plots",
                      write_plots,
                      "Draw contact_pressure.png (every joint) and "
                      "convergence.png with gnuplot (skipped with a note "
                      "when gnuplot is not installed).");
    prm.add_parameter("Write report",
                      write_report,
                      "Write report.md: the verdict, the bodies, the joint "
                      "table, the strength of the bodies.");
    prm.add_parameter("Print timing",
                      print_timing,
                      "Print the wall times at the end of the run (they "
                      "are always in summary.json).");
    prm.leave_subsection();
  }



  void
  StackParameters::validate() const
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        std::string        path = "Geometry/" + bodies[b] + "/";
        const RingDrawing &r    = rings[b];
        if (drawn_as_section(b))
          path = "Geometry/" + bodies[b] + " section: its equivalent ring's ";
        require(r.length > 0., path + "Length", r.length, "above 0 mm");
        require(r.outer_diameter > r.inner_diameter,
                path + "Outer diameter",
                r.outer_diameter,
                "above " + path + "Inner diameter = " + number(r.inner_diameter)
                  + " mm");
        // Where sections meet is checked by StackSections.
        if (b > 0 && !sections)
          {
            require(r.inner_diameter > 0.,
                    path + "Inner diameter",
                    r.inner_diameter,
                    "above 0 mm: only the innermost body (" + bodies[0]
                      + ") may be solid");
            const double below = rings[b - 1].outer_diameter;
            if (std::abs(r.inner_diameter - below) > 1e-9 * below)
              throw InputError(
                "parameter " + path
                + "Inner diameter = " + number(r.inner_diameter)
                + ": the bodies " + bodies[b - 1] + " and " + bodies[b]
                + (r.inner_diameter < below ? " overlap" : " do not meet")
                + " (Geometry/" + bodies[b - 1]
                + "/Outer diameter = " + number(below)
                + " mm); the diameters of the drawing must be equal, the "
                  "interference is given in Fit/"
                + joint_name(b - 1) + "/Diametral interference");
          }
        materials[b].validate("Material/" + bodies[b]);
        if (materials[b].plastic)
          throw InputError("parameter Material/" + bodies[b]
                           + "/Plasticity = von Mises: elastic-plastic "
                             "bodies are computed for two bodies (a shaft "
                             "and a hub) in this version, not in a stack of "
                             "several (Assembly/Bodies); allowed here is "
                             "Plasticity = none");
      }
    for (unsigned int k = 0; k < n_joints(); ++k)
      {
        const double D = joint_diameter(k);
        const double U = fits[k].nominal_interference;
        if (std::abs(U) > 0.01 * D)
          throw InputError("parameter Fit/" + joint_name(k)
                           + "/Diametral interference = " + number(U)
                           + ": allowed |U| <= 1 % of the joint diameter "
                           + number(D) + " mm (the linear range)");
        const double U_w = fits[k].diametral_interference;
        if (std::abs(U_w) > 0.01 * D)
          throw InputError(
            "parameter Fit/" + joint_name(k)
            + "/Inner roughness Rz, Outer roughness Rz: the smoothing loss "
            + number(fits[k].smoothing_loss) + " mm leaves U_w = " + number(U_w)
            + " mm; allowed |U_w| <= 1 % of the joint diameter " + number(D)
            + " mm (the linear range)");
      }
    require(operation.assembly_temperature > absolute_zero,
            "Operation/Assembly temperature",
            operation.assembly_temperature,
            "-273.15 < T <= 1000 degrees C");
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const std::string name = "Operation/" + bodies[b] + " temperature";
        check_temperature_entry(operation.temperature_of(b),
                                b < operation.temperature_text.size() ?
                                  operation.temperature_text[b] :
                                  std::string(),
                                name);
        if (operation.temperature_of(b) != operation.assembly_temperature
            && materials[b].thermal_expansion == 0.)
          throw InputError("parameter Material/" + bodies[b]
                           + "/Thermal expansion = 0 (unknown) but " + name
                           + " = " + number(operation.temperature_of(b))
                           + " differs from Operation/Assembly temperature = "
                           + number(operation.assembly_temperature)
                           + ": allowed is a coefficient > 0 in 1/K (or a "
                             "Name that gives it)");
        if (operation.speed > 0. && materials[b].density == 0.)
          throw InputError("parameter Material/" + bodies[b]
                           + "/Density = 0 (unknown) but Operation/Speed = "
                           + number(operation.speed)
                           + " 1/min: allowed is a density > 0 in kg/m^3 (or "
                             "a Name that gives it)");
      }
    for (unsigned int k = 0; k < n_joints(); ++k)
      {
        const double D = joint_diameter(k);
        const double s
          = joining_clearance_entry(operation.joining_clearance_text, D);
        if (std::isnan(s) || s < 0. || s > 0.1 * D)
          throw InputError("parameter Operation/Joining clearance = '"
                           + operation.joining_clearance_text
                           + "': allowed is auto or a number of mm from 0 to "
                             "0.1 D of every joint (the joint "
                           + joint_name(k) + ": D " + number(D) + " mm)");
      }
    if (operation.bore_pressure > 0. && rings[0].inner_diameter == 0.)
      throw InputError("parameter Operation/" + bodies[0]
                       + " bore pressure = " + number(operation.bore_pressure)
                       + ": the body " + bodies[0] + " is solid ("
                       + (!drawn_as_section(0) ?
                            "Geometry/" + bodies[0] + "/Inner diameter = 0" :
                            "its section reaches the axis")
                       + "); allowed is 0");
    // Fit/Case chooses among an ISO fit's interferences.
    bool iso = false;
    for (const JointFit &fit : fits)
      iso = iso || !fit.iso_fit.empty();
    if (running_clearance > 0.)
      {
        bool any = false;
        for (const JointFit &fit : fits)
          any = any || fit.nominal_interference < 0.;
        if (!any)
          throw InputError("parameter Design/Running clearance = "
                           + number(running_clearance)
                           + ": no joint is given a clearance (a Diametral "
                             "interference < 0) that could keep it; allowed "
                             "is 0 here");
      }
    if (select_mode())
      {
        if (std::find(selected.begin(), selected.end(), true) == selected.end())
          throw InputError("parameter Design/Selected joints = " + selected_text
                           + ": no joint is left to choose a fit for (each "
                             "is given a clearance, a running fit); name "
                             "the joints to choose, or set Design/Mode = "
                             "check");
        for (unsigned int k = 0; k < n_joints(); ++k)
          if (selected[k] && candidate_fits(joint_diameter(k)).empty())
            throw InputError("parameter Design/Mode = select: the joint "
                             + joint_name(k) + " has D "
                             + number(joint_diameter(k))
                             + " mm, where ISO 286 gives no fits (allowed: "
                               "over 1 up to 500 mm)");
      }
    for (unsigned int k = 0; k < n_joints(); ++k)
      {
        const std::string &c = joint_cases[k];
        if (!c.empty() && c != "min" && c != "mean" && c != "max")
          throw InputError("parameter Fit/" + joint_name(k) + "/Case = " + c
                           + ": allowed is min, mean, max or nothing "
                             "(Fit/Case's)");
        if (!c.empty() && fits[k].iso_fit.empty()
            && !(select_mode() && selected[k]))
          throw InputError("parameter Fit/" + joint_name(k) + "/Case = " + c
                           + ": the joint has no ISO fit, whose smallest or "
                             "largest interference it would choose (its "
                             "Diametral interference is used as given); "
                             "allowed: nothing, or an ISO fit");
      }
    if (fit_case != "mean" && !iso && !select_mode())
      throw InputError("parameter Fit/Case = " + fit_case
                       + ": no joint has an ISO fit, whose smallest or "
                         "largest interference it would choose (a "
                         "Diametral interference is used as given); allowed "
                         "is mean, or an ISO fit");
    for (unsigned int k = 0; k < n_joints(); ++k)
      {
        const double mu = joint_entries[k].press_in_friction_coefficient;
        if (mu > 0. && mu < 1e-6)
          throw InputError("parameter Fit/" + joint_name(k)
                           + "/Press-in friction coefficient = " + number(mu)
                           + ": allowed is 0 (Fit's value) or 1e-6 <= nu_e "
                             "<= 1");
      }
    if (slip_judged())
      for (unsigned int k = 0; k < n_joints(); ++k)
        if (fits[k].friction_coefficient == 0.)
          throw InputError(
            std::string("parameter Design/")
            + (required_torque > 0. ?
                 "Required torque = " + number(required_torque) :
                 "Required axial force = " + number(required_axial_force))
            + ": the joint " + joint_name(k)
            + " has no friction coefficient (set Fit/Friction coefficient "
              "or Fit/"
            + joint_name(k)
            + "/Friction coefficient: auto or 1e-6 <= nu_r <= 1, for its "
              "safety "
              "against slip)");
    for (const std::string &surface : report_surfaces)
      {
        bool known = false;
        for (const std::string &b : bodies)
          known = known || surface == b + " bore" || surface == b + " outer";
        if (!known)
          throw InputError("parameter Assembly/Report surfaces: '" + surface
                           + "' names no surface (allowed: '<body> bore' or "
                             "'<body> outer' with a body of "
                             "Assembly/Bodies)");
        if (surface == bodies[0] + " bore" && rings[0].inner_diameter == 0.)
          throw InputError("parameter Assembly/Report surfaces: '" + surface
                           + "': the body " + bodies[0]
                           + " is solid (no bore)");
      }
    if (sections)
      {
        double l_min = std::numeric_limits<double>::infinity();
        for (unsigned int k = 0; k < n_joints(); ++k)
          l_min = std::min(l_min, 2. * sections->joint_half_length(k));
        if (mesh.cell_size != 0.)
          require(mesh.cell_size >= l_min / 1000.
                    && mesh.cell_size <= l_min / 4.,
                  "Mesh/Cell size",
                  mesh.cell_size,
                  "0, or l / 1000 = " + number(l_min / 1000., 6)
                    + " to l / 4 = " + number(l_min / 4., 6)
                    + " mm of the shortest joint's length l from end to "
                      "end");
        require(mesh.grading_ratio <= 3.,
                "Mesh/Grading ratio",
                mesh.grading_ratio,
                "1 to 3 with sections");
      }
    else
      {
        if (mesh.cell_size != 0.)
          throw InputError("parameter Mesh/Cell size = "
                           + number(mesh.cell_size)
                           + ": it sizes the meshes of sections, and no "
                             "body has a Geometry/<body> section; allowed "
                             "is 0 (plain rings take Mesh/Axial cells and "
                             "Radial cells)");
        mesh.validate();
      }
  }



  std::vector<std::string>
  StackParameters::warnings() const
  {
    std::vector<std::string> list;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const Material &m = materials[b];
        // The state of assembly at the assembly temperature; in service at
        // the body's own (the same without loads: said once).
        std::vector<std::pair<std::string, double>> states
          = {{"at assembly", operation.assembly_temperature}};
        if (operation.temperature_of(b) != operation.assembly_temperature)
          states.emplace_back("in service", operation.temperature_of(b));
        for (const auto &[when, T] : states)
          if (m.temperature_limit > 0. && T > m.temperature_limit)
            list.push_back(when + " " + bodies[b] + " (" + m.name + ") at "
                           + number(T) + " C is above its temperature limit "
                           + number(m.temperature_limit) + " C, "
                           + m.temperature_limit_reason
                           + ": its strength figures do not hold there");
      }
    // A piece of a joint much shorter than its others: its mean is its
    // ends' peaks, no seat's.
    for (unsigned int k = 0; sections && k < n_joints(); ++k)
      {
        const auto &pieces = sections->joint_drawn_pieces(k);
        double      l      = 0.;
        for (const auto &[lo, hi] : pieces)
          l += hi - lo;
        for (const auto &[lo, hi] : pieces)
          if (pieces.size() > 1 && hi - lo < 0.05 * l)
            list.push_back("joint " + joint_name(k)
                           + " bears on a piece from z " + number(lo, 6)
                           + " to " + number(hi, 6) + " only "
                           + number(hi - lo, 3) + " mm long, under 5 % of its "
                           + number(l, 6)
                           + " mm: its mean pressure is that of its ends' "
                             "peaks, not a seat's");
      }
    return list;
  }



  std::string
  part_text(const std::vector<std::string> &part)
  {
    std::string s;
    for (const std::string &b : part)
      s += (s.empty() ? "" : " + ") + b;
    return s;
  }



  void
  StackParameters::use_iso_fit(const unsigned int k, const IsoFit &iso)
  {
    JointFit    &fit           = fits[k];
    const double U_min         = 1e-3 * iso.min_interference();
    const double U_max         = 1e-3 * iso.max_interference();
    fit.nominal_interference   = case_of(k) == "min" ? U_min :
                                 case_of(k) == "max" ? U_max :
                                                       0.5 * (U_min + U_max);
    fit.diametral_interference = fit.nominal_interference - fit.smoothing_loss;
    fit.largest_interference   = U_max;
    fit.iso_fit                = iso.name;
    fit.source                 = "ISO fit " + iso.name + ", " + case_of(k)
                 + ", chosen by Design/Mode = select";
  }



  std::vector<std::string>
  assembly_bodies(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    std::string list;
    bool        overridden = false;
    for (const auto &[path, value] : overrides)
      if (path == "Assembly/Bodies")
        {
          list       = value;
          overridden = true;
        }
    if (overridden && trim(list).empty())
      throw InputError("--set Assembly/Bodies=" + list
                       + ": empty; allowed 2 to 20 bodies, listed inside out "
                         "(a file of one Shaft and one Hub gives no "
                         "Assembly subsection)");
    if (overridden)
      return split_bodies(list);
    // A file the full reading refuses (not a regular file, an include
    // cycle, too large) is left to it: it names what is wrong.
    try
      {
        check_parameter_file(filename);
      }
    catch (const std::exception &)
      {
        return {};
      }
    std::ifstream in(filename);
    if (!in)
      return {}; // the full reading names the file
    // Only a file that mentions the subsection is parsed twice.
    std::string line;
    bool        assembly = false, include = false;
    while (!assembly && std::getline(in, line))
      {
        assembly = assembly || line.find("Assembly") != std::string::npos;
        include  = include || line.find("include") != std::string::npos;
      }
    if (!assembly && !include)
      return {};
    ParameterHandler prm;
    declare_bodies_entry(prm, list);
    try
      {
        prm.parse_input(filename, "", true, false);
      }
    catch (const std::exception &error)
      {
        // A file that names an Assembly is a stack's: say what is wrong
        // with it (a missing included file); else the full reading of a
        // two-body file reports it.
        if (assembly)
          throw InputError("in parameter file '" + filename
                           + "': " + one_line_message(error));
        return {};
      }
    prm.enter_subsection("Assembly");
    list = prm.get("Bodies");
    prm.leave_subsection();
    return split_bodies(list);
  }



  namespace
  {
    /**
     * The sections of @p p: for every body with `Geometry/<body> section`
     * its ring entries must not be given (taken from @p missing), for the
     * others they must; with any section, every body's outline (a ring's
     * rectangle) is placed (StackSections) and a section body's ring
     * becomes its equivalent one.
     */
    void
    read_sections(StackParameters &p, std::set<std::string> &missing)
    {
      bool any = false;
      for (unsigned int b = 0; b < p.bodies.size(); ++b)
        {
          std::string &text = p.section_text[b];
          text.erase(0, text.find_first_not_of(" \t"));
          text.erase(text.find_last_not_of(" \t") + 1);
          if (text.empty())
            continue;
          any = true;
          for (const std::string entry :
               {"Inner diameter", "Outer diameter", "Length"})
            if (missing.erase("Geometry." + p.bodies[b] + "." + entry) == 0)
              throw InputError("parameter Geometry/" + p.bodies[b] + "/" + entry
                               + ": give either Geometry/" + p.bodies[b]
                               + " section or the plain ring's Inner "
                                 "diameter, Outer diameter and Length, not "
                                 "both");
        }
      if (!any)
        return;
      std::vector<std::string> entries, texts;
      for (unsigned int b = 0; b < p.bodies.size(); ++b)
        if (!p.section_text[b].empty())
          {
            entries.push_back("Geometry/" + p.bodies[b] + " section");
            texts.push_back(p.section_text[b]);
          }
        else
          {
            // A ring's entries must be there and in range to draw it.
            const std::string  path = "Geometry/" + p.bodies[b] + "/";
            const RingDrawing &r    = p.rings[b];
            for (const std::string entry :
                 {"Inner diameter", "Outer diameter", "Length"})
              if (missing.count("Geometry." + p.bodies[b] + "." + entry) > 0)
                throw InputError("parameter file does not give " + path + entry
                                 + " (or Geometry/" + p.bodies[b]
                                 + " section)");
            require(r.length > 0., path + "Length", r.length, "above 0 mm");
            require(r.outer_diameter > r.inner_diameter,
                    path + "Outer diameter",
                    r.outer_diameter,
                    "above " + path
                      + "Inner diameter = " + number(r.inner_diameter) + " mm");
            std::ostringstream outline;
            outline.precision(17);
            const double z = 0.5 * r.length;
            outline << -z << ", " << r.inner_diameter << "; " << z << ", "
                    << r.inner_diameter << "; " << z << ", " << r.outer_diameter
                    << "; " << -z << ", " << r.outer_diameter << "; " << -z
                    << ", " << r.inner_diameter;
            entries.push_back("Geometry/" + p.bodies[b]);
            texts.push_back(outline.str());
          }
      p.sections = std::make_shared<const StackSections>(entries, texts);
      const unsigned int N = p.bodies.size();
      for (unsigned int b = 0; b < N; ++b)
        if (!p.section_text[b].empty())
          {
            p.rings[b].inner_diameter
              = p.sections->equivalent_inner_diameter(b);
            p.rings[b].outer_diameter
              = p.sections->equivalent_outer_diameter(b);
            p.rings[b].length = p.sections->length(b);
          }
        else
          {
            // A ring's joints at the joints' diameters, which a section
            // beside it may set within the drawing tolerance.
            if (b > 0)
              p.rings[b].inner_diameter = 2. * p.sections->joint_radius(b - 1);
            if (b + 1 < N)
              p.rings[b].outer_diameter = 2. * p.sections->joint_radius(b);
          }
    }
  } // namespace



  namespace
  {
    /**
     * A stack of the bodies of @p filename (the first pass), its lists
     * sized for the second.
     */
    StackParameters
    sized_stack(
      const std::string                                      &filename,
      const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      check_parameter_file(filename);
      StackParameters p;
      p.bodies = assembly_bodies(filename, overrides);
      if (p.bodies.empty())
        throw InputError("parameter file '" + filename
                         + "' gives no Assembly/Bodies");
      p.rings.resize(p.bodies.size());
      p.section_text.resize(p.bodies.size());
      p.materials.resize(p.bodies.size());
      p.joint_entries.resize(p.n_joints());
      p.joint_cases.resize(p.n_joints());
      return p;
    }
  } // namespace



  void
  print_stack_parameters(std::ostream &out, const std::string &filename)
  {
    StackParameters  p = sized_stack(filename, {});
    ParameterHandler prm;
    p.declare_parameters(prm);
    out << "# coaxfit: the parameters of a stack of the bodies of '" << filename
        << "' with their defaults and documentation\n";
    prm.print_parameters(out, ParameterHandler::Text);
  }



  namespace
  {
    /**
     * The friction coefficient of joint @p k of @p p into @p fit: its own
     * entry @p entries unless 0, else Fit's; `auto` DIN 7190-1's value of
     * the two bodies' materials and Design/Joining.
     * @throws InputError naming the entry and what is allowed.
     */
    void
    resolve_friction(const StackParameters &p,
                     const unsigned int     k,
                     const JointFit        &entries,
                     JointFit              &fit)
    {
      const bool        own = trimmed(entries.friction_text) != "0";
      const std::string text
        = trimmed(own ? entries.friction_text : p.default_fit.friction_text);
      const std::string entry
        = own ? "Fit/" + p.joint_name(k) + "/Friction coefficient" :
                std::string("Fit/Friction coefficient");
      fit.friction_text = text;
      if (text == "auto")
        {
          // A body without a Name is taken as steel: refused where its
          // entries say it is not (a bronze E of 110000 MPa would get
          // steel's 0.14 where DIN 7190 gives 0.17, an aluminium hub 0.14
          // for 0.10: unsafe).
          for (const unsigned int b : {k, k + 1})
            {
              const Material &m = p.materials[b];
              if (m.family == MaterialFamily::unknown
                  && (m.E < 180000. || m.E > 230000.
                      || m.kind == MaterialKind::brittle))
                throw InputError(
                  "parameter " + entry + " = auto: " + p.bodies[b]
                  + " has no Material Name, and auto takes such a body as "
                    "steel, which its E = "
                  + number(m.E, 6) + " MPa"
                  + (m.kind == MaterialKind::brittle ?
                       " and Kind = brittle contradict" :
                       " contradicts")
                  + " (steel: E 180000 to 230000 MPa, "
                    "ductile); name its material (Material/"
                  + p.bodies[b] + "/Name) or give the coefficient (1e-6 to 1)");
            }
          try
            {
              const FrictionValue value
                = din7190_friction(p.materials[k].family,
                                   p.materials[k + 1].family,
                                   p.joining,
                                   p.bodies[k],
                                   p.bodies[k + 1]);
              fit.friction_coefficient = value.coefficient;
              fit.friction_source = value.source + "; " + entry + " = auto";
            }
          catch (const InputError &)
            {
              throw InputError(
                "parameter " + entry
                + " = auto: DIN 7190-1 tabulates the "
                  "coefficient of friction for pairings with steel, not for "
                + to_string(p.materials[k].family) + " (" + p.bodies[k]
                + ") in " + to_string(p.materials[k + 1].family) + " ("
                + p.bodies[k + 1] + ") at the joint " + p.joint_name(k)
                + "; allowed is a number from 1e-6 to 1 (the value of your "
                  "tests)");
            }
          return;
        }
      const double mu = plain_number(text);
      if (!(mu == 0. || (mu >= 1e-6 && mu <= 1.)))
        throw InputError("parameter " + entry + " = '" + text
                         + "' is not allowed: allowed is auto, 0 ("
                         + (own ? "Fit's value" : "not given")
                         + ") or a number from 1e-6 to 1");
      fit.friction_coefficient = mu;
      fit.friction_source      = mu > 0. ? entry : std::string();
    }
  } // namespace



  StackParameters
  read_stack_parameters(
    const std::string                                      &filename,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    StackParameters p = sized_stack(filename, overrides);

    ParameterHandler prm;
    p.declare_parameters(prm);
    try
      {
        parse_parameter_file(prm, filename);
      }
    catch (const InputError &error)
      {
        // A subsection of a body or joint the list does not have.
        const std::string message = error.what();
        const std::string marker  = "no such subsection to be entered: ";
        const std::size_t at      = message.find(marker);
        if (at != std::string::npos)
          {
            std::string path = message.substr(at + marker.size());
            path             = path.substr(0, path.find_first_of(" \n"));
            std::replace(path.begin(), path.end(), '.', '/');
            check_subsection(p,
                             path,
                             true,
                             "in parameter file '" + filename + "'");
          }
        // An entry of Operation the stack does not have.
        const std::string entry_marker = "No entry with name <";
        const std::size_t entry_at     = message.find(entry_marker);
        if (entry_at != std::string::npos
            && message.find("declared in subsection Operation")
                 != std::string::npos)
          {
            const std::size_t begin = entry_at + entry_marker.size();
            check_operation_entry(
              p,
              message.substr(begin, message.find('>', begin) - begin),
              "in parameter file '" + filename + "'");
          }
        // A section of a body the list does not have.
        if (entry_at != std::string::npos
            && message.find("declared in subsection Geometry")
                 != std::string::npos)
          {
            const std::size_t begin = entry_at + entry_marker.size();
            const std::string entry
              = message.substr(begin, message.find('>', begin) - begin);
            std::string list;
            for (const std::string &b : p.bodies)
              list += (list.empty() ? "" : ", ") + b;
            throw InputError("parameter Geometry/" + entry
                             + " in parameter file '" + filename
                             + "': no such entry; allowed are "
                               "`<body> section` of the bodies of "
                               "Assembly/Bodies ("
                             + list + ")");
          }
        throw;
      }
    for (const auto &[path, value] : overrides)
      {
        check_subsection(p, path, false, "--set " + path + "=" + value);
        const std::vector<std::string> parts = split_path(path);
        if (parts.size() == 2 && parts[0] == "Operation")
          check_operation_entry(p, parts[1], "--set " + path + "=" + value);
        if (parts.size() == 2 && parts[0] == "Geometry" && !p.declares(path))
          throw InputError("--set " + path + "=" + value
                           + ": no such entry; allowed are Geometry/<body> "
                             "section of the bodies of Assembly/Bodies");
        set_entry(prm, path, value);
      }

    // The selections, by name.
    prm.enter_subsection("Solver");
    p.method = prm.get("Method") == "monolithic" ? SolverMethod::monolithic :
                                                   SolverMethod::staggered;
    prm.leave_subsection();
    prm.enter_subsection("Coupling");
    p.ordering = prm.get("Ordering") == "jacobi" ? StackOrdering::jacobi :
                                                   StackOrdering::gauss_seidel;
    const std::string accelerator = prm.get("Accelerator");
    p.accelerator = accelerator == "none"   ? StackAccelerator::none :
                    accelerator == "aitken" ? StackAccelerator::aitken :
                                              StackAccelerator::iqn_ils;
    prm.leave_subsection();

    std::set<std::string> missing = entries_not_set(prm);
    for (unsigned int b = 0; b < p.bodies.size(); ++b)
      fill_material(p.materials[b], p.bodies[b], missing);
    // A section from a gmsh file: its path relative to the parameter
    // file, written absolute so that the run's parameters.prm repeats it
    // from anywhere.
    for (unsigned int b = 0; b < p.bodies.size(); ++b)
      if (is_section_file_name(p.section_text[b]))
        {
          p.section_text[b]
            = resolved_section_file(p.section_text[b],
                                    filename,
                                    "Geometry/" + p.bodies[b] + " section");
          prm.enter_subsection("Geometry");
          prm.set(p.bodies[b] + " section", p.section_text[b]);
          prm.leave_subsection();
        }
    read_sections(p, missing);
    const bool default_given = missing.erase("Fit.Diametral interference") == 0;
    if (default_given && !p.default_fit.iso_fit.empty())
      throw InputError("parameter Fit/ISO fit = " + p.default_fit.iso_fit
                       + ": give either Fit/Diametral interference or "
                         "Fit/ISO fit, not both");
    // Design/Mode = select: the joints whose fits are chosen.
    p.joining = joining_method(p.joining_text);
    std::set<std::string> listed;
    const bool            all_listed = p.selected_text == "all";
    if (p.select_mode() && !all_listed
        && Utilities::split_string_list(p.selected_text, ',').empty())
      throw InputError("parameter Design/Selected joints = '" + p.selected_text
                       + "': names no joint (allowed: all, or joints of "
                         "Assembly/Bodies named <inner>-<outer>, separated "
                         "by commas)");
    if (p.select_mode() && !all_listed)
      for (const std::string &name :
           Utilities::split_string_list(p.selected_text, ','))
        {
          bool known = false;
          for (unsigned int k = 0; k < p.n_joints(); ++k)
            known = known || name == p.joint_name(k);
          if (!known || !listed.insert(name).second)
            {
              std::string joints;
              for (unsigned int k = 0; k < p.n_joints(); ++k)
                joints += (k ? ", " : "") + p.joint_name(k);
              throw InputError("parameter Design/Selected joints = "
                               + p.selected_text + ": '" + name + "' "
                               + (known ? "is named twice" : "names no joint")
                               + " (allowed: all, or joints of " + joints
                               + ", separated by commas)");
            }
        }
    p.selected.assign(p.n_joints(), false);
    p.fits.clear();
    for (unsigned int k = 0; k < p.n_joints(); ++k)
      {
        const bool chosen
          = p.select_mode() && (all_listed || listed.count(p.joint_name(k)));
        const std::string path = "Fit/" + p.joint_name(k) + "/";
        const std::string own
          = "Fit." + p.joint_name(k) + ".Diametral interference";
        const bool      own_given = missing.erase(own) == 0;
        const JointFit &entries   = p.joint_entries[k];
        if (own_given && !entries.iso_fit.empty())
          throw InputError("parameter " + path + "ISO fit = " + entries.iso_fit
                           + ": give either " + path
                           + "Diametral interference or " + path
                           + "ISO fit, not both");
        JointFit fit;
        // The joint's own entry wins over Fit's; an ISO fit over Fit's
        // interference.
        if (own_given)
          {
            fit        = entries;
            fit.source = path + "Diametral interference";
          }
        else if (!entries.iso_fit.empty() || !p.default_fit.iso_fit.empty())
          {
            const bool        mine = !entries.iso_fit.empty();
            const std::string name
              = mine ? entries.iso_fit : p.default_fit.iso_fit;
            const IsoFit iso = [&]() {
              try
                {
                  return iso_fit(name, p.rings[k].outer_diameter);
                }
              catch (const InputError &error)
                {
                  // iso_fit() names Fit/ISO fit: say which joint, and
                  // the joint's own entry where it gives the fit.
                  std::string       message = error.what();
                  const std::string generic = "Fit/ISO fit";
                  const std::size_t at      = message.find(generic);
                  if (mine && at != std::string::npos)
                    message.replace(at, generic.size(), path + "ISO fit");
                  throw InputError(message + " (joint " + p.joint_name(k)
                                   + ", D " + number(p.rings[k].outer_diameter)
                                   + " mm)");
                }
            }();
            const double U_min = 1e-3 * iso.min_interference();
            const double U_max = 1e-3 * iso.max_interference();
            fit.diametral_interference
              = p.case_of(k) == "min" ? U_min :
                p.case_of(k) == "max" ? U_max :
                                        0.5 * (U_min + U_max);
            fit.iso_fit              = iso.name;
            fit.largest_interference = U_max;
            fit.source = (mine ? path : std::string("Fit/")) + "ISO fit "
                         + iso.name + ", " + p.case_of(k);
          }
        else if (default_given)
          {
            fit        = p.default_fit;
            fit.source = "Fit/Diametral interference";
          }
        else if (chosen)
          {
            // Until the selection has chosen: 0.001 D.
            fit.diametral_interference = 1e-3 * p.joint_diameter(k);
            fit.source                 = "chosen (Design/Mode = select)";
          }
        else
          missing.insert(own);
        // With `all`, a joint given a clearance keeps it (a running fit).
        p.selected[k] = chosen
                        && !(all_listed && fit.iso_fit.empty()
                             && (own_given || default_given)
                             && fit.diametral_interference <= 0.);
        // A friction coefficient given for the joint wins over Fit's.
        resolve_friction(p, k, entries, fit);
        // So does a roughness; the smoothing loss (DIN 7190-1) is taken
        // off the nominal interference.
        fit.inner_roughness = entries.inner_roughness > 0. ?
                                entries.inner_roughness :
                                p.default_fit.inner_roughness;
        fit.outer_roughness = entries.outer_roughness > 0. ?
                                entries.outer_roughness :
                                p.default_fit.outer_roughness;
        fit.press_in_friction_coefficient
          = entries.press_in_friction_coefficient > 0. ?
              entries.press_in_friction_coefficient :
              p.default_fit.press_in_friction_coefficient;
        fit.nominal_interference = fit.diametral_interference;
        if (fit.iso_fit.empty())
          fit.largest_interference = fit.diametral_interference;
        fit.smoothing_loss
          = 0.8e-3 * (fit.inner_roughness + fit.outer_roughness);
        fit.diametral_interference -= fit.smoothing_loss;
        p.fits.push_back(fit);
      }
    if (!missing.empty())
      {
        throw InputError("parameter file '" + filename
                         + "' does not give the scene entries "
                         + entry_list(missing)
                         + " (geometry, interference and materials have no "
                           "defaults; a Material Name gives E and nu, "
                           "Fit/Diametral interference every joint's "
                           "interference)");
      }

    // A relief shallower than the interference would touch at its
    // bottom, which is not modelled (a joint whose fit is chosen: the
    // selection leaves out the fits that would close it).
    for (unsigned int k = 0; k < p.fits.size() && p.sections; ++k)
      if (const auto relief
          = p.sections->closing_relief(k, p.fits[k].largest_interference);
          relief && !p.selected[k])
        throw InputError(
          "parameter Fit/" + p.joint_name(k) + ": the joint's " + relief->name()
          + " from z = " + number(relief->from, 6) + " to "
          + number(relief->to, 6) + " leaves " + number(relief->clearance, 6)
          + " mm between the sections, no more than the largest radial "
            "interference "
          + number(p.fits[k].largest_interference / 2., 6)
          + " mm, so its bottom would touch, which is not modelled; "
            "allowed: a relief deeper than the radial interference");
    // The case name: the file's base name.
    std::string base = filename.substr(filename.find_last_of('/') + 1);
    if (base.size() > 4 && base.substr(base.size() - 4) == ".prm")
      base.resize(base.size() - 4);
    p.case_name = base.empty() ? "default" : base;
    p.operation.temperature.clear();
    for (const std::string &text : p.operation.temperature_text)
      p.operation.temperature.push_back(
        temperature_entry(text, p.operation.assembly_temperature));
    std::string order;
    p.joining_order = joining_order(p, order);
    p.order_text    = order;
    p.validate();

    // The written parameters must repeat the run: the values a material
    // Name filled in are written as given.
    for (unsigned int b = 0; b < p.bodies.size(); ++b)
      set_material_entries(prm, p.bodies[b], p.materials[b]);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    p.used_prm = "# coaxfit: the parameters of this run (file '" + filename
                 + "' with the --set overrides)\n"
                 + without_entries(text.str(), entries_not_set(prm));
    return p;
  }



  std::string
  StackParameters::required_loads_text() const
  {
    std::string text;
    if (required_torque > 0.)
      text = number(required_torque, 6) + " N m";
    if (required_axial_force > 0.)
      text += (text.empty() ? "" : " and ") + number(required_axial_force, 6)
              + " N axially";
    if (application_factor != 1.)
      text += ", times K_A " + number(application_factor, 6);
    return text;
  }
} // namespace coaxfit
