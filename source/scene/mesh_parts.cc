#include <fosls_contact/scene/mesh_parts.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

namespace FoslsContact
{
  template <int dim>
  void
  MeshParts<dim>::check(const Triangulation<dim> &                          tria,
                        const std::function<bool(const types::boundary_id)> &is_dirichlet,
                        const std::function<bool(const types::boundary_id)> &is_contact,
                        const double                                         length,
                        const std::string &                                  mesh)
  {
    // the parts: the cells joined through their inner faces (union-find)
    const unsigned int        n = tria.n_active_cells();
    std::vector<unsigned int> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&parent](unsigned int c) {
      while (parent[c] != c)
        c = parent[c] = parent[parent[c]];
      return c;
    };
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        // (a refined neighbour's children join this cell from their side)
        if (!cell->at_boundary(f) && !cell->neighbor(f)->has_children())
          {
            const unsigned int a = root(cell->active_cell_index());
            const unsigned int b = root(cell->neighbor(f)->active_cell_index());
            parent[std::max(a, b)] = std::min(a, b);
          }
    std::vector<unsigned int> cells(n, 0);
    std::vector<bool>         held(n, false), touches(n, false);
    unsigned int              n_parts = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int part = root(cell->active_cell_index());
        n_parts += part == cell->active_cell_index();
        ++cells[part];
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              held[part]    = held[part] || is_dirichlet(cell->face(f)->boundary_id());
              touches[part] = touches[part] || is_contact(cell->face(f)->boundary_id());
            }
      }
    if (n_parts < 2)
      return;
    // the first part that nothing holds, named by the centre of its first cell
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int part = root(cell->active_cell_index());
        if (held[part] || part != cell->active_cell_index())
          continue;
        std::ostringstream text;
        text.precision(6);
        text << mesh << " has " << n_parts
             << " parts that are not connected through faces (cells that meet at most at a "
                "vertex or an edge are not connected), and the part of "
             << cells[part] << (cells[part] == 1 ? " cell" : " cells") << " around (";
        for (unsigned int d = 0; d < dim; ++d)
          text << (d ? ", " : "") << length * cell->center()[d];
        text << ") "
             << (touches[part] ?
                   "has a contact boundary but no Dirichlet boundary: it is not held against "
                   "rigid motion (the frictionless obstacle bounds it from one side only)" :
                   "has no Dirichlet and no contact boundary: nothing holds it against rigid "
                   "motion")
             << "; give it a Dirichlet boundary id of its own ('Boundary conditions/Dirichlet "
                "boundary ids'), or connect it to the rest of the mesh through a face";
        AssertThrow(false, ExcMessage(text.str()));
      }
  }

  template struct MeshParts<2>;
  template struct MeshParts<3>;
} // namespace FoslsContact
