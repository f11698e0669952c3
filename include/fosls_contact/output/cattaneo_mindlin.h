#ifndef fosls_contact_output_cattaneo_mindlin_h
#define fosls_contact_output_cattaneo_mindlin_h

#include <deal.II/base/tensor.h>

#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/hertz_pressure.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Cattaneo and Mindlin's tangential traction for the Hertz contact of a
   * cylinder in 2D or a sphere in 3D (HertzPressure) pressed with the
   * normal force P and then loaded, monotonically, by a tangential force
   * Q < f P under Coulomb friction with the coefficient f (Johnson,
   * *Contact Mechanics*, §7.1 and §7.2): the middle of the contact sticks,
   * |x| < c with c = a sqrt(1 - Q/(f P)) (cylinder), or the disc r < c
   * with c = a (1 - Q/(f P))^(1/3) (sphere), and the tangential traction
   * along Q is
   *   q(x) = f p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]   for |x| < c,
   *   q(x) = f p(x)                                               for c <= |x| < a,
   * x the distance from the contact point (along Q for the cylinder).
   * Past Q = f P the whole contact slips (c = 0). The solution assumes that the normal and the
   * tangential problems decouple: Dundurs' constant beta = 0, which holds
   * for a rigid obstacle and an incompressible body (lambda = inf); with
   * beta != 0 the normal pressure itself brings tangential tractions.
   *
   * Against the computed contact table (ContactTable::rows() with its
   * friction columns): the stick zone's ends along Q (on a sphere's
   * contact, among the vertices on the line through the contact point
   * along Q), each placed midway between its outermost stick vertex and
   * the next vertex beyond it, and
   * their distances from +-c in units of that vertex spacing (the
   * computed end is within one spacing of c when this is <= 1); and the
   * relative L2 error of the tangential traction along Q on the contact
   * boundary (by the vertex rule, as HertzPressure's), against |q| and
   * against |f p| (the slip limit; the only one at Q = 0, where q = 0:
   * below Q/(f P) = 1e-6 the error against |q| is not computed, null in
   * summary.json).
   */
  template <int dim>
  class CattaneoMindlin
  {
  public:
    /**
     * @p hertz: evaluated for the same solution; @p coefficient: Coulomb's
     * f at the contact point.
     */
    CattaneoMindlin(const HertzPressure<dim> &hertz, const double coefficient);

    /** Compare with @p force and the contact table @p rows. */
    void evaluate(const Tensor<1, dim> &                               force,
                  const std::vector<typename ContactRow<dim>::Values> &rows);

    /** The tangential traction q at the distance @p r from the contact point. */
    double traction(const double r) const;

    /** Two lines for the screen. */
    std::string report() const;
    /** The JSON object for summary.json ("cattaneo_mindlin"). */
    std::string json() const;

  private:
    const HertzPressure<dim> &hertz;
    const double              f;

    /** Q (the full model's, as HertzPressure's P) and Q / (f P). */
    double tangential_force = 0, ratio = 0;
    /** Cattaneo-Mindlin's half-width of the stick zone. */
    double c = 0;
    /** Whether a contact vertex sticks. */
    bool sticks = false;
    /** The computed ends of the stick zone along Q. */
    double stick_from = 0, stick_to = 0;
    /** Their distances from -c and c in vertex spacings. */
    double from_error = 0, to_error = 0;
    double error_of_q = 0, error_of_fp = 0;
  };
} // namespace FoslsContact

#endif
