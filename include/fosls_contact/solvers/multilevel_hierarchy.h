#ifndef fosls_contact_solvers_multilevel_hierarchy_h
#define fosls_contact_solvers_multilevel_hierarchy_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_meshes.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/qp/matrix_list_memory.h>
#include <fosls_contact/solvers/contact_face_relations.h>
#include <fosls_contact/solvers/vertex_patches.h>

#include <memory>

namespace FoslsContact
{
  /**
   * Everything the monotone multilevel method needs to know about the
   * levels 0..finest of a Discretization (its uniformly refined levels)
   * or of an adaptively refined mesh (LevelMeshes: the uniform levels, the
   * meshes between them and the adaptive mesh), built once, on this
   * process; the solvers see only this class, so both hierarchies are
   * one code path:
   * - the prolongations in the normal-tangential basis of every level,
   *   P_rot = R_l^{-1} P R_{l-1} (section 4.3: the change of basis enters
   *   the transfer operators once and for all), for the local fine DoFs,
   * - the Arnold-Falk-Winther vertex patches of every level that this
   *   process relaxes, with their colors (VertexPatches),
   * - the contact relations of its coarse contact faces, for the coarse
   *   obstacles and the flux rerouting (ContactFaceRelations).
   */
  template <int dim>
  class MultilevelHierarchy
  {
  public:
    MultilevelHierarchy(const Discretization<dim> &discretization,
                        const LevelTransfer<dim> & transfer,
                        const unsigned int         finest_level);

    /**
     * The levels of an adaptively refined mesh (LevelMeshes): the uniform
     * levels, the coarsened meshes and the adaptive mesh on top.
     */
    explicit MultilevelHierarchy(const LevelMeshes<dim> &meshes);

    unsigned int finest_level() const { return finest; }

    /**
     * Whether level @p l is a level of an adaptively refined mesh
     * (LevelMeshes) above the uniformly refined ones: a mesh with hanging
     * nodes that refines some cells of the level below.
     */
    bool adaptive_level(const unsigned int l) const { return level(l).active_mesh; }
    const LevelData<dim> &level(const unsigned int l) const
    {
      return sources[l].discretization->level(sources[l].index);
    }
    /**
     * Rotated prolongation from level @p l - 1 to level @p l: the rows of
     * all local fine DoFs, the columns local coarse DoFs.
     */
    const SparseMatrix<double> &prolongation(const unsigned int l) const
    {
      return *rotated[l];
    }
    /**
     * The vertex patches of level @p l relaxed here (each sorted by global
     * index, in local indices), in the order of their vertices' VertexKey.
     */
    const std::vector<std::vector<types::global_dof_index>> &
    patches(const unsigned int l) const
    {
      return level_patches[l].patches;
    }
    /**
     * The color of every patch of level @p l: the level scheduling of the
     * patch order over the coupling of patches whose vertices share a
     * cell of the level, over all processes. Relaxing color by color keeps
     * the order of every pair of patches the matrix of the level can
     * couple (its entries lie on the coupling pattern of the level's
     * cells: the Galerkin operators too, see LevelOperators), so the
     * colored sweep is the sequential sweep in patch order, for any number
     * of processes and threads.
     */
    const std::vector<unsigned int> &patch_colors(const unsigned int l) const
    {
      return level_patches[l].colors;
    }
    /** The number of colors of level @p l, over all processes. */
    unsigned int n_colors(const unsigned int l) const { return level_patches[l].n_colors; }

    /** Coarse contact faces of level @p l - 1 owned here. */
    const std::vector<FaceRelation> &face_relations(const unsigned int l) const
    {
      return contact_faces[l].faces;
    }
    /**
     * The entries (local fine DoF, local coarse contact face DoF) the flux
     * rerouting may give the prolongation from level @p l - 1 (the fine
     * DoFs inside the face's coarse cell, FaceRelation::inside), for every
     * coarse contact face with a cell here: the owner of the face computes
     * the rerouted column, every process with one of its rows stores it.
     */
    const std::vector<std::pair<types::global_dof_index, types::global_dof_index>> &
    rerouting_entries(const unsigned int l) const
    {
      return contact_faces[l].rerouting;
    }

    /**
     * The bytes of the rotated prolongations and the vertex patches by
     * level (the levels' own data is the discretizations').
     */
    LevelBytes memory_consumption() const;

  private:
    /** Level l: a level of a discretization, and the prolongation to it. */
    struct Source
    {
      const Discretization<dim> * discretization;
      unsigned int                index;
      const SparseMatrix<double> *prolongation;
    };

    /** Everything above, for the levels @p sources. */
    void build(const std::vector<Source> &sources);

    /** The rotated prolongation from level @p l - 1 to @p l. */
    void rotate_prolongation(const unsigned int l);

    std::vector<Source> sources;
    unsigned int        finest = 0;
    std::vector<std::unique_ptr<SparsityPattern>>      rotated_sparsity;
    std::vector<std::unique_ptr<SparseMatrix<double>>> rotated;
    std::vector<VertexPatches<dim>>        level_patches;
    std::vector<ContactFaceRelations<dim>> contact_faces;
  };
} // namespace FoslsContact

#endif
