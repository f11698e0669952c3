#ifndef fosls_contact_base_json_h
#define fosls_contact_base_json_h

#include <deal.II/base/tensor.h>

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

  /** A vector (a force, a position) as a JSON array of its components. */
  template <int dim>
  std::string
  json_vector(const dealii::Tensor<1, dim> &v)
  {
    std::vector<std::string> items;
    for (unsigned int d = 0; d < dim; ++d)
      items.push_back(json_number(v[d]));
    return json_array(items);
  }
} // namespace FoslsContact

#endif
