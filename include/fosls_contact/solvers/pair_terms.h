#ifndef fosls_contact_solvers_pair_terms_h
#define fosls_contact_solvers_pair_terms_h

#include <fosls_contact/qp/level_algebra.h>

#include <vector>

namespace FoslsContact
{
  /**
   * A symmetric term K that the linear problem of a Newton step adds to A
   * at the 3D friction pairs (NewtonStep::set_pair_role()): the curvature
   * kappa u u^T of a pair's norm or circle. On local DoFs, owned and
   * ghost: (K v)_i = diagonal[i] v_i + coupling[i] v_partner[i], where
   * partner is FrictionTerms::partner (both coordinates of a pair have one
   * owner).
   *
   * The linear cycle that preconditions CG for the Newton matrix sees K on
   * the finest level, in the patch matrices of the smoother
   * (PackedPatches::set_linear_roles()) and in the defect it restricts
   * (MonotoneCycle): without K it preconditions A, not A + K. K must be
   * in both: with K in the smoother alone the cycle is not symmetric (its
   * coarse correction and its smoothers solve for different matrices),
   * and prm/sliding_block_3d.prm on 2 levels took up to 21 Newton steps
   * per Tresca problem instead of 5. The pairs that move along one
   * direction only are left to CG's projection (P B P, NewtonStep): held
   * to it in the smoother and the coarse corrections as well, the same
   * scene on 3 levels took up to 52 Newton steps per Tresca problem
   * instead of 13 (doc/method.md section 7.7).
   */
  struct PairTerms
  {
    std::vector<unsigned int> partner;
    std::vector<double>       diagonal, coupling;

    bool
    empty() const
    {
      return partner.empty();
    }

    bool
    operator==(const PairTerms &other) const
    {
      return partner == other.partner && diagonal == other.diagonal &&
             coupling == other.coupling;
    }

    /**
     * @p residual -= K @p v on the owned DoFs (@p v's ghost values need
     * not be valid: a pair's partner has the same owner).
     */
    void
    subtract_product(const LevelVector &v, LevelVector &residual) const
    {
      const unsigned int n_owned = residual.locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        if (diagonal[i] != 0 || coupling[i] != 0)
          residual.local_element(i) -=
            diagonal[i] * v.local_element(i) + coupling[i] * v.local_element(partner[i]);
    }
  };
} // namespace FoslsContact

#endif
