#ifndef fosls_contact_output_output_directory_h
#define fosls_contact_output_output_directory_h

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * The output directory of one run (parameter Output/Directory), whose
   * files appear all at once when the run ends, or not at all, and which
   * never loses or hides a file of the user's, wherever a run is killed.
   *
   * The constructor, called before the set-up, checks that the directory
   * can be made and written and locks it against a second run into it
   * (flock on `.<name>.lock` beside it: the second run fails at once). A
   * run into a directory inside the output directory of a running run, or
   * into a directory that holds the output directory of a running run, is
   * refused too: the publication of the outer one moves the inner one.
   * Then it repairs what killed runs left (DirectorySwap::recover) and
   * makes a staging directory `.<name>.staging-<pid>` beside it, with the
   * record that identifies it (DirectorySwap); an unusable directory is an
   * error before any work is done. The run writes every file into the
   * staging directory (each process its own pieces) and fsyncs it;
   * publish() then puts the staging directory in the place of the old
   * directory in one step (DirectorySwap::replace).
   *
   * Files the run did not write are kept: a file `.fosls-contact-files` in
   * the directory lists the files the run wrote; the next run removes
   * those of them it does not write again, and carries every other file
   * and directory over into the new directory. A file with the name of an
   * output file is replaced. As the directory is replaced, it must be one
   * the program wrote (with that list), or new, or hold nothing but output
   * files: the swap never takes someone's other directory (/tmp, a home
   * directory, the current directory). That is checked again when the
   * results are published: if the path has become a file or such a
   * directory during the run, it is left alone and the results are kept
   * in `<name>.results-<pid>` beside it.
   *
   * Every error is thrown on every process with the same one-line text,
   * naming Output/Directory; the destructor removes the staging
   * directory, the lock file and the parent directories the run made, if
   * the files were not published.
   */
  class OutputDirectory
  {
  public:
    /** Check, lock and prepare @p directory (collective on @p comm). */
    OutputDirectory(const std::string &directory, const MPI_Comm comm);
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &operator=(const OutputDirectory &) = delete;

    /**
     * Write the file @p name of this process into the staging directory
     * with @p writer, and fsync it. Throws (on this process) if the file
     * cannot be written completely.
     */
    void write(const std::string &name, const std::function<void(std::ostream &)> &writer);

    /**
     * Publish the files every process wrote (collective). @p error is this
     * process's failure to write its files ("" if none): if any process
     * failed, nothing is published and every process throws the first
     * failure.
     */
    void publish(const std::string &error);

    /** The name of the list of the files a run wrote, in the directory. */
    static const std::string manifest_name;

  private:
    /** The work of the constructor on the first process. */
    void prepare();
    /**
     * The absolute path of the directory (a symbolic link followed), which
     * must not contain the current directory.
     */
    void resolve();
    /** Make the missing parent directories (noted in #made). */
    void make_parents();
    /** Lock the directory: flock on #lock_path. */
    void lock();
    /** Whether the locked file is (still) the file named #lock_path. */
    bool held_is_named() const;
    /**
     * Refuse a directory inside the output directory of a running run, or
     * one that holds the output directory of a running run (their lock
     * files are held).
     */
    void check_nesting() const;
    /** Check that the existing directory may be written and replaced. */
    void check_existing() const;
    /** The work of publish() on the first process (DirectorySwap). */
    void publish_here(const std::set<std::string> &names);
    /**
     * Remove the staging directory (unless published), the lock file and
     * the parent directories made (unless published).
     */
    void release() noexcept;
    /** "parameter 'Output/Directory' = '...'" for messages. */
    std::string parameter() const;

    const std::string     given;
    const MPI_Comm        comm;
    const bool            first;
    std::filesystem::path directory, staging, lock_path;
    int                   lock_fd = -1;
    /** The record of the staging directory, locked while the run lives. */
    int record_fd = -1;
    /** Parent directories this run made (removed if nothing is published). */
    std::vector<std::filesystem::path> made;
    /** The files this process wrote. */
    std::vector<std::string> written;
    bool                     published = false;
  };
} // namespace FoslsContact

#endif
