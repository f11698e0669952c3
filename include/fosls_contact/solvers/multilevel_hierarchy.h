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
  };

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
    const std::vector<std::vector<types::global_dof_index>> &
    patches(const unsigned int l) const
    {
      return level_patches[l];
    }
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
    std::vector<std::vector<VertexRelation>> vertex_rel;
    std::vector<std::vector<FaceRelation>>   face_rel;
  };
} // namespace FoslsContact

#endif
