#ifndef fosls_contact_qp_definiteness_check_h
#define fosls_contact_qp_definiteness_check_h

#include <fosls_contact/qp/constrained_qp.h>

namespace FoslsContact
{
  /**
   * Is the quadratic form of a ConstrainedQP positive definite on the
   * space of non-fixed DoFs?
   *
   * Only the complementarity term can spoil definiteness (paper section 3
   * and 7), and it couples only the contact normal DoFs C (the bounded
   * ones). With I the other non-fixed DoFs, A is positive definite iff
   * A_II is (it is: plain FOSLS with a Dirichlet part) and the Schur
   * complement S = A_CC - A_CI A_II^{-1} A_IC is. S is small and dense: it
   * costs one sparse factorization and |C| solves. It runs on a problem of
   * one process (a GatheredQP).
   */
  struct DefinitenessCheck
  {
    /** Smallest eigenvalue of D^{-1/2} S D^{-1/2}, D = diag(A_CC). */
    double       min_relative_eigenvalue = 1;
    unsigned int n_contact_dofs          = 0;
    bool         definite() const { return min_relative_eigenvalue > 0; }

    static DefinitenessCheck run(const ConstrainedQP &qp);
  };
} // namespace FoslsContact

#endif
