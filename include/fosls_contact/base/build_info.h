#ifndef fosls_contact_base_build_info_h
#define fosls_contact_base_build_info_h

#include <string>

namespace FoslsContact
{
  /**
   * What the executable was built from: `--version` prints it and
   * summary.json records it, so that a result can be traced to the source
   * that computed it. The git revision is taken at build time
   * (cmake/git_revision.cmake), "unknown" outside a git checkout.
   */
  class BuildInfo
  {
  public:
    /** The program's version (CMake's project version). */
    static std::string version();
    /** `git describe --always --dirty` of the source tree, or "unknown". */
    static std::string git_revision();
    /** The deal.II version the program was compiled against. */
    static std::string deal_ii_version();
  };
} // namespace FoslsContact

#endif
