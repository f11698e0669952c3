#ifndef fosls_contact_output_directory_swap_h
#define fosls_contact_output_directory_swap_h

#include <filesystem>
#include <set>
#include <string>

namespace FoslsContact
{
  /**
   * The system calls by which a run's output appears in its directory, and
   * by which the next run repairs what a killed run left: their order is
   * what makes them safe, so it is in one place. OutputDirectory decides
   * whether a run may write into a directory; this class moves the
   * directories.
   *
   * A staging directory `.<name>.staging-<pid>` holds the *record*
   * `.fosls-contact-staging`, made first and locked (flock) by its run as
   * long as the run lives. The record names the staging directory's own
   * identity (device and inode); before the first rename of the
   * publication a line is added with the identity of the directory it
   * replaces. The record travels with the staging directory: found in
   * Output/Directory it says that the publication did not finish, and
   * which `.<name>.staging-*` directory is the old directory whose entries
   * (the user's files and subdirectories) still have to be carried over.
   * Identities, not names, tell the old directory from the new, so that a
   * kill between any two system calls leaves a state that recover() can
   * finish or undo:
   *
   *  - before the rename that puts the new directory in place (the
   *    exchange, the second of the two renames, or the first rename into a
   *    new path): undone; the old directory stays (the aside directory of
   *    the two renames is renamed back), the staging directory is removed;
   *  - after it: finished; the user's entries move from the old directory
   *    into the new one, the old run's files are removed;
   *  - while undoing a rename that took something else than the recorded
   *    directory away (the path changed just before it; replace() undoes
   *    that and keeps the results in `<name>.results-<pid>`): that is put
   *    back under the directory's name, found by the name the rename gave
   *    it (the record names the run's process id).
   *
   * Everything in a staging directory whose record describes it was
   * written by its run (or is a hard link to a file of the directory), so
   * it is removed without looking at names; the files of an old directory
   * are told apart by its list `.fosls-contact-files` (or, for a directory
   * without one, by the names of the output files), so that the user's
   * entries are never removed. Nothing is removed while a run still holds
   * the lock on the record.
   */
  struct DirectorySwap
  {
    /** The name of the record in a staging directory. */
    static const std::string record_name;

    /**
     * Whether @p name is the name of a file the program writes (or of its
     * list): used for directories that have no list.
     */
    static bool is_output_name(const std::string &name);

    /**
     * The first entry of the existing directory @p directory that rules
     * out replacing it ("" if none): a directory with a list
     * `.fosls-contact-files` was written by the program and may be
     * replaced; any other must hold nothing but output files.
     */
    static std::string foreign_entry(const std::filesystem::path &directory);

    /**
     * The first subdirectory of @p directory under the name of an output
     * file ("" if none): the run writes a file of that name, and the user's
     * directory could neither stay in the new directory beside it nor be
     * removed, so the run is refused before the computation (and its
     * results are kept aside if one appears during the run).
     */
    static std::string directory_under_output_name(const std::filesystem::path &directory);

    /**
     * Whether a run of the program holds the lock file (or record) @p path:
     * another open file has a flock on it.
     */
    static bool locked(const std::filesystem::path &path);

    /**
     * Make the record in the new, empty @p staging and lock it; returns its
     * file descriptor, held open (and locked) until the run ends. Throws a
     * message beginning with @p parameter.
     */
    static int make_record(const std::filesystem::path &staging, const std::string &parameter);

    /**
     * Remove the unpublished @p staging of this run, if it still is the
     * directory its record describes (else what is at that name now is
     * not the run's, and stays).
     */
    static void discard(const std::filesystem::path &staging);

    /**
     * Finish or undo what killed runs left beside and in @p directory (its
     * lock held): see the class description. Throws a message beginning
     * with @p parameter if a live run still uses a staging directory of
     * @p directory (its lock file was removed).
     */
    static void recover(const std::filesystem::path &directory, const std::string &parameter);

    /**
     * Put @p staging (holding the files @p names, their list and the
     * record, open as @p record_fd) in the place of @p directory, which may
     * not exist, and carry the user's entries of the old directory over
     * (files as hard links before the swap, the rest moved after it).
     * Throws a message beginning with @p parameter if it cannot; then
     * @p directory is as it was. If the path @p directory has become
     * something the run may not replace (a file, a directory the program
     * did not write), the results are kept in `<name>.results-<pid>`
     * beside it, which the message names.
     */
    static void replace(const std::filesystem::path &directory,
                        const std::filesystem::path &staging,
                        const int                    record_fd,
                        const std::set<std::string> &names,
                        const std::string &          parameter);
  };
} // namespace FoslsContact

#endif
