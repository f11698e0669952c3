#ifndef fosls_contact_discretization_hanging_nodes_h
#define fosls_contact_discretization_hanging_nodes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/level_data.h>

#include <algorithm>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * deal.II's hanging-node constraints of the active mesh of
   * @p dof_handler (Q1 and RT0) into @p constraints (global indices, for
   * the locally relevant DoFs), and their elimination from @p data, the
   * level of that mesh: LevelData::hanging in local indices, and every
   * constrained DoF fixed at zero without a bound. A hanging vertex is no
   * contact vertex and no Dirichlet vertex of its own: its values follow
   * from its masters (which are). Boundary faces are never constrained.
   */
  template <int dim>
  void
  eliminate_hanging_dofs(const DoFHandler<dim> &    dof_handler,
                         AffineConstraints<double> &constraints,
                         LevelData<dim> &           data);

  /**
   * LevelData::vertex_masters of @p data (of a triangulation with
   * @p n_vertices vertices) from its hanging displacement DoFs
   * (LevelData::hanging); empty arrays without hanging nodes.
   */
  template <int dim>
  void
  set_vertex_masters(LevelData<dim> &data, const unsigned int n_vertices);

  /**
   * The DoFs that the terms of a cell couple, with hanging nodes
   * eliminated (C^T K C): @p dofs (local indices of a level) and the
   * masters of those of them that are constrained (LevelData::hanging),
   * which may lie on the coarse neighbour; sorted, each once, so that a
   * sparsity pattern takes them as one row at once.
   */
  template <int dim>
  void
  sort_with_masters(const LevelData<dim> &data, std::vector<types::global_dof_index> &dofs)
  {
    const std::size_t n = dofs.size();
    for (std::size_t k = 0; k < n; ++k)
      {
        const auto h = data.hanging.find(dofs[k]);
        if (h != data.hanging.end())
          for (const auto &master : h->second)
            dofs.push_back(master.first);
      }
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  }

  /**
   * The terms of one cell of a level with hanging nodes (@p data), its
   * @p matrices and @p vectors on its DoFs @p dofs (local indices), on the
   * DoFs that remain: C^T K C and C^T r, where C replaces each constrained
   * DoF by its masters (LevelData::hanging). @p dofs becomes the DoFs that
   * remain: the cell's unconstrained ones, then the masters of its
   * constrained ones (which may lie on the coarse neighbour), each once.
   * Returns false, changing nothing, if the cell has no constrained DoF.
   */
  template <int dim>
  bool
  eliminate_hanging_dofs_of_cell(const LevelData<dim> &                   data,
                                 std::vector<types::global_dof_index> &   dofs,
                                 const std::vector<FullMatrix<double> *> &matrices,
                                 const std::vector<Vector<double> *> &    vectors);
} // namespace FoslsContact

#endif
