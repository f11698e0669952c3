#include <deal.II/base/utilities.h>

#include <fosls_contact/base/error_line.h>
#include <fosls_contact/input/parameter_reader.h>
#include <fosls_contact/input/pattern_description.h>
#include <fosls_contact/input/text_file.h>

#include <boost/algorithm/string/case_conv.hpp>
#include <boost/property_tree/json_parser.hpp>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    using ptree = boost::property_tree::ptree;

    std::string
    join(const std::vector<std::string> &sections, const std::string &name)
    {
      std::string path;
      for (const auto &s : sections)
        path += s + "/";
      return path + name;
    }

    bool
    starts_with(const std::string &text, const std::string &lower_case)
    {
      std::string upper = lower_case;
      for (auto &c : upper)
        c = std::toupper(static_cast<unsigned char>(c));
      return text.rfind(lower_case, 0) == 0 || text.rfind(upper, 0) == 0;
    }

    /** The extension of @p file in lower case, without the dot. */
    std::string
    extension(const std::string &file)
    {
      const std::string e = std::filesystem::path(file).extension().string();
      return boost::algorithm::to_lower_copy(e.empty() ? e : e.substr(1));
    }

    /** The most includes one scene may make (a DAG of includes can grow exponentially). */
    constexpr unsigned int max_includes = 1000;
  } // namespace


  ParameterReader::ParameterReader(ParameterHandler &prm)
    : prm(prm)
    , declared(prm)
  {}


  void
  ParameterReader::read_file(const std::string &file)
  {
    const std::string text = TextFile::read(file, "parameter file", "command line");
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
        for (const auto &[full, pattern] : declared.parameters())
          if (PatternDescription::is_file_name(pattern))
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
    const std::string text = TextFile::read(path.string(), "included file", where);
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
            const bool known = parameter ? declared.pattern(join(path, name)) != nullptr :
                                           declared.is_section(join(path, name));
            if (!known && DeclaredParameters::demangle(name) != name)
              name = DeclaredParameters::demangle(name);
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
    if (!declared.is_section(path))
      throw InputError(where,
                  "there is no section '" + ErrorLine::quote(path) + "'" +
                    declared.suggestion(path, true));
  }


  void
  ParameterReader::set_entry(const std::vector<std::string> &path,
                             const std::string &             name,
                             const std::string &             text,
                             const std::string &             where,
                             const std::string &             from)
  {
    const std::string full = join(path, name);
    const std::string *pattern = declared.pattern(full);
    if (!pattern)
      throw InputError(where,
                  "there is no parameter '" + ErrorLine::quote(full) + "'" +
                    declared.suggestion(full, false));
    // A file name (Geometry/Mesh file) is relative to the file that sets
    // it, like an include, and is kept absolute: used_parameters.prm and
    // --print-parameters then name the same file from any directory.
    std::string value = text;
    if (PatternDescription::is_file_name(*pattern) && !value.empty())
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
                    "'; " + PatternDescription::valid_values(*pattern));
  }


} // namespace FoslsContact
