#ifndef fosls_contact_qp_algebraic_level_h
#define fosls_contact_qp_algebraic_level_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/matrix_entry_import.h>

#include <memory>
#include <vector>

namespace FoslsContact
{
  /**
   * One level as the algebra sees it, on this process: its DoFs
   * distributed over the processes (`partitioner`: the owned DoFs and the
   * ghost DoFs around them), and for all of them, in local indices
   * (LevelVector), the role, the value of a fixed DoF and the bound of a
   * bounded one; the pattern every matrix of the level lies on, and the
   * import of its ghost rows. This is what a ConstrainedQP is sized from
   * (ConstrainedQP::reinit()); the discretization adds the mesh's view of
   * the level (LevelData).
   */
  struct AlgebraicLevel
  {
    /** The number of DoFs of the level (all processes). */
    types::global_dof_index                            n_dofs = 0;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    /** The space dimension of the mesh the level comes from. */
    unsigned int dimension = 0;
    /**
     * How many times smaller its smallest cells are than its largest, by
     * refinement: 2^(finest - coarsest level of its cells); 1 on a
     * uniformly refined level.
     */
    double refinement_ratio = 1;

    /** Local DoFs: owned, then ghosts. */
    unsigned int n_owned() const { return partitioner->locally_owned_size(); }
    unsigned int n_local() const
    {
      return partitioner->locally_owned_size() + partitioner->n_ghost_indices();
    }
    /** The global index of local DoF @p i. */
    types::global_dof_index global(const unsigned int i) const
    {
      return partitioner->local_to_global(i);
    }

    std::vector<DoFRole> role;
    /** In the normal-tangential basis (paper section 4.3). */
    LevelVector fixed_values;
    LevelVector upper_bounds;
    /**
     * The coupling pattern of the level's cells, in local indices, for the
     * rows this process holds: its own DoFs, and the ghost DoFs of the
     * vertex patches at the vertices of its cells (the patch smoother
     * relaxes every patch with a DoF of its own, and needs the rows of all
     * the patch's DoFs). Every level matrix lies on it: the assembled one
     * and the Galerkin operators (LevelOperators).
     */
    SparsityPattern sparsity;
    /** The ghost rows of `sparsity`, copied from their owners. */
    MatrixEntryImport ghost_rows;
  };
} // namespace FoslsContact

#endif
