#ifndef fosls_contact_base_input_error_h
#define fosls_contact_base_input_error_h

#include <stdexcept>
#include <string>

namespace FoslsContact
{
  /**
   * An error in what the user gave the program (command line, scene file,
   * --set): where it is (`file:line`, `--set '...'`, `command line`) and
   * one line saying what is wrong. main() prints it as
   * `fosls-contact: error in <where>: <what>`.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &where, const std::string &what)
      : std::runtime_error(what)
      , location(where)
    {}

    const std::string &where() const { return location; }

  private:
    std::string location;
  };
} // namespace FoslsContact

#endif
