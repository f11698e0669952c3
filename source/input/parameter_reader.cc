#include <deal.II/base/utilities.h>

#include <fosls_contact/input/parameter_reader.h>
#include <fosls_contact/output/error_line.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    using ptree = boost::property_tree::ptree;

    /** Undo ParameterHandler's mangling of names (`_xx`: the byte 0xxx). */
    std::string
    demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() + 0 && std::isxdigit(name[i + 1]) &&
            std::isxdigit(name[i + 2]))
          {
            out += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    /** Every entry and section of a tree printed by ParameterHandler (XML). */
    void
    collect(const ptree &                       tree,
            const std::string &                 prefix,
            std::map<std::string, std::string> &entries,
            std::set<std::string> &             sections)
    {
      for (const auto &[key, node] : tree)
        {
          const std::string path = prefix + demangle(key);
          if (node.get_child_optional("value"))
            entries[path] = node.get<std::string>("pattern_description", "");
          else
            {
              sections.insert(path);
              collect(node, path + "/", entries, sections);
            }
        }
    }

    std::string
    lower(std::string text)
    {
      for (auto &c : text)
        c = std::tolower(static_cast<unsigned char>(c));
      return text;
    }

    /** Edit distance with transpositions (optimal string alignment), case-blind. */
    std::size_t
    distance(const std::string &a_text, const std::string &b_text)
    {
      const std::string a = lower(a_text), b = lower(b_text);
      std::vector<std::vector<std::size_t>> d(a.size() + 1,
                                              std::vector<std::size_t>(b.size() + 1));
      for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
      for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
      for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j)
          {
            d[i][j] = std::min({d[i - 1][j] + 1,
                                d[i][j - 1] + 1,
                                d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
              d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
          }
      return d[a.size()][b.size()];
    }

    std::string
    parent(const std::string &path)
    {
      const auto slash = path.rfind('/');
      return slash == std::string::npos ? "" : path.substr(0, slash);
    }

    std::string
    last(const std::string &path)
    {
      const auto slash = path.rfind('/');
      return slash == std::string::npos ? path : path.substr(slash + 1);
    }

    std::string
    join(const std::vector<std::string> &sections, const std::string &name)
    {
      std::string path;
      for (const auto &s : sections)
        path += s + "/";
      return path + name;
    }

    /** A bound of a pattern's description in words ("2147483647" is none). */
    bool
    is_limit(const std::string &bound)
    {
      return bound == "2147483647" || bound == "-2147483648" || bound == "MAX_DOUBLE" ||
             bound == "-MAX_DOUBLE" || bound == "4294967295";
    }

    /**
     * What a pattern accepts, in words, from its description
     * ("[Selection V|W|F ]" -> "valid values: 'V', 'W', 'F'").
     */
    std::string
    valid_values(const std::string &description)
    {
      const auto range = [](const std::string &text, const std::string &kind) {
        const auto dots = text.find("...");
        if (dots == std::string::npos)
          return kind;
        const std::string low  = text.substr(text.rfind(' ', dots) + 1,
                                            dots - text.rfind(' ', dots) - 1);
        const std::string high = text.substr(dots + 3, text.find(' ', dots) - dots - 3);
        if (is_limit(low) && is_limit(high))
          return kind;
        if (is_limit(high))
          return kind + " >= " + low;
        if (is_limit(low))
          return kind + " <= " + high;
        return kind + " from " + low + " to " + high;
      };
      if (description.rfind("[Selection ", 0) == 0)
        {
          std::string text = description.substr(11, description.size() - 11 - 2);
          std::string list;
          for (const auto &choice : Utilities::split_string_list(text, '|'))
            list += (list.empty() ? "'" : ", '") + choice + "'";
          return "valid values: " + list;
        }
      if (description == "[Bool]")
        return "valid values: 'true', 'false'";
      if (description.rfind("[Integer", 0) == 0)
        return "expected " + range(description, "an integer");
      if (description.rfind("[Double", 0) == 0)
        return "expected " + range(description, "a number");
      if (description.rfind("[List of <", 0) == 0)
        {
          const auto close = description.find(">]");
          const auto open  = description.find(" of length ", close);
          std::string what = "a comma separated list of entries, each " +
                             valid_values(description.substr(10, close - 8));
          if (open != std::string::npos)
            {
              const std::string length = description.substr(open + 11);
              const auto        dots   = length.find("...");
              const std::string low    = length.substr(0, dots);
              const std::string high   = length.substr(dots + 3, length.find(' ') - dots - 3);
              what += is_limit(high) ? (low == "0" ? "" : ", at least " + low + " of them") :
                                       ", " + low + " to " + high + " of them";
            }
          return what;
        }
      return "expected " + description;
    }

    bool
    starts_with(const std::string &text, const std::string &lower_case)
    {
      std::string upper = lower_case;
      for (auto &c : upper)
        c = std::toupper(static_cast<unsigned char>(c));
      return text.rfind(lower_case, 0) == 0 || text.rfind(upper, 0) == 0;
    }

    /** Whether the pattern described by @p pattern is a Patterns::FileName. */
    bool
    is_file_name(const std::string &pattern)
    {
      return pattern.rfind("[FileName", 0) == 0;
    }

    /** The extension of @p file in lower case, without the dot. */
    std::string
    extension(const std::string &file)
    {
      const std::string e = std::filesystem::path(file).extension().string();
      return lower(e.empty() ? e : e.substr(1));
    }

    /** The most includes one scene may make (a DAG of includes can grow exponentially). */
    constexpr unsigned int max_includes = 1000;
  } // namespace


  ParameterReader::ParameterReader(ParameterHandler &prm)
    : prm(prm)
  {
    std::stringstream xml;
    prm.print_parameters(xml, ParameterHandler::XML);
    ptree tree;
    boost::property_tree::read_xml(xml, tree);
    collect(tree.get_child("ParameterHandler"), "", entries, sections);
  }


  std::string
  ParameterReader::read_text(const std::string &file,
                             const std::string &what,
                             const std::string &where)
  {
    const std::string name = what + " '" + ErrorLine::quote(file) + "'";
    struct stat       status;
    if (::stat(file.c_str(), &status) != 0)
      {
        const int   error = errno;
        struct stat link;
        if (error == ENOENT && ::lstat(file.c_str(), &link) == 0)
          throw InputError(where, name + " is a symbolic link to a file that does not exist");
        throw InputError(where,
                    name + (error == ENOENT  ? " does not exist" :
                            error == ENOTDIR ? " does not exist: a component of its path "
                                               "is not a directory" :
                            error == EACCES  ? " cannot be reached: permission denied on a "
                                               "directory of its path" :
                                               std::string(" cannot be read: ") +
                                                 std::strerror(error)));
      }
    const auto kind = [](const mode_t mode) {
      return S_ISDIR(mode)  ? "a directory" :
             S_ISFIFO(mode) ? "a FIFO (named pipe), not a regular file" :
             S_ISSOCK(mode) ? "a socket, not a regular file" :
             S_ISCHR(mode)  ? "a character device, not a regular file" :
             S_ISBLK(mode)  ? "a block device, not a regular file" :
                              "not a regular file";
    };
    if (!S_ISREG(status.st_mode))
      throw InputError(where, name + " is " + kind(status.st_mode));
    // (O_NONBLOCK: if the file was replaced by a FIFO since, open() does
    // not wait for a writer; fstat() below finds it)
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
      {
        const int error = errno;
        throw InputError(where,
                    name + " cannot be read: " +
                      (error == EACCES ? std::string("permission denied") :
                                         std::string(std::strerror(error))));
      }
    std::string text;
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode))
      {
        ::close(fd);
        throw InputError(where, name + " is " + kind(status.st_mode));
      }
    char buffer[65536];
    for (;;)
      {
        const ssize_t n = ::read(fd, buffer, sizeof(buffer));
        if (n > 0)
          text.append(buffer, n);
        else if (n == 0)
          break;
        else if (errno != EINTR)
          {
            const int error = errno;
            ::close(fd);
            throw InputError(where, name + " cannot be read: " + std::strerror(error));
          }
      }
    ::close(fd);
    return text;
  }


  void
  ParameterReader::read_file(const std::string &file)
  {
    const std::string text = read_text(file, "parameter file", "command line");
    const std::string type = extension(file);
    if (type == "json")
      read_json(file, text);
    else if (type == "xml")
      {
        std::istringstream in(text);
        try
          {
            prm.parse_input_from_xml(in);
          }
        catch (const std::exception &e)
          {
            throw InputError(file, ErrorLine::text(e));
          }
        // file names relative to the scene file, as from a .prm file
        for (const auto &[full, pattern] : entries)
          if (is_file_name(pattern))
            {
              auto path = Utilities::split_string_list(full, '/');
              const std::string name = path.back();
              path.pop_back();
              for (const auto &s : path)
                prm.enter_subsection(s);
              const std::string value = prm.get(name);
              for (std::size_t i = 0; i < path.size(); ++i)
                prm.leave_subsection();
              set_entry(path, name, value, file, file);
            }
      }
    else if (type == "prm")
      {
        n_includes = 0;
        read_prm(file, std::filesystem::weakly_canonical(file).string(), text);
      }
    else
      throw InputError("command line",
                       "parameter file '" + ErrorLine::quote(file) +
                         "' has neither of the extensions .prm, .json, .xml");
  }


  void
  ParameterReader::read_prm(const std::string &file,
                            const std::string &canonical,
                            const std::string &text)
  {
    reading.push_back(canonical);
    const std::size_t depth = current.size();
    std::vector<unsigned int> opened; // the line of every 'subsection' still open
    std::istringstream        in(text);
    std::string               physical, logical;
    unsigned int              line_number = 0, first_line = 0;
    bool                      continued   = false;
    auto scan = [&](std::string line, const unsigned int n) {
      const std::string where    = file + ":" + std::to_string(n);
      const std::string original = Utilities::trim(line);
      // as ParameterHandler: '#' starts a comment, tabs are spaces
      if (line.find('#') != std::string::npos)
        line.erase(line.find('#'));
      std::replace(line.begin(), line.end(), '\t', ' ');
      line = Utilities::trim(line);
      if (line.empty())
        return;
      if (starts_with(line, "subsection "))
        {
          const std::string name = Utilities::trim(line.substr(11));
          check_section(join(current, name), where);
          current.push_back(name);
          opened.push_back(n);
        }
      else if (starts_with(line, "end"))
        {
          if (!Utilities::trim(line.substr(3)).empty())
            throw InputError(where, "cannot read the line '" + ErrorLine::quote(original) +
                                 "': text after 'end'");
          if (current.size() == depth)
            throw InputError(where, "'end' without a 'subsection' in this file");
          current.pop_back();
          opened.pop_back();
        }
      else if (starts_with(line, "set "))
        {
          const auto equal = line.find('=');
          if (equal == std::string::npos)
            throw InputError(where, "cannot read the line '" + ErrorLine::quote(original) +
                                 "': expected 'set Name = value'");
          set_entry(current,
                    Utilities::trim(line.substr(4, equal - 4)),
                    Utilities::trim(line.substr(equal + 1)),
                    where,
                    file);
        }
      else if (starts_with(line, "include "))
        include(Utilities::trim(line.substr(8)), file, where);
      else
        throw InputError(where,
                    "cannot read the line '" + ErrorLine::quote(original) +
                      "': expected 'set', 'subsection', 'end' or 'include'");
    };
    // as ParameterHandler: a line ending in '\' continues on the next one
    while (std::getline(in, physical))
      {
        ++line_number;
        if (!continued)
          first_line = line_number;
        physical = Utilities::trim(physical);
        if (!physical.empty() && physical.back() == '\\')
          {
            logical += physical.substr(0, physical.size() - 1);
            continued = true;
            continue;
          }
        logical += physical;
        continued = false;
        scan(logical, first_line);
        logical.clear();
      }
    if (continued)
      scan(logical, first_line);
    if (current.size() != depth)
      throw InputError(file + ":" + std::to_string(opened.back()),
                  "'subsection " + ErrorLine::quote(current.back()) +
                    "' has no 'end' in this file");
    reading.pop_back();
  }


  void
  ParameterReader::include(const std::string &name,
                           const std::string &from,
                           const std::string &where)
  {
    namespace fs = std::filesystem;
    if (name.empty())
      throw InputError(where, "'include' names no file");
    // relative to the including file, not to the current directory
    fs::path path(name);
    if (path.is_relative())
      path = fs::path(from).parent_path() / path;
    std::error_code   error;
    const std::string canonical = fs::weakly_canonical(path, error).string();
    const auto        cycle     = std::find(reading.begin(), reading.end(), canonical);
    if (!error && cycle != reading.end())
      throw InputError(where,
                  "'include " + ErrorLine::quote(name) + "' makes a cycle: " +
                    (cycle + 1 == reading.end() ? "the file includes itself" :
                                                  "'" + ErrorLine::quote(*cycle) +
                                                    "' includes itself through it"));
    if (++n_includes > max_includes)
      throw InputError(where,
                  "more than " + std::to_string(max_includes) +
                    " includes in one scene (does a file include another several times?)");
    const std::string text = read_text(path.string(), "included file", where);
    read_prm(path.string(), error ? path.string() : canonical, text);
  }


  void
  ParameterReader::read_json(const std::string &file, const std::string &text)
  {
    std::istringstream in(text);
    ptree              tree;
    try
      {
        boost::property_tree::read_json(in, tree);
      }
    catch (const boost::property_tree::json_parser_error &e)
      {
        throw InputError(file + ":" + std::to_string(e.line()),
                    "not valid JSON: " + ErrorLine::quote(e.message()));
      }
    // a parameter is a string, or an object with a "value" (as
    // --print-parameters writes it); anything else is a section. The names
    // are taken as they are, or demangled as deal.II writes them.
    std::function<void(const ptree &, std::vector<std::string> &)> walk =
      [&](const ptree &node, std::vector<std::string> &path) {
        for (const auto &[key, child] : node)
          {
            std::string name = key;
            const bool  parameter =
              child.empty() || static_cast<bool>(child.get_child_optional("value"));
            const bool known = parameter ? entries.count(join(path, name)) > 0 :
                                           sections.count(join(path, name)) > 0;
            if (!known && demangle(name) != name)
              name = demangle(name);
            const std::string where = file + " (" + ErrorLine::quote(join(path, name)) + ")";
            if (parameter)
              {
                if (!child.empty() && !child.get_child("value").empty())
                  throw InputError(where, "the \"value\" of a parameter must be a string");
                set_entry(path,
                          name,
                          child.empty() ? child.data() : child.get<std::string>("value"),
                          where,
                          file);
              }
            else
              {
                check_section(join(path, name), where);
                path.push_back(name);
                walk(child, path);
                path.pop_back();
              }
          }
      };
    std::vector<std::string> path;
    walk(tree, path);
  }


  void
  ParameterReader::set(const std::string &assignment)
  {
    const std::string where = "--set '" + ErrorLine::quote(assignment) + "'";
    const auto        equal = assignment.find('=');
    if (equal == std::string::npos)
      throw InputError(where, "expected --set \"Section/Name=value\"");
    auto path = Utilities::split_string_list(assignment.substr(0, equal), '/');
    if (path.size() < 2)
      throw InputError(where, "the parameter needs its section: --set \"Section/Name=value\"");
    const std::string name = path.back();
    path.pop_back();
    for (std::size_t i = 1; i <= path.size(); ++i)
      check_section(join(std::vector<std::string>(path.begin(), path.begin() + i - 1),
                         path[i - 1]),
                    where);
    set_entry(path, name, Utilities::trim(assignment.substr(equal + 1)), where, "");
  }


  void
  ParameterReader::check_section(const std::string &path, const std::string &where) const
  {
    if (sections.count(path) == 0)
      throw InputError(where,
                  "there is no section '" + ErrorLine::quote(path) + "'" +
                    suggestion(path, true));
  }


  void
  ParameterReader::set_entry(const std::vector<std::string> &path,
                             const std::string &             name,
                             const std::string &             text,
                             const std::string &             where,
                             const std::string &             from)
  {
    const std::string full = join(path, name);
    const auto        entry = entries.find(full);
    if (entry == entries.end())
      throw InputError(where,
                  "there is no parameter '" + ErrorLine::quote(full) + "'" +
                    suggestion(full, false));
    // A file name (Geometry/Mesh file) is relative to the file that sets
    // it, like an include, and is kept absolute: used_parameters.prm and
    // --print-parameters then name the same file from any directory.
    std::string value = text;
    if (is_file_name(entry->second) && !value.empty())
      {
        namespace fs = std::filesystem;
        fs::path path(value);
        if (path.is_relative() && !from.empty())
          path = fs::path(from).parent_path() / path;
        std::error_code error;
        const fs::path  absolute = fs::absolute(path, error);
        if (!error)
          value = absolute.lexically_normal().string();
      }
    // (a control character would be written into used_parameters.prm,
    // which could then not be read back)
    for (const char c : value)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        throw InputError(where,
                    "the value '" + ErrorLine::quote(value) + "' of parameter '" + full +
                      "' has a control character");
    for (const auto &s : path)
      prm.enter_subsection(s);
    bool valid = true;
    try
      {
        prm.set(name, value);
      }
    catch (const ParameterHandler::ExcValueDoesNotMatchPattern &)
      {
        valid = false;
      }
    for (std::size_t i = 0; i < path.size(); ++i)
      prm.leave_subsection();
    if (!valid)
      throw InputError(where,
                  "invalid value '" + ErrorLine::quote(value) + "' for parameter '" + full +
                    "'; " + valid_values(entry->second));
  }


  std::string
  ParameterReader::suggestion(const std::string &path, const bool section) const
  {
    // the closest name in the same section; else a parameter (section)
    // of that name elsewhere, or the closest path
    const std::string name  = last(path);
    const std::size_t limit = std::max<std::size_t>(1, std::min<std::size_t>(3, name.size() / 3));
    std::string       best;
    std::size_t       best_distance = limit + 1;
    auto              consider      = [&](const std::string &candidate) {
      if (parent(candidate) == parent(path))
        {
          const std::size_t d = distance(last(candidate), name);
          if (d < best_distance)
            best = candidate, best_distance = d;
        }
    };
    if (section)
      for (const auto &s : sections)
        consider(s);
    else
      for (const auto &[e, pattern] : entries)
        consider(e);
    if (best.empty())
      {
        const auto candidates = [&]() {
          std::vector<std::string> all;
          if (section)
            all.assign(sections.begin(), sections.end());
          else
            for (const auto &[e, pattern] : entries)
              all.push_back(e);
          return all;
        }();
        for (const auto &c : candidates)
          if (lower(last(c)) == lower(name))
            return "; did you mean '" + c + "'?";
        for (const auto &c : candidates)
          {
            const std::size_t d = distance(c, path);
            if (d < best_distance)
              best = c, best_distance = d;
          }
      }
    return best.empty() ? "" : "; did you mean '" + best + "'?";
  }
} // namespace FoslsContact
