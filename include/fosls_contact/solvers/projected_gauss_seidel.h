#ifndef fosls_contact_solvers_projected_gauss_seidel_h
#define fosls_contact_solvers_projected_gauss_seidel_h

#include <fosls_contact/solvers/qp_solver.h>

namespace FoslsContact
{
  /**
   * Projected Gauss-Seidel (coordinate descent with projection): the
   * classic baseline whose rate deteriorates as h -> 0 (paper section 4.2).
   * Each coordinate step minimizes J exactly along e_i within the bounds,
   * so J never increases. With friction (ConstrainedQP::FrictionTerms) a
   * tangential traction is cut at its slip bound, and a slip DoF's step
   * minimizes the quadratic plus w_i |x_i - p_i| (soft thresholding: the
   * step without the term, moved toward p_i by w_i / a_ii, or to p_i);
   * a 3D pair (FrictionTerms::partner) takes one 2x2 block step, in its
   * disc or with its Euclidean norm (TangentialPair): this is the
   * reference solver of friction.
   *
   * The sweep is sequential, on the first process (the baseline, meant
   * for one process), in the order of Discretization::sweep_order(): the
   * DoFs by their support points, the numbering of one process, so that
   * the sweep is the same on any number of processes.
   */
  class ProjectedGaussSeidel : public QPSolver
  {
  public:
    /**
     * @p order: on process 0 the global indices of all DoFs in the order
     * of the sweep (Discretization::sweep_order()), ignored elsewhere.
     */
    explicit ProjectedGaussSeidel(std::vector<types::global_dof_index> order)
      : order(std::move(order))
    {}

    void solve(const ConstrainedQP &qp, LevelVector &x, IterationObserver &observer) override;

  private:
    std::vector<types::global_dof_index> order;
  };
} // namespace FoslsContact

#endif
