#ifndef fosls_contact_qp_gathered_qp_h
#define fosls_contact_qp_gathered_qp_h

#include <fosls_contact/qp/constrained_qp.h>

#include <array>

namespace FoslsContact
{
  /**
   * The entries of the owned rows of @p pattern (with the values of
   * @p matrix if given, else 0) in global indices: (row, column, value).
   */
  std::vector<std::array<double, 3>>
  owned_entries(const SparsityPattern &            pattern,
                const SparseMatrix<double> *       matrix,
                const Utilities::MPI::Partitioner &partitioner);

  /**
   * @p pattern (and, if given, @p matrix on it) of size @p n from the
   * entries of owned_entries() gathered from every process (one part per
   * process): what a process needs to work on a whole matrix alone.
   */
  void
  assemble_gathered_entries(const std::vector<std::vector<std::array<double, 3>>> &parts,
                            const types::global_dof_index                           n,
                            SparsityPattern &                                       pattern,
                            SparseMatrix<double> *                                  matrix);

  /** The roles of the first @p n_owned DoFs, as integers to gather. */
  std::vector<unsigned int>
  owned_roles(const std::vector<DoFRole> &role, const unsigned int n_owned);

  /** The parts of owned_roles() gathered from every process, in order. */
  std::vector<DoFRole>
  gathered_roles(const std::vector<std::vector<unsigned int>> &parts);

  /**
   * A ConstrainedQP gathered in global numbering on the first process, as
   * a problem of that process alone (MPI_COMM_SELF):
   * for what works on the whole matrix at once and is meant for one
   * process, the definiteness check (a small level) and projected
   * Gauss-Seidel (the serial baseline, which sweeps the DoFs in their
   * global order). It holds A, its coupling pattern, b, the roles, the
   * fixed values, the bounds and the complementarity part of A (for the
   * limit of its weight), not the equilibrium part.
   */
  class GatheredQP
  {
  public:
    /** Collective. */
    explicit GatheredQP(const ConstrainedQP &distributed);

    /** Whether this process holds the gathered problem (the first). */
    bool here() const { return holder; }
    /** The gathered problem (on the holders). */
    const ConstrainedQP &qp() const { return serial; }

    /**
     * The owned entries of @p x of all processes, in global order, as a
     * vector of the gathered problem (on the first process). Collective.
     */
    LevelVector gather(const LevelVector &x) const;
    /**
     * The entries of @p whole (a vector of the gathered problem, on the
     * first process) to the owned entries of @p x on every process.
     * Collective.
     */
    void scatter(const LevelVector &whole, LevelVector &x) const;

  private:
    MPI_Comm                  comm;
    bool                      holder;
    /** The first global index and the number of owned DoFs per process. */
    std::vector<int>          first, count;
    SparsityPattern           coupling;
    ConstrainedQP             serial;
  };
} // namespace FoslsContact

#endif
