#include <deal.II/base/mpi.h>

#include <fosls_contact/solvers/vertex_patches.h>

#include <algorithm>
#include <map>
#include <set>

namespace FoslsContact
{
  template <int dim>
  bool
  VertexKey<dim>::operator<(const VertexKey &other) const
  {
    if (creation_level != other.creation_level)
      return creation_level < other.creation_level;
    if (kind != other.kind)
      return kind < other.kind;
    for (unsigned int d = 0; d < dim; ++d)
      if (position[d] != other.position[d])
        return position[d] < other.position[d];
    return false;
  }


  template <int dim, typename CellIterator>
  VertexKey<dim>
  vertex_key(const CellIterator &cell, const unsigned int v)
  {
    VertexKey<dim> key;
    key.position = cell->vertex(v);
    // Walk up while the vertex is a vertex of the parent: child c of an
    // isotropically refined cell has the parent's vertex c as its vertex
    // c; its vertex v != c lies at the midpoint of the parent along the
    // axes where the bits of c and v differ.
    auto         c      = cell;
    unsigned int vertex = v;
    while (c->level() > 0)
      {
        const auto         parent = c->parent();
        const unsigned int child  = parent->child_iterator_to_index(c);
        if (vertex == child)
          {
            c = parent;
            continue;
          }
        const unsigned int bits = child ^ vertex;
        const unsigned int n    = __builtin_popcount(bits);
        key.creation_level      = c->level();
        if (n == dim)
          {
            key.kind = (dim - 1) * dim + 1; // cell center
            return key;
          }
        // the parent line from vertex `child` along the one bit, or (3D)
        // the normal of the parent face through `child` spanned by the two
        // bits, as the cross product of its diagonals: the same vectors,
        // up to sign, from every cell that shares the line or face
        Tensor<1, dim> direction;
        if (n == 1)
          direction = parent->vertex(child ^ bits) - parent->vertex(child);
        else
          {
            const unsigned int b1 = bits & (~bits + 1), b2 = bits ^ b1;
            Tensor<1, 3>       d1, d2;
            const auto         p1 = parent->vertex(child ^ bits) - parent->vertex(child);
            const auto         p2 = parent->vertex(child ^ b1) - parent->vertex(child ^ b2);
            for (unsigned int d = 0; d < dim; ++d)
              d1[d] = p1[d], d2[d] = p2[d];
            const Tensor<1, 3> normal = cross_product_3d(d1, d2);
            for (unsigned int d = 0; d < dim; ++d)
              direction[d] = normal[d];
          }
        unsigned int axis = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(direction[d]) > std::abs(direction[axis]))
            axis = d;
        key.kind = (n - 1) * dim + 1 + axis;
        return key;
      }
    return key; // a vertex of the coarse mesh
  }


  template <int dim>
  std::vector<unsigned int>
  VertexPatches<dim>::level_schedule(
    const std::vector<std::vector<unsigned int>> &           coupled,
    const std::vector<types::global_dof_index> &             color_dof,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    // the color of item p travels in the local DoF color_dof[p] (-1: not
    // known yet); its owner decides it once the colors of all earlier items
    // coupled with it are known
    const unsigned int n_owned = partitioner->locally_owned_size();
    LevelVector        color(partitioner);
    color = -1.;
    for (;;)
      {
        update_ghosts(color);
        unsigned int pending = 0;
        for (unsigned int p = 0; p < coupled.size(); ++p)
          if (color_dof[p] < n_owned && color.local_element(color_dof[p]) < 0)
            {
              double c     = 0;
              bool   known = true;
              for (const unsigned int q : coupled[p])
                if (q < p)
                  {
                    const double cq = color.local_element(color_dof[q]);
                    known &= cq >= 0;
                    c = std::max(c, cq + 1);
                  }
              if (known)
                color.local_element(color_dof[p]) = c;
              else
                ++pending;
            }
        if (Utilities::MPI::sum(pending, partitioner->get_mpi_communicator()) == 0)
          break;
      }
    update_ghosts(color);
    std::vector<unsigned int> result(coupled.size());
    for (unsigned int p = 0; p < coupled.size(); ++p)
      result[p] = static_cast<unsigned int>(color.local_element(color_dof[p]));
    return result;
  }


  namespace
  {
    constexpr unsigned int none = numbers::invalid_unsigned_int;

    /**
     * The vertices of the cells here, the items of the level scheduling,
     * in VertexKey order, and the DoFs the patch of each vertex of a cell
     * this process owns gathers from its cells (with repetitions). The DoFs are gathered
     * in one array (counted, then filled), not in a container per patch,
     * whose many small blocks outlived the constructor as holes in the
     * heap.
     */
    template <int dim>
    struct LevelVertices
    {
      LevelVertices(const DoFHandler<dim> &      dof_handler,
                    const LevelData<dim> &       data,
                    const PatchDofsInCell<dim> &in_cell);

      /** The vertices with their keys, sorted by key. */
      std::vector<std::pair<VertexKey<dim>, unsigned int>> order;
      /** Of every vertex: its position in order (none if no cell here has it). */
      std::vector<unsigned int> position;
      /** The DoFs of vertex v's patch: gathered[start[v] .. start[v+1]). */
      std::vector<std::size_t>             start;
      std::vector<types::global_dof_index> gathered;
    };


    template <int dim>
    LevelVertices<dim>::LevelVertices(const DoFHandler<dim> &      dof_handler,
                                      const LevelData<dim> &       data,
                                      const PatchDofsInCell<dim> &in_cell)
      : position(dof_handler.get_triangulation().n_vertices(), none)
      , start(dof_handler.get_triangulation().n_vertices() + 1, 0)
    {
      const unsigned int       n_vertices = dof_handler.get_triangulation().n_vertices();
      // (LevelData::for_patches_at(): a vertex's patch, and with hanging
      // nodes eliminated a master's patch takes the DoFs of the cells at
      // its hanging vertices too, the support of its basis function;
      // without them the divergence-free functions of the stress around a
      // hanging vertex, the curls of the masters' basis functions, belong
      // to no patch, and an adaptive hierarchy whose coarser levels keep
      // hanging vertices where the finest has them stalls)
      data.for_each_cell(dof_handler, [&](const auto &cell) {
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int vertex = cell->vertex_index(v);
            if (position[vertex] == none)
              {
                position[vertex] = order.size();
                order.emplace_back(vertex_key<dim>(cell, v), vertex);
              }
            data.for_patches_at(vertex, [&](const unsigned int p) { start[p + 1] += in_cell[v].size(); });
          }
      });
      for (unsigned int vertex = 0; vertex < n_vertices; ++vertex)
        start[vertex + 1] += start[vertex];
      gathered.resize(start.back());
      std::vector<types::global_dof_index> dofs;
      std::vector<std::size_t>             next(start.begin(), start.end() - 1);
      data.for_each_cell(dof_handler, [&](const auto &cell) {
        data.get_local_dofs(cell, dofs);
        for (const unsigned int v : cell->vertex_indices())
          data.for_patches_at(cell->vertex_index(v), [&](const unsigned int p) {
            for_patch_dofs_in_cell(in_cell, dofs, v, [&](const auto dof) {
              gathered[next[p]++] = dof;
            });
          });
      });
      // (distinct vertices have distinct keys; the index only makes the
      // order independent of the cell order should two ever tie)
      std::sort(order.begin(), order.end(), [](const auto &a, const auto &b) {
        return a.first < b.first || (!(b.first < a.first) && a.second < b.second);
      });
      for (unsigned int p = 0; p < order.size(); ++p)
        position[order[p].second] = p;
    }


    /**
     * For every item of @p vertices, the items it is coupled with: patches
     * are coupled if their vertices share a cell. With hanging nodes
     * eliminated (an adaptive mesh) a cell also couples the masters of its
     * constrained DoFs, which lie on the coarse neighbour's face or edge:
     * the patches of the master's vertex (a displacement DoF) or of its
     * face's vertices (an RT DoF) are coupled with the cell's too.
     */
    template <int dim>
    std::vector<std::vector<unsigned int>>
    coupled_items(const DoFHandler<dim> &      dof_handler,
                  const LevelData<dim> &       data,
                  const PatchDofsInCell<dim> &in_cell,
                  const LevelVertices<dim> &   vertices_here)
    {
      std::map<types::global_dof_index, std::set<unsigned int>> master_vertices;
      for (const auto &[dof, masters] : data.hanging)
        for (const auto &master : masters)
          master_vertices[master.first];
      std::vector<types::global_dof_index> dofs;
      if (!master_vertices.empty())
        data.for_each_cell(dof_handler, [&](const auto &cell) {
          data.get_local_dofs(cell, dofs);
          for (const unsigned int v : cell->vertex_indices())
            for_patch_dofs_in_cell(in_cell, dofs, v, [&](const auto dof) {
              const auto m = master_vertices.find(dof);
              if (m != master_vertices.end())
                m->second.insert(cell->vertex_index(v));
            });
        });
      const std::vector<unsigned int> &      position = vertices_here.position;
      std::vector<std::vector<unsigned int>> coupled(vertices_here.order.size());
      std::vector<unsigned int>              vertices;
      data.for_each_cell(dof_handler, [&](const auto &cell) {
        vertices.clear();
        for (const unsigned int v : cell->vertex_indices())
          vertices.push_back(cell->vertex_index(v));
        if (!master_vertices.empty())
          {
            data.get_local_dofs(cell, dofs);
            for (const auto dof : dofs)
              {
                const auto h = data.hanging.find(dof);
                if (h != data.hanging.end())
                  for (const auto &master : h->second)
                    for (const unsigned int w : master_vertices.at(master.first))
                      vertices.push_back(w);
              }
          }
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        for (const unsigned int v : vertices)
          for (const unsigned int w : vertices)
            if (v != w)
              coupled[position[v]].push_back(position[w]);
      });
      return coupled;
    }
  } // namespace


  template <int dim>
  VertexPatches<dim>::VertexPatches(const Discretization<dim> &discretization,
                                    const unsigned int         l)
  {
    // Vertex patches in the order of their VertexKey, and their colors. A
    // process relaxes the patches with a DoF it owns; their vertices are
    // vertices of its own cells, whose cells are all here.
    const auto &                dof_handler = discretization.get_dof_handler();
    const auto &                data        = discretization.level(l);
    const PatchDofsInCell<dim> in_cell     = patch_dofs_in_cell(dof_handler.get_fe());
    const LevelVertices<dim>    vertices(dof_handler, data, in_cell);
    std::vector<types::global_dof_index> color_dof;
    for (const auto &[k, vertex] : vertices.order)
      color_dof.push_back(data.vertex_dofs.at(vertex)[0]);
    const std::vector<unsigned int> color =
      level_schedule(coupled_items(dof_handler, data, in_cell, vertices),
                     color_dof,
                     data.partitioner);

    std::vector<types::global_dof_index> dofs;
    for (unsigned int p = 0; p < vertices.order.size(); ++p)
      {
        const unsigned int vertex = vertices.order[p].second;
        if (vertices.start[vertex] == vertices.start[vertex + 1])
          continue;
        dofs.assign(vertices.gathered.begin() + vertices.start[vertex],
                    vertices.gathered.begin() + vertices.start[vertex + 1]);
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        if (std::none_of(dofs.begin(), dofs.end(), [&](const auto dof) {
              return dof < data.n_owned();
            }))
          continue;
        // the patch's DoFs in global order, so that every process that
        // relaxes it computes the same numbers in the same order
        std::sort(dofs.begin(), dofs.end(), [&](const auto a, const auto b) {
          return data.global(a) < data.global(b);
        });
        patches.emplace_back(dofs.begin(), dofs.end());
        colors.push_back(color[p]);
        n_colors = std::max(n_colors, color[p] + 1);
      }
    n_colors = Utilities::MPI::max(n_colors, discretization.get_communicator());
  }


  template struct VertexKey<2>;
  template struct VertexKey<3>;
  template struct VertexPatches<2>;
  template struct VertexPatches<3>;
} // namespace FoslsContact
