#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/discretization/level_meshes.h>
#include <fosls_contact/discretization/rt_signs.h>
#include <fosls_contact/qp/matrix_list_memory.h>

#include <map>

namespace FoslsContact
{
  namespace
  {
    /**
     * The cell of level @p data of @p discretization with the CellId of
     * @p id, as an iterator with the DoFs of that level: a level cell on a
     * uniform level, an active cell on an active mesh.
     */
    template <int dim, typename Function>
    void
    with_cell(const Discretization<dim> &discretization,
              const LevelData<dim> &     data,
              const CellId &             id,
              const Function &           f)
    {
      const auto &tria = discretization.get_triangulation();
      const auto  cell = tria.create_cell_iterator(id);
      const auto *dofs = &discretization.get_dof_handler();
      if (data.active_mesh)
        f(typename DoFHandler<dim>::cell_iterator(&tria, cell->level(), cell->index(), dofs));
      else
        f(typename DoFHandler<dim>::level_cell_iterator(&tria, cell->level(), cell->index(), dofs));
    }
  } // namespace


  template <int dim>
  LevelMeshes<dim>::LevelMeshes(const Discretization<dim> &discretization,
                                const LevelTransfer<dim> & transfer)
  {
    AssertThrow(discretization.adaptive(),
                ExcMessage("LevelMeshes: the mesh is not adaptively refined"));
    const unsigned int n_uniform = discretization.n_uniform_levels();
    const unsigned int finest    = discretization.get_triangulation().n_global_levels() - 1;
    sources.resize(finest + 1);
    for (unsigned int l = 0; l < n_uniform; ++l)
      sources[l] = {&discretization, l, l > 0 ? &transfer.prolongation(l) : nullptr};
    // Level l - 1 is level l with every family of active cells above the
    // uniform levels coarsened at once (deal.II's
    // MGTransferGlobalCoarseningTools::create_geometric_coarsening_sequence()
    // coarsens so), coarsened on a serial copy of the mesh and built as a
    // mesh of its own from the uniform levels
    Triangulation<dim> coarsened;
    coarsened.copy_triangulation(discretization.get_triangulation());
    coarser.resize(finest - n_uniform);
    for (unsigned int l = finest - 1; l + 1 > n_uniform; --l)
      {
        for (const auto &cell : coarsened.active_cell_iterators())
          if (static_cast<unsigned int>(cell->level()) >= n_uniform)
            cell->set_coarsen_flag();
        coarsened.execute_coarsening_and_refinement();
        // (every family of the finest cells can be coarsened: their
        // neighbours are at most one level coarser)
        AssertThrow(coarsened.n_global_levels() == l + 1,
                    ExcMessage("LevelMeshes: coarsening every family once left cells of mesh "
                               "level " + std::to_string(coarsened.n_global_levels() - 1) +
                               " on multigrid level " + std::to_string(l)));
        auto &mesh = coarser[l - n_uniform];
        mesh       = std::make_unique<Discretization<dim>>(discretization.get_scene(),
                                                     n_uniform,
                                                     discretization.get_communicator(),
                                                     discretization.get_mesh_distribution());
        mesh->refine_as(coarsened);
        sources[l] = {mesh.get(), mesh->finest_level(), nullptr};
      }
    sources[finest] = {&discretization, discretization.finest_level(), nullptr};
    sparsities.resize(finest + 1);
    matrices.resize(finest + 1);
    for (unsigned int l = n_uniform; l <= finest; ++l)
      {
        build_prolongation(l);
        sources[l].prolongation = matrices[l].get();
      }
  }


  template <int dim>
  void
  LevelMeshes<dim>::build_prolongation(const unsigned int l)
  {
    const auto &coarse_discretization = discretization(l - 1);
    const auto &fine_discretization   = discretization(l);
    const auto &coarse                = level(l - 1);
    const auto &fine                  = level(l);
    const auto &fe                    = fine_discretization.get_fe();
    const unsigned int n              = fe.n_dofs_per_cell();
    RtFaceFlips<dim>   face_flips(fine_discretization.get_mapping());

    // Row by row: a fine DoF's row is the coarse function's value there,
    // the same from every cell at it, so the first cell that has the DoF
    // writes it.
    std::vector<std::map<types::global_dof_index, double>> rows(fine.n_local());
    std::vector<bool>                                      done(fine.n_local(), false);
    std::vector<types::global_dof_index> fine_dofs, coarse_dofs;
    FullMatrix<double>                   embedding(n, n);
    fine.for_each_cell(fine_discretization.get_dof_handler(), [&](const auto &cell) {
      fine.get_local_dofs(cell, fine_dofs);
      // a cell is a cell of level l - 1 too, or a child of a cell of level
      // l - 1 that level l refines: on a uniform level l - 1 a child of one
      // of its cells, on an active mesh a cell whose parent is active there
      const bool refined_here =
        coarse.active_mesh ?
          cell->level() > 0 && !coarse_discretization.get_triangulation()
                                  .create_cell_iterator(cell->parent()->id())
                                  ->has_children() :
          static_cast<unsigned int>(cell->level()) > index(l - 1);
      const auto coarse_id    = refined_here ? cell->parent()->id() : cell->id();
      with_cell(coarse_discretization, coarse, coarse_id, [&](const auto &coarse_cell) {
        coarse.get_local_dofs(coarse_cell, coarse_dofs);
        if (refined_here)
          {
            const auto parent_signs = rt_signs(fe, face_flips(coarse_cell));
            const auto child_signs  = rt_signs(fe, face_flips(cell));
            embedding = fe.get_prolongation_matrix(cell->parent()->child_iterator_to_index(cell),
                                                   cell->parent()->refinement_case());
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                embedding(i, j) *= child_signs[i] * parent_signs[j];
          }
        else
          {
            // the same cell, the same shape functions
            embedding = IdentityMatrix(n);
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto row = fine_dofs[i];
            if (done[row] || fine.hanging.count(row))
              continue;
            done[row] = true;
            for (unsigned int j = 0; j < n; ++j)
              if (embedding(i, j) != 0)
                {
                  const auto h = coarse.hanging.find(coarse_dofs[j]);
                  if (h == coarse.hanging.end())
                    rows[row][coarse_dofs[j]] += embedding(i, j);
                  else
                    for (const auto &[master, weight] : h->second)
                      rows[row][master] += embedding(i, j) * weight;
                }
          }
      });
    });

    DynamicSparsityPattern dsp(fine.n_local(), coarse.n_local());
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (const auto &[j, value] : rows[i])
        dsp.add(i, j);
    sparsities[l] = std::make_unique<SparsityPattern>();
    sparsities[l]->copy_from(dsp);
    matrices[l] = std::make_unique<SparseMatrix<double>>(*sparsities[l]);
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (const auto &[j, value] : rows[i])
        matrices[l]->set(i, j, value);
  }


  template <int dim>
  LevelBytes
  LevelMeshes<dim>::memory_consumption() const
  {
    // (coarser[k] is the mesh of level n_uniform + k, the levels below it
    // in sources those of the adaptive mesh's own discretization)
    LevelBytes         bytes     = matrix_list_memory_consumption(matrices, sparsities);
    const unsigned int n_uniform = matrices.size() - 1 - coarser.size();
    for (unsigned int k = 0; k < coarser.size(); ++k)
      bytes[n_uniform + k] += coarser[k]->mesh_memory_consumption() +
                              total_bytes(coarser[k]->level_memory_consumption());
    return bytes;
  }

  template class LevelMeshes<2>;
  template class LevelMeshes<3>;
} // namespace FoslsContact
