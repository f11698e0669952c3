#ifndef fosls_contact_scene_mesh_check_h
#define fosls_contact_scene_mesh_check_h

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

namespace FoslsContact
{
  /**
   * The nodes and cells of a mesh file (.msh, .inp, .ucd or .vtk), read
   * from its text here, before deal.II's GridIn sees it, and the checks
   * that GridIn does not make.
   *
   * deal.II's readers trust the file: a cell that names a node past the
   * points (VTK, AVS UCD) is an index out of range in
   * GridTools::delete_unused_vertices (a crash), a count larger than the
   * lines that follow is read on for as long as the stream lasts (a Gmsh
   * 4.1 header over a format 2 body took minutes), a coordinate that is no
   * number ends the section early (so the error names the next section),
   * and a cell listed twice hangs GridTools::consistently_order_cells (its
   * nodes rotated) or gives a mesh of two layers (in the same order). What
   * reads as a mesh but is none is refused too: a 2D mesh that does not
   * lie in the plane z = 0 (GridIn drops z), and a mesh that is not
   * conforming, which the program would take as a body with cracks or
   * with two layers.
   *
   * So the file is read in its own structure: every section's counts
   * against the lines that are there, every coordinate a finite double,
   * every node a cell names present in the file, the number of nodes of
   * every element of the types the program reads (lines, triangles,
   * quadrilaterals, tetrahedra, hexahedra, points), every physical tag
   * (Gmsh) or material (AVS UCD) a number from 0, and at most the largest
   * boundary id 'Boundary conditions' accepts where it is the id of a
   * boundary face (deal.II's Gmsh reader takes -1 as id 0). Then, if the file
   * holds cells of the scene's dimension that are all quadrilaterals (2D)
   * or hexahedra (3D), the mesh:
   *  - in 2D, every node of a cell at z = 0;
   *  - no cell that lists a node twice, and no two cells with the same
   *    nodes (in any order);
   *  - no edge (2D) or face (3D) shared by more than two cells;
   *  - no node of a cell lying on another cell other than as one of that
   *    cell's nodes: at one of its corners, the two nodes are one point
   *    listed twice (the cells are not connected there); on one of its
   *    edges or faces, a hanging node (the mesh is not conforming); inside
   *    it, the cells overlap. The centre of each cell is tested the same
   *    way against the other cells (two cells that overlap without a node
   *    of one inside the other). "On" is to 1e-6 of the cell's size, in
   *    the cell's reference coordinates (found by Newton's method on its
   *    bilinear or trilinear map), so that meshes far from the origin
   *    pass.
   *
   * A file of the other dimension, or of triangles or tetrahedra, is left
   * to the checks after GridIn, which name it as such. Every problem is one
   * line, with the line of the file it is on where there is one.
   */
  class MeshCheck
  {
  public:
    /**
     * Read the @p text of a file of the extension @p type ("msh", "inp",
     * "ucd" or "vtk"; any other is not checked) for a mesh of dimension
     * @p dim, and check it.
     */
    MeshCheck(const std::string &text, const std::string &type, const unsigned int dim);

    /**
     * Why the file is no mesh the program can take, to follow the file's
     * name (", line 12: ...", " cannot be read: ..." or " is not
     * conforming: ..."), or "".
     */
    const std::string &problem() const { return reason; }

  private:
    /** The element types the readers know (Gmsh's numbering of them). */
    enum Kind
    {
      line          = 1,
      triangle      = 2,
      quadrilateral = 3,
      tetrahedron   = 4,
      hexahedron    = 5,
      point         = 15
    };

    struct Node
    {
      std::array<double, 3> x;
      unsigned int          line;  // of the file, from 1
      long                  label; // its number in the file
    };

    struct Cell
    {
      Kind                      kind;
      std::vector<unsigned int> nodes; // indices into nodes, in the file's (cyclic) order
      unsigned int              line;
      long                      label;
    };

    /** The parsers: "" or "line N: why". */
    std::string read_gmsh(const std::vector<std::string> &lines);
    std::string read_vtk(const std::vector<std::string> &lines);
    std::string read_ucd(const std::vector<std::string> &lines);
    std::string read_abaqus(const std::vector<std::string> &lines);

