#include <deal.II/base/geometry_info.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/solvers/multilevel_hierarchy.h>

#include <algorithm>
#include <iterator>
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
  MultilevelHierarchy<dim>::level_schedule(
    const std::vector<std::vector<unsigned int>> &coupled)
  {
    std::vector<unsigned int> color(coupled.size(), 0);
    for (unsigned int p = 0; p < coupled.size(); ++p)
      for (const unsigned int q : coupled[p])
        if (q < p)
          color[p] = std::max(color[p], color[q] + 1);
    return color;
  }


  namespace
  {
    /** The rotation R of a level as a sparse matrix (or its inverse). */
    template <int dim>
    void
    rotation_matrix(const LevelData<dim> &level,
                    const bool            inverse,
                    SparsityPattern &     sparsity,
                    SparseMatrix<double> &R)
    {
      DynamicSparsityPattern dsp(level.n_dofs, level.n_dofs);
      for (types::global_dof_index i = 0; i < level.n_dofs; ++i)
        dsp.add(i, i);
      for (const auto &block : level.rotations)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            dsp.add(block.dofs[a], block.dofs[b]);
      sparsity.copy_from(dsp);
      R.reinit(sparsity);
      for (types::global_dof_index i = 0; i < level.n_dofs; ++i)
        if (level.rotation_of_dof[i] == numbers::invalid_unsigned_int)
          R.set(i, i, 1.);
      for (const auto &block : level.rotations)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            R.set(block.dofs[a],
                  block.dofs[b],
                  inverse ? block.inverse(a, b) : block.matrix(a, b));
    }
  } // namespace


  template <int dim>
  MultilevelHierarchy<dim>::MultilevelHierarchy(
    const Discretization<dim> &discretization,
    const LevelTransfer<dim> & transfer,
    const unsigned int         finest_level)
    : discretization(discretization)
    , finest(finest_level)
  {
    const unsigned int n = finest + 1;
    rotated_sparsity.resize(n);
    rotated.resize(n);
    level_patches.resize(n);
    vertex_rel.resize(n);
    face_rel.resize(n);

    // Rotated prolongations R_l^{-1} P R_{l-1}.
    for (unsigned int l = 1; l < n; ++l)
      {
        SparsityPattern      sp_c, sp_f, sp_tmp;
        SparseMatrix<double> R_coarse, R_fine_inverse, tmp;
        rotation_matrix(discretization.level(l - 1), false, sp_c, R_coarse);
        rotation_matrix(discretization.level(l), true, sp_f, R_fine_inverse);
        sp_tmp.reinit(0, 0, 0);
        sp_tmp.compress();
        tmp.reinit(sp_tmp);
        transfer.prolongation(l).mmult(tmp, R_coarse);
        rotated_sparsity[l] = std::make_unique<SparsityPattern>();
        rotated_sparsity[l]->reinit(0, 0, 0);
        rotated_sparsity[l]->compress();
        rotated[l] = std::make_unique<SparseMatrix<double>>(*rotated_sparsity[l]);
        R_fine_inverse.mmult(*rotated[l], tmp);
      }

    // Vertex patches, in the order of their VertexKey, and their colors.
    const auto &dof_handler = discretization.get_dof_handler();
    level_colors.resize(n);
    for (unsigned int l = 0; l < n; ++l)
      {
        const auto &data = discretization.level(l);
        std::map<unsigned int, std::set<types::global_dof_index>> patch;
        std::map<unsigned int, VertexKey<dim>>                     key;
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
          for (const unsigned int v : cell->vertex_indices())
            {
              auto &p = patch[cell->vertex_index(v)];
              if (p.empty())
                key[cell->vertex_index(v)] = vertex_key<dim>(cell, v);
              for (const auto dof : data.vertex_dofs.at(cell->vertex_index(v)))
                p.insert(dof);
              for (const unsigned int f : cell->face_indices())
                for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face; ++i)
                  if (GeometryInfo<dim>::face_to_cell_vertices(f, i) == v)
                    for (const auto dof : data.face_dofs.at(cell->face(f)->index()))
                      p.insert(dof);
            }
        std::vector<std::pair<VertexKey<dim>, unsigned int>> order;
        for (const auto &[vertex, k] : key)
          order.emplace_back(k, vertex);
        std::sort(order.begin(), order.end(), [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        std::map<unsigned int, unsigned int> position;
        for (const auto &[k, vertex] : order)
          {
            position[vertex] = level_patches[l].size();
            const auto &dofs = patch[vertex];
            level_patches[l].emplace_back(dofs.begin(), dofs.end());
          }
        // patches are coupled if their vertices share a cell
        std::vector<std::vector<unsigned int>> coupled(order.size());
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
          for (const unsigned int v : cell->vertex_indices())
            for (const unsigned int w : cell->vertex_indices())
              if (v != w)
                coupled[position[cell->vertex_index(v)]].push_back(
                  position[cell->vertex_index(w)]);
        level_colors[l] = level_schedule(coupled);
      }

    // Contact relations between level l-1 (coarse) and l (fine).
    const auto &scene = discretization.get_scene();
    if (!scene.has_contact())
      return;
    for (unsigned int l = 1; l < n; ++l)
      {
        const auto &coarse = discretization.level(l - 1);
        const auto &fine   = discretization.level(l);
        auto fine_normal_dof = [&](const unsigned int vertex) {
          return fine.vertex_dofs.at(vertex)[0];
        };
        std::map<types::global_dof_index, VertexRelation> vrel;
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->at_boundary(f) ||
                  !scene.is_contact(cell->face(f)->boundary_id()))
                continue;
              const auto face = cell->face(f);
              FaceRelation frel;
              frel.coarse_dof = coarse.face_dofs.at(face->index())[0];
              for (unsigned int c = 0; c < face->n_children(); ++c)
                frel.sons.push_back(fine.face_dofs.at(face->child(c)->index())[0]);
              {
                // the DoFs of the children, minus those on the other faces
                std::set<types::global_dof_index> all, other_faces;
                for (unsigned int ch = 0; ch < cell->n_children(); ++ch)
                  {
                    const auto child = cell->child(ch);
                    for (const unsigned int v : child->vertex_indices())
                      for (const auto dof : fine.vertex_dofs.at(child->vertex_index(v)))
                        all.insert(dof);
                    for (const unsigned int cf : child->face_indices())
                      for (const auto dof : fine.face_dofs.at(child->face(cf)->index()))
                        all.insert(dof);
                  }
                for (const unsigned int g : cell->face_indices())
                  if (g != f)
                    for (unsigned int c = 0; c < cell->face(g)->n_children(); ++c)
                      {
                        const auto son = cell->face(g)->child(c);
                        for (const unsigned int v : son->vertex_indices())
                          for (const auto dof : fine.vertex_dofs.at(son->vertex_index(v)))
                            other_faces.insert(dof);
                        for (const auto dof : fine.face_dofs.at(son->index()))
                          other_faces.insert(dof);
                      }
                std::set_difference(all.begin(), all.end(),
                                    other_faces.begin(), other_faces.end(),
                                    std::back_inserter(frel.inside));
              }
              face_rel[l].push_back(frel);

              // coarse contact edges of this face (the face itself in 2D)
              std::vector<std::array<unsigned int, 3>> edges; // a, b, midpoint
              unsigned int center = numbers::invalid_unsigned_int;
              if (dim == 2)
                edges.push_back({face->vertex_index(0),
                                 face->vertex_index(1),
                                 face->child(0)->vertex_index(1)});
              else
                {
                  for (unsigned int e = 0; e < GeometryInfo<dim>::lines_per_face; ++e)
                    {
                      const auto line = face->line(e);
                      edges.push_back({line->vertex_index(0),
                                       line->vertex_index(1),
                                       line->child(0)->vertex_index(1)});
                    }
                  // the face center is the one vertex all sons share
                  std::map<unsigned int, unsigned int> count;
                  for (unsigned int c = 0; c < face->n_children(); ++c)
                    for (const unsigned int v : face->child(c)->vertex_indices())
                      ++count[face->child(c)->vertex_index(v)];
                  for (const auto &[v, k] : count)
                    if (k == face->n_children())
                      center = v;
                }
              for (const auto &[a, b, m] : edges)
                for (const auto &[self, other] : {std::make_pair(a, b), std::make_pair(b, a)})
                  {
                    const auto coarse_dof = coarse.vertex_dofs.at(self)[0];
                    if (coarse.role[coarse_dof] != DoFRole::bounded)
                      continue;
                    auto &r      = vrel[coarse_dof];
                    r.coarse_dof = coarse_dof;
                    r.fine_self  = fine_normal_dof(self);
                    r.edges.push_back({fine_normal_dof(other), fine_normal_dof(m)});
                  }
              if (center != numbers::invalid_unsigned_int)
                for (const unsigned int v : face->vertex_indices())
                  {
                    const auto coarse_dof = coarse.vertex_dofs.at(face->vertex_index(v))[0];
                    if (coarse.role[coarse_dof] == DoFRole::bounded)
                      vrel[coarse_dof].centers.push_back(fine_normal_dof(center));
                  }
            }
        for (auto &[dof, r] : vrel)
          vertex_rel[l].push_back(r);
      }
  }

  template struct VertexKey<2>;
  template struct VertexKey<3>;
  template class MultilevelHierarchy<2>;
  template class MultilevelHierarchy<3>;
} // namespace FoslsContact
