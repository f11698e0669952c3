// The distributed mesh that Discretization<dim> builds from the scene's
// serial coarse mesh (Scene::make_coarse_mesh):
//  - its mesh smoothing includes limit_level_difference_at_vertices, which
//    DoFHandler::distribute_mg_dofs() requires (deal.II's debug build
//    checks it there). The serial coarse mesh has no smoothing, so a copy
//    that takes the serial mesh's smoothing loses it; and deal.II allows a
//    mesh's smoothing to be set only while the mesh is empty, so it cannot
//    be restored once the cells are there.
//  - its coarse level is the serial coarse mesh: the same cells with the
//    same vertices, material and manifold ids, boundary and manifold ids of
//    the faces (in 3D of the lines too);
//  - the manifolds came along: the finest level's vertices are those of
//    the serial coarse mesh refined as often with its manifolds, and not
//    those of the flat refinement (checked to differ on curved bodies, so
//    the check can fail).
// For a box, the half disc, the half ball and a mesh file with manifolds
// from the parameter file. One MPI process: every cell is here.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <fosls_contact/discretization/discretization.h>

#include <algorithm>
#include <limits>

#include "tests.h"

using namespace FoslsContactTests;

/**
 * The largest distance of a vertex of the active cells of @p a from the
 * nearest vertex of the active cells of @p b, and the other way round (0:
 * the same vertex sets).
 */
template <int dim>
double
vertex_set_distance(const Triangulation<dim> &a, const Triangulation<dim> &b)
{
  const auto vertices = [](const Triangulation<dim> &tria) {
    std::vector<bool> used(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        used[cell->vertex_index(v)] = true;
    std::vector<Point<dim>> points;
    for (unsigned int v = 0; v < used.size(); ++v)
      if (used[v])
        points.push_back(tria.get_vertices()[v]);
    return points;
  };
  const auto one_way = [](const std::vector<Point<dim>> &from, const std::vector<Point<dim>> &to) {
    double largest = 0;
    for (const auto &p : from)
      {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto &q : to)
          nearest = std::min(nearest, p.distance(q));
        largest = std::max(largest, nearest);
      }
    return largest;
  };
  const auto va = vertices(a), vb = vertices(b);
  if (va.size() != vb.size())
    return std::numeric_limits<double>::infinity();
  return std::max(one_way(va, vb), one_way(vb, va));
}


/** Whether the coarse cells of @p a and @p b agree in everything the mesh description holds. */
template <int dim>
bool
same_coarse_cells(const Triangulation<dim> &a, const Triangulation<dim> &b)
{
  if (a.n_cells(0) != b.n_cells(0))
    return false;
  auto cb = b.begin(0);
  for (auto ca = a.begin(0); ca != a.end(0); ++ca, ++cb)
    {
      if (ca->material_id() != cb->material_id() || ca->manifold_id() != cb->manifold_id())
        return false;
      for (const unsigned int v : ca->vertex_indices())
        if (ca->vertex(v).distance(cb->vertex(v)) != 0.)
          return false;
      for (const unsigned int f : ca->face_indices())
        if (ca->face(f)->boundary_id() != cb->face(f)->boundary_id() ||
            ca->face(f)->manifold_id() != cb->face(f)->manifold_id())
          return false;
      for (unsigned int l = 0; dim == 3 && l < ca->n_lines(); ++l)
        if (ca->line(l)->manifold_id() != cb->line(l)->manifold_id())
          return false;
    }
  return true;
}


template <int dim>
void
test(const std::string &                                     name,
     const std::string &                                     file,
     const unsigned int                                      n_levels,
     const std::vector<std::pair<std::string, std::string>> &overrides,
     const bool                                              curved)
{
  const Scene<dim>          scene(make_parameters(scene_file(file), overrides));
  const Discretization<dim> discretization(scene, n_levels, MPI_COMM_WORLD);
  const auto &              distributed = discretization.get_triangulation();

  Triangulation<dim> coarse;
  scene.make_coarse_mesh(coarse);
  Triangulation<dim> refined, flat;
  refined.copy_triangulation(coarse);
  refined.refine_global(n_levels - 1);
  flat.copy_triangulation(coarse);
  flat.reset_all_manifolds();
  flat.refine_global(n_levels - 1);

  std::cout << "--- " << name << ", " << n_levels << " levels: " << coarse.n_active_cells()
            << " coarse cells, " << distributed.n_active_cells() << " finest cells" << std::endl;
  check((distributed.get_mesh_smoothing() &
         Triangulation<dim>::limit_level_difference_at_vertices) != 0,
        "mesh smoothing includes limit_level_difference_at_vertices");
  check(same_coarse_cells(static_cast<const Triangulation<dim> &>(distributed), coarse),
        "coarse level = the scene's coarse mesh (vertices, material, boundary and manifold ids)");
  const double size = GridTools::diameter(coarse);
  check(vertex_set_distance(static_cast<const Triangulation<dim> &>(distributed), refined) <=
          1e-14 * size,
        "finest level = the coarse mesh refined with its manifolds (vertices within 1e-14 of its size)");
  if (curved)
    check(vertex_set_distance(refined, flat) > 1e-3 * size,
          "the flat refinement differs (by more than 1e-3 of the size)");
}


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  test<2>("square (box)", "square.prm", 3, {}, false);
  test<2>("half disc", "hertz.prm", 3, {}, true);
  test<3>("cube (box)", "cube3d.prm", 2, {}, false);
  test<3>("half ball", "half_ball.prm", 2, {}, true);
  test<3>("quarter ball from a mesh file",
          "quarter_ball_file.prm",
          2,
          {{"Geometry/Mesh file", std::string(FOSLS_SOURCE_DIR) + "/prm/meshes/quarter_ball.msh"}},
          true);
  return exit_code();
}
