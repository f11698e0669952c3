#ifndef fosls_contact_base_json_h
#define fosls_contact_base_json_h

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * A number for summary.json: 12 significant digits, and null for NaN or
   * Inf, which JSON has no literal for.
   */
  inline std::string
  json_number(const double value)
  {
    if (!std::isfinite(value))
      return "null";
    std::ostringstream s;
    s << std::setprecision(12) << value;
    return s.str();
  }

  /** A JSON array of @p items, each already JSON text: "[a, b, c]". */
  inline std::string
  json_array(const std::vector<std::string> &items)
  {
    std::string text = "[";
    for (unsigned int i = 0; i < items.size(); ++i)
      text += (i ? ", " : "") + items[i];
    return text + "]";
  }
} // namespace FoslsContact

#endif
