// Checks the coarse meshes from files (Geometry/Shape = file, MeshFile and
// BoundaryManifolds) against the built-in curved bodies (CurvedBody):
//  - every format by extension: the built-in half disc (2D) and half ball
//    (3D), written by deal.II's GridOut as .msh (Gmsh format 1), .ucd,
//    .vtk and .vtu, read back with the same cells, vertices and number of
//    boundary faces per id;
//  - the manifold option: a mesh file of the built-in body with the body's
//    surface given in Geometry/Manifolds, refined, has the built-in body's
//    vertices (sphere: the quarter ball of prm/meshes/quarter_ball.msh
//    against the half ball of prm/half_ball.prm; cylinder: the half
//    cylinder of prm/half_cylinder.prm written to a file), and the
//    vertices of its curved faces lie on the surface on the finest level
//    (also for Gmsh's unstructured half disc); without the option the
//    faces stay flat and the vertices do not.
// The files are written into the test's directory.
// ctest: timeout=120
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>

#include <fosls_contact/scene/curved_body.h>
#include <fosls_contact/scene/mesh_file.h>
#include <fosls_contact/scene/scene.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "tests.h"

using namespace FoslsContactTests;

/** The number of boundary faces per boundary id. */
template <int dim>
std::map<types::boundary_id, unsigned int>
faces_per_id(const Triangulation<dim> &tria)
{
  std::map<types::boundary_id, unsigned int> n;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        ++n[face->boundary_id()];
  return n;
}

template <int dim>
std::string
text(const std::map<types::boundary_id, unsigned int> &n)
{
  std::string s;
  for (const auto &[id, count] : n)
    s += (s.empty() ? "" : ", ") + std::to_string(id) + ": " + std::to_string(count);
  return s;
}

/** The largest distance of a vertex of @p a from the closest of @p b. */
template <int dim>
double
vertex_distance(const Triangulation<dim> &a, const Triangulation<dim> &b)
{
  double largest = 0;
  for (const auto &p : a.get_vertices())
    {
      double closest = std::numeric_limits<double>::max();
      for (const auto &q : b.get_vertices())
        closest = std::min(closest, p.distance(q));
      largest = std::max(largest, closest);
    }
  return largest;
}


template <int dim>
void
formats(const std::string &scene)
{
  const auto       parameters = make_parameters(scene_file(scene));
  Triangulation<dim> body;
  CurvedBody::make(parameters.geometry, 1., body);
  std::cout << "--- " << dim << "D, the coarse mesh of " << scene << ": " << body.n_active_cells()
            << " cells, boundary faces per id " << text<dim>(faces_per_id(body)) << std::endl;
  GridOut out;
  out.set_flags(GridOutFlags::Msh(true, true));
  out.set_flags(GridOutFlags::Ucd(false, true, true));
  out.set_flags(GridOutFlags::Vtu(true));
  for (const std::string format : {"msh", "ucd", "vtk", "vtu"})
    {
      const std::string file =
        std::filesystem::absolute("body" + std::to_string(dim) + "d." + format).string();
      {
        std::ofstream stream(file);
        stream.precision(17);
        out.write(body, stream, GridOut::parse_output_format(format));
      }
      const MeshFile<dim> mesh(file);
      const auto &        read = mesh.triangulation();
      check(read.n_active_cells() == body.n_active_cells() &&
              read.n_used_vertices() == body.n_used_vertices(),
            "." + format + ": the same number of cells and vertices");
      check(faces_per_id(read) == faces_per_id(body),
            "." + format + ": the same number of boundary faces per id");
      check(vertex_distance(read, body) < 1e-12 && vertex_distance(body, read) < 1e-12,
            "." + format + ": the same vertices");
    }
}


/** The largest and smallest distance of the vertices of @p id's faces from the surface. */
template <int dim>
std::pair<double, double>
off_surface(const Triangulation<dim> &tria,
            const types::boundary_id  id,
            const Point<dim> &        center,
            const double              radius,
            const bool                cylinder)
{
  double largest = 0, smallest = std::numeric_limits<double>::max();
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        for (const unsigned int v : face->vertex_indices())
          {
            Tensor<1, dim> d = face->vertex(v) - center;
            if (cylinder)
              d[dim - 1] = 0;
            largest  = std::max(largest, std::abs(d.norm() - radius));
            smallest = std::min(smallest, d.norm());
          }
  return {largest, smallest};
}


/**
 * The scene @p scene with @p overrides, its coarse mesh refined @p n times
 * (in the scene's units).
 */
