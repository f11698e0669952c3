#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
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
    /** The rotation R of a level as a local sparse matrix (or its inverse). */
    template <int dim>
    void
    rotation_matrix(const LevelData<dim> &level,
                    const bool            inverse,
                    SparsityPattern &     sparsity,
                    SparseMatrix<double> &R)
    {
      const unsigned int     n = level.n_local();
      DynamicSparsityPattern dsp(n, n);
      for (unsigned int i = 0; i < n; ++i)
        dsp.add(i, i);
      for (const auto &block : level.rotations)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            dsp.add(block.dofs[a], block.dofs[b]);
      sparsity.copy_from(dsp);
      R.reinit(sparsity);
      for (unsigned int i = 0; i < n; ++i)
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


  namespace
  {
    /**
     * The fine DoFs of the children of @p cell (those with DoFs here) that
     * do not lie on one of its faces other than @p f, sorted. Child c of an
     * isotropically refined cell touches the parent's face 2d + s iff bit d
     * of c is s; its vertex v lies on that face iff bit d of v is s too.
     */
    template <int dim, typename Iterator>
    std::vector<types::global_dof_index>
    inside_dofs(const Iterator &cell, const unsigned int f, const LevelData<dim> &fine)
    {
      std::set<types::global_dof_index> inside;
      auto on_other_face = [&](const unsigned int c, const unsigned int d, const unsigned int s) {
        return ((c >> d) & 1u) == s && 2 * d + s != f;
      };
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        {
          const auto child = cell->child(c);
          if (!Discretization<dim>::is_present(child))
            continue;
          for (const unsigned int v : child->vertex_indices())
            {
              bool outside = false;
              for (unsigned int d = 0; d < dim; ++d)
                outside |= ((v >> d) & 1u) == ((c >> d) & 1u) &&
                           on_other_face(c, d, (c >> d) & 1u);
              if (!outside)
                for (const auto dof : fine.vertex_dofs.at(child->vertex_index(v)))
                  inside.insert(dof);
            }
          for (const unsigned int cf : child->face_indices())
            if (!on_other_face(c, cf / 2, cf % 2))
              for (const auto dof : fine.face_dofs.at(child->face(cf)->index()))
                inside.insert(dof);
        }
      return {inside.begin(), inside.end()};
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
    level_colors.resize(n);
    level_n_colors.assign(n, 0);
    face_rel.resize(n);
    rerouting.resize(n);
    // (level 0 is solved directly: no patches)
    for (unsigned int l = 1; l < n; ++l)
      {
        rotate_prolongation(l, transfer);
        find_patches(l);
      }
    if (discretization.get_scene().has_contact())
      for (unsigned int l = 1; l < n; ++l)
        relate_contact_faces(l);
  }


  template <int dim>
  void
  MultilevelHierarchy<dim>::rotate_prolongation(const unsigned int        l,
                                                const LevelTransfer<dim> &transfer)
  {
    // R_l^{-1} P R_{l-1}, for the local fine DoFs (their coarse DoFs are
    // local: the parents of the cells here are here)
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


  template <int dim>
  void
  MultilevelHierarchy<dim>::find_patches(const unsigned int l)
  {
    // Vertex patches in the order of their VertexKey, and their colors. A
    // process relaxes the patches with a DoF it owns; their vertices are
    // vertices of its own cells, whose cells are all here.
    const auto &dof_handler = discretization.get_dof_handler();
    const auto &data        = discretization.level(l);
    std::map<unsigned int, VertexKey<dim>>                     key;
    std::map<unsigned int, std::set<types::global_dof_index>> patch;
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (Discretization<dim>::is_present(cell))
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int vertex = cell->vertex_index(v);
            if (key.count(vertex) == 0)
              key[vertex] = vertex_key<dim>(cell, v);
            if (data.owned_cell_vertices.count(vertex) == 0)
              continue;
            auto &p = patch[vertex];
            for_patch_dofs_in_cell(data, cell, v, [&](const auto dof) { p.insert(dof); });
          }

    // every vertex of a cell here is an item of the level scheduling
    std::vector<std::pair<VertexKey<dim>, unsigned int>> order;
    for (const auto &[vertex, k] : key)
      order.emplace_back(k, vertex);
    std::sort(order.begin(), order.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    std::map<unsigned int, unsigned int> position;
    std::vector<types::global_dof_index> color_dof;
    for (const auto &[k, vertex] : order)
      {
        position[vertex] = color_dof.size();
        color_dof.push_back(data.vertex_dofs.at(vertex)[0]);
      }
    // patches are coupled if their vertices share a cell
    std::vector<std::vector<unsigned int>> coupled(order.size());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (Discretization<dim>::is_present(cell))
        for (const unsigned int v : cell->vertex_indices())
          for (const unsigned int w : cell->vertex_indices())
            if (v != w)
              coupled[position[cell->vertex_index(v)]].push_back(
                position[cell->vertex_index(w)]);
    const std::vector<unsigned int> color =
      level_schedule(coupled, color_dof, data.partitioner);

    unsigned int n_colors = 0;
    for (const auto &[k, vertex] : order)
      {
        const auto it = patch.find(vertex);
        if (it == patch.end())
          continue;
        std::vector<types::global_dof_index> dofs(it->second.begin(), it->second.end());
        if (std::none_of(dofs.begin(), dofs.end(), [&](const auto dof) {
              return dof < data.n_owned();
            }))
          continue;
        // the patch's DoFs in global order, so that every process that
        // relaxes it computes the same numbers in the same order
        std::sort(dofs.begin(), dofs.end(), [&](const auto a, const auto b) {
          return data.global(a) < data.global(b);
        });
        level_patches[l].push_back(dofs);
        level_colors[l].push_back(color[position[vertex]]);
        n_colors = std::max(n_colors, color[position[vertex]] + 1);
      }
    level_n_colors[l] = Utilities::MPI::max(n_colors, discretization.get_communicator());
  }


  template <int dim>
  void
  MultilevelHierarchy<dim>::relate_contact_faces(const unsigned int l)
  {
    // Contact relations between level l-1 (coarse) and l (fine), for the
    // coarse contact faces owned here; the entries the rerouting may give
    // for every coarse contact face with a cell here.
    const auto &scene       = discretization.get_scene();
    const auto &dof_handler = discretization.get_dof_handler();
    const auto &coarse      = discretization.level(l - 1);
    const auto &fine        = discretization.level(l);
    auto        on_contact  = [&](const auto &cell, const unsigned int f) {
      return cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id());
    };
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
      if (Discretization<dim>::is_present(cell))
        for (const unsigned int f : cell->face_indices())
          if (on_contact(cell, f))
            {
              const auto j = coarse.face_dofs.at(cell->face(f)->index())[0];
              for (const auto i : inside_dofs(cell, f, fine))
                rerouting[l].emplace_back(i, j);
            }
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
      if (cell->is_locally_owned_on_level())
        for (const unsigned int f : cell->face_indices())
          if (on_contact(cell, f))
            face_rel[l].push_back(face_relation(cell, f, coarse, fine));
  }


  template <int dim>
  template <typename Iterator>
  FaceRelation
  MultilevelHierarchy<dim>::face_relation(const Iterator &      cell,
                                          const unsigned int    f,
                                          const LevelData<dim> &coarse,
                                          const LevelData<dim> &fine) const
  {
    auto fine_normal_dof = [&](const unsigned int vertex) {
      return fine.vertex_dofs.at(vertex)[0];
    };
    auto coarse_normal_dof = [&](const unsigned int vertex) {
      const auto dof = coarse.vertex_dofs.at(vertex)[0];
      return coarse.role[dof] == DoFRole::bounded ? dof : numbers::invalid_dof_index;
    };
    const auto   face = cell->face(f);
    FaceRelation frel;
    frel.coarse_dof = coarse.face_dofs.at(face->index())[0];
    for (unsigned int c = 0; c < face->n_children(); ++c)
      frel.sons.push_back(fine.face_dofs.at(face->child(c)->index())[0]);
    // (all children of an owned cell are here)
    frel.inside = inside_dofs(cell, f, fine);

    // coarse contact edges of this face (the face itself in 2D)
    std::vector<std::array<unsigned int, 3>> edges; // a, b, midpoint
    if (dim == 2)
      edges.push_back(
        {{face->vertex_index(0), face->vertex_index(1), face->child(0)->vertex_index(1)}});
    else
      {
        for (unsigned int e = 0; e < GeometryInfo<dim>::lines_per_face; ++e)
          {
            const auto line = face->line(e);
            edges.push_back(
              {{line->vertex_index(0), line->vertex_index(1), line->child(0)->vertex_index(1)}});
          }
        // the face center is the one vertex all sons share
        std::map<unsigned int, unsigned int> count;
        for (unsigned int c = 0; c < face->n_children(); ++c)
          for (const unsigned int v : face->child(c)->vertex_indices())
            ++count[face->child(c)->vertex_index(v)];
        for (const auto &[v, k] : count)
          if (k == face->n_children())
            frel.fine_center = fine_normal_dof(v);
        for (const unsigned int v : face->vertex_indices())
          if (coarse_normal_dof(face->vertex_index(v)) != numbers::invalid_dof_index)
            frel.coarse_vertices.push_back(coarse_normal_dof(face->vertex_index(v)));
      }
    for (const auto &[a, b, m] : edges)
      frel.edges.push_back({{{coarse_normal_dof(a), coarse_normal_dof(b)}},
                            {{fine_normal_dof(a), fine_normal_dof(b)}},
                            fine_normal_dof(m)});
    return frel;
  }

  template struct VertexKey<2>;
  template struct VertexKey<3>;
  template class MultilevelHierarchy<2>;
  template class MultilevelHierarchy<3>;
} // namespace FoslsContact
