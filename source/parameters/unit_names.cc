#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/unit_names.h>

#include <map>

namespace FoslsContact
{
  namespace Parameters
  {
    using namespace dealii;

    void
    UnitNames::parse(const std::string &text, const std::string &name)
    {
      *this                    = UnitNames();
      const std::string value  = Utilities::trim(text);
      const std::string prefix = "parameter '" + name + "' = '" + value + "' ";
      if (value.empty())
        return;
      std::map<std::string, std::string *> slots = {{"length", &length},
                                                    {"force", &force},
                                                    {"stress", &stress}};
      for (const std::string &entry : Utilities::split_string_list(value, ','))
        {
          const auto equals = entry.find('=');
          AssertThrow(equals != std::string::npos,
                      ExcMessage(prefix + "has entry '" + entry +
                                 "'; expected 'name=unit' with name length, force or "
                                 "stress, e.g. 'length=mm, force=N, stress=MPa'"));
          const std::string key  = Utilities::trim(entry.substr(0, equals));
          const std::string unit = Utilities::trim(entry.substr(equals + 1));
          const auto        slot = slots.find(key);
          AssertThrow(slot != slots.end(),
                      ExcMessage(prefix + "names '" + key +
                                 "'; valid names: length, force, stress"));
          AssertThrow(slot->second->empty(),
                      ExcMessage(prefix + "names '" + key + "' twice"));
          AssertThrow(!unit.empty(), ExcMessage(prefix + "gives '" + key + "' no unit"));
          for (const char c : unit)
            AssertThrow(c > ' ' && c < 127 && c != ',' && c != ';' && c != '=' && c != '"' &&
                          c != '\\',
                        ExcMessage(prefix + "gives '" + key + "' the unit '" + unit +
                                   "'; a unit is one word of printable ASCII characters "
                                   "other than , ; = \" and \\"));
          *slot->second = unit;
        }
      for (const auto &[key, slot] : slots)
        AssertThrow(!slot->empty(),
                    ExcMessage(prefix + "does not name '" + key +
                               "'; name all of length, force and stress (e.g. 'length=mm, "
                               "force=N, stress=MPa'), or none for the scene's units"));
    }


    std::string
    UnitNames::reported_force(const unsigned int dim) const
    {
      if (!named())
        return "";
      return dim == 2 ? force + "/" + length : force;
    }


    std::string
    UnitNames::contact_measure(const unsigned int dim) const
    {
      if (!named())
        return "";
      return dim == 2 ? length : length + "^2";
    }


    std::string
    UnitNames::functional(const unsigned int dim) const
    {
      if (!named())
        return "";
      return length + "^" + std::to_string(dim);
    }
  } // namespace Parameters
} // namespace FoslsContact
