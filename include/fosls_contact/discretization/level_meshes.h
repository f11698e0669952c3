#ifndef fosls_contact_discretization_level_meshes_h
#define fosls_contact_discretization_level_meshes_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>

#include <memory>
#include <vector>

namespace FoslsContact
{
  /**
   * The levels of the multilevel solvers on an adaptively refined mesh.
   *
   * The finest level is the adaptive mesh; level l - 1 is level l with
   * every family of active cells above the uniform levels coarsened at
   * once, down to the top uniform level (deal.II's global coarsening
   * sequence, as MGTransferGlobalCoarseningTools::
   * create_geometric_coarsening_sequence() builds it). Every family of the
   * finest cells can be coarsened, so level l's cells are at most of mesh
   * level l, and the levels below the adaptive part are the uniform levels
   * themselves (Discretization::level(l)). Each level in between is a
   * mesh with hanging nodes of its own (Discretization::refine_as()), a
   * conforming space with its hanging nodes eliminated as on the adaptive
   * mesh (LevelData::hanging); the levels are nested and each refines
   * some cells of the one below once, so the monotone multilevel method
   * sees them as it sees the uniform levels: nested spaces with
   * prolongations, vertex patches and contact faces.
   *
   * Why every family at once: the levels then shrink as the uniform
   * levels do, about by 2^dim where the mesh is refined, and hold 1.4 to
   * 1.7 times the adaptive mesh's DoFs together (`summary.json`'s
   * `level_dofs`; doc/method.md, section 9). Capping the mesh at each mesh
   * level instead keeps every cell coarser than the cap, so that each
   * level above the uniform ones has about as many DoFs as the adaptive
   * mesh, and the Galerkin operators and meshes of the levels grow with
   * their number (bench/adaptive_memory.py measures the memory).
   *
   * The prolongation from level l - 1 to level l is the same function:
   * the identity on a cell both levels have, the FESystem's embedding with
   * the RT signs of parent and child (as in LevelTransfer) on a cell that
   * level l refines, applied to the coarse function with its hanging DoFs
   * restored from their masters; the rows of the fine hanging DoFs are
   * empty (they are eliminated). Below the adaptive part the prolongations
   * are LevelTransfer's. The coarsened meshes are held as the adaptive
   * mesh is (Discretization::MeshDistribution::replicated: whole on every
   * process, each partitioned on its own), so the coarse cell of every
   * fine cell, and every coarse DoF, is on every process.
   */
  template <int dim>
  class LevelMeshes
  {
  public:
    /**
     * The levels of the adaptively refined @p discretization, whose
     * uniform levels' prolongations are @p transfer's.
     */
    LevelMeshes(const Discretization<dim> &discretization, const LevelTransfer<dim> &transfer);

    /** The finest level: the mesh level of the finest cells. */
    unsigned int finest_level() const { return sources.size() - 1; }

    /** The discretization that holds level @p l, and its index there. */
    const Discretization<dim> &discretization(const unsigned int l) const
    {
      return *sources[l].discretization;
    }
    unsigned int index(const unsigned int l) const { return sources[l].index; }
    const LevelData<dim> &level(const unsigned int l) const
    {
      return sources[l].discretization->level(sources[l].index);
    }

    /**
     * The prolongation from level @p l - 1 to level @p l in Cartesian
     * coordinates (local fine rows, local coarse columns).
     */
    const SparseMatrix<double> &prolongation(const unsigned int l) const
    {
      return *sources[l].prolongation;
    }

    /**
     * The bytes of the meshes of their own (each with its level data) and
     * the prolongations, by level.
     */
    LevelBytes memory_consumption() const;

  private:
    /**
     * The prolongation from level @p l - 1 to level @p l of the
     * adaptive part.
     */
    void build_prolongation(const unsigned int l);

    struct Source
    {
      const Discretization<dim> *discretization = nullptr;
      unsigned int               index          = 0;
      const SparseMatrix<double> *prolongation  = nullptr;
    };
    std::vector<Source> sources;
    /** The meshes between the uniform levels and the adaptive mesh. */
    std::vector<std::unique_ptr<Discretization<dim>>> coarser;
    std::vector<std::unique_ptr<SparsityPattern>>      sparsities;
    std::vector<std::unique_ptr<SparseMatrix<double>>> matrices;
  };
} // namespace FoslsContact

#endif
