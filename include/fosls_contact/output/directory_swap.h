#ifndef fosls_contact_output_directory_swap_h
#define fosls_contact_output_directory_swap_h

#include <filesystem>
#include <set>
#include <string>

namespace FoslsContact
{
  /**
   * The step in which a run's output appears: the staging directory takes
   * the place of the output directory in one rename (renameat2 with
   * RENAME_EXCHANGE, or two renames where the filesystem has no exchange),
   * and the files of the old directory that no run wrote are carried over
   * (files as hard links before the swap, directories moved after it).
   * OutputDirectory decides whether the swap may happen; this class does
   * it, so that the order of the system calls, which is what makes it
   * safe, is in one place.
   */
  struct DirectorySwap
  {
    /**
     * Put @p staging (holding the files @p names and their list) in the
     * place of @p directory, which may not exist; @p old_listed are the
     * files the old directory's list names (written by the last run), which
     * are not carried over. Throws a message beginning with @p parameter;
     * nothing is changed in @p directory if it throws.
     */
    static void replace(const std::filesystem::path &directory,
                        const std::filesystem::path &staging,
                        const std::set<std::string> &names,
                        const std::set<std::string> &old_listed,
                        const std::string &          parameter);
  };
} // namespace FoslsContact

#endif