    /** A Gmsh file's format and the names of its sections (mesh_check.cc). */
    struct GmshFormat;
    /**
     * The nodes of a Gmsh file of @p format ($Nodes; $NOD in format 1), in
     * its entity blocks from format 4 on: "" or why not.
     */
    std::string read_gmsh_nodes(const std::vector<std::string> &lines, const GmshFormat &format);
    /** Its elements ($Elements; $ELM in format 1), the same way. */
    std::string read_gmsh_elements(const std::vector<std::string> &lines,
                                   const GmshFormat &              format);
    /**
     * The element of the @p words of the @p line at @p line_number, of
     * the @p type of its entity block (format 4; before 4 the line gives
     * its type and physical tag): added with add_cell() if it is a cell or
     * boundary face the program knows, "" or why not.
     */
    std::string read_gmsh_element(const std::vector<std::string> &words,
                                  const std::string &             line,
                                  const unsigned int              line_number,
                                  const GmshFormat &              format,
                                  long                            type);

    /**
     * The physical tags of a Gmsh 4 file's $Entities section, which become
     * the boundary ids of the faces (and the material ids of the cells) of
     * each entity: "" or why one is no id the program can take.
     */
    std::string read_gmsh_entities(const std::vector<std::string> &lines, const int version) const;

    /**
     * "" or why the physical tag @p tag of an element (or entity) of
     * dimension @p element_dim is no id the program can take: negative (a
     * boundary id is a number from 0), or, on a boundary face, above the
     * ids 'Boundary conditions' accepts. @p what names the element and the
     * tag's kind ("line 9: element 3 has the physical tag").
     */
    std::string physical_tag_problem(const long         tag,
                                     const unsigned int element_dim,
                                     const std::string &what) const;

    /**
     * Add the node labelled @p label at @p line with the coordinate tokens
     * @p coordinates (2 or 3): "" or why not.
     */
    std::string add_node(const long                      label,
                         const std::vector<std::string> &coordinates,
                         const unsigned int              line);

    /**
     * Add a cell of @p kind with the node labels @p labels: "" or why
     * not (a node the file does not have; the wrong number of nodes).
     */
    std::string add_cell(const Kind                      kind,
                         const std::vector<std::string> &labels,
                         const long                      label,
                         const unsigned int              line);

    /** The checks of the mesh once read: "" or why it is none. */
    std::string check_mesh() const;

    /**
     * A hexahedron whose sides bend across a diagonal (its upper face
     * listed rotated): "" or why the mesh is none. @p sides are the
     * hexahedron's sides as cyclic lists of its node positions.
     */
    std::string check_twist(const std::vector<unsigned int> &             mesh_cells,
                            const std::vector<std::vector<unsigned int>> &sides) const;

    /** The checks by position: coincident nodes, hanging nodes, overlaps. */
    std::string check_geometry(const std::vector<unsigned int> &mesh_cells) const;
    /** The points to test, and where they are (mesh_check.cc). */
    struct TestPoints;
    /** The nodes and centres of the @p mesh_cells, and the cells' corners and sizes. */
    TestPoints test_points(const std::vector<unsigned int> &mesh_cells) const;
    /**
     * "" or why the test point near cell @p i of @p mesh_cells that lies in
     * it (and is none of its nodes) makes the mesh no mesh: a second node
     * at a corner, a hanging node on a side, or an overlap.
     */
    std::string points_in_cell(const std::vector<unsigned int> &mesh_cells,
                               const TestPoints &               points,
                               const unsigned int               i) const;

    /** "element 3 (line 30)" */
    std::string describe(const Cell &cell) const;
    /** "node 5 (line 9)" */
    std::string describe(const Node &node) const;

    const unsigned int dim;
    /** "node" or "point"; "element" or "cell": the file format's words. */
    std::string node_word, cell_word;
    /** Labels are positions from 0 (VTK) instead of names. */
    bool by_position = false;

    std::vector<Node> nodes;
    std::vector<Cell> cells;
    /** The node of each label. */
    std::unordered_map<long, unsigned int> labels;

    std::string reason;
  };
} // namespace FoslsContact

#endif
