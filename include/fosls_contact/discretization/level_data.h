#ifndef fosls_contact_discretization_level_data_h
#define fosls_contact_discretization_level_data_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/qp/algebraic_level.h>

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
    /**
     * vertex index -> its displacement DoFs (component by component), for
     * the vertices of the cells here; local indices.
     */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> vertex_dofs;
    /** face index -> its RT DoFs (stress row by row); local indices. */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> face_dofs;
    /**
     * Whether a vertex (by its index in the triangulation, of all levels)
     * is a vertex of a cell this process owns on the level: it relaxes the
     * patches there that have a DoF it owns, and all cells at them are
     * here. (A bit per vertex of the triangulation; a set of this level's
     * vertices took 40 bytes each.)
     */
    std::vector<bool> owned_cell_vertices;
  };

  /**
   * Call @p f(dof) for the DoFs of the Arnold-Falk-Winther patch of vertex
   * @p v of @p cell that lie in this cell: the vertex's displacement DoFs
   * and the RT DoFs (all stress rows) of the cell's faces at the vertex.
   * The patch is the union over the cells at the vertex.
   */
  template <int dim, typename Iterator, typename Function>
  void
  for_patch_dofs_in_cell(const LevelData<dim> &level,
                         const Iterator &      cell,
                         const unsigned int    v,
                         const Function &      f)
  {
    for (const auto dof : level.vertex_dofs.at(cell->vertex_index(v)))
      f(dof);
    for (const unsigned int face : cell->face_indices())
      for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face; ++i)
        if (GeometryInfo<dim>::face_to_cell_vertices(face, i) == v)
          for (const auto dof : level.face_dofs.at(cell->face(face)->index()))
            f(dof);
  }
} // namespace FoslsContact

#endif
