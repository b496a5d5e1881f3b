#include <deal.II/base/exceptions.h>

#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/material_library.h>
#include <coaxfit/parameters/parameter_file.h>
#include <coaxfit/parameters/parameter_reading.h>

#include <cctype>
#include <string>

namespace coaxfit
{
  std::set<std::string>
  entries_not_set(const ParameterHandler &prm)
  {
    std::set<std::string> entries;
    for (const std::string &mangled : prm.get_entries_wrongly_not_set())
      {
        std::string entry;
        for (std::size_t i = 0; i < mangled.size(); ++i)
          if (mangled[i] == '_' && i + 2 < mangled.size()
              && std::isxdigit(static_cast<unsigned char>(mangled[i + 1]))
              && std::isxdigit(static_cast<unsigned char>(mangled[i + 2])))
            {
              entry += static_cast<char>(
                std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
              i += 2;
            }
          else
            entry += mangled[i];
        entries.insert(entry);
      }
    return entries;
  }



  std::string
  entry_list(const std::set<std::string> &entries)
  {
    std::string list;
    for (std::string entry : entries)
      {
        // The prm syntax joins the path with '/'.
        for (char &c : entry)
          if (c == '.')
            c = '/';
        list += (list.empty() ? "" : ", ") + entry;
      }
    return list;
  }



  bool
  declares_entry(ParameterHandler &prm, const std::string &path)
  {
    const std::vector<std::string> parts = split_path(path);
    if (parts.size() < 2)
      return false;
    try
      {
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        prm.set(parts.back(), "");
        return true;
      }
    catch (const ParameterHandler::ExcEntryUndeclared &)
      {
        return false;
      }
    catch (const std::exception &)
      {
        return true;
      }
  }



  std::vector<std::string>
  split_path(const std::string &path)
  {
    std::vector<std::string> parts;
    std::size_t              start = 0;
    while (true)
      {
        const std::size_t slash = path.find('/', start);
        parts.push_back(path.substr(start, slash - start));
        if (slash == std::string::npos)
          return parts;
        start = slash + 1;
      }
  }



  void
  set_entry(ParameterHandler  &prm,
            const std::string &path,
            const std::string &value)
  {
    const std::vector<std::string> parts = split_path(path);
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
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &exc)
      {
        throw InputError("--set " + path + "=" + value + ": "
                         + one_line_message(exc));
      }
  }



  void
  parse_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    try
      {
        prm.parse_input(filename, "", false, false);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &exc)
      {
        // deal.II's messages about a line already name the file; they
        // name an entry without its subsection, which is added.
        std::string       message = one_line_message(exc);
        const std::size_t at      = message.find("Line <");
        const std::size_t of      = message.find("> of file <");
        const std::size_t named   = message.find("for the entry named ");
        const std::string current = "in the current subsection";
        const std::size_t where   = message.find(current);
        if (at != std::string::npos && of != std::string::npos
            && (named != std::string::npos || where != std::string::npos))
          {
            const std::size_t file_end = message.find('>', of + 11);
            const std::string file
              = message.substr(of + 11, file_end - of - 11);
            const std::string section = subsection_at_line(
              file, std::stoi(message.substr(at + 6, of - at - 6)));
            if (!section.empty() && named != std::string::npos)
              message = message.substr(0, named + 20) + section + "/"
                        + message.substr(named + 20);
            else if (where != std::string::npos)
              message.replace(where,
                              current.size(),
                              section.empty() ? "at the top level" :
                                                "in subsection " + section);
          }
        throw InputError(message.find("of file <") != std::string::npos ?
                           message :
                           "in parameter file '" + filename + "': " + message);
      }
  }



  void
  set_material_entries(ParameterHandler  &prm,
                       const std::string &path,
                       const Material    &material)
  {
    if (material.name == "custom")
      return;
    prm.enter_subsection("Material");
    prm.enter_subsection(path);
    prm.set("E", material.E);
    prm.set("nu", material.nu);
    prm.set("Yield strength", material.yield_strength);
    prm.set("Density", material.density);
    prm.set("Thermal expansion", material.thermal_expansion);
    prm.set("Tensile strength", material.tensile_strength);
    prm.set("Cooling expansion", material.cooling_expansion);
    prm.set("Temperature limit", material.temperature_limit);
    prm.leave_subsection();
    prm.leave_subsection();
  }



  void
  fill_material(Material              &material,
                const std::string     &path,
                std::set<std::string> &missing)
  {
    const MaterialData *data = find_material(material.name);
    // deal.II names the entries with '.' between the sections.
    const std::string prefix = "Material." + path + ".";
    material.E_given         = missing.count(prefix + "E") == 0;
    if (material.temperature_limit > 0.)
      material.temperature_limit_reason
        = "Material/" + path + "/Temperature limit";
    if (material.kind_text == "brittle")
      material.kind = MaterialKind::brittle;
    else if (material.kind_text == "polymer")
      material.kind = MaterialKind::polymer;
    else if (material.kind_text == "auto" && data != nullptr)
      material.kind = data->kind;
    else
      material.kind = MaterialKind::metal;
    material.plastic = material.plasticity_text == "von Mises";
    if (data == nullptr)
      return;
    material.family = data->family;
    if (missing.erase(prefix + "E") > 0)
      material.E = data->E;
    if (missing.erase(prefix + "nu") > 0)
      material.nu = data->nu;
    if (material.yield_strength == 0.)
      material.yield_strength = data->yield_strength;
    if (material.tensile_strength == 0.)
      material.tensile_strength = data->tensile_strength;
    if (material.density == 0.)
      material.density = data->density;
    if (material.thermal_expansion == 0.)
      material.thermal_expansion = data->thermal_expansion;
    if (material.cooling_expansion == 0.)
      material.cooling_expansion = data->cooling_expansion;
    // parameters.prm writes the library's limit back as given.
    if (material.temperature_limit == 0.
        || material.temperature_limit == data->temperature_limit)
      {
        material.temperature_limit        = data->temperature_limit;
        material.temperature_limit_reason = data->limit_reason;
      }
  }
} // namespace coaxfit
