#include <fosls_contact/input/declared_parameters.h>

#include <boost/algorithm/string/case_conv.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <sstream>
#include <vector>

namespace FoslsContact
{
  namespace
  {
    using ptree = boost::property_tree::ptree;

    /** Every entry and section of a tree printed by ParameterHandler (XML). */
    void
    collect(const ptree &                       tree,
            const std::string &                 prefix,
            std::map<std::string, std::string> &entries,
            std::set<std::string> &             sections)
    {
      for (const auto &[key, node] : tree)
        {
          const std::string path = prefix + DeclaredParameters::demangle(key);
          if (node.get_child_optional("value"))
            entries[path] = node.get<std::string>("pattern_description", "");
          else
            {
              sections.insert(path);
              collect(node, path + "/", entries, sections);
            }
        }
    }

    /** Edit distance with transpositions (optimal string alignment), case-blind. */
    std::size_t
    distance(const std::string &a_text, const std::string &b_text)
    {
      const std::string a = boost::algorithm::to_lower_copy(a_text),
                        b = boost::algorithm::to_lower_copy(b_text);
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
  } // namespace


  DeclaredParameters::DeclaredParameters(const ParameterHandler &prm)
  {
    std::stringstream xml;
    prm.print_parameters(xml, ParameterHandler::XML);
    ptree tree;
    boost::property_tree::read_xml(xml, tree);
    collect(tree.get_child("ParameterHandler"), "", patterns, sections);
  }


  std::string
  DeclaredParameters::demangle(const std::string &name)
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


  std::string
  DeclaredParameters::suggestion(const std::string &path, const bool section) const
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
      for (const auto &[e, pattern] : patterns)
        consider(e);
    if (best.empty())
      {
        const auto candidates = [&]() {
          std::vector<std::string> all;
          if (section)
            all.assign(sections.begin(), sections.end());
          else
            for (const auto &[e, pattern] : patterns)
              all.push_back(e);
          return all;
        }();
        for (const auto &c : candidates)
          if (boost::algorithm::to_lower_copy(last(c)) == boost::algorithm::to_lower_copy(name))
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
