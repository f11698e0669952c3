#ifndef fosls_contact_input_text_file_h
#define fosls_contact_input_text_file_h

#include <string>

namespace FoslsContact
{
  /**
   * Reading an input file (a scene, an included file, a mesh) whole, with
   * an InputError that names the real cause when it cannot be read. The
   * standard streams report every such cause as one failed open(), and a
   * FIFO given as a scene would block the run; the checks here are the
   * same for every file the program reads.
   */
  struct TextFile
  {
    /**
     * The content of the regular file @p file, or an InputError (at @p where)
     * that names the real cause: does not exist, permission denied, a
     * directory, a FIFO or device, ... @p what says what the file is
     * ("parameter file", "included file").
     */
    static std::string read(const std::string &file,
                            const std::string &what,
                            const std::string &where);
  };
} // namespace FoslsContact

#endif
