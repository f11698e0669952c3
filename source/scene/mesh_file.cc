#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/input_error.h>
#include <fosls_contact/input/text_file.h>
#include <fosls_contact/scene/mesh_check.h>
#include <fosls_contact/scene/mesh_file.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    /** The formats read, by extension: GridIn's format and a name for messages. */
    const std::map<std::string, std::pair<GridIn<2>::Format, std::string>> &
    formats()
    {
      static const std::map<std::string, std::pair<GridIn<2>::Format, std::string>> table = {
        {"msh", {GridIn<2>::msh, "Gmsh"}},
        {"inp", {GridIn<2>::abaqus, "Abaqus"}},
        {"ucd", {GridIn<2>::ucd, "AVS UCD"}},
        {"vtk", {GridIn<2>::vtk, "VTK"}},
        {"vtu", {GridIn<2>::vtu, "deal.II VTU"}}};
      return table;
    }

    std::string
    upper(std::string text)
    {
      std::transform(text.begin(), text.end(), text.begin(), [](const unsigned char c) {
        return std::toupper(c);
      });
      return text;
    }

    /** "1 quadrilateral", "42 triangles" */
    std::string
    count(const unsigned int n, const std::string &singular, const std::string &plural)
    {
      return std::to_string(n) + " " + (n == 1 ? singular : plural);
    }

    /**
     * The reason why the Gmsh @p text cannot be read, or "": its header
     * must be ASCII of a version deal.II's reader knows.
     */
    std::string
    check_gmsh(const std::string &text)
    {
      std::istringstream in(text);
      std::string        first;
      in >> first;
      if (first == "$NOD")
        return ""; // format 1
      if (first != "$MeshFormat")
        return "it does not begin with $MeshFormat (or $NOD): not a Gmsh mesh";
      std::string version;
      int         binary = -1;
      in >> version >> binary;
      if (!in)
        return "its $MeshFormat section has no version and file type";
      if (binary != 0)
        return "it is a binary Gmsh file: save it as ASCII (Gmsh: File > Export, "
               "uncheck binary; or gmsh FILE -save -format msh41)";
      if (version != "2" && version != "2.0" && version != "2.1" && version != "2.2" &&
          version != "4" && version != "4.0" && version != "4.1")
        return "it has Gmsh format version " + ErrorLine::quote(version, 20) +
               "; read are the ASCII versions 1, 2.0-2.2, 4.0 and 4.1";
      return "";
    }

    /** The integers of the comma separated @p line (ignoring what is none). */
    std::vector<long>
    integers(const std::string &line)
    {
      std::vector<long>  values;
      std::istringstream tokens(line);
      for (std::string token; std::getline(tokens, token, ',');)
        try
          {
            values.push_back(std::stol(Utilities::trim(token)));
          }
        catch (...)
          {}
      return values;
    }

    /**
     * Why the *SURFACE name @p name (upper case) gives no boundary id the
     * program can take, or "". deal.II's Abaqus reader takes all the digits
     * of the name, wherever they are, as the surface's boundary id: SS-1
     * becomes id 1 (the '-' dropped), S1TOP2 id 12, and a name without
     * digits no id at all; so the name must hold its id as its only number,
     * without a sign, and the id must be one that 'Boundary conditions'
     * accepts (0 to 255).
     */
    std::string
    surface_name_problem(const std::string &name)
    {
      std::string digits;
      unsigned int groups = 0;
      bool         signed_number = false;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (std::isdigit(static_cast<unsigned char>(name[i])))
          {
            if (i == 0 || !std::isdigit(static_cast<unsigned char>(name[i - 1])))
              {
                ++groups;
                signed_number = signed_number || (i > 0 && (name[i - 1] == '-' || name[i - 1] == '+'));
              }
            digits += name[i];
          }
      const std::string rule = "deal.II's reader takes the digits of a surface's name, all of "
                               "them, as its boundary id: name each surface with its boundary id "
                               "0 to 255 as the only number in the name, without a sign (e.g. "
                               "NAME=SS1)";
      const std::string what = "the *SURFACE NAME='" + ErrorLine::quote(name, 40) + "'";
      if (groups == 0)
        return what + " has no number, so no boundary id: " + rule;
      if (groups > 1 || signed_number)
        return what + " would become boundary id " + ErrorLine::quote(digits, 20) +
               (signed_number ? " (the sign dropped)" : " (its numbers joined)") + ": " + rule;
      if (digits.size() > 3 || std::stoi(digits) > 255)
        return what + " gives the boundary id " + ErrorLine::quote(digits, 20) +
               ", out of the range 0 to 255 the program supports (the ids 'Boundary "
               "conditions' accepts): number the surface 0 to 255";
      return "";
    }

    /**
     * The reason why the Abaqus @p text is no mesh of quadrilaterals (2D)
     * or hexahedra (3D) that deal.II's reader can take, or "". That reader
     * takes every element of every *ELEMENT block as a cell with 2^dim
     * nodes, whatever its type (a Gmsh export's boundary lines, T3D2, would
     * become garbage cells), and looks the elements of a *SURFACE up by
     * their position without a check (an element or face number out of
     * range reads memory that is not its own); both are checked here.
     */
    std::string
    check_abaqus(const std::string &text, const unsigned int dim)
    {
      std::istringstream in(text);
      std::map<std::string, std::pair<unsigned int, unsigned int>> blocks; // type -> (n, nodes)
      std::map<std::string, long> elset_max; // the largest element of an *ELSET
      std::string line, type, block, name, element;
      long        n_elements = 0;
      unsigned int number    = 0; // of the line read last
      std::string reason;
      auto        finish = [&]() {
        // (an element continues on the next line after a trailing comma)
        const auto n = integers(element).size();
        if (n > 0)
          {
            auto &b = blocks[type];
            b.first += 1;
            b.second = std::max<unsigned int>(b.second, n - 1);
            ++n_elements;
          }
        element.clear();
      };
      auto value_of = [](const std::string &header, const std::string &key) {
        const auto pos = header.find(key + "=");
        return pos == std::string::npos ?
                 std::string() :
                 header.substr(pos + key.size() + 1,
                               header.find(',', pos) - pos - key.size() - 1);
      };
      while (std::getline(in, line) && reason.empty())
        {
          ++number;
          std::string t;
          for (const char c : upper(line))
            if (c != ' ' && c != '\t' && c != '\r')
              t += c;
          if (t.rfind("**", 0) == 0 || t.empty())
            continue;
          if (t[0] == '*')
            {
              finish();
              block = t.rfind("*ELEMENT", 0) == 0 ? "element" :
                      t.rfind("*SURFACE", 0) == 0 ? "surface" :
                      t.rfind("*ELSET", 0) == 0   ? "elset" :
                                                    "";
              type = value_of(t, "TYPE");
              name = value_of(t, "ELSET");
              if (block == "elset" && t.find("GENERATE") != std::string::npos)
                block = "generate";
              if (block == "surface")
                {
                  const std::string why = surface_name_problem(value_of(t, "NAME"));
                  if (!why.empty())
                    reason = "line " + std::to_string(number) + ": " + why;
                }
              continue;
            }
          if (block == "element")
            {
              element += t;
              if (t.back() != ',')
                finish();
            }
          else if (block == "elset" || block == "generate")
            {
              const auto values = integers(t);
              for (std::size_t i = 0; i < values.size(); ++i)
                if (block == "elset" || i < 2)
                  elset_max[name] = std::max(elset_max[name], values[i]);
            }
          else if (block == "surface")
            {
              // "element, Sk" or "elset, Sk"
              const auto comma = t.find(',');
              const auto first = t.substr(0, comma);
              const auto face  = comma == std::string::npos ? std::string() : t.substr(comma + 1);
              const auto ids   = integers(first);
              const long last  = ids.empty() ? (elset_max.count(first) ? elset_max[first] : -1) :
                                               ids[0];
              long       k     = 0;
              if (face.size() > 1 && (face[0] == 'S' || face[0] == 'E'))
                try
                  {
                    k = std::stol(face.substr(1));
                  }
                catch (...)
                  {}
              if (last < 1 || last > n_elements || k < 1 || k > 2 * long(dim))
                reason = "its *SURFACE line '" + ErrorLine::quote(Utilities::trim(line), 40) +
                         "' names no element face of it (an element 1 to " +
                         std::to_string(n_elements) + " given above, or an *ELSET of them, "
                         "and a face S1 to S" + std::to_string(2 * dim) + ")";
            }
        }
      finish();
      if (!reason.empty())
        return reason;
      if (blocks.empty())
        return "it has no *ELEMENT block";
      const unsigned int nodes = dim == 2 ? 4 : 8;
      for (const auto &[kind, b] : blocks)
        {
          // 2D: 4 nodes and no 3D element (C3D4 is a tetrahedron); 3D: the
          // 8-node bricks C3D8, C3D8R, DC3D8, ...
          const bool fits = b.second == nodes && (dim == 2 ? kind.find("3D") == std::string::npos :
                                                             kind.find("3D8") != std::string::npos);
          if (!fits)
            return "it holds " + std::to_string(b.first) + " elements of type '" +
                   ErrorLine::quote(kind, 20) + "' (" + std::to_string(b.second) +
                   " nodes); the mesh must consist of " +
                   (dim == 2 ? "quadrilaterals (4 nodes, e.g. CPE4)" : "hexahedra (C3D8)") +
                   ", its boundary ids given as *SURFACE sets named with their number "
                   "(e.g. NAME=SS1)";
        }
      return "";
    }
  } // namespace


  template <int dim>
  MeshFile<dim>::MeshFile(const std::string &file_name)
    : file(file_name)
  {
    std::string text;
    try
      {
        text = TextFile::read(file, "mesh file", "");
      }
    catch (const InputError &e)
      {
        // the scene names the file: the error is the scene's
        AssertThrow(false, ExcMessage(std::string(e.what())));
      }
    std::string type = std::filesystem::path(file).extension().string();
    type             = type.empty() ? type : type.substr(1);
    std::transform(type.begin(), type.end(), type.begin(), [](const unsigned char c) {
      return std::tolower(c);
    });
    std::string known;
    for (const auto &[extension, format] : formats())
      known += (known.empty() ? "." : ", .") + extension + " (" + format.second + ")";
    AssertThrow(formats().count(type),
                ExcMessage(name() + " has " +
                           (type.empty() ? std::string("no extension") :
                                           "the extension '." + ErrorLine::quote(type, 20) + "'") +
                           "; read are " + known));
    AssertThrow(!Utilities::trim(text).empty(), ExcMessage(name() + " is empty"));
    // a UTF-8 byte order mark and CRLF (or CR) line ends read as the text
    // they stand for, in every format
    if (text.rfind("\xEF\xBB\xBF", 0) == 0)
      text.erase(0, 3);
    std::string plain;
    plain.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] != '\r')
        plain += text[i];
      else if (i + 1 == text.size() || text[i + 1] != '\n')
        plain += '\n';
    text.swap(plain);
    const std::string reason = check_text(text, type);
    AssertThrow(reason.empty(),
                ExcMessage(name() + (reason.rfind("line ", 0) == 0 ? ", " : " cannot be read: ") +
                           reason));
    // what deal.II's readers would crash, hang or be misled on
    const MeshCheck check(text, type, dim);
    AssertThrow(check.problem().empty(), ExcMessage(name() + check.problem()));

    try
      {
        read(text, type, mesh);
      }
    catch (const std::exception &e)
      {
        // GridIn turns cells of negative measure around and fails on a
        // cell whose measure is not positive either way
        AssertThrow(std::string(e.what()).find("invert_cells_with_negative_measure") ==
                      std::string::npos,
                    ExcMessage(name() + " holds a cell whose volume is not positive with "
                                        "either orientation (a twisted or flat cell; or a "
                                        "body so far from the origin against its size that "
                                        "double precision cannot resolve its cells)"));
        const std::string other = other_dimension(text, type);
        AssertThrow(other.empty(), ExcMessage(name() + " " + other));
        AssertThrow(false,
                    ExcMessage(name() + " cannot be read by deal.II's " +
                               formats().at(type).second + " reader: " + ErrorLine::text(e)));
      }

    // FE_Q and FE_RaviartThomas here live on quadrilaterals and hexahedra
    std::map<std::string, unsigned int> kinds;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const auto kind = cell->reference_cell();
        ++kinds[kind == ReferenceCells::Quadrilateral ? "quadrilateral" :
                kind == ReferenceCells::Hexahedron    ? "hexahedron" :
                kind == ReferenceCells::Triangle      ? "triangle" :
                kind == ReferenceCells::Tetrahedron   ? "tetrahedron" :
                kind == ReferenceCells::Wedge         ? "wedge" :
                                                        "pyramid"];
      }
    const std::string hypercube = dim == 2 ? "quadrilateral" : "hexahedron";
    if (kinds.size() > 1 || kinds.count(hypercube) == 0)
      {
        const std::map<std::string, std::string> plural = {{"quadrilateral", "quadrilaterals"},
                                                           {"hexahedron", "hexahedra"},
                                                           {"triangle", "triangles"},
                                                           {"tetrahedron", "tetrahedra"},
                                                           {"wedge", "wedges"},
                                                           {"pyramid", "pyramids"}};
        std::string holds;
        for (const auto &[kind, n] : kinds)
          holds += (holds.empty() ? "" : " and ") + count(n, kind, plural.at(kind));
        AssertThrow(false,
                    ExcMessage(name() + " holds " + holds + "; the mesh must consist of " +
                               (dim == 2 ? "quadrilaterals (Gmsh: Recombine Surface, or "
                                           "Mesh.RecombineAll = 1)" :
                                           "hexahedra (Gmsh: Mesh.SubdivisionAlgorithm = 2 "
                                           "makes hexahedra of tetrahedra; or extrude a "
                                           "recombined surface with Layers and Recombine)")));
      }
  }


  template <int dim>
  template <int d>
  void
  MeshFile<dim>::read(const std::string &text, const std::string &type, Triangulation<d> &tria)
  {
    std::istringstream in(text);
    GridIn<d>          grid_in(tria);
    // deal.II's Abaqus reader writes to std::cerr before it throws: the
    // error is reported once, in one line, by the caller
    std::ostringstream muted;
    struct CerrRestore
    {
      std::streambuf *buffer;
      ~CerrRestore() { std::cerr.rdbuf(buffer); }
    } restore{std::cerr.rdbuf(muted.rdbuf())};
    try
      {
        grid_in.read(in, static_cast<typename GridIn<d>::Format>(formats().at(type).first));
      }
    catch (const std::exception &)
      {
        // (its exception then says only that the message is above)
        const std::string above = muted.str();
        const auto        pos   = above.find("Additional information:");
        if (pos == std::string::npos)
          throw;
        const std::string info = above.substr(pos + 23);
        throw std::runtime_error(info.substr(0, info.find("-----")));
      }
  }


  template <int dim>
  std::string
  MeshFile<dim>::check_text(const std::string &text, const std::string &type) const
  {
    if (type == "msh")
      return check_gmsh(text);
    if (type == "inp")
      {
        const std::string reason = check_abaqus(text, dim);
        // a mesh of the other dimension is named as such
        if (!reason.empty() && check_abaqus(text, dim == 2 ? 3 : 2).empty())
          return "it holds a " + std::to_string(dim == 2 ? 3 : 2) +
                 "D mesh; set 'Geometry/Dimension' = " + std::to_string(dim == 2 ? 3 : 2);
        return reason;
      }
    return "";
  }


  template <int dim>
  std::string
  MeshFile<dim>::other_dimension(const std::string &text, const std::string &type) const
  {
    constexpr int other = dim == 2 ? 3 : 2;
    // (a file GridIn would crash or hang on as a mesh of the other
    // dimension is not read as one)
    if (!MeshCheck(text, type, other).problem().empty())
      return "";
    Triangulation<other> tria;
    try
      {
        read(text, type, tria);
      }
    catch (...)
      {
        return "";
      }
    return "holds a " + std::to_string(other) + "D mesh (" +
           std::to_string(tria.n_active_cells()) + " cells); set 'Geometry/Dimension' = " +
           std::to_string(other) +
           (dim == 3 ? " (or, if the file holds only the surface of a 3D body: Gmsh "
                       "saves only the elements of physical groups when there are any, so "
                       "put the volume into a Physical Volume)" :
                       "");
  }


  template <int dim>
  BoundingBox<dim>
  MeshFile<dim>::bounding_box() const
  {
    return GridTools::compute_bounding_box(mesh);
  }


  template <int dim>
  double
  MeshFile<dim>::distance_in_cells() const
  {
    double distance = 0, diameter = std::numeric_limits<double>::max();
    for (const auto &p : mesh.get_vertices())
      distance = std::max(distance, p.norm());
    for (const auto &cell : mesh.active_cell_iterators())
      diameter = std::min(diameter, cell->diameter());
    return distance / diameter;
  }


  template <int dim>
  std::string
  MeshFile<dim>::name() const
  {
    return "mesh file '" + ErrorLine::quote(file, 1000) + "'";
  }

  template class MeshFile<2>;
  template class MeshFile<3>;
} // namespace FoslsContact
