#ifndef fosls_contact_scene_mesh_file_h
#define fosls_contact_scene_mesh_file_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A coarse mesh read from a file (Geometry/Shape = file), in the scene's
   * units, with the file's boundary ids.
   *
   * deal.II's GridIn reads it, chosen by the file's extension: .msh (Gmsh
   * ASCII, formats 1, 2, 4.0 and 4.1: deal.II's own stream reader reads
   * all of them), .inp (Abaqus; deal.II's default for .inp would be AVS
   * UCD), .ucd, .vtk and .vtu. GridIn orders the cells of a quadrilateral
   * or hexahedral mesh consistently (GridTools::consistently_order_cells),
   * which the Raviart-Thomas level transfer needs, and turns cells of
   * negative measure around.
   *
   * GridIn trusts the nodes and cells of the file: MeshCheck reads them
   * before it does (indices, counts, coordinates, cells twice, hanging
   * nodes, overlaps). A UTF-8 byte order mark and CRLF (or CR) line ends
   * are made plain first: GridIn's VTK reader compares its header lines
   * whole.
   *
   * What GridIn cannot say in terms of the file is checked here, so that
   * every problem is one line that names the file: a file that cannot be
   * read (with the reason), an unknown extension, a binary or unknown Gmsh
   * version (deal.II's reader does not check them in a release build and
   * would read garbage), Abaqus elements that are not quadrilaterals or
   * hexahedra (deal.II's Abaqus reader reads every element as one, whatever
   * its type), a mesh of the other dimension, and cells that are not
   * quadrilaterals or hexahedra (GridIn reads triangles and tetrahedra,
   * which FE_Q and FE_RaviartThomas on hypercubes cannot use).
   */
  template <int dim>
  class MeshFile
  {
  public:
    /** Read @p file; every problem is an exception with one line naming it. */
    explicit MeshFile(const std::string &file);

    /** The mesh, in the scene's units. */
    const Triangulation<dim> &triangulation() const { return mesh; }

    /** The axis-parallel box around all vertices. */
    BoundingBox<dim> bounding_box() const;

    /** "mesh file '<name>'", for messages. */
    std::string name() const;

    /**
     * The largest distance of a vertex from the origin per smallest cell
     * diameter. GridIn computes the cells' volumes from the absolute
     * coordinates, to turn negative ones around: above about 1e5 the
     * round-off of these products reaches the volume of the smallest cell
     * and a cell can be turned inside out (doc/performance.md, "Figures behind the code").
     */
    double distance_in_cells() const;

  private:
    /** Read the @p text of the file into @p tria (GridIn's exceptions pass). */
    template <int d>
    static void read(const std::string &text, const std::string &type, Triangulation<d> &tria);

    /**
     * The one-line reason why the .msh or .inp @p text cannot be a mesh of
     * this dimension, or "" (checks GridIn does not make).
     */
    std::string check_text(const std::string &text, const std::string &type) const;

    /** What the file holds instead, if it reads as a mesh of the other dimension. */
    std::string other_dimension(const std::string &text, const std::string &type) const;

    const std::string  file;
    Triangulation<dim> mesh;
  };
} // namespace FoslsContact

#endif
