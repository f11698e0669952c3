#ifndef fosls_contact_solvers_flux_rerouting_h
#define fosls_contact_solvers_flux_rerouting_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/matrix_entry_import.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

#include <array>
#include <map>
#include <vector>

namespace FoslsContact
{
  /**
   * What the truncation of a normal stress DoF does to the coarse contact
   * face above it (paper eq. 34; doc/method.md section 6, Truncation).
   * Where a contact zone ends inside a coarse face, some of the face's
   * sons are truncated; the father's column of the prolongation then
   * either
   * - keeps a basis function that carries its flux through the free sons
   *   only (reroute(): the plain cycle). Without it no coarse function can
   *   change the total contact force, and the plain cycle stalls;
   * - or goes (linear_columns(): the linear cycle that preconditions the
   *   Newton step, where the rerouted basis converges worse on the finer
   *   half discs).
   * (The cycles of both, with and without rerouting: doc/performance.md,
   * "Figures behind the code".)
   *
   * With friction in 2D the tangential traction of a contact face is held at
   * its slip bound by the Newton step's linear problem where it slips, so
   * where a slip zone ends inside a coarse face its tangential row is cut
   * too. The linear cycle reroutes that row (linear_columns()): cut, its
   * column's divergence has no coarse function that can carry the
   * traction of a free son next to held ones, and CG paid with steps
   * that grew by about one per level (`prm/sliding_block.prm`, where
   * Coulomb's bound leaves the traction of the block's end faces free
   * beside held ones; doc/method.md section 7.7).
   *
   * Rerouting gives the free sons the flux the truncated ones lost and
   * restores the balance of the fine cells at the sons by a local
   * correction: the change d of the face's column (at its sons) is
   * extended to the free, unbounded DoFs coupled to the sons by A inside
   * the coarse cell (FaceRelation::inside: the column stays inside the
   * cell, so the Galerkin operator stays on the coupling pattern of the
   * coarse cells, which the patch colors rely on), minimizing
   * (d + e)^T A (d + e), so that the column stays nearly divergence free.
   * (A column cut at a son has a divergence of order 1/h in the son's
   * cell, and an energy orders of magnitude above the corrected one.) A
   * face with all sons truncated goes.
   *
   * Distributed: the owner of a coarse face (the owner of its cell)
   * decides; the operator's entries between the DoFs inside the coarse
   * cell whose rows other processes own are imported after every change
   * of the operator (import_values()).
   */
  template <int dim>
  class FluxRerouting
  {
  public:
    /**
     * A change of the prolongation's column of a coarse face: (fine row,
     * coarse column, value), the rows and columns as global indices.
     */
    using ColumnEntry = std::array<double, 3>;

    /**
     * Set up for the levels of @p hierarchy, whose finest level's operator
     * is on @p fine_sparsity; the imports only if @p enabled (the plain
     * cycle, or tangential rows: ContactFaceRelations::tangential_rows()).
     * Collective.
     */
    FluxRerouting(const MultilevelHierarchy<dim> &hierarchy,
                  const SparsityPattern &         fine_sparsity,
                  const bool                      enabled);

    /**
     * Import the entries of the operator @p A of level @p l that the
     * rerouting reads and other processes own (collective; nothing unless
     * enabled and l > 0).
     */
    void import_values(const unsigned int l, const SparseMatrix<double> &A);

    /**
     * The rerouted columns of the prolongation @p P from level l - 1 to l
     * for the coarse contact faces owned here whose sons are partly
     * truncated (@p truncated, local fine DoFs): the changes of their
     * columns are appended to @p entries, the faces that go to
     * @p removed (global coarse indices). Sets face_scale(l).
     */
    void reroute(const unsigned int                    l,
                 const SparseMatrix<double> &          A,
                 const SparseMatrix<double> &          P,
                 const std::vector<DoFRole> &          role,
                 const std::vector<bool> &             truncated,
                 std::vector<types::global_dof_index> &removed,
                 std::vector<ColumnEntry> &            entries);

    /**
     * The columns of the linear cycle: the coarse contact faces owned here
     * with a truncated normal son go (to @p removed, global coarse
     * indices); their tangential rows (friction in 2D) are rerouted as
     * reroute() does, into @p entries. face_scale(l) is 1.
     */
    void linear_columns(const unsigned int                    l,
                        const SparseMatrix<double> &          A,
                        const SparseMatrix<double> &          P,
                        const std::vector<DoFRole> &          role,
                        const std::vector<bool> &             truncated,
                        std::vector<types::global_dof_index> &removed,
                        std::vector<ColumnEntry> &            entries);

    /**
     * Per coarse contact face of level l - 1 owned here (FaceRelation):
     * the factor its coarse obstacle is divided by, the largest weight of
     * a free son (at least 1: such a son moves by that factor times the
     * coarse value, CoarseObstacles).
     */
    const std::vector<double> &face_scale(const unsigned int l) const { return scale[l]; }

  private:
    /**
     * The entries of the level-@p l operator the rerouting reads on the
     * faces owned here whose rows other processes own (global indices,
     * sorted): the requests of imports[l].
     */
    std::vector<MatrixEntryImport::Entry> requests(const unsigned int l) const;
    /**
     * Entry (a, b) (local) of the operator @p A of level @p l between DoFs
     * inside a coarse cell here: from @p A for an owned row, else from the
     * last import.
     */
    double entry(const unsigned int            l,
                 const SparseMatrix<double> &  A,
                 const types::global_dof_index a,
                 const types::global_dof_index b) const;
    /**
     * Reroute the column of the coarse DoF @p j of a contact face with the
     * sons @p sons (one row of the face) and the fine DoFs @p inside its
     * coarse cell (FaceRelation::inside), if some sons are truncated: the
     * changes to @p entries, or @p j to @p removed if all are. Returns the
     * largest weight of a free son (1 if none changed).
     */
    double reroute_column(const unsigned int                          l,
                          const types::global_dof_index               j,
                          const std::vector<types::global_dof_index> &sons,
                          const std::vector<types::global_dof_index> &inside,
                          const SparseMatrix<double> &                A,
                          const SparseMatrix<double> &                P,
                          const std::vector<DoFRole> &                role,
                          const std::vector<bool> &                   truncated,
                          std::vector<types::global_dof_index> &      removed,
                          std::vector<ColumnEntry> &                  entries) const;
    /**
     * The local correction of the rerouted column @p j with the change
     * @p d at its sons @p sons: the entries of the free, unbounded DoFs of
     * @p inside coupled to the sons.
     */
    void correct_column(const unsigned int                               l,
                        const types::global_dof_index                    j,
                        const std::vector<types::global_dof_index> &     sons,
                        const std::vector<types::global_dof_index> &     inside,
                        const SparseMatrix<double> &                     A,
                        const std::vector<DoFRole> &                     role,
                        const std::vector<bool> &                        truncated,
                        const std::map<types::global_dof_index, double> &d,
                        std::vector<ColumnEntry> &                       entries) const;

    const MultilevelHierarchy<dim> &hierarchy;
    const bool                      is_enabled;
    std::vector<std::vector<double>> scale;
    /**
     * Per level: the import of the entries inside the coarse cells of the
     * contact faces owned here whose rows other processes own, the
     * requests as (local row, local column), and their values in the last
     * operator.
     */
    std::vector<MatrixEntryImport> imports;
    std::vector<std::vector<std::pair<types::global_dof_index, types::global_dof_index>>>
      imported_entries;
    std::vector<std::map<std::pair<types::global_dof_index, types::global_dof_index>, double>>
      imported_values;
  };
} // namespace FoslsContact

#endif
