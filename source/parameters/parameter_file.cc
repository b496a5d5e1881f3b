#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/parameter_file.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace coaxfit
{
  namespace
  {
    constexpr unsigned int   max_include_depth = 16;
    constexpr unsigned int   max_nesting       = 32;
    constexpr std::uintmax_t max_file_size     = 16u << 20; // 16 MiB

    /**
     * A parameter file must be a regular file (not a directory, device or
     * pipe, which deal.II would skip or read for ever) of at most 16 MiB.
     * @p what says how it was named (the command line or an include line).
     */
    void
    check_readable(const std::string &filename, const std::string &what)
    {
      namespace fs = std::filesystem;
      std::error_code       error;
      const fs::file_status status = fs::status(filename, error);
      if (status.type() == fs::file_type::not_found)
        return; // deal.II names a file it cannot open, with the line
      if (status.type() == fs::file_type::directory)
        throw InputError(what + " '" + filename
                         + "' is a directory, not a parameter file");
      if (status.type() != fs::file_type::regular)
        throw InputError(what + " '" + filename
                         + "' is not a regular file (a device, pipe or "
                           "socket); give a parameter file");
      const std::uintmax_t size = fs::file_size(filename, error);
      if (!error && size > max_file_size)
        throw InputError(what + " '" + filename + "' has "
                         + std::to_string(size)
                         + " bytes; a parameter file may have at most "
                         + std::to_string(max_file_size) + " (16 MiB)");
    }

    bool
    ends_with(const std::string &text, const std::string &suffix)
    {
      return text.size() >= suffix.size()
             && text.compare(text.size() - suffix.size(), suffix.size(), suffix)
                  == 0;
    }

    /** The file named by an `include` line of a .prm file, or "". */
    std::string
    included_file(std::string line)
    {
      line             = line.substr(0, line.find('#'));
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      line = line.substr(first);
      if (line.rfind("include ", 0) != 0 && line.rfind("INCLUDE ", 0) != 0)
        return "";
      line.erase(0, 8);
      const auto begin = line.find_first_not_of(" \t\r");
      const auto end   = line.find_last_not_of(" \t\r");
      return begin == std::string::npos ? "" :
                                          line.substr(begin, end - begin + 1);
    }

    void
    check_includes(const std::string        &filename,
                   std::vector<std::string> &chain,
                   std::vector<std::string> &files)
    {
      check_readable(filename,
                     chain.empty() ? "parameter file" :
                                     "included file (line 'include " + filename
                                       + "' of " + chain.back() + ")");
      std::error_code   error;
      const std::string id
        = std::filesystem::weakly_canonical(filename, error).string();
      for (const std::string &outer : chain)
        if (outer == id)
          throw InputError(
            "parameter file '" + filename + "' includes itself (through "
            + std::to_string(chain.size()) + " include level(s))");
      if (chain.size() >= max_include_depth)
        throw InputError("parameter file '" + filename + "': more than "
                         + std::to_string(max_include_depth)
                         + " levels of include statements");
      std::ifstream in(filename);
      if (!in)
        return; // deal.II reports a file it cannot open, with the line
      chain.push_back(id);
      files.push_back(id);
      std::string line;
      while (std::getline(in, line))
        {
          const std::string included = included_file(line);
          if (!included.empty())
            check_includes(included, chain, files);
        }
      chain.pop_back();
    }

    /** Nesting depth of brackets (JSON) or elements (XML), strings aside. */
    void
    check_nesting(const std::string &filename, const bool json)
    {
      std::ifstream      in(filename);
      std::ostringstream text;
      text << in.rdbuf();
      const std::string content = text.str();
      int               depth = 0, deepest = 0;
      bool              in_string = false;
      for (std::size_t i = 0; i < content.size(); ++i)
        {
          const char c = content[i];
          if (json)
            {
              if (in_string)
                {
                  if (c == '\\')
                    ++i;
                  else if (c == '"')
                    in_string = false;
                }
              else if (c == '"')
                in_string = true;
              else if (c == '{' || c == '[')
                ++depth;
              else if (c == '}' || c == ']')
                --depth;
            }
          else if (c == '<' && i + 1 < content.size())
            {
              const char next = content[i + 1];
              if (next == '/')
                --depth;
              else if (next != '?' && next != '!')
                ++depth;
            }
          else if (!json && c == '>' && i > 0 && content[i - 1] == '/')
            --depth;
          deepest = std::max(deepest, depth);
        }
      if (deepest > static_cast<int>(max_nesting))
        throw InputError(
          "parameter file '" + filename + "' nests " + std::to_string(deepest)
          + " levels deep; allowed at most " + std::to_string(max_nesting));
    }
  } // namespace



  std::vector<std::string>
  check_parameter_file(const std::string &filename)
  {
    std::vector<std::string> files;
    if (ends_with(filename, ".json") || ends_with(filename, ".xml"))
      {
        check_readable(filename, "parameter file");
        check_nesting(filename, ends_with(filename, ".json"));
        std::error_code error;
        files.push_back(
          std::filesystem::weakly_canonical(filename, error).string());
      }
    else
      {
        std::vector<std::string> chain;
        check_includes(filename, chain, files);
      }
    return files;
  }



  std::string
  subsection_at_line(const std::string &filename, const unsigned int line)
  {
    std::ifstream            in(filename);
    std::vector<std::string> path;
    std::string              text;
    for (unsigned int n = 1; n < line && std::getline(in, text); ++n)
      {
        // The first word of the line, comments removed.
        text                    = text.substr(0, text.find('#'));
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string::npos)
          continue;
        const std::size_t end  = text.find_first_of(" \t", first);
        const std::string word = text.substr(first, end - first);
        if (word == "subsection" && end != std::string::npos)
          {
            const std::size_t name = text.find_first_not_of(" \t", end);
            const std::size_t last = text.find_last_not_of(" \t\r");
            if (name != std::string::npos)
              path.push_back(text.substr(name, last + 1 - name));
          }
        else if (word == "end" && !path.empty())
          path.pop_back();
      }
    std::string joined;
    for (const std::string &p : path)
      joined += (joined.empty() ? "" : "/") + p;
    return joined;
  }
} // namespace coaxfit
