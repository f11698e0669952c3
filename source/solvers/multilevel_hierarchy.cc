#include <deal.II/base/memory_consumption.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/matrix_list_memory.h>
#include <fosls_contact/qp/product_pattern.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

namespace FoslsContact
{
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
      // (the identity but for the blocks: rows of one or dim entries)
      const unsigned int        n = level.n_local();
      std::vector<unsigned int> row_lengths(n, 1);
      for (const auto &block : level.rotations)
        for (const auto dof : block.dofs)
          row_lengths[dof] = dim;
      sparsity.reinit(n, n, row_lengths);
      for (const auto &block : level.rotations)
        for (const auto dof : block.dofs)
          sparsity.add_entries(dof, block.dofs.begin(), block.dofs.end());
      sparsity.compress();
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


  template <int dim>
  MultilevelHierarchy<dim>::MultilevelHierarchy(const Discretization<dim> &discretization,
                                                const LevelTransfer<dim> & transfer,
                                                const unsigned int         finest_level)
  {
    std::vector<Source> levels;
    for (unsigned int l = 0; l <= finest_level; ++l)
      levels.push_back({&discretization, l, l > 0 ? &transfer.prolongation(l) : nullptr});
    build(levels);
  }


  template <int dim>
  MultilevelHierarchy<dim>::MultilevelHierarchy(const LevelMeshes<dim> &meshes)
  {
    std::vector<Source> levels;
    for (unsigned int l = 0; l <= meshes.finest_level(); ++l)
      levels.push_back(
        {&meshes.discretization(l), meshes.index(l), l > 0 ? &meshes.prolongation(l) : nullptr});
    build(levels);
  }


  template <int dim>
  void
  MultilevelHierarchy<dim>::build(const std::vector<Source> &levels)
  {
    sources        = levels;
    finest         = sources.size() - 1;
    const unsigned int n = finest + 1;
    rotated_sparsity.resize(n);
    rotated.resize(n);
    level_patches.resize(n);
    contact_faces.resize(n);
    // (level 0 is solved directly: no patches)
    for (unsigned int l = 1; l < n; ++l)
      {
        rotate_prolongation(l);
        level_patches[l] = VertexPatches<dim>(*sources[l].discretization, sources[l].index);
      }
    if (sources[0].discretization->get_scene().has_contact())
      for (unsigned int l = 1; l < n; ++l)
        contact_faces[l] = ContactFaceRelations<dim>(*sources[l - 1].discretization,
                                                     sources[l - 1].index,
                                                     *sources[l].discretization,
                                                     sources[l].index);
  }


  template <int dim>
  void
  MultilevelHierarchy<dim>::rotate_prolongation(const unsigned int l)
  {
    // R_l^{-1} P R_{l-1}, for the local fine DoFs (their coarse DoFs are
    // local: the parents of the cells here are here)
    SparsityPattern      sp_c, sp_f, sp_tmp;
    SparseMatrix<double> R_coarse, R_fine_inverse, tmp;
    rotation_matrix(level(l - 1), false, sp_c, R_coarse);
    rotation_matrix(level(l), true, sp_f, R_fine_inverse);
    const SparseMatrix<double> &P = *sources[l].prolongation;
    ProductPattern(P.get_sparsity_pattern(), sp_c, P.m()).fill(sp_tmp, P.n());
    tmp.reinit(sp_tmp);
    P.mmult(tmp, R_coarse, Vector<double>(), false);
    rotated_sparsity[l] = std::make_unique<SparsityPattern>();
    ProductPattern(sp_f, sp_tmp, sp_f.n_rows()).fill(*rotated_sparsity[l], sp_tmp.n_cols());
    rotated[l] = std::make_unique<SparseMatrix<double>>(*rotated_sparsity[l]);
    R_fine_inverse.mmult(*rotated[l], tmp, Vector<double>(), false);
  }


  template <int dim>
  LevelBytes
  MultilevelHierarchy<dim>::memory_consumption() const
  {
    LevelBytes bytes = matrix_list_memory_consumption(rotated, rotated_sparsity);
    bytes.resize(std::max(bytes.size(), level_patches.size()), 0);
    for (unsigned int l = 0; l < level_patches.size(); ++l)
      bytes[l] += MemoryConsumption::memory_consumption(level_patches[l].patches) +
                  MemoryConsumption::memory_consumption(level_patches[l].colors);
    return bytes;
  }

  template class MultilevelHierarchy<2>;
  template class MultilevelHierarchy<3>;
} // namespace FoslsContact
