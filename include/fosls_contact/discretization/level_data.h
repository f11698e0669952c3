#ifndef fosls_contact_discretization_level_data_h
#define fosls_contact_discretization_level_data_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/qp/algebraic_level.h>

#include <boost/container/flat_map.hpp>

#include <array>
#include <map>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Whether @p cell (of any level) has DoFs on this process: owned or
   * ghost. Every loop over the cells of a level that builds level data
   * asks this, so it is said once.
   */
  template <typename Iterator>
  bool
  level_cell_is_present(const Iterator &cell)
  {
    return cell->level_subdomain_id() != numbers::artificial_subdomain_id;
  }


  /**
   * A block of DoFs whose coordinates are changed to the normal-tangential
   * system of paper section 4.3: x_cartesian = matrix * x_rotated on
   * `dofs` (local indices). The first rotated coordinate is the normal one.
   */
  template <int dim>
  struct RotationBlock
  {
    std::array<types::global_dof_index, dim> dofs;
    FullMatrix<double>                       matrix;
    FullMatrix<double>                       inverse;
  };

  /**
   * A contact vertex on one level: u.n <= g bounds DoF `normal_dof` (a
   * local index; `owned` if this process owns it).
   */
  template <int dim>
  struct ContactVertex
  {
    unsigned int             vertex_index;
    types::global_dof_index  normal_dof;
    Point<dim>               point;
    Tensor<1, dim>           normal;
    double                   gap;
    bool                     owned;
  };

  /** A contact face on one level: (sigma n).n <= 0 bounds `normal_dof`. */
  template <int dim>
  struct ContactFace
  {
    unsigned int             face_index;
    types::global_dof_index  normal_dof;
    Point<dim>               center;
    Tensor<1, dim>           normal;
    double                   area;
    bool                     owned;
  };

  /**
   * With friction (Friction/Law): a contact face and what the friction
   * terms of J need of it (FrictionLaw): its tangential traction DoFs and
   * its normal one (rotated coordinates, local indices), the weight
   * |F| / 2^(dim-1) of each of its vertices in the trapezoidal rule, its
   * center, and the tangential displacement DoFs (DoFRole::slip) of its
   * vertices that have them.
   */
  template <int dim>
  struct FrictionFace
  {
    /** The face's index in the triangulation (face->index()). */
    unsigned int                                              face_index;
    std::array<types::global_dof_index, dim - 1>              traction;
    types::global_dof_index                                   normal;
    double                                                    weight;
    Point<dim>                                                center;
    std::vector<std::array<types::global_dof_index, dim - 1>> slips;
  };

  /**
   * One level of the discretization on this process: the algebra's view
   * of it (AlgebraicLevel: the DoFs it owns and its ghost DoFs, those of
   * the ghost cells around its own cells, their roles, fixed values and
   * upper bounds in the rotated basis, the coupling pattern), and the
   * mesh's: the rotations, the contact entities, and which DoFs belong to
   * which vertex and face. All DoFs are local indices (LevelVector).
   */
  template <int dim>
  struct LevelData : AlgebraicLevel
  {
    LevelData() { dimension = dim; }

    /**
     * The level's cells: those of mesh level `level` with their level DoFs,
     * or, for the level of an adaptively refined mesh (`active_mesh`), the
     * active cells of all mesh levels with their active DoFs.
     */
    unsigned int level       = 0;
    bool         active_mesh = false;

    /** The local DoFs of @p cell (a cell of this level). */
    template <typename Iterator>
    void get_local_dofs(const Iterator &cell, std::vector<types::global_dof_index> &dofs) const
    {
      dofs.resize(cell->get_dof_handler().get_fe().n_dofs_per_cell());
      cell->get_active_or_mg_dof_indices(dofs);
      for (auto &dof : dofs)
        dof = partitioner->global_to_local(dof);
    }

    /**
     * Call @p f(cell) for the cells of this level with DoFs on this
     * process (owned or ghost): a level_cell_iterator on a level of the
     * uniform hierarchy, a cell_iterator of an active cell on the active
     * mesh.
     */
    template <typename Function>
    void for_each_cell(const DoFHandler<dim> &dof_handler, const Function &f) const
    {
      if (active_mesh)
        {
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
              f(typename DoFHandler<dim>::cell_iterator(cell));
        }
      else
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
          if (level_cell_is_present(cell))
            f(cell);
    }

    /** Whether @p cell, a cell of this level, is owned by this process. */
    template <typename Iterator>
    static bool owns(const Iterator &cell)
    {
      return Iterator::AccessorType::is_level_cell() ? cell->is_locally_owned_on_level() :
                                                       cell->is_locally_owned();
    }

    /**
     * The hanging-node constraints of the active mesh (empty on a uniform
     * level): a constrained DoF (local index) -> its masters and weights,
     * in Cartesian coordinates, u_h = sum w_j u_j. A constrained DoF is
     * eliminated: it is fixed at zero in the algebra (the matrix is
     * C^T A C), and its value is restored from its masters for output
     * (Discretization::to_active()).
     */
    std::map<types::global_dof_index, std::vector<std::pair<types::global_dof_index, double>>>
      hanging;

    std::vector<RotationBlock<dim>>         rotations;
    /** For each local DoF, the index of its rotation block, or invalid. */
    std::vector<unsigned int>               rotation_of_dof;
    /** The contact vertices and faces of the cells of this process. */
    std::vector<ContactVertex<dim>>         contact_vertices;
    std::vector<ContactFace<dim>>           contact_faces;
    /** With friction: the contact faces of the cells here (else empty). */
    std::vector<FrictionFace<dim>>          friction_faces;
    /**
     * An index of the triangulation (of a vertex or a face) -> the dim DoFs
     * there, for the cells here; local indices. A sorted array: the
     * patches, the coupling pattern and the contact set-up look up every
     * vertex and face of every cell, and a std::map's nodes took 48 bytes
     * an entry and a cache miss a step (the entries are 12 bytes in 2D,
     * 16 in 3D here).
     */
    using DofsAt =
      boost::container::flat_map<unsigned int, std::array<types::global_dof_index, dim>>;
    /** vertex index -> its displacement DoFs (component by component). */
    DofsAt vertex_dofs;
    /** face index -> its RT DoFs (stress row by row). */
    DofsAt face_dofs;
    /**
     * The master vertices of each hanging vertex (those of the masters of
     * its displacement DoFs), by triangulation vertex index:
     * vertex_masters[vertex_masters_start[v] .. vertex_masters_start[v+1]),
     * empty where v does not hang. A master's basis function reaches into
     * the cells at its hanging vertices, and so does its vertex patch.
     */
    std::vector<std::size_t>  vertex_masters_start;
    std::vector<unsigned int> vertex_masters;
    /**
     * Whether this process relaxes the patch of a vertex (by its index in
     * the triangulation, of all levels), if the patch has a DoF it owns:
     * the vertices of the cells it owns on the level, and the masters of
     * their hanging vertices; all cells of these patches are here. (A bit
     * per vertex of the triangulation; a set of this level's vertices
     * took 40 bytes each.)
     */
    std::vector<bool> relaxed_vertices;

    /**
     * Call @p f(p) for each vertex p whose patch takes the DoFs that a
     * cell has at its vertex @p vertex and that this process relaxes:
     * @p vertex itself and the masters of a hanging one.
     */
    template <typename Function>
    void
    for_patches_at(const unsigned int vertex, const Function &f) const
    {
      if (relaxed_vertices[vertex])
        f(vertex);
      if (!vertex_masters_start.empty())
        for (std::size_t k = vertex_masters_start[vertex]; k < vertex_masters_start[vertex + 1];
             ++k)
          if (relaxed_vertices[vertex_masters[k]])
            f(vertex_masters[k]);
    }
  };

  /**
   * The DoFs of the Arnold-Falk-Winther patch of each vertex of a cell
   * that lie in the cell, as positions among the cell's DoFs: the
   * vertex's displacement DoFs (component by component), then the RT DoFs
   * (stress row by row) of the cell's faces at the vertex, face by face.
   * The patch is the union over the cells at the vertex. The table is the
   * element's, the same for every cell: the loops that gather patches
   * read a cell's DoFs once and index them with it.
   */
  template <int dim>
  using PatchDofsInCell =
    std::array<std::vector<unsigned int>, GeometryInfo<dim>::vertices_per_cell>;

  template <int dim>
  PatchDofsInCell<dim>
  patch_dofs_in_cell(const FiniteElement<dim> &fe)
  {
    // (base element 0 is Q1^dim, one DoF per vertex and copy; base element
    // 1 is RT0^dim, one DoF per face and copy)
    const auto position = [&](const unsigned int base, const unsigned int copy,
                              const unsigned int where) {
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_base_index(i) ==
            std::make_pair(std::make_pair(base, copy), where))
          return i;
      Assert(false, ExcInternalError());
      return numbers::invalid_unsigned_int;
    };
    PatchDofsInCell<dim> table;
    for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
      {
        for (unsigned int c = 0; c < dim; ++c)
          table[v].push_back(position(0, c, v));
        for (const unsigned int face : GeometryInfo<dim>::face_indices())
          for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face; ++i)
            if (GeometryInfo<dim>::face_to_cell_vertices(face, i) == v)
              for (unsigned int r = 0; r < dim; ++r)
                table[v].push_back(position(1, r, face));
      }
    return table;
  }

  /**
   * Call @p f(dof) for the DoFs of the patch of the cell's vertex @p v that
   * lie in the cell (see patch_dofs_in_cell()); @p cell_dofs are the
   * cell's DoFs (LevelData::get_local_dofs()).
   */
  template <typename Table, typename Function>
  void
  for_patch_dofs_in_cell(const Table &                               table,
                         const std::vector<types::global_dof_index> &cell_dofs,
                         const unsigned int                          v,
                         const Function &                            f)
  {
    for (const unsigned int i : table[v])
      f(cell_dofs[i]);
  }
} // namespace FoslsContact

#endif
