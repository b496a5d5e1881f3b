#include <coaxfit/base/input_error.h>
#include <coaxfit/base/interruption.h>
#include <coaxfit/io/result_directory.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace coaxfit
{
  namespace fs = std::filesystem;

  namespace
  {
    /**
     * Whether @p name is a file of an assembly of several bodies, named
     * after its bodies and joints (`sleeve.vtu`, `interface_Shaft-Sleeve.vtp`,
     * `contact_pressure_Shaft-Sleeve.csv`): an earlier result of another
     * body list, which a run may replace.
     */
    bool
    assembly_result_file(const std::string &name)
    {
      static const std::regex files(
        "[a-z][a-z0-9_]{0,39}\\.vtu|"
        "(interface|contact_pressure)_[A-Za-z][A-Za-z0-9_]{0,39}-"
        "[A-Za-z][A-Za-z0-9_]{0,39}\\.(vtp|csv)");
      return std::regex_match(name, files);
    }

    /**
     * Whether @p name is a mixed corner's directory of a stack's Fit/Case =
     * all (min, mean or max joined by '-': `min-max`): an earlier study's.
     */
    bool
    corner_directory(const std::string &name)
    {
      static const std::regex corner("(min|mean|max)(-(min|mean|max))+");
      return std::regex_match(name, corner);
    }

    const std::string partial_marker = ".partial-";

    [[noreturn]] void
    refuse(const std::string &target, const std::string &why)
    {
      const std::string shown
        = target.size() > 80 ? target.substr(0, 77) + "..." : target;
      throw InputError("parameter Output/Directory = " + shown + ": " + why);
    }

    /** Names of the path short enough for the staging name beside them. */
    void
    check_path_length(const std::string &target)
    {
      if (target.size() > PATH_MAX - 64)
        refuse(target,
               "the path is " + std::to_string(target.size())
                 + " characters long; allowed at most "
                 + std::to_string(PATH_MAX - 64));
      for (const auto &part : fs::path(target))
        if (part.native().size() > NAME_MAX - 32)
          refuse(target,
                 "a name in the path is " + std::to_string(part.native().size())
                   + " characters long; allowed at most "
                   + std::to_string(NAME_MAX - 32));
    }

    /** fsync a file or directory; throws if the data cannot be flushed. */
    void
    sync_path(const std::string &path, const bool directory)
    {
      const int fd
        = ::open(path.c_str(),
                 O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
      if (fd < 0)
        throw std::runtime_error("cannot open '" + path
                                 + "' to flush it: " + std::strerror(errno));
      const int result = ::fsync(fd);
      const int error  = errno;
      ::close(fd);
      // Some file systems cannot sync directories (EINVAL): nothing to do.
      if (result != 0 && !(directory && error == EINVAL))
        throw std::runtime_error("writing '" + path
                                 + "' to disk failed: " + std::strerror(error));
    }

    /**
     * The nearest directory above @p target that holds a coaxfit result
     * (parameters.prm beside summary.json, fit_cases.csv or sweep.csv;
     * staging directories aside), or "".
     */
    std::string
    enclosing_result(const fs::path &target)
    {
      std::error_code error;
      for (fs::path above = target.parent_path();
           !above.empty() && above != above.root_path();
           above = above.parent_path())
        {
          if (above.filename().string().find(partial_marker)
              != std::string::npos)
            return "";
          if (!fs::exists(above / "parameters.prm", error))
            continue;
          for (const char *file :
               {"summary.json", "fit_cases.csv", "sweep.csv"})
            if (fs::exists(above / file, error))
              return above.string();
        }
      return "";
    }
  } // namespace



  std::string
  normalized_directory(const std::string &path)
  {
    if (path.empty())
      return path;
    std::string normal = fs::path(path).lexically_normal().string();
    while (normal.size() > 1 && normal.back() == '/')
      normal.pop_back();
    const std::string last = fs::path(normal).filename().string();
    if (last == "." || last == "..")
      {
        normal = fs::absolute(normal).lexically_normal().string();
        while (normal.size() > 1 && normal.back() == '/')
          normal.pop_back();
      }
    return normal;
  }



  std::string
  staging_directory_of(const std::string &target, const int pid)
  {
    std::error_code error;
    const fs::path  whole
      = fs::weakly_canonical(fs::absolute(normalized_directory(target)), error);
    return (whole.parent_path()
            / ("." + whole.filename().string() + partial_marker
               + std::to_string(pid)))
      .string();
  }



  ResultDirectory::ResultDirectory(const std::string           &given_name,
                                   const std::set<std::string> &result_files,
                                   const std::set<std::string> &top_level)
  {
    // As given in the messages; a trailing slash would name no directory.
    const std::string &target_name = given_name;
    const std::string  normal      = normalized_directory(given_name);
    if (target_name.empty())
      refuse(target_name, "empty");
    check_path_length(target_name);
    std::error_code error;
    // Work on the directory itself if the target is a symbolic link.
    target = fs::weakly_canonical(fs::absolute(normal), error).string();
    if (error)
      refuse(target_name, "cannot resolve the path (" + error.message() + ")");
    check_path_length(target);
    const fs::path    parent    = fs::path(target).parent_path();
    const std::string enclosing = enclosing_result(target);
    if (!enclosing.empty())
      refuse(target_name,
             "lies inside " + enclosing
               + ", an earlier coaxfit result, which a run into it replaces "
                 "as a whole; give a directory outside it");

    const fs::file_status status = fs::status(target, error);
    if (status.type() == fs::file_type::directory)
      {
        // Subdirectories (the cases of Fit/Case = all, the values of a
        // study) are replaced too: everything in them must be coaxfit's as
        // well (a stack's files in a study's value directories).
        for (auto entry = fs::recursive_directory_iterator(target, error);
             entry != fs::recursive_directory_iterator();
             entry.increment(error))
          if (entry.depth() == 0 && entry->is_directory()
              && corner_directory(entry->path().filename().string()))
            continue;
          else if (!top_level.empty() && entry.depth() == 0 ?
                     top_level.count(entry->path().filename().string()) == 0 :
                     (result_files.count(entry->path().filename().string()) == 0
                      && !(entry.depth() <= 1 && entry->is_regular_file()
                           && assembly_result_file(
                             entry->path().filename().string())))
                       || (entry->is_directory()
                           && entry.depth() > (top_level.empty() ? 0 : 1)))
            refuse(target_name,
                   "contains '" + fs::relative(entry->path(), target).string()
                     + "', which coaxfit does not write; the results replace "
                       "the whole directory, so give an empty directory, a "
                       "new one or an earlier coaxfit result directory");
        if (error)
          refuse(target_name,
                 "cannot read the directory (" + error.message() + ")");
      }
    else if (status.type() != fs::file_type::not_found)
      refuse(target_name,
             error ? "cannot be examined (" + error.message() + ")" :
                     "exists and is not a directory");
    error.clear();

    fs::create_directories(parent, error);
    if (error || !fs::is_directory(parent))
      refuse(target_name,
             "cannot create the directory ("
               + (error ? error.message() : std::string("not a directory"))
               + ")");
    remove_stale_staging();

    std::lock_guard<std::mutex> lock(Interruption::mutex());
    staging = staging_directory_of(target, ::getpid());
    fs::remove_all(staging, error);
    Interruption::set_staging(staging, target_name);
    if (::mkdir(staging.c_str(), 0777) != 0)
      {
        const std::string reason = std::strerror(errno);
        Interruption::set_staging("", "");
        staging.clear();
        refuse(target_name, "cannot write beside it (" + reason + ")");
      }
  }



  ResultDirectory::~ResultDirectory()
  {
    if (staging.empty())
      return;
    std::lock_guard<std::mutex> lock(Interruption::mutex());
    std::error_code             error;
    fs::remove_all(staging, error);
    Interruption::set_staging("", "");
  }



  const std::string &
  ResultDirectory::staging_path() const
  {
    return staging;
  }



  void
  ResultDirectory::remove_stale_staging() const
  {
    const fs::path    parent = fs::path(target).parent_path();
    const std::string prefix
      = "." + fs::path(target).filename().string() + partial_marker;
    std::error_code error;
    for (const auto &entry : fs::directory_iterator(parent, error))
      {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0)
          continue;
        const std::string pid = name.substr(prefix.size());
        if (pid.empty()
            || pid.find_first_not_of("0123456789") != std::string::npos
            || pid.size() > 9)
          continue;
        if (::kill(std::stoi(pid), 0) != 0 && errno == ESRCH)
          fs::remove_all(entry.path(), error);
      }
  }



  void
  ResultDirectory::commit(std::ostream &console)
  {
    if (committed || staging.empty())
      throw std::logic_error("ResultDirectory::commit() called twice");
    console.flush();
    if (!console)
      throw ResourceError("cannot write to standard output; the results "
                          "were not put in place");
    for (const auto &entry : fs::recursive_directory_iterator(staging))
      sync_path(entry.path().string(), entry.is_directory());
    sync_path(staging, true);

    std::lock_guard<std::mutex> lock(Interruption::mutex());
    swap_into_place();
    committed = true;
    Interruption::set_committed();
    sync_path(fs::path(target).parent_path().string(), true);
    // The staging path now holds the previous result (or nothing).
    std::error_code error;
    fs::remove_all(staging, error);
    staging.clear();
    Interruption::set_staging("", "");
  }



  void
  ResultDirectory::swap_into_place() const
  {
    // Another run may create or replace the target meanwhile: retry.
    for (unsigned int attempt = 0; attempt < 100; ++attempt)
      {
        if (::renameat2(AT_FDCWD,
                        staging.c_str(),
                        AT_FDCWD,
                        target.c_str(),
                        RENAME_EXCHANGE)
            == 0)
          return;
        if (errno == ENOENT)
          {
            // No previous result: a plain rename, which fails if one
            // appeared meanwhile (then exchange with it).
            if (::renameat2(AT_FDCWD,
                            staging.c_str(),
                            AT_FDCWD,
                            target.c_str(),
                            RENAME_NOREPLACE)
                == 0)
              return;
            if (errno == EEXIST)
              continue;
          }
        if (errno == EINVAL)
          {
            // The file system cannot exchange: move the previous result
            // aside first (a short window in which the target is missing).
            const std::string aside = staging + ".previous";
            if (::rename(target.c_str(), aside.c_str()) == 0
                && ::rename(staging.c_str(), target.c_str()) == 0
                && ::rename(aside.c_str(), staging.c_str()) == 0)
              return;
          }
        throw std::runtime_error("cannot move the results into '" + target
                                 + "': " + std::strerror(errno));
      }
    throw std::runtime_error("cannot move the results into '" + target
                             + "': it keeps changing");
  }
} // namespace coaxfit
