#ifndef fosls_contact_problem_friction_law_h
#define fosls_contact_problem_friction_law_h

#include <fosls_contact/discretization/level_data.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The friction law of a scene (Friction/Law) on the finest level: the
   * slip bounds s_F of its contact faces and, from them, the friction terms
   * of the problem (ConstrainedQP::FrictionTerms, doc/method.md section
   * 7.7):
   *
   * - a tangential traction of face F is bounded by |x| <= s_F;
   * - a slip DoF of vertex v gets the weight w_v = C_compl sum_F |F| /
   *   2^(dim-1) s_F over the contact faces F at v (the trapezoidal rule of
   *   C_compl int s |u_t - p_t|), and the reference p_v, the step's
   *   starting displacement.
   *
   * Tresca: s_F is Friction/Bound at the face's center. Coulomb: s_F = f
   * max(0, -(sigma n).n) with the face's mean normal traction of an
   * iterate, f = Friction/Coefficient at its center, the map of the fixed
   * point over Tresca problems that FoslsProblem iterates.
   */
  template <int dim>
  class FrictionLaw
  {
  public:
    /** On @p fine, the finest level's data, with the weight @p c_compl. */
    FrictionLaw(const Scene<dim> &scene, const LevelData<dim> &fine, const double c_compl);

    /**
     * The slip bounds: Tresca's bound, or Coulomb's f times the pressure of
     * @p x (rotated coordinates, with ghost values), one per friction face
     * of the level (LevelData::friction_faces).
     */
    std::vector<double> slip_bounds(const LevelVector &x) const;

    /** Set the friction terms of @p qp for the slip bounds @p s. Collective. */
    void set_bounds(ConstrainedQP &qp, const std::vector<double> &s) const;

    /**
     * The reference displacement of @p qp's slip DoFs: @p reference
     * (rotated coordinates, with ghost values) at them. Collective.
     */
    void set_reference(ConstrainedQP &qp, const LevelVector &reference) const;

    /**
     * The largest change between the slip bounds @p s and @p t relative to
     * the largest of @p t (0 where both are 0). Collective.
     */
    double relative_change(const std::vector<double> &s, const std::vector<double> &t) const;

  private:
    const Scene<dim> &    scene;
    const LevelData<dim> &fine;
    const double          c_compl;
  };
} // namespace FoslsContact

#endif
