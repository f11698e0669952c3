#ifndef fosls_contact_solvers_level_truncation_h
#define fosls_contact_solvers_level_truncation_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/qp/level_algebra.h>

#include <memory>
#include <utility>
#include <vector>

namespace FoslsContact
{
  /**
   * The truncation of one level of the monotone cycle at its iterate
   * (paper eq. 34) and the defect obstacle it leaves (eqs. 35-36): a DoF
   * that is fixed, active (v_i >= ub_i) or switched off (zero diagonal,
   * which the truncation of the finer level does to the DoFs it drops) is
   * truncated: the coarse correction does not move it, and its defect
   * obstacle is +inf; any other bounded DoF may move by up to ub_i - v_i.
   *
   * Most of the decision does not depend on the iterate: the fixed and
   * the switched-off DoFs change only with the operator (which changes
   * only with the finer level's truncation) or with the roles (those of
   * the Newton step's linear problem). That part is computed by prepare()
   * when one of them changes; a visit (truncate()) only looks at the
   * bounded DoFs that are left.
   */
  class LevelTruncation
  {
  public:
    /**
     * What identifies an operator across its updates: its address and
     * the number of times it was rebuilt (LevelOperators::Version).
     */
    using Version = std::pair<const void *, unsigned int>;

    /**
     * Bring the iterate-independent part up to date for the operator
     * @p A (identified by @p version) on the level of @p partitioner and
     * the roles @p role. (The partitioner decides when the arrays are set
     * up: a process may own no DoF of the level, so their sizes cannot.)
     */
    void prepare(const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                 const SparseMatrix<double> &                              A,
                 const Version                                             version,
                 const std::vector<DoFRole> &                              role);

    /**
     * The truncation at @p v for the obstacles @p ub. (The ghost values of
     * v and ub must be valid: the ghost DoFs get the same decision as at
     * their owners.)
     */
    void truncate(const LevelVector &ub, const LevelVector &v);

    /** Whether each local DoF (owned and ghost) is truncated. */
    const std::vector<bool> &truncated() const { return truncated_dofs; }

    /** The defect obstacle of the last truncate(): ub - v, or +inf. */
    const LevelVector &defect_obstacle() const { return defect; }

    /** The local bounded DoFs that are neither fixed nor switched off. */
    const std::vector<types::global_dof_index> &bounded() const { return bounded_dofs; }

  private:
    std::vector<bool> truncated_dofs;
    /** On the level's partitioner: prepare() sets it up when that changes. */
    LevelVector defect;
    /** Fixed or switched off: truncated in every visit. */
    std::vector<bool>                    fixed_truncated;
    std::vector<types::global_dof_index> bounded_dofs;
    /**
     * The diagonal of the operator (with ghost values): recomputed when the
     * operator changes, which every process sees at once (the update is
     * collective), while the roles can change on some processes only.
     */
    LevelVector diagonal_values;
    /** The operator and roles the diagonal and fixed_truncated belong to. */
    Version              operator_version{nullptr, 0};
    std::vector<DoFRole> roles;
  };
} // namespace FoslsContact

#endif
