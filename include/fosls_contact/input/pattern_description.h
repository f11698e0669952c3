#ifndef fosls_contact_input_pattern_description_h
#define fosls_contact_input_pattern_description_h

#include <string>

namespace FoslsContact
{
  /**
   * What a deal.II Patterns object's description says, read for the input
   * errors: the valid values in words for "invalid value" messages, and
   * whether a parameter is a file name (which the reader makes absolute).
   * ParameterReader knows a parameter only by this description (from
   * DeclaredParameters), so reading it is a job of its own.
   */
  struct PatternDescription
  {
    /**
     * What a pattern accepts, in words, from its description
     * ("[Selection V|W|F ]" -> "valid values: 'V', 'W', 'F'").
     */
    static std::string valid_values(const std::string &description);

    /** Whether the pattern described by @p pattern is a Patterns::FileName. */
    static bool is_file_name(const std::string &pattern);
  };
} // namespace FoslsContact

#endif
