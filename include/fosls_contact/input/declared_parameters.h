#ifndef fosls_contact_input_declared_parameters_h
#define fosls_contact_input_declared_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <set>
#include <string>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The sections and parameters that a ParameterHandler declares, with the
   * description of each parameter's pattern: what ParameterReader checks a
   * scene's names against before it sets a value, and where the "did you
   * mean" for a misspelt name comes from. ParameterHandler itself answers
   * an unknown name with an exception that names neither the line nor a
   * close declared name.
   */
  class DeclaredParameters
  {
  public:
    /** The names declared in @p prm (read from its XML description). */
    explicit DeclaredParameters(const ParameterHandler &prm);

    /** Whether the section @p path ("Section/Subsection") is declared. */
    bool is_section(const std::string &path) const { return sections.count(path) > 0; }
    /** The description of the pattern of parameter @p path, or nullptr if undeclared. */
    const std::string *pattern(const std::string &path) const
    {
      const auto entry = patterns.find(path);
      return entry == patterns.end() ? nullptr : &entry->second;
    }
    /** Every declared parameter ("Section/Name") with its pattern's description. */
    const std::map<std::string, std::string> &parameters() const { return patterns; }

    /** "; did you mean 'X'?" for the declared name closest to @p path, or "". */
    std::string suggestion(const std::string &path, const bool section) const;

    /** Undo ParameterHandler's mangling of names (`_xx`: the byte 0xxx). */
    static std::string demangle(const std::string &name);

  private:
    std::map<std::string, std::string> patterns;
    std::set<std::string>              sections;
  };
} // namespace FoslsContact

#endif
