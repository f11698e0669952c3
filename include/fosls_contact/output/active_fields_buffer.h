#ifndef fosls_contact_output_active_fields_buffer_h
#define fosls_contact_output_active_fields_buffer_h

#include <ostream>
#include <streambuf>
#include <string>

namespace FoslsContact
{
  /**
   * A VTU piece on its way into its file with VTK's active fields named:
   * the characters written to this buffer go on to a sink, the first
   * <PointData Scalars="scalars"> (deal.II's header, which names a field
   * that does not exist) replaced by <PointData @p active>. VTK's filters
   * (warp by vector, glyphs) use the active vector.
   *
   * The piece is not held as text: deal.II writes the tag after the points
   * and cells, and the text of a large mesh is as large as the solver's
   * largest structures (doc/performance.md, "Figures behind the code"). What is written
   * is searched where it arrives; only the last characters, which may begin
   * the tag, are held back, and a write is copied only where the tag may
   * straddle it and the one before (tests/unit/active_fields_buffer splits
   * a text at every position).
   */
  class ActiveFieldsBuffer : public std::streambuf
  {
  public:
    /** The tag that is replaced. */
    static const std::string tag;

    ActiveFieldsBuffer(std::ostream &sink, const std::string &active);

    /** Pass on what is held back: at the end of the piece. */
    void finish();

  protected:
    std::streamsize xsputn(const char *s, std::streamsize n) override;
    int_type        overflow(int_type c) override;

  private:
    /** Write @p n characters at @p s and the replacement after them. */
    void replace_after(const char *s, std::size_t n);

    std::ostream &    sink;
    const std::string replacement;
    /** Up to tag.size() - 1 characters, not yet passed on. */
    std::string held;
    bool        replaced = false;
  };
} // namespace FoslsContact

#endif
