#include <fosls_contact/output/active_fields_buffer.h>

#include <algorithm>
#include <string_view>

namespace FoslsContact
{
  const std::string ActiveFieldsBuffer::tag = "<PointData Scalars=\"scalars\">";


  ActiveFieldsBuffer::ActiveFieldsBuffer(std::ostream &sink, const std::string &active)
    : sink(sink)
    , replacement("<PointData " + active + ">")
  {}


  void
  ActiveFieldsBuffer::finish()
  {
    sink.write(held.data(), held.size());
    held.clear();
  }


  void
  ActiveFieldsBuffer::replace_after(const char *s, const std::size_t n)
  {
    sink.write(s, n);
    sink << replacement;
    held.clear();
    replaced = true;
  }


  std::streamsize
  ActiveFieldsBuffer::xsputn(const char *s, const std::streamsize n)
  {
    const std::size_t size = n;
    if (replaced)
      sink.write(s, size);
    else
      {
        // the held characters and the first tag.size() - 1 of s: a tag that
        // begins among the held ones ends there
        const std::size_t head  = std::min(size, tag.size() - 1);
        const std::string joint = held + std::string(s, head);
        const auto        at    = joint.find(tag);
        if (at != std::string::npos)
          {
            const std::size_t used = at + tag.size() - held.size(); // of s
            replace_after(joint.data(), at);
            sink.write(s + used, size - used);
          }
        else if (size < tag.size() - 1)
          {
            // s is short: hold the joint's end
            held = joint;
            if (held.size() >= tag.size())
              {
                const std::size_t passed = held.size() - (tag.size() - 1);
                sink.write(held.data(), passed);
                held.erase(0, passed);
              }
          }
        else
          {
            // not among the held characters: in s, or beginning in its end
            sink.write(held.data(), held.size());
            const auto in_s = std::string_view(s, size).find(tag);
            if (in_s != std::string_view::npos)
              {
                replace_after(s, in_s);
                sink.write(s + in_s + tag.size(), size - in_s - tag.size());
              }
            else
              {
                const std::size_t passed = size - (tag.size() - 1);
                sink.write(s, passed);
                held.assign(s + passed, tag.size() - 1);
              }
          }
      }
    // (a failed sink fails this stream, and deal.II's writer throws)
    return sink ? n : 0;
  }


  ActiveFieldsBuffer::int_type
  ActiveFieldsBuffer::overflow(const int_type c)
  {
    if (traits_type::eq_int_type(c, traits_type::eof()))
      return traits_type::not_eof(c);
    const char character = traits_type::to_char_type(c);
    return xsputn(&character, 1) == 1 ? c : traits_type::eof();
  }
} // namespace FoslsContact
