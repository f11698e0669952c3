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
   * A coarse contact face of level l - 1 owned here and what its coarse
   * obstacles need from level l (paper eqs. 13, 25-30): its sons, and the
   * coarse contact edges of the face (the face itself in 2D) with the fine
   * normal DoFs at their ends and midpoints; in 3D the face's center. All
   * DoFs are local indices: coarse ones of level l - 1, fine ones of
   * level l. The coarse cell of a boundary face is the one cell at it, so
   * every coarse contact face is owned by exactly one process, which has
   * all its children.
   */
  struct FaceRelation
  {
    types::global_dof_index              coarse_dof;
    std::vector<types::global_dof_index> sons;
    /**
     * The fine DoFs of the coarse cell's children that do not lie on one
     * of its other faces (sorted): the DoFs the flux rerouting may use, so
     * that the rerouted column stays inside the coarse cell and the
     * Galerkin operator on the coupling pattern of the coarse cells.
     */
    std::vector<types::global_dof_index> inside;
    /** A coarse contact edge of the face: both ends and the midpoint. */
    struct Edge
    {
      /** coarse normal DoFs of the ends (invalid if an end is not bounded) */
      std::array<types::global_dof_index, 2> coarse;
      /** fine normal DoFs of the ends */
      std::array<types::global_dof_index, 2> fine;
      types::global_dof_index                fine_midpoint;
    };
    std::vector<Edge> edges;
    /** 3D: the fine normal DoF of the face center, or invalid. */
    types::global_dof_index fine_center = numbers::invalid_dof_index;
    /** 3D: the coarse normal DoFs of the face's bounded vertices. */
    std::vector<types::global_dof_index> coarse_vertices;
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
   * levels 0..finest of a Discretization, built once, on this process:
   * - the prolongations in the normal-tangential basis of every level,
   *   P_rot = R_l^{-1} P R_{l-1} (section 4.3: the change of basis enters
   *   the transfer operators once and for all), for the local fine DoFs,
   * - the Arnold-Falk-Winther vertex patches of every level that this
   *   process relaxes (those with a DoF it owns): the vertex's
   *   displacement DoFs and the RT DoFs (all stress rows) of every face
   *   that contains the vertex, in the patch order (VertexKey), with
   *   their colors,
   * - the contact relations of its coarse contact faces, for the coarse
   *   obstacles and the flux rerouting.
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
      return level_patches[l];
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
      return level_colors[l];
    }
    /** The number of colors of level @p l, over all processes. */
    unsigned int n_colors(const unsigned int l) const { return level_n_colors[l]; }

    /** Coarse contact faces of level @p l - 1 owned here. */
    const std::vector<FaceRelation> &face_relations(const unsigned int l) const
    {
      return face_rel[l];
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
      return rerouting[l];
    }

    /**
     * Level scheduling, distributed: item p gets the color 1 + the largest
     * color of the items q < p in @p coupled[p] (0 if there is none).
     * Items are local (sorted by their key: q < p is the patch order) and
     * carry their color in the local DoF @p color_dof[p] of @p partitioner;
     * the process owning that DoF computes the color, in rounds with a
     * ghost exchange between them, until every process has all colors.
     * With one process one pass in order does it.
     */
    static std::vector<unsigned int>
    level_schedule(const std::vector<std::vector<unsigned int>> &           coupled,
                   const std::vector<types::global_dof_index> &             color_dof,
                   const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

  private:
    /** The rotated prolongation from level @p l - 1 to @p l. */
    void rotate_prolongation(const unsigned int l, const LevelTransfer<dim> &transfer);
    /** The vertex patches of level @p l relaxed here, and their colors. Collective. */
    void find_patches(const unsigned int l);
    /** The contact relations and rerouting entries of level @p l. */
    void relate_contact_faces(const unsigned int l);
    /** The FaceRelation of contact face @p f of the coarse @p cell. */
    template <typename Iterator>
    FaceRelation face_relation(const Iterator &      cell,
                               const unsigned int    f,
                               const LevelData<dim> &coarse,
                               const LevelData<dim> &fine) const;

    const Discretization<dim> &discretization;
    const unsigned int         finest;
    std::vector<std::unique_ptr<SparsityPattern>>      rotated_sparsity;
    std::vector<std::unique_ptr<SparseMatrix<double>>> rotated;
    std::vector<std::vector<std::vector<types::global_dof_index>>> level_patches;
    std::vector<std::vector<unsigned int>>                           level_colors;
    std::vector<unsigned int>                                        level_n_colors;
    std::vector<std::vector<FaceRelation>>                           face_rel;
    std::vector<std::vector<std::pair<types::global_dof_index, types::global_dof_index>>>
      rerouting;
  };
} // namespace FoslsContact

#endif