template <int dim>
void
refined(const std::string &                                     scene,
        const std::vector<std::pair<std::string, std::string>> &overrides,
        const unsigned int                                      n,
        Triangulation<dim> &                                    tria)
{
  const Scene<dim> s(make_parameters(scene_file(scene), overrides));
  s.make_coarse_mesh(tria);
  tria.refine_global(n);
  GridTools::scale(s.scaling().length, tria);
}


void
manifolds()
{
  const std::string meshes = std::string(FOSLS_SOURCE_DIR) + "/tests/meshes/";
  {
    std::cout << "--- 2D, Gmsh's unstructured half disc, refined 3 times" << std::endl;
    const std::vector<std::pair<std::string, std::string>> file = {
      {"Geometry/Shape", "file"},
      {"Geometry/Mesh file", meshes + "half_disc_unstructured_v2.msh"},
      {"Boundary conditions/Dirichlet boundary ids", "2"},
      {"Boundary conditions/Contact boundary ids", "1"}};
    auto with = file;
    with.emplace_back("Geometry/Manifolds", "1: sphere 0, 1 radius 0.5");
    Triangulation<2> curved, flat;
    refined<2>("hertz.prm", with, 3, curved);
    refined<2>("hertz.prm", file, 3, flat);
    const auto on  = off_surface(curved, 1, Point<2>(0, 1), 0.5, false);
    const auto off = off_surface(flat, 1, Point<2>(0, 1), 0.5, false);
    check(on.first < 1e-12, "with the circle, the curved side's vertices lie on it");
    std::cout << "without: the closest to the center at " << rounded(off.second, 4) << std::endl;
    check(off.second < 0.5 * (1 - 1e-3), "without, they do not (chords)");
  }
  {
    std::cout << "--- 3D, prm/quarter_ball_file.prm against prm/half_ball.prm, refined 2 times"
              << std::endl;
    const std::vector<std::pair<std::string, std::string>> file = {
      {"Geometry/Mesh file", std::string(FOSLS_SOURCE_DIR) + "/prm/meshes/quarter_ball.msh"}};
    Triangulation<3> quarter, half, flat;
    refined<3>("quarter_ball_file.prm", file, 2, quarter);
    refined<3>("half_ball.prm", {}, 2, half);
    auto without = file;
    without.emplace_back("Geometry/Manifolds", "");
    refined<3>("quarter_ball_file.prm", without, 2, flat);
    const Point<3> center(0, 0, 1);
    check(off_surface(quarter, 1, center, 0.5, false).first < 1e-12,
          "with the sphere, the curved surface's vertices lie on it");
    check(vertex_distance(quarter, half) < 1e-12,
          "with the sphere, the quarter's vertices are the half ball's");
    std::cout << "without: the closest to the center at "
              << rounded(off_surface(flat, 1, center, 0.5, false).second, 4) << std::endl;
    check(vertex_distance(flat, half) > 1e-3, "without, they are not");
  }
  {
    std::cout << "--- 3D, prm/half_cylinder.prm from a file, refined 2 times" << std::endl;
    const auto       parameters = make_parameters(scene_file("half_cylinder.prm"));
    Triangulation<3> body;
    CurvedBody::make(parameters.geometry, 1., body);
    const std::string name = std::filesystem::absolute("half_cylinder.msh").string();
    {
      std::ofstream stream(name);
      stream.precision(17);
      GridOut out;
      out.set_flags(GridOutFlags::Msh(true, true));
      out.write_msh(body, stream);
    }
    const std::vector<std::pair<std::string, std::string>> file = {{"Geometry/Shape", "file"},
                                                                   {"Geometry/Mesh file", name}};
    auto with = file;
    with.emplace_back("Geometry/Manifolds", "0: cylinder 0, 1, 0 direction 0, 0, 1 radius 0.5");
    Triangulation<3> curved, flat, built_in;
    refined<3>("half_cylinder.prm", with, 2, curved);
    refined<3>("half_cylinder.prm", file, 2, flat);
    refined<3>("half_cylinder.prm", {}, 2, built_in);
    const Point<3> axis(0, 1, 0);
    check(off_surface(curved, 0, axis, 0.5, true).first < 1e-12,
          "with the cylinder, the curved side's vertices lie on it");
    check(vertex_distance(curved, built_in) < 1e-12 && vertex_distance(built_in, curved) < 1e-12,
          "with the cylinder, the vertices are the built-in half cylinder's");
    std::cout << "without: the closest to the axis at "
              << rounded(off_surface(flat, 0, axis, 0.5, true).second, 4) << std::endl;
    check(off_surface(flat, 0, axis, 0.5, true).first > 1e-3, "without, they are not on it");
  }
}


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  formats<2>("hertz.prm");
  formats<3>("half_ball.prm");
  manifolds();
  return exit_code();
}
