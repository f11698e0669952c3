// Checks ActiveFieldsBuffer, which names VTK's active fields in a VTU piece
// on its way into its file: what comes out must be the text with the first
// <PointData Scalars="scalars"> replaced, however the writes cut the text.
// A text with the tag in its middle (and a second tag after it, which
// stays) is written in pieces of every length from 1 to past the tag's,
// and cut once at every position (one write up to it, one after); also a
// text without the tag and one whose end is the tag's beginning (held back
// and passed on by finish()), and a failed sink.
#include <fosls_contact/output/active_fields_buffer.h>

#include "tests.h"

#include <sstream>

using namespace FoslsContactTests;

namespace
{
  const std::string active = "Scalars=\"von_mises\" Vectors=\"u\"";

  /** What the buffer passes on when @p text is written in @p cuts. */
  std::string
  through_buffer(const std::string &text, const std::vector<std::size_t> &cuts)
  {
    std::ostringstream sink;
    ActiveFieldsBuffer buffer(sink, active);
    std::ostream       stream(&buffer);
    std::size_t        begin = 0;
    for (const std::size_t end : cuts)
      {
        stream.write(text.data() + begin, end - begin);
        begin = end;
      }
    stream.write(text.data() + begin, text.size() - begin);
    buffer.finish();
    return sink.str();
  }

  /** The text with its first tag replaced. */
  std::string
  expected(std::string text)
  {
    const auto at = text.find(ActiveFieldsBuffer::tag);
    if (at != std::string::npos)
      text.replace(at, ActiveFieldsBuffer::tag.size(), "<PointData " + active + ">");
    return text;
  }

  void
  test(const std::string &label, const std::string &text)
  {
    bool by_length = true, by_position = true;
    for (std::size_t length = 1; length <= 2 * ActiveFieldsBuffer::tag.size() + 3; ++length)
      {
        std::vector<std::size_t> cuts;
        for (std::size_t at = length; at < text.size(); at += length)
          cuts.push_back(at);
        by_length = by_length && through_buffer(text, cuts) == expected(text);
      }
    for (std::size_t at = 0; at <= text.size(); ++at)
      by_position = by_position && through_buffer(text, {at}) == expected(text);
    check(by_length, label + ": written in pieces of every length, the text with its tag replaced");
    check(by_position, label + ": cut at every position, the text with its tag replaced");
  }
} // namespace

int
main()
{
  const std::string &tag = ActiveFieldsBuffer::tag;
  test("tag in the middle", "<Points>x<</Points><P" + tag + "<DataArray/>" + tag + "</Piece>");
  test("tag at the start", tag + "<DataArray/>");
  test("no tag", "<PointData Scalars=\"u\"><PointData Scalars=\"scalar\"></Piece>");
  test("the end begins the tag", "<Points/>" + tag.substr(0, tag.size() - 3));

  // a failed sink fails the stream the writer writes to
  std::ostringstream sink;
  sink.setstate(std::ios::badbit);
  ActiveFieldsBuffer buffer(sink, active);
  std::ostream       stream(&buffer);
  stream << "<Points/>" << tag << "<DataArray/>";
  check(!stream, "a failed sink: the writer's stream fails");
  return exit_code();
}
