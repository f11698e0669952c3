#include <deal.II/base/utilities.h>

#include <fosls_contact/input/pattern_description.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace
  {
    /** A bound of a pattern's description in words ("2147483647" is none). */
    bool
    is_limit(const std::string &bound)
    {
      return bound == "2147483647" || bound == "-2147483648" || bound == "MAX_DOUBLE" ||
             bound == "-MAX_DOUBLE" || bound == "4294967295";
    }
  } // namespace


  std::string
  PatternDescription::valid_values(const std::string &description)
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
  PatternDescription::is_file_name(const std::string &pattern)
  {
    return pattern.rfind("[FileName", 0) == 0;
  }
} // namespace FoslsContact
