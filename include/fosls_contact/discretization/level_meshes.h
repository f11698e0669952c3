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
   * Level l is the mesh with every cell finer than mesh level l replaced by
   * its ancestor on level l: below the uniformly refined levels (where this
   * is the uniform mesh level l, Discretization::level(l)), above them a
   * mesh with hanging nodes of its own (Discretization::refine_as()), and
   * on top the adaptive mesh itself. The levels are nested, each refines
   * some cells of the one below once, and each is a conforming space with
   * its hanging nodes eliminated as on the adaptive mesh (LevelData::
   * hanging), so the monotone multilevel method sees them as it sees the
   * uniform levels: a hierarchy of nested spaces with prolongations,
   * vertex patches and contact faces. This is deal.II's "global
   * coarsening" sequence of meshes, one level per mesh level; with one
   * refinement of the finest cells per adaptive step it is one level per
   * step, as in adaptive monotone multigrid (Kornhuber, Krause).
   *
   * The prolongation from level l - 1 to level l is the same function:
   * the identity on a cell both levels have, the FESystem's embedding with
   * the RT signs of parent and child (as in LevelTransfer) on a cell that
   * level l refines, applied to the coarse function with its hanging DoFs
   * restored from their masters; the rows of the fine hanging DoFs are
   * empty (they are eliminated). Below the adaptive part the prolongations
   * are LevelTransfer's. The capped meshes are held as the adaptive mesh
   * is (Discretization::MeshDistribution::replicated: whole on every
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
    std::vector<std::unique_ptr<Discretization<dim>>> capped;
    std::vector<std::unique_ptr<SparsityPattern>>      sparsities;
    std::vector<std::unique_ptr<SparseMatrix<double>>> matrices;
  };
} // namespace FoslsContact

#endif
