#ifndef fosls_contact_input_parameter_reader_h
#define fosls_contact_input_parameter_reader_h

#include <deal.II/base/parameter_handler.h>

#include <fosls_contact/base/input_error.h>
#include <fosls_contact/input/declared_parameters.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Reads a scene into a ParameterHandler whose parameters are declared:
   * a `.prm` file (with `include`), a `.json` file (as `--print-parameters`
   * writes it) or an `.xml` file, then `--set` overrides.
   *
   * The `.prm` and `.json` formats are read here and not by
   * ParameterHandler::parse_input(), which resolves `include` relative to
   * the current directory instead of the including file, recurses into an
   * include cycle until the stack overflows, checks no value that contains
   * `{`, and reads its own JSON output back wrongly (it demangles the
   * names, so `C_compl` becomes `C\xC0mpl`). Every value is still set
   * through ParameterHandler::set(), which checks it against its pattern.
   *
   * A file name in a scene (`Geometry/Mesh file`) is relative to the file
   * that names it, like an include; with --set, to the current directory.
   *
   * Every error is thrown as InputError, with where it is
   * (`file:line`, or the --set argument) and one line saying what is
   * wrong: an unknown name comes with the closest declared one ("did you
   * mean"), an invalid value with the valid values, the same for a file
   * and for --set.
   */
  class ParameterReader
  {
  public:
    /** Reads into @p prm, whose parameters are all declared already. */
    explicit ParameterReader(ParameterHandler &prm);

    /**
     * Read the scene file @p file: `.prm`, `.json` or `.xml` by its
     * extension.
     */
    void read_file(const std::string &file);

    /** Apply one `--set "Section/Subsection/Name=value"`. */
    void set(const std::string &assignment);


  private:
    /** Read the `.prm` @p text of @p file (canonical path @p canonical). */
    void read_prm(const std::string &file,
                  const std::string &canonical,
                  const std::string &text);
    void include(const std::string &name, const std::string &from, const std::string &where);
    void read_json(const std::string &file, const std::string &text);

    /**
     * Set the parameter @p name of the section @p sections to @p value,
     * or throw an InputError at @p where. A file name (a parameter with a
     * Patterns::FileName) is made absolute, relative to the directory of
     * the scene file @p from that sets it, or to the current directory if
     * @p from is empty (--set).
     */
    void set_entry(const std::vector<std::string> &sections,
                   const std::string &             name,
                   const std::string &             value,
                   const std::string &             where,
                   const std::string &             from);

    /** An Error at @p where if the section @p path is not declared. */
    void check_section(const std::string &path, const std::string &where) const;

    ParameterHandler &       prm;
    const DeclaredParameters declared;
    /** The sections entered at the current line of a `.prm` file. */
    std::vector<std::string> current;
    /** The canonical paths of the files being read (to find include cycles). */
    std::vector<std::string> reading;
    unsigned int              n_includes = 0;
  };
} // namespace FoslsContact

#endif
