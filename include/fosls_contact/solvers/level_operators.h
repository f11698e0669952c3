#ifndef fosls_contact_solvers_level_operators_h
#define fosls_contact_solvers_level_operators_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/matrix_list_memory.h>
#include <fosls_contact/solvers/flux_rerouting.h>
#include <fosls_contact/solvers/galerkin_product.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/pair_terms.h>

#include <utility>
#include <vector>

namespace FoslsContact
{
  /**
   * The operators of the levels below the finest: the truncated
   * prolongations P~ (paper eq. 34: the fine DoFs that are fixed or active
   * are dropped) and the Galerkin operators A_{l-1} = P~^T A_l P~ of the
   * monotone multilevel method, with the version of every level's
   * operator.
   *
   * Truncation: for a displacement DoF the row of P is zeroed (Kornhuber).
   * For a normal stress DoF the father's column is changed instead
   * (FluxRerouting): an RT coarse function stripped of the flux through
   * one son face has a large divergence there, while the father without
   * that face is a proper H(div) function that leaves the son alone.
   *
   * Because A_{l-1} is the Galerkin product, Q_{l-1}(c) = Q_l(v + P~ c) -
   * Q_l(v): every coarse correction minimizes the fine functional itself.
   * The Galerkin operators keep the sparsity of the untruncated product
   * (GalerkinProduct), so a change of the truncation only recomputes
   * values, and they are recomputed only when the truncation or the finer
   * operator changed (needs_update()).
   *
   * Distributed: every process has the rows of P~ of its local fine DoFs;
   * the coarse operators are local matrices with the owned rows and the
   * ghost rows of the patches, copied from their owners after every
   * product.
   */
  template <int dim>
  class LevelOperators
  {
  public:
    /**
     * A level operator and the version of its values: a change of the
     * values (a new product, a new fine problem) makes a new version.
     */
    using Version = std::pair<const void *, unsigned int>;

    /**
     * Set up the patterns of the truncated prolongations (P's pattern plus
     * the entries the flux rerouting may add) and of the Galerkin products
     * for the hierarchy's levels, with the finest level's operator on
     * @p fine_sparsity. Collective.
     */
    LevelOperators(const MultilevelHierarchy<dim> &hierarchy,
                   const SparsityPattern &         fine_sparsity,
                   FluxRerouting<dim> &            rerouting);

    /**
     * The finest level's operator is @p A with new values (a new
     * problem). Collective.
     */
    void new_fine_operator(const SparseMatrix<double> &A);

    /**
     * Whether the operator of level l - 1 must be rebuilt for the
     * truncation @p truncated of level l (local DoFs), with the faces of
     * truncated sons rerouted or removed (@p reroute): the truncation, the
     * operator of level l or the way differs from the last rebuild. The
     * same on every process. Collective.
     */
    bool needs_update(const unsigned int       l,
                      const std::vector<bool> &truncated,
                      const bool               reroute) const;

    /**
     * Rebuild P~ of level l and the operator of level l - 1 for the
     * truncation @p truncated of the operator @p A of level l with the
     * roles @p role. Collective.
     */
    void update(const unsigned int          l,
                const SparseMatrix<double> &A,
                const std::vector<DoFRole> &role,
                const std::vector<bool> &   truncated,
                const bool                  reroute);

    /** The Galerkin operator of level @p l < finest. */
    const SparseMatrix<double> &galerkin(const unsigned int l) const { return coarse[l]; }
    /** The truncated prolongation from level @p l - 1 to level @p l. */
    const SparseMatrix<double> &truncated_prolongation(const unsigned int l) const
    {
      return prolongation[l];
    }
    /** The operator @p A of level @p l and the version of its values. */
    Version version_of(const unsigned int l, const SparseMatrix<double> &A) const
    {
      return {&A, version[l]};
    }
    /** The face scales of the coarse obstacles (FluxRerouting::face_scale()). */
    const std::vector<double> &face_scale(const unsigned int l) const
    {
      return rerouting.face_scale(l);
    }

    /**
     * The coarse defect of @p v on level @p l, @p r_coarse = P~^T (r - A v)
     * for the last P~ of level l, with the fine residual left in
     * @p residual; with @p pair_terms, of A + K (the Newton step's linear
     * cycle with 3D friction, PairTerms). The ghost values of @p v must be
     * valid. Collective.
     */
    void restrict_defect(const unsigned int          l,
                         const SparseMatrix<double> &A,
                         const LevelVector &         r,
                         const LevelVector &         v,
                         LevelVector &               residual,
                         LevelVector &               r_coarse,
                         const PairTerms *           pair_terms = nullptr) const;
    /**
     * The difference of @p r_coarse to P~^T (r - A v) recomputed, relative
     * to a bound of the terms' size, |P~^T| (|A| |v| + |r|) (max norms),
     * since near the solution r - A v is the small difference of large
     * terms and carries their round-off. NaN if anything is not finite.
     * Collective.
     */
    double coarse_defect_difference(const unsigned int          l,
                                    const SparseMatrix<double> &A,
                                    const LevelVector &         r,
                                    const LevelVector &         v,
                                    const LevelVector &         r_coarse) const;

    /**
     * The bytes of the Galerkin products' index arrays by level (that of
     * level l builds the operator of level l - 1).
     */
    LevelBytes product_memory_consumption() const;
    /**
     * The bytes of the Galerkin operators and the truncated prolongations
     * by level (the operator of level l, the prolongation into it).
     */
    LevelBytes memory_consumption() const;

  private:
    /** P~ of level l: the rows of P at truncated DoFs are zero. */
    void truncate_rows(const unsigned int l, const std::vector<bool> &truncated);
    /**
     * The faces decided by their owners, applied by every process to its
     * rows of P~ of level @p l: the rerouted @p entries added, the columns
     * of the @p removed faces zeroed. Collective.
     */
    void apply_face_changes(const unsigned int                                      l,
                            const std::vector<types::global_dof_index> &            removed,
                            const std::vector<typename FluxRerouting<dim>::ColumnEntry> &entries);

    const MultilevelHierarchy<dim> &hierarchy;
    FluxRerouting<dim> &            rerouting;
    const unsigned int              finest;
    /** P's pattern plus the DoFs the flux rerouting may use (per level). */
    std::vector<SparsityPattern>      prolongation_sparsity;
    std::vector<SparseMatrix<double>> prolongation;
    std::vector<GalerkinProduct>      product;
    /** The Galerkin operators, on the levels' coupling patterns. */
    std::vector<SparseMatrix<double>> coarse;
    /** What the operator of level l - 1 was last built from. */
    std::vector<std::vector<bool>> truncation_used;
    std::vector<unsigned int>      version, version_used;
    std::vector<bool>              reroute_used;
  };
} // namespace FoslsContact

#endif
