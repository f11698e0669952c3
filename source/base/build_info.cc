#include <deal.II/base/config.h>

#include <fosls_contact/base/build_info.h>

#include <fosls_contact_git_revision.h>

namespace FoslsContact
{
  std::string
  BuildInfo::version()
  {
    return FOSLS_VERSION;
  }


  std::string
  BuildInfo::git_revision()
  {
    return FOSLS_GIT_REVISION;
  }


  std::string
  BuildInfo::deal_ii_version()
  {
    return DEAL_II_PACKAGE_VERSION;
  }
} // namespace FoslsContact
