#ifndef fosls_contact_solvers_multilevel_hierarchy_h
#define fosls_contact_solvers_multilevel_hierarchy_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>

#include <memory>

namespace FoslsContact
{
  /**
   * Geometric relations between a coarse contact vertex (level l-1) and
   * the fine contact nodes (level l) that its coarse obstacle must respect
   * (paper eqs. 25-29): the vertex itself, and for every coarse contact
   * edge at the vertex the other end and the fine midpoint; in 3D also the
   * centers of the coarse contact faces at the vertex. All given as the
   * fine levels' normal DoFs.
   */
  struct VertexRelation
  {
    types::global_dof_index coarse_dof;
    types::global_dof_index fine_self;
    /** (fine DoF of the other end, fine DoF of the midpoint) per edge */
    std::vector<std::array<types::global_dof_index, 2>> edges;
    std::vector<types::global_dof_index>                centers;
  };

  /** A coarse contact face and its sons (paper eqs. 13, 30). */
  struct FaceRelation
  {
    types::global_dof_index              coarse_dof;
    std::vector<types::global_dof_index> sons;
    /**
     * The fine DoFs of the coarse cell's children that do not lie on one
     * of its other faces (sorted): the DoFs the flux rerouting may use, so
     * that the rerouted column stays inside the coarse cell and the
     * Galerkin operator on the coarse coupling pattern.
     */
    std::vector<types::global_dof_index> inside;
  };

  /**
   * The place of a vertex in the patch order of a level: the level on
   * which it first appears, what created it there (a vertex of the coarse
   * mesh, the midpoint of a parent line, the center of a parent face or
   * cell; lines by the axis they run along, faces by the axis of their
   * normal) and, within that, its position.
   *
   * In this order the vertices of each kind are pairwise not vertices of
   * a common cell on a uniformly refined mesh (each cell has exactly one
   * vertex of every kind), so the patches of one kind are independent
   * and the level scheduling of the order needs 2^dim colors: the old
   * vertices, the midpoints of lines along x, along y (, z), (the face
   * centers by normal,) the cell centers. Only geometry enters, so every
   * process of a distributed mesh computes the same key for a vertex from
   * any cell that contains it.
   */
  template <int dim>
  struct VertexKey
  {
    unsigned int creation_level = 0;
    unsigned int kind           = 0;
    Point<dim>   position;

    bool operator<(const VertexKey &other) const;
  };

  /** The key of vertex @p v of @p cell (VertexKey). */
  template <int dim, typename CellIterator>
  VertexKey<dim> vertex_key(const CellIterator &cell, const unsigned int v);

  /**
   * Everything the monotone multilevel method needs to know about the
   * levels 0..finest of a Discretization, built once:
   * - the prolongations in the normal-tangential basis of every level,
   *   P_rot = R_l^{-1} P R_{l-1} (section 4.3: the change of basis enters
   *   the transfer operators once and for all),
   * - the Arnold-Falk-Winther vertex patches of every level: the vertex's
   *   displacement DoFs and the RT DoFs (all stress rows) of every face
   *   that contains the vertex,
   * - the contact relations for the coarse obstacles.
   */
  template <int dim>
  class MultilevelHierarchy
  {
  public:
    MultilevelHierarchy(const Discretization<dim> &discretization,
                        const LevelTransfer<dim> & transfer,
                        const unsigned int         finest_level);

    unsigned int finest_level() const { return finest; }
    const LevelData<dim> &level(const unsigned int l) const
    {
      return discretization.level(l);
    }
    /** Rotated prolongation from level @p l - 1 to level @p l. */
    const SparseMatrix<double> &prolongation(const unsigned int l) const
    {
      return *rotated[l];
    }
    /**
     * The Arnold-Falk-Winther vertex patches of level @p l (each sorted),
     * in the order of their vertices' VertexKey.
     */
    const std::vector<std::vector<types::global_dof_index>> &
    patches(const unsigned int l) const
    {
      return level_patches[l];
    }
    /**
     * The color of every patch of level @p l: the level scheduling of the
     * patch order over the coupling of patches whose vertices share a
     * cell of the level. Relaxing color by color keeps the order of every
     * pair of patches the matrix of the level can couple (its entries lie
     * on the coupling pattern of the level's cells: the Galerkin operators
     * too, see MonotoneMultigrid), so the colored sweep is the sequential
     * sweep in patch order.
     */
    const std::vector<unsigned int> &patch_colors(const unsigned int l) const
    {
      return level_colors[l];
    }

    /**
     * Level scheduling: item p gets the color 1 + the largest color of the
     * items q < p in @p coupled[p] (0 if there is none). @p coupled lists,
     * for every item, the items coupled with it (either order).
     */
    static std::vector<unsigned int>
    level_schedule(const std::vector<std::vector<unsigned int>> &coupled);
    /** Relations of coarse level @p l - 1 to fine level @p l. */
    const std::vector<VertexRelation> &vertex_relations(const unsigned int l) const
    {
      return vertex_rel[l];
    }
    const std::vector<FaceRelation> &face_relations(const unsigned int l) const
    {
      return face_rel[l];
    }

  private:
    const Discretization<dim> &discretization;
    const unsigned int         finest;
    std::vector<std::unique_ptr<SparsityPattern>>      rotated_sparsity;
    std::vector<std::unique_ptr<SparseMatrix<double>>> rotated;
    std::vector<std::vector<std::vector<types::global_dof_index>>> level_patches;
    std::vector<std::vector<unsigned int>>                           level_colors;
    std::vector<std::vector<VertexRelation>> vertex_rel;
    std::vector<std::vector<FaceRelation>>   face_rel;
  };
} // namespace FoslsContact

#endif
