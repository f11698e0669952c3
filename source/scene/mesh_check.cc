#include <fosls_contact/base/error_line.h>
#include <fosls_contact/parameters/boundary_conditions.h>
#include <fosls_contact/scene/mesh_check.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <unordered_map>

namespace FoslsContact
{
  namespace
  {
    using Point3 = std::array<double, 3>;

    /** The words of @p line, split at whitespace (and at commas if @p commas). */
    std::vector<std::string>
    split(const std::string &line, const bool commas = false)
    {
      std::vector<std::string> words;
      std::string              word;
      for (const char c : line)
        if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || (commas && c == ','))
          {
            if (!word.empty())
              words.push_back(word);
            word.clear();
          }
        else
          word += c;
      if (!word.empty())
        words.push_back(word);
      return words;
    }

    std::string
    quote(const std::string &text)
    {
      return "'" + ErrorLine::quote(text, 40) + "'";
    }

    /** The integer @p word, if all of it is one. */
    bool
    integer(const std::string &word, long &value)
    {
      const char *begin = word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0);
      const char *end   = word.data() + word.size();
      const auto  r     = std::from_chars(begin, end, value);
      return r.ec == std::errc() && r.ptr == end;
    }

    /**
     * "" if all of @p word is a finite double (to @p value), else why not.
     * Underflow reads as 0, as the readers' streams read it.
     */
    std::string
    number(const std::string &word, double &value)
    {
      const char *begin = word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0);
      const char *end   = word.data() + word.size();
      const auto  r     = std::from_chars(begin, end, value);
      if (r.ec == std::errc::result_out_of_range && r.ptr == end)
        {
          value = std::strtod(std::string(begin, end).c_str(), nullptr);
          if (std::abs(value) <= 1)
            return "";
          return quote(word) + ", which is outside the range of double";
        }
      if (r.ec != std::errc() || r.ptr != end)
        return quote(word) + ", which is not a number";
      if (!std::isfinite(value))
        return quote(word) + ", which is not a finite number";
      return "";
    }

    std::string
    line_of(const unsigned int line)
    {
      return "line " + std::to_string(line) + ": ";
    }

    /** "(0.5, 1)" */
    std::string
    format(const Point3 &x, const unsigned int dim)
    {
      std::ostringstream out;
      out.precision(6);
      out << "(";
      for (unsigned int d = 0; d < dim; ++d)
        out << (d ? ", " : "") << x[d];
      out << ")";
      return out.str();
    }

    /** "a, b and c" */
    std::string
    listed(const std::vector<std::string> &items)
    {
      std::string text;
      for (std::size_t i = 0; i < items.size(); ++i)
        text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
      return text;
    }

    /**
     * The lines of a file, one after the other, and where a section ends:
     * at a line that begins with @p stop (Gmsh's '$'; none for the others)
     * or at the end of the file.
     */
    struct Cursor
    {
      Cursor(const std::vector<std::string> &lines, const char stop, const std::size_t at = 0)
        : lines(lines)
        , stop(stop)
        , at(at)
      {}

      const std::vector<std::string> &lines;
      const char                      stop;
      std::size_t                     at;    // the next line to read
      std::vector<std::string>        words; // of the line read last
      unsigned int                    number = 0;

      /** The next line that is not empty, or false at the section's end. */
      bool
      next()
      {
        while (at < lines.size())
          {
            words  = split(lines[at]);
            number = at + 1;
            ++at;
            if (words.empty())
              continue;
            if (stop != 0 && words[0][0] == stop)
              {
                --at;
                return false;
              }
            return true;
          }
        words.clear();
        number = lines.size();
        return false;
      }

      /** Where a section ended after @p k of its @p n @p items. */
      std::string
      ended(const std::size_t  k,
            const std::size_t  n,
            const std::string &items,
            const std::string &section) const
      {
        const std::string counts = " after " + std::to_string(k) + " of the " + std::to_string(n) +
                                   " " + items + " of its " + section + " section";
        if (at >= lines.size())
          return "the file ends" + counts;
        return line_of(number) + quote(words.empty() ? lines[at] : words[0]) + " comes" + counts;
      }
    };

    /** @p n integers, all >= 0, on the line read last. */
    bool
    counts(const Cursor &cursor, const std::size_t n, std::vector<long> &values)
    {
      values.clear();
      if (cursor.words.size() != n)
        return false;
      for (const auto &word : cursor.words)
        {
          long value = 0;
          if (!integer(word, value) || value < 0)
            return false;
          values.push_back(value);
        }
      return true;
    }

    /** The reference corners of the cyclic order of Gmsh, VTK, AVS UCD and Abaqus. */
    constexpr int corner[8][3] = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

    /** The bilinear (2D) or trilinear (3D) map of the cell with corners @p X at @p xi. */
    void
    map(const std::vector<Point3> &X,
        const unsigned int         dim,
        const Point3 &             xi,
        Point3 &                   x,
        double                     J[3][3])
    {
      x = {{0, 0, 0}};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          J[i][j] = 0;
      for (std::size_t k = 0; k < X.size(); ++k)
        {
          double w[3], dw[3];
          for (unsigned int d = 0; d < dim; ++d)
            {
              w[d]  = corner[k][d] ? xi[d] : 1 - xi[d];
              dw[d] = corner[k][d] ? 1 : -1;
            }
          for (unsigned int j = 0; j < dim; ++j)
            {
              double N = 1, dN = dw[j];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  N *= w[d];
                  if (d != j)
                    dN *= w[d];
                }
              for (unsigned int i = 0; i < dim; ++i)
                {
                  if (j == 0)
                    x[i] += N * X[k][i];
                  J[i][j] += dN * X[k][i];
                }
            }
        }
    }

    /** J d = r by Cramer's rule; false if J is (nearly) singular. */
    bool
    solve(const double J[3][3], const double r[3], const unsigned int dim, double d[3])
    {
      double scale = 0;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          scale = std::max(scale, std::abs(J[i][j]));
      if (dim == 2)
        {
          const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          if (!(std::abs(det) > 1e-12 * scale * scale))
            return false;
          d[0] = (r[0] * J[1][1] - J[0][1] * r[1]) / det;
          d[1] = (J[0][0] * r[1] - r[0] * J[1][0]) / det;
          return true;
        }
      auto det3 = [](const double a[3], const double b[3], const double c[3]) {
        // det of the columns a, b, c
        return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) +
               c[0] * (a[1] * b[2] - a[2] * b[1]);
      };
      const double c0[3] = {J[0][0], J[1][0], J[2][0]}, c1[3] = {J[0][1], J[1][1], J[2][1]},
                   c2[3] = {J[0][2], J[1][2], J[2][2]};
      const double det   = det3(c0, c1, c2);
      if (!(std::abs(det) > 1e-12 * scale * scale * scale))
        return false;
      d[0] = det3(r, c1, c2) / det;
      d[1] = det3(c0, r, c2) / det;
      d[2] = det3(c0, c1, r) / det;
      return true;
    }

    /**
     * The reference coordinates @p xi of @p p in the cell with corners
     * @p X (of size @p size), by Newton's method; false if it does not
     * converge (a point far outside a distorted cell).
     */
    bool
    reference_point(const std::vector<Point3> &X,
                    const unsigned int         dim,
                    const Point3 &             p,
                    const double               size,
                    Point3 &                   xi)
    {
      xi = {{0.5, 0.5, dim == 3 ? 0.5 : 0.}};
      for (unsigned int iteration = 0; iteration < 50; ++iteration)
        {
          Point3 x;
          double J[3][3], d[3];
          map(X, dim, xi, x, J);
          const double r[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
          if (!solve(J, r, dim, d))
            return false;
          double step = 0;
          for (unsigned int i = 0; i < dim; ++i)
            {
              xi[i] += d[i];
              step = std::max(step, std::abs(d[i]));
              if (!(std::abs(xi[i]) < 10))
                return false;
            }
          if (step < 1e-12)
            {
              map(X, dim, xi, x, J);
              for (unsigned int i = 0; i < dim; ++i)
                if (!(std::abs(p[i] - x[i]) <= 1e-9 * size))
                  return false;
              return true;
            }
        }
      return false;
    }
  } // namespace


  MeshCheck::MeshCheck(const std::string &text, const std::string &type, const unsigned int dim)
    : dim(dim)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    node_word = "node";
    cell_word = "element";
    if (type == "msh")
      reason = read_gmsh(lines);
    else if (type == "vtk")
      reason = read_vtk(lines);
    else if (type == "ucd")
      reason = read_ucd(lines);
    else if (type == "inp")
      reason = read_abaqus(lines);
    else
      return;
    if (!reason.empty())
      reason = reason.rfind("line ", 0) == 0 ? ", " + reason : " cannot be read: " + reason;
    else
      {
        reason = check_mesh();
        if (!reason.empty())
          reason = " " + reason;
      }
  }


  std::string
  MeshCheck::add_node(const long                      label,
                      const std::vector<std::string> &coordinates,
                      const unsigned int              line)
  {
    Node node{{{0, 0, 0}}, line, label};
    for (std::size_t d = 0; d < coordinates.size(); ++d)
      {
        const std::string why = number(coordinates[d], node.x[d]);
        if (!why.empty())
          return line_of(line) + node_word + " " + std::to_string(label) + " has the coordinate " +
                 why;
      }
    const auto [at, fresh] = labels.emplace(label, nodes.size());
    if (!fresh)
      return line_of(line) + node_word + " " + std::to_string(label) + " is given twice (also on " +
             "line " + std::to_string(nodes[at->second].line) + ")";
    nodes.push_back(node);
    return "";
  }


  std::string
  MeshCheck::add_cell(const Kind                      kind,
                      const std::vector<std::string> &node_labels,
                      const long                      label,
                      const unsigned int              line)
  {
    static const std::map<Kind, std::pair<std::string, unsigned int>> kinds = {
      {Kind::point, {"a point", 1}},
      {Kind::line, {"a line", 2}},
      {Kind::triangle, {"a triangle", 3}},
      {Kind::quadrilateral, {"a quadrilateral", 4}},
      {Kind::tetrahedron, {"a tetrahedron", 4}},
      {Kind::hexahedron, {"a hexahedron", 8}}};
    const auto &[name, n] = kinds.at(kind);
    const std::string what = line_of(line) + cell_word + " " + std::to_string(label);
    if (node_labels.size() != n)
      return what + " is " + name + ", which has " + std::to_string(n) + " nodes, but lists " +
             std::to_string(node_labels.size());
    Cell cell{kind, {}, line, label};
    for (const auto &word : node_labels)
      {
        long node = 0;
        if (!integer(word, node))
          return what + " has the " + node_word + " " + quote(word) + ", which is no integer";
        const auto found = labels.find(node);
        if (found == labels.end())
          return what + " names " + node_word + " " + std::to_string(node) +
                 (by_position ? ", but the file has " + node_word + "s 0 to " +
                                  std::to_string(long(nodes.size()) - 1) :
                                ", which the file does not have");
        cell.nodes.push_back(found->second);
      }
    cells.push_back(cell);
    return "";
  }


  /**
   * A Gmsh file's format (1 for $NOD, 2, 40 or 41 from the $MeshFormat
   * line, which MeshFile::check_text has checked) and the words of its
   * sections that the messages name.
   */
  struct MeshCheck::GmshFormat
  {
    explicit GmshFormat(const std::vector<std::string> &lines)
    {
      Cursor cursor(lines, 0);
      if (!cursor.next())
        return;
      if (cursor.words[0] == "$NOD")
        {
          version        = 1;
          nodes_begin    = "$NOD";
          nodes_end      = "$ENDNOD";
          elements_begin = "$ELM";
          elements_end   = "$ENDELM";
        }
      else if (cursor.words[0] == "$MeshFormat")
        {
          std::string v = cursor.words.size() > 1 ? cursor.words[1] : "";
          if (v.empty() && cursor.next())
            v = cursor.words[0];
          version = v.empty() ? 0 : v[0] == '2' ? 2 : v == "4" || v == "4.0" ? 40 : 41;
          header  = v;
        }
      another = " (is its body of another format than its header's " + header + "?)";
    }

    /** 1, 2, 40 or 41; 0: no Gmsh file. */
    int version = 0;
    /** The header's version, for messages. */
    std::string header = "1";
    std::string nodes_begin = "$Nodes", nodes_end = "$EndNodes", elements_begin = "$Elements",
                elements_end = "$EndElements";
    /** The end of a message on a body that may not be of the header's format. */
    std::string another;

    /** The number of counts at the beginning of a section. */
    std::size_t
    n_counts() const
    {
      return version < 40 ? 1 : version == 40 ? 2 : 4;
    }

    /** What the counts at the beginning of a section of @p items are. */
    std::string
    section_head(const std::string &items) const
    {
      return version < 40  ? "the number of " + items + " alone" :
             version == 40 ? "2 integers (entity blocks, " + items + ")" :
                             "4 integers (entity blocks, " + items + ", smallest and largest tag)";
    }

    /** What the counts at the beginning of an entity block of @p what are. */
    std::string
    block(const std::string &what) const
    {
      return version == 40 ? "4 integers (entity tag, dimension, " + what + ")" :
                             "4 integers (dimension, entity tag, " + what + ")";
    }

    /** The line of @p lines that begins with @p marker, or lines.size(). */
    static std::size_t
    find(const std::vector<std::string> &lines, const std::string &marker)
    {
      for (std::size_t i = 0; i < lines.size(); ++i)
        {
          const auto words = split(lines[i]);
          if (!words.empty() && words[0] == marker)
            return i;
        }
      return lines.size();
    }
  };


  std::string
  MeshCheck::read_gmsh(const std::vector<std::string> &lines)
  {
    const GmshFormat format(lines);
    if (format.version == 0)
      return "";
    if (format.version >= 40)
      {
        const std::string why = read_gmsh_entities(lines, format.version);
        if (!why.empty())
          return why;
      }
    const std::string why = read_gmsh_nodes(lines, format);
    if (!why.empty())
      return why;
    return read_gmsh_elements(lines, format);
  }


  std::string
  MeshCheck::read_gmsh_nodes(const std::vector<std::string> &lines, const GmshFormat &format)
  {
    const int          version     = format.version;
    const std::string &nodes_begin = format.nodes_begin, &nodes_end = format.nodes_end;
    const std::string &another     = format.another;
    const std::size_t  nodes_at    = GmshFormat::find(lines, nodes_begin);
    if (nodes_at == lines.size())
      return "it has no " + nodes_begin + " section";
    Cursor            cursor(lines, '$', nodes_at + 1);
    std::vector<long> values;
    if (!cursor.next() || !counts(cursor, format.n_counts(), values))
      return line_of(cursor.number) + "the " + nodes_begin + " section of a Gmsh " +
             format.header + " file begins with " + format.section_head("nodes") + ", not " +
             quote(cursor.number <= lines.size() && cursor.number > 0 ?
                     lines[cursor.number - 1] :
                     "") +
             another;
    const std::size_t n_nodes  = values[version < 40 ? 0 : 1];
    const std::size_t n_blocks = version < 40 ? 1 : values[0];
    std::size_t       k        = 0;
    for (std::size_t b = 0; b < n_blocks; ++b)
      {
        std::size_t in_block   = n_nodes;
        bool        parametric = false;
        if (version >= 40)
          {
            if (!cursor.next())
              return cursor.ended(k, n_nodes, "nodes", nodes_begin);
            if (!counts(cursor, 4, values))
              return line_of(cursor.number) + "an entity block of the " + nodes_begin +
                     " section begins with " + format.block("parametric, nodes") + ", not " +
                     quote(lines[cursor.number - 1]) + another;
            parametric = values[2] != 0;
            in_block   = values[3];
          }
        if (k + in_block > n_nodes)
          return line_of(cursor.number) + "the entity blocks of the " + nodes_begin +
                 " section hold more nodes than its " + std::to_string(n_nodes) + another;
        std::vector<long> tags;
        if (version == 41)
          for (std::size_t i = 0; i < in_block; ++i)
            {
              if (!cursor.next())
                return cursor.ended(k, n_nodes, "nodes", nodes_begin);
              long tag = 0;
              if (cursor.words.size() != 1 || !integer(cursor.words[0], tag))
                return line_of(cursor.number) + "a node tag of the " + nodes_begin +
                       " section (one integer on a line) is " + quote(lines[cursor.number - 1]) +
                       another;
              tags.push_back(tag);
            }
        for (std::size_t i = 0; i < in_block; ++i, ++k)
          {
            if (!cursor.next())
              return cursor.ended(k, n_nodes, "nodes", nodes_begin);
            auto        words = cursor.words;
            long        tag   = version == 41 ? tags[i] : 0;
            std::string form  = version == 41 ? "x y z" : "tag x y z";
            if (version != 41)
              {
                if (!integer(words[0], tag))
                  return line_of(cursor.number) + "the node line " +
                         quote(lines[cursor.number - 1]) + " does not begin with a tag" + another;
                words.erase(words.begin());
              }
            if (words.size() < 3 || (words.size() > 3 && !parametric))
              return line_of(cursor.number) + "node " + std::to_string(tag) + " has " +
                     std::to_string(words.size()) + " coordinates: a node line is '" + form +
                     "'" + (parametric ? " and its parametric coordinates" : "") +
                     (words.size() < 3 ? "" : another);
            words.resize(3);
            const std::string why = add_node(tag, words, cursor.number);
            if (!why.empty())
              return why;
          }
      }
    if (cursor.next())
      return line_of(cursor.number) + "the " + nodes_begin + " section has more lines than its " +
             std::to_string(n_nodes) + " nodes" + another;
    if (cursor.words.empty() || cursor.words[0] != nodes_end)
      return cursor.at >= lines.size() ?
               "the file ends in its " + nodes_begin + " section, before " + nodes_end :
               line_of(cursor.number) + quote(cursor.words[0]) + " where " + nodes_end +
                 " ends the " + nodes_begin + " section";
    return "";
  }


  std::string
  MeshCheck::read_gmsh_elements(const std::vector<std::string> &lines, const GmshFormat &format)
  {
    const int          version        = format.version;
    const std::string &elements_begin = format.elements_begin,
                      &elements_end   = format.elements_end;
    const std::string &another        = format.another;
    const std::size_t  elements_at    = GmshFormat::find(lines, elements_begin);
    if (elements_at == lines.size())
      return "it has no " + elements_begin + " section";
    Cursor            cursor(lines, '$', elements_at + 1);
    std::vector<long> values;
    if (!cursor.next() || !counts(cursor, format.n_counts(), values))
      return line_of(cursor.number) + "the " + elements_begin + " section of a Gmsh " +
             format.header + " file begins with " + format.section_head("elements") +
             ", not " + quote(cursor.number > 0 ? lines[cursor.number - 1] : "") + another;
    const std::size_t n_elements       = values[version < 40 ? 0 : 1];
    const std::size_t n_element_blocks = version < 40 ? 1 : values[0];
    std::size_t       k                = 0;
    for (std::size_t b = 0; b < n_element_blocks; ++b)
      {
        std::size_t in_block = n_elements;
        long        type     = 0;
        if (version >= 40)
          {
            if (!cursor.next())
              return cursor.ended(k, n_elements, "elements", elements_begin);
            if (!counts(cursor, 4, values))
              return line_of(cursor.number) + "an entity block of the " + elements_begin +
                     " section begins with " + format.block("element type, elements") +
                     ", not " + quote(lines[cursor.number - 1]) + another;
            type     = values[2];
            in_block = values[3];
          }
        if (k + in_block > n_elements)
          return line_of(cursor.number) + "the entity blocks of the " + elements_begin +
                 " section hold more elements than its " + std::to_string(n_elements) + another;
        for (std::size_t i = 0; i < in_block; ++i, ++k)
          {
            if (!cursor.next())
              return cursor.ended(k, n_elements, "elements", elements_begin);
            const std::string why = read_gmsh_element(
              cursor.words, lines[cursor.number - 1], cursor.number, format, type);
            if (!why.empty())
              return why;
          }
      }
    if (cursor.next())
      return line_of(cursor.number) + "the " + elements_begin +
             " section has more lines than its " + std::to_string(n_elements) + " elements" +
             another;
    if (cursor.words.empty() || cursor.words[0] != elements_end)
      return cursor.at >= lines.size() ?
               "the file ends in its " + elements_begin + " section, before " + elements_end :
               line_of(cursor.number) + quote(cursor.words[0]) + " where " + elements_end +
                 " ends the " + elements_begin + " section";
    return "";
  }


  std::string
  MeshCheck::read_gmsh_element(const std::vector<std::string> &words,
                               const std::string &             line,
                               const unsigned int              line_number,
                               const GmshFormat &              format,
                               long                            type)
  {
    const int         version = format.version;
    const std::string what    = line_of(line_number) + "the element line " + quote(line);
    // the element's number and the position of its first node
    long        label = 0;
    std::size_t first = 1;
    if (!integer(words[0], label))
      return what + " does not begin with an element number" + format.another;
    if (version < 40)
      {
        // 1: number type reg-phys reg-elem n-nodes nodes...
        // 2: number type n-tags tags... nodes...
        long n = 0;
        if (words.size() < (version == 1 ? 5u : 3u) || !integer(words[1], type) ||
            !integer(words[version == 1 ? 4 : 2], n) || n < 0)
          return what + " does not begin with " +
                 (version == 1 ? "'number type region element nodes'" : "'number type tags'") +
                 format.another;
        first = version == 1 ? 5 : 3 + n;
        if (first > words.size() || (version == 1 && first + n != words.size()))
          return what + " does not hold the " + std::to_string(n) +
                 (version == 1 ? " nodes" : " tags") + " it announces" + format.another;
        // (the physical tag: the region of format 1, the first tag of 2)
        long tag = 0;
        if ((version == 1 || n > 0) && integer(words[version == 1 ? 2 : 3], tag))
          {
            const std::map<long, unsigned int> dims = {{Kind::point, 0},
                                                       {Kind::line, 1},
                                                       {Kind::triangle, 2},
                                                       {Kind::quadrilateral, 2},
                                                       {Kind::tetrahedron, 3},
                                                       {Kind::hexahedron, 3}};
            const std::string                  why = physical_tag_problem(
              tag, dims.count(type) ? dims.at(type) : 0, what + " has the physical tag");
            if (!why.empty())
              return why;
          }
      }
    if (type == Kind::point || type == Kind::line || type == Kind::triangle ||
        type == Kind::quadrilateral || type == Kind::tetrahedron || type == Kind::hexahedron)
      return add_cell(static_cast<Kind>(type),
                      std::vector<std::string>(words.begin() + first, words.end()),
                      label,
                      line_number);
    // (elements of other types: deal.II's reader names them)
    return "";
  }


  std::string
  MeshCheck::physical_tag_problem(const long         tag,
                                  const unsigned int element_dim,
                                  const std::string &what) const
  {
    const std::string most = std::to_string(Parameters::BoundaryConditions::max_id);
    if (tag < 0)
      return what + " " + std::to_string(tag) +
             ", but it becomes a boundary id (of a face) or a material id (of a cell), a "
             "number from 0 (deal.II's reader would take it as 0); number it 0 to " + most;
    if (element_dim + 1 == dim && tag > long(Parameters::BoundaryConditions::max_id))
      return what + " " + std::to_string(tag) + ", the boundary id of a face, out of the range "
             "0 to " + most + " the program supports (the ids 'Boundary conditions' accepts); "
             "number it 0 to " + most;
    return "";
  }


  std::string
  MeshCheck::read_gmsh_entities(const std::vector<std::string> &lines, const int version) const
  {
    std::size_t at = 0;
    while (at < lines.size() && (split(lines[at]).empty() || split(lines[at])[0] != "$Entities"))
      ++at;
    if (at == lines.size())
      return "";
    // numPoints numCurves numSurfaces numVolumes, then one line per entity:
    // tag, its box (4.1: a point's position alone), the number of physical
    // tags and the tags
    Cursor            cursor(lines, '$', at + 1);
    std::vector<long> n;
    if (!cursor.next() || !counts(cursor, 4, n))
      return "";
    const char *names[] = {"point", "curve", "surface", "volume"};
    for (unsigned int d = 0; d < 4; ++d)
      for (long e = 0; e < n[d]; ++e)
        {
          if (!cursor.next())
            return "";
          const std::size_t count_at = version == 41 && d == 0 ? 4 : 7;
          long              n_tags   = 0;
          if (cursor.words.size() <= count_at || !integer(cursor.words[count_at], n_tags))
            return "";
          for (long t = 0; t < n_tags && count_at + 1 + t < cursor.words.size(); ++t)
            {
              long tag = 0;
              if (!integer(cursor.words[count_at + 1 + t], tag))
                continue;
              const std::string why =
                physical_tag_problem(tag, d,
                                     line_of(cursor.number) + "the " + names[d] + " " +
                                       quote(cursor.words[0]) +
                                       " of the $Entities section has the physical tag");
              if (!why.empty())
                return why;
            }
        }
    return "";
  }


  std::string
  MeshCheck::read_vtk(const std::vector<std::string> &lines)
  {
    node_word   = "point";
    cell_word   = "cell";
    by_position = true;
    // deal.II's reader names a header that is not its own
    if (lines.size() < 4 || lines[0] != "# vtk DataFile Version 3.0" || lines[2] != "ASCII" ||
        lines[3] != "DATASET UNSTRUCTURED_GRID")
      return "";
    // the words after the header, with their lines
    std::vector<std::pair<std::string, unsigned int>> words;
    for (std::size_t i = 4; i < lines.size(); ++i)
      for (const auto &word : split(lines[i]))
        words.emplace_back(word, i + 1);
    std::size_t at   = 0;
    auto        last = [&]() {
      return words.empty() ? 4u : words[std::min(at, words.size() - 1)].second;
    };
    auto        keyword = [](const std::string &word) {
      return !word.empty() && std::all_of(word.begin(), word.end(), [](const char c) {
        return (c >= 'A' && c <= 'Z') || c == '_';
      });
    };
    // "KEYWORD n" and the integer
    auto section = [&](const std::string &name, long &n) -> std::string {
      if (at >= words.size() || words[at].first != name)
        return at >= words.size() ? "the file ends where its " + name + " section should begin" :
                                    line_of(words[at].second) + quote(words[at].first) +
                                      " where the " + name + " section should begin";
      ++at;
      if (at >= words.size() || !integer(words[at].first, n) || n < 0)
        return line_of(last()) + "the " + name + " keyword is not followed by a count";
      ++at;
      return "";
    };

    long        n_points = 0;
    std::string why      = section("POINTS", n_points);
    if (!why.empty())
      return why;
    ++at; // the data type
    for (long i = 0; i < n_points; ++i)
      {
        std::vector<std::string> coordinates;
        unsigned int             line = 0;
        for (unsigned int d = 0; d < 3; ++d, ++at)
          {
            if (at >= words.size() || (keyword(words[at].first) && words[at].first != "NAN" &&
                                       words[at].first != "INF"))
              return (at >= words.size() ? std::string("the file ends") :
                                           line_of(words[at].second) + quote(words[at].first) +
                                             " comes") +
                     " after " + std::to_string(i) + " of the " + std::to_string(n_points) +
                     " points of its POINTS section (each 3 coordinates)";
            coordinates.push_back(words[at].first);
            line = line == 0 ? words[at].second : line;
          }
        why = add_node(i, coordinates, line);
        if (!why.empty())
          return why;
      }

    long n_cells = 0, n_integers = 0;
    why = section("CELLS", n_cells);
    if (!why.empty())
      return why;
    if (at >= words.size() || !integer(words[at].first, n_integers))
      return line_of(last()) + "the CELLS keyword is not followed by two counts";
    ++at;
    std::vector<std::vector<std::string>> cell_nodes;
    std::vector<unsigned int>             cell_lines;
    for (long i = 0; i < n_cells; ++i)
      {
        long n = 0;
        if (at >= words.size() || !integer(words[at].first, n) || n < 0)
          return (at >= words.size() ? std::string("the file ends") :
                                       line_of(words[at].second) + quote(words[at].first) +
                                         " comes") +
                 " where cell " + std::to_string(i) + " of the " + std::to_string(n_cells) +
                 " of its CELLS section should begin with its number of points";
        cell_lines.push_back(words[at].second);
        ++at;
        if (at + n > words.size())
          return "the file ends in cell " + std::to_string(i) + " of its CELLS section";
        cell_nodes.emplace_back();
        for (long j = 0; j < n; ++j, ++at)
          cell_nodes.back().push_back(words[at].first);
      }
    long n_types = 0;
    why          = section("CELL_TYPES", n_types);
    if (!why.empty())
      return why;
    if (n_types != n_cells)
      return line_of(last()) + "the CELL_TYPES section lists " + std::to_string(n_types) +
             " types for the " + std::to_string(n_cells) + " cells of the CELLS section";
    const std::map<long, Kind> kinds = {{1, Kind::point},
                                        {3, Kind::line},
                                        {5, Kind::triangle},
                                        {9, Kind::quadrilateral},
                                        {10, Kind::tetrahedron},
                                        {12, Kind::hexahedron}};
    for (long i = 0; i < n_cells; ++i, ++at)
      {
        long type = 0;
        if (at >= words.size() || !integer(words[at].first, type))
          return (at >= words.size() ? std::string("the file ends") :
                                       line_of(words[at].second) + quote(words[at].first) +
                                         " comes") +
                 " after " + std::to_string(i) + " of the " + std::to_string(n_cells) +
                 " cell types of its CELL_TYPES section";
        // (cells of other types: deal.II's reader names them)
        if (kinds.count(type))
          {
            why = add_cell(kinds.at(type), cell_nodes[i], i, cell_lines[i]);
            if (!why.empty())
              return why;
          }
      }
    return "";
  }


  std::string
  MeshCheck::read_ucd(const std::vector<std::string> &lines)
  {
    cell_word = "cell";
    Cursor cursor(lines, 0);
    // comments at the beginning
    while (cursor.at < lines.size() && !lines[cursor.at].empty() && lines[cursor.at][0] == '#')
      ++cursor.at;
    std::vector<long> values;
    if (!cursor.next())
      return "it has no header line (nodes, cells, and 3 data counts) after its comments";
    if (!counts(cursor, 5, values))
      return line_of(cursor.number) + "the header line of an AVS UCD file is 5 integers (nodes, "
                                      "cells, and 3 data counts), not " +
             quote(lines[cursor.number - 1]);
    const long n_nodes = values[0], n_cells = values[1];
    for (long i = 0; i < n_nodes; ++i)
      {
        if (!cursor.next())
          return "the file ends after " + std::to_string(i) + " of its " +
                 std::to_string(n_nodes) + " nodes";
        long label = 0;
        if (cursor.words.size() != 4 || !integer(cursor.words[0], label))
          return line_of(cursor.number) + "the node line " + quote(lines[cursor.number - 1]) +
                 " is not 'number x y z'";
        const std::string why = add_node(label,
                                         std::vector<std::string>(cursor.words.begin() + 1,
                                                                  cursor.words.end()),
                                         cursor.number);
        if (!why.empty())
          return why;
      }
    const std::map<std::string, Kind> kinds = {{"pt", Kind::point},
                                               {"line", Kind::line},
                                               {"tri", Kind::triangle},
                                               {"quad", Kind::quadrilateral},
                                               {"tet", Kind::tetrahedron},
                                               {"hex", Kind::hexahedron}};
    for (long i = 0; i < n_cells; ++i)
      {
        if (!cursor.next())
          return "the file ends after " + std::to_string(i) + " of its " +
                 std::to_string(n_cells) + " cells";
        long label = 0, material = 0;
        if (cursor.words.size() < 3 || !integer(cursor.words[0], label) ||
            !integer(cursor.words[1], material))
          return line_of(cursor.number) + "the cell line " + quote(lines[cursor.number - 1]) +
                 " is not 'number material type nodes...'";
        // (the material: a face's boundary id, a cell's material id)
        const std::map<std::string, unsigned int> dims = {
          {"pt", 0}, {"line", 1}, {"tri", 2}, {"quad", 2}, {"tet", 3}, {"hex", 3}};
        const std::string problem = physical_tag_problem(
          material,
          dims.count(cursor.words[2]) ? dims.at(cursor.words[2]) : dim,
          line_of(cursor.number) + "cell " + std::to_string(label) + " has the material");
        if (!problem.empty())
          return problem;
        // (cells of other types: deal.II's reader names them)
        if (kinds.count(cursor.words[2]))
          {
            const std::string why =
              add_cell(kinds.at(cursor.words[2]),
                       std::vector<std::string>(cursor.words.begin() + 3, cursor.words.end()),
                       label,
                       cursor.number);
            if (!why.empty())
              return why;
          }
      }
    return "";
  }


  std::string
  MeshCheck::read_abaqus(const std::vector<std::string> &lines)
  {
    // (MeshFile::check_text has checked the element types and their
    // numbers of nodes, and that the mesh has this dimension)
    std::string  block, element;
    unsigned int element_line = 0;
    auto         finish       = [&]() -> std::string {
      // an element continues on the next line after a trailing comma
      auto words = split(element, true);
      element.clear();
      if (words.empty())
        return "";
      long label = 0;
      if (!integer(words[0], label))
        return line_of(element_line) + "the element line does not begin with its number";
      return add_cell(dim == 2 ? Kind::quadrilateral : Kind::hexahedron,
                      std::vector<std::string>(words.begin() + 1, words.end()),
                      label,
                      element_line);
    };
    for (std::size_t i = 0; i < lines.size(); ++i)
      {
        std::string t;
        for (const char c : lines[i])
          if (c != ' ' && c != '\t' && c != '\r')
            t += std::toupper(static_cast<unsigned char>(c));
        if (t.empty())
          continue;
        if (t[0] == '*')
          {
            const std::string why = finish();
            if (!why.empty())
              return why;
            // (not *NODE OUTPUT, *ELEMENT OUTPUT, ...: "*NODE" or "*NODE,...")
            auto is = [&t](const std::string &keyword) {
              return t == keyword || t.rfind(keyword + ",", 0) == 0;
            };
            block = t.rfind("**", 0) == 0 ? block :
                    is("*NODE")           ? "node" :
                    is("*ELEMENT")        ? "element" :
                                            "";
            continue;
          }
        if (block == "node")
          {
            auto words = split(lines[i], true);
            long label = 0;
            if (!integer(words[0], label) || words.size() < 1 + dim || words.size() > 4)
              return line_of(i + 1) + "the node line " + quote(lines[i]) + " is not 'number, x, y" +
                     (dim == 3 ? ", z'" : "' or 'number, x, y, z'");
            const std::string why =
              add_node(label, std::vector<std::string>(words.begin() + 1, words.end()), i + 1);
            if (!why.empty())
              return why;
          }
        else if (block == "element")
          {
            if (element.empty())
              element_line = i + 1;
            element += lines[i];
            if (t.back() != ',')
              {
                const std::string why = finish();
                if (!why.empty())
                  return why;
              }
          }
      }
    return finish();
  }


  std::string
  MeshCheck::describe(const Cell &cell) const
  {
    return cell_word + " " + std::to_string(cell.label) + " (line " + std::to_string(cell.line) +
           ")";
  }


  std::string
  MeshCheck::describe(const Node &node) const
  {
    return node_word + " " + std::to_string(node.label) + " (line " + std::to_string(node.line) +
           ")";
  }


  std::string
  MeshCheck::check_mesh() const
  {
    std::map<Kind, unsigned int> n;
    for (const auto &cell : cells)
      ++n[cell.kind];
    const bool has_3d = n[Kind::tetrahedron] + n[Kind::hexahedron] > 0;
    // a mesh of the other dimension, or of triangles or tetrahedra: named
    // after GridIn
    if ((dim == 2) == has_3d)
      return "";
    const Kind cube    = dim == 2 ? Kind::quadrilateral : Kind::hexahedron;
    const Kind simplex = dim == 2 ? Kind::triangle : Kind::tetrahedron;
    if (n[simplex] > 0 || n[cube] == 0)
      return "";
    std::vector<unsigned int> mesh_cells;
    std::vector<bool>         used(nodes.size(), false);
    for (unsigned int c = 0; c < cells.size(); ++c)
      if (cells[c].kind == cube)
        {
          mesh_cells.push_back(c);
          for (const auto v : cells[c].nodes)
            used[v] = true;
        }

    // 2D: in the plane z = 0 (to round-off against the size)
    if (dim == 2)
      {
        double size = 0;
        for (unsigned int v = 0; v < nodes.size(); ++v)
          if (used[v])
            size = std::max({size, std::abs(nodes[v].x[0]), std::abs(nodes[v].x[1])});
        for (unsigned int v = 0; v < nodes.size(); ++v)
          if (used[v] && std::abs(nodes[v].x[2]) > 1e-12 * size)
            {
              std::ostringstream z;
              z.precision(6);
              z << nodes[v].x[2];
              return "is a 2D mesh that does not lie in the plane z = 0: " +
                     describe(nodes[v]) + " has z = " + z.str() +
                     " (deal.II's readers would drop z)";
            }
      }

    // a node twice in a cell, a cell twice
    std::map<std::vector<unsigned int>, unsigned int> by_nodes;
    for (const auto c : mesh_cells)
      {
        auto sorted = cells[c].nodes;
        std::sort(sorted.begin(), sorted.end());
        const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
        if (twice != sorted.end())
          return "has a degenerate cell: " + describe(cells[c]) + " lists " +
                 describe(nodes[*twice]) + " twice";
        const auto [at, fresh] = by_nodes.emplace(sorted, c);
        if (!fresh)
          return "lists a cell twice: " + describe(cells[at->second]) + " and " +
                 describe(cells[c]) + " have the same " + node_word + "s" +
                 (cells[at->second].nodes == cells[c].nodes ? "" : " (in another order)");
      }

    // every edge (2D) or face (3D) a side of at most two cells
    static const std::vector<std::vector<unsigned int>> sides[2] = {
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
    std::map<std::vector<unsigned int>, std::vector<unsigned int>> side_cells;
    for (const auto c : mesh_cells)
      for (const auto &side : sides[dim - 2])
        {
          std::vector<unsigned int> key;
          for (const auto i : side)
            key.push_back(cells[c].nodes[i]);
          std::sort(key.begin(), key.end());
          auto &owners = side_cells[key];
          owners.push_back(c);
          if (owners.size() == 3)
            {
              std::vector<std::string> of_nodes, of_cells;
              for (const auto v : key)
                of_nodes.push_back(std::to_string(nodes[v].label));
              for (const auto o : owners)
                of_cells.push_back(describe(cells[o]));
              return "has overlapping cells: the " + std::string(dim == 2 ? "edge" : "face") +
                     " of the " + node_word + "s " + listed(of_nodes) + " is a side of 3 " +
                     cell_word + "s, " + listed(of_cells);
            }
        }

    if (dim == 3)
      {
        const std::string twisted = check_twist(mesh_cells, sides[1]);
        if (!twisted.empty())
          return twisted;
      }
    return check_geometry(mesh_cells);
  }


  std::string
  MeshCheck::check_twist(const std::vector<unsigned int> &             mesh_cells,
                         const std::vector<std::vector<unsigned int>> &sides) const
  {
    // A hexahedron whose upper face is listed rotated against its lower one
    // keeps a positive Jacobian at its corners (and, for a quarter turn,
    // inside: its least value is half the cube's), so CellShapeCheck lets
    // it pass; but its sides join nodes across a diagonal of the body, each
    // bending by 90 degrees or more, and its neighbours no longer share
    // sides with it: the mesh is not the body the file describes. The bend
    // of a side is the angle between the normals of its two triangles,
    // across either diagonal: a quarter turn bends a side of a box cell by
    // 90 degrees (a long thin box) to 172 (a flat one), half a turn or a
    // reversed face by 180. A side of a sound mesh is flat, or curved with
    // the surface it approximates by less, even as coarse a mesh of a ball
    // as the 12 cells of prm/meshes/quarter_ball.msh.
    constexpr double limit_degrees = 85;
    const auto       minus         = [](const Point3 &a, const Point3 &b) {
      return Point3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
    };
    const auto normal = [&](const Point3 &a, const Point3 &b, const Point3 &c) {
      const Point3 u = minus(b, a), v = minus(c, a);
      return Point3{
        {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
    };
    const auto angle = [](const Point3 &m, const Point3 &n) {
      const double mn = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
      const double mm = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
      const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      // (a degenerate triangle: CellShapeCheck names the cell)
      if (!(mm > 0 && nn > 0))
        return 0.;
      return std::acos(std::max(-1., std::min(1., mn / std::sqrt(mm * nn)))) * 180 / M_PI;
    };
    for (const auto c : mesh_cells)
      for (const auto &side : sides)
        {
          // the side's corners in their cyclic order
          const Point3 &a = nodes[cells[c].nodes[side[0]]].x, &b = nodes[cells[c].nodes[side[1]]].x,
                       &p = nodes[cells[c].nodes[side[2]]].x, &d = nodes[cells[c].nodes[side[3]]].x;
          const double bend = std::max(angle(normal(a, b, p), normal(a, p, d)),
                                       angle(normal(b, p, d), normal(b, d, a)));
          if (bend > limit_degrees)
            {
              std::vector<std::string> of_nodes;
              for (const auto i : side)
                of_nodes.push_back(std::to_string(nodes[cells[c].nodes[i]].label));
              std::ostringstream degrees;
              degrees << std::lround(bend);
              return "has a twisted cell: the side of the " + node_word + "s " +
                     listed(of_nodes) + " of " + describe(cells[c]) + " bends by " +
                     degrees.str() + " degrees across a diagonal (more than " +
                     std::to_string(int(limit_degrees)) +
                     "; its nodes listed in the wrong order?)";
            }
        }
    return "";
  }


  /**
   * The points check_geometry() tests against the cells: the nodes of the
   * cells and the cells' centres (owner: the node's index, or nodes.size()
   * + the cell's position in mesh_cells), each cell's corners and size, and
   * the points sorted into boxes of about the mean cell size, so that a
   * cell is tested against the points near it only.
   */
  struct MeshCheck::TestPoints
  {
    std::vector<Point3>              positions;
    std::vector<unsigned int>        owner;
    std::vector<std::vector<Point3>> corners;
    std::vector<double>              sizes;
    Point3                           lower = {{0, 0, 0}}, upper = {{0, 0, 0}};
    double                           mean_size = 0;

    /** At most this many boxes along an axis. */
    static constexpr std::int64_t most = 1 << 20;
    std::int64_t                  boxes[3] = {1, 1, 1};
    std::unordered_map<std::int64_t, std::vector<unsigned int>> grid;

    /** The box of coordinate @p x along axis @p d. */
    std::int64_t
    box(const double x, const unsigned int d) const
    {
      const double b = std::floor((x - lower[d]) / mean_size);
      return std::int64_t(std::max(0., std::min(double(boxes[d] - 1), b)));
    }

    static std::int64_t
    key(const std::int64_t i, const std::int64_t j, const std::int64_t k)
    {
      return i + most * (j + most * k);
    }

    /** Sort the positions into boxes of about mean_size. */
    void
    fill_grid(const unsigned int dim)
    {
      for (unsigned int d = 0; d < dim; ++d)
        boxes[d] = std::int64_t(std::min<double>(most, (upper[d] - lower[d]) / mean_size + 1));
      for (unsigned int p = 0; p < positions.size(); ++p)
        grid[key(box(positions[p][0], 0),
                 box(positions[p][1], 1),
                 dim == 3 ? box(positions[p][2], 2) : 0)]
          .push_back(p);
    }

    /**
     * The points in the boxes of the box [@p low, @p high]: all of them in
     * order where that spans more boxes than there are points.
     */
    std::vector<unsigned int>
    near(const Point3 &low, const Point3 &high, const unsigned int dim) const
    {
      std::int64_t from[3] = {0, 0, 0}, to[3] = {0, 0, 0};
      double       n_boxes = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          from[d] = box(low[d], d);
          to[d]   = box(high[d], d);
          n_boxes *= to[d] - from[d] + 1;
        }
      std::vector<unsigned int> candidates;
      if (n_boxes > positions.size())
        for (unsigned int p = 0; p < positions.size(); ++p)
          candidates.push_back(p);
      else
        for (auto a = from[0]; a <= to[0]; ++a)
          for (auto b = from[1]; b <= to[1]; ++b)
            for (auto c = from[2]; c <= to[2]; ++c)
              {
                const auto found = grid.find(key(a, b, c));
                if (found != grid.end())
                  candidates.insert(candidates.end(), found->second.begin(), found->second.end());
              }
      return candidates;
    }
  };


  MeshCheck::TestPoints
  MeshCheck::test_points(const std::vector<unsigned int> &mesh_cells) const
  {
    TestPoints points;
    std::vector<bool> used(nodes.size(), false);
    for (const auto c : mesh_cells)
      for (const auto v : cells[c].nodes)
        used[v] = true;
    points.corners.resize(mesh_cells.size());
    points.sizes.resize(mesh_cells.size());
    bool first = true;
    for (unsigned int v = 0; v < nodes.size(); ++v)
      if (used[v])
        {
          points.positions.push_back(nodes[v].x);
          points.owner.push_back(v);
          for (unsigned int d = 0; d < dim; ++d)
            {
              points.lower[d] = first ? nodes[v].x[d] : std::min(points.lower[d], nodes[v].x[d]);
              points.upper[d] = first ? nodes[v].x[d] : std::max(points.upper[d], nodes[v].x[d]);
            }
          first = false;
        }
    for (unsigned int i = 0; i < mesh_cells.size(); ++i)
      {
        Point3 centre = {{0, 0, 0}}, low = nodes[cells[mesh_cells[i]].nodes[0]].x, high = low;
        for (const auto v : cells[mesh_cells[i]].nodes)
          {
            points.corners[i].push_back(nodes[v].x);
            for (unsigned int d = 0; d < dim; ++d)
              {
                centre[d] += nodes[v].x[d] / cells[mesh_cells[i]].nodes.size();
                low[d]  = std::min(low[d], nodes[v].x[d]);
                high[d] = std::max(high[d], nodes[v].x[d]);
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          points.sizes[i] = std::max(points.sizes[i], high[d] - low[d]);
        points.mean_size += points.sizes[i] / mesh_cells.size();
        points.positions.push_back(centre);
        points.owner.push_back(nodes.size() + i);
      }
    return points;
  }


  std::string
  MeshCheck::check_geometry(const std::vector<unsigned int> &mesh_cells) const
  {
    TestPoints points = test_points(mesh_cells);
    if (!(points.mean_size > 0) || !std::isfinite(points.mean_size))
      return "";
    points.fill_grid(dim);
    for (unsigned int i = 0; i < mesh_cells.size(); ++i)
      {
        const std::string why = points_in_cell(mesh_cells, points, i);
        if (!why.empty())
          return why;
      }
    return "";
  }


  std::string
  MeshCheck::points_in_cell(const std::vector<unsigned int> &mesh_cells,
                            const TestPoints &               points,
                            const unsigned int               i) const
  {
    const double tolerance = 1e-6;
    const Cell & cell      = cells[mesh_cells[i]];
    const auto & corners   = points.corners[i];
    const double size      = points.sizes[i];
    Point3       low = corners[0], high = low;
    for (const auto &x : corners)
      for (unsigned int d = 0; d < dim; ++d)
        {
          low[d]  = std::min(low[d], x[d] - tolerance * size);
          high[d] = std::max(high[d], x[d] + tolerance * size);
        }
    for (const auto p : points.near(low, high, dim))
      {
        const auto &x    = points.positions[p];
        bool        near = true;
        for (unsigned int d = 0; d < dim; ++d)
          near = near && x[d] >= low[d] && x[d] <= high[d];
        const unsigned int owner = points.owner[p];
        if (!near || owner == nodes.size() + i ||
            std::find(cell.nodes.begin(), cell.nodes.end(), owner) != cell.nodes.end())
          continue;
        Point3 xi;
        if (!reference_point(corners, dim, x, size, xi))
          continue;
        unsigned int on = 0;
        bool         in = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            in = in && xi[d] >= -tolerance && xi[d] <= 1 + tolerance;
            on += std::abs(xi[d]) <= tolerance || std::abs(xi[d] - 1) <= tolerance;
          }
        if (!in)
          continue;
        if (owner >= nodes.size())
          return "has overlapping cells: " + describe(cells[mesh_cells[owner - nodes.size()]]) +
                 " and " + describe(cell) + " overlap (the centre of one lies in the other)";
        const Node &node = nodes[owner];
        if (on == dim)
          {
            // at a corner: which one
            unsigned int nearest = cell.nodes[0];
            for (const auto v : cell.nodes)
              {
                double a = 0, b = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    a += std::pow(nodes[v].x[d] - x[d], 2);
                    b += std::pow(nodes[nearest].x[d] - x[d], 2);
                  }
                if (a < b)
                  nearest = v;
              }
            return "has the point " + format(x, dim) + " twice, as " + describe(nodes[nearest]) +
                   " and " + describe(node) +
                   ": the cells are not connected there (merge the two " + node_word + "s)";
          }
        if (on > 0)
          return "is not conforming: " + describe(node) + " lies on " +
                 (dim == 2 ? "an edge" : "the boundary") + " of " + describe(cell) +
                 " without being one of its " + node_word + "s (a hanging node)";
        return "has overlapping cells: " + describe(node) + " lies inside " + describe(cell);
      }
    return "";
  }
} // namespace FoslsContact
