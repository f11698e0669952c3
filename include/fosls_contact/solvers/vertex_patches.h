#ifndef fosls_contact_solvers_vertex_patches_h
#define fosls_contact_solvers_vertex_patches_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>

#include <fosls_contact/discretization/discretization.h>

#include <memory>
#include <vector>

namespace FoslsContact
{
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
   * The Arnold-Falk-Winther vertex patches of one level that this process
   * relaxes (those with a DoF it owns): the vertex's displacement DoFs and
   * the RT DoFs (all stress rows) of every face that contains the vertex,
   * in the patch order (VertexKey), with the colors that let the smoother
   * relax patches of one color concurrently and still compute the
   * sequential sweep. Built once per level by MultilevelHierarchy.
   */
  template <int dim>
  struct VertexPatches
  {
    VertexPatches() = default;
    /**
     * The patches of level @p l of @p discretization, and their colors.
     * With hanging nodes eliminated the patch of a master vertex takes the
     * DoFs of the cells at its hanging vertices too (the support of its
     * basis function). Collective.
     */
    VertexPatches(const Discretization<dim> &discretization, const unsigned int l);

    /** Each patch sorted by global index, in local indices, in VertexKey order. */
    std::vector<std::vector<types::global_dof_index>> patches;
    /** The color of every patch (MultilevelHierarchy::patch_colors()). */
    std::vector<unsigned int> colors;
    /** The number of colors, over all processes. */
    unsigned int n_colors = 0;

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
  };
} // namespace FoslsContact

#endif
