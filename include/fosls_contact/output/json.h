#ifndef fosls_contact_output_json_h
#define fosls_contact_output_json_h

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

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
} // namespace FoslsContact

#endif
