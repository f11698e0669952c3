#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/value_parsing.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace FoslsContact
{
  namespace Parameters
  {
    using namespace dealii;

    double
    parse_extended_double(const std::string &text, const std::string &name)
    {
      const std::string t = Utilities::trim(text);
      if (t == "inf" || t == "infinity" || t == "+inf")
        return std::numeric_limits<double>::infinity();
      try
        {
          std::size_t  pos   = 0;
          const double value = std::stod(t, &pos);
          if (pos == t.size() && std::isfinite(value))
            return value;
        }
      catch (...)
        {}
      AssertThrow(false,
                  ExcMessage("parameter '" + name + "' has value '" + t +
                             "', which is neither a number nor 'inf'"));
      return 0;
    }

    void
    check_resolvable(const double size, const double distance, const std::string &what)
    {
      AssertThrow(std::isfinite(size) && std::isfinite(distance),
                  ExcMessage(what + " is too large for double precision"));
      std::ostringstream text;
      text << what << " (" << size << ") is too small against the distance of the body "
           << "from the origin (" << distance << ") to be resolved in double precision; "
           << "put the origin near the body";
      AssertThrow(size > 1e-6 * distance, ExcMessage(text.str()));
    }

    std::vector<double>
    parse_double_list(const std::string &text)
    {
      std::vector<double> values;
      for (const auto &entry : Utilities::split_string_list(text, ','))
        values.push_back(Utilities::string_to_double(entry));
      return values;
    }
  } // namespace Parameters
} // namespace FoslsContact
