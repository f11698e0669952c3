#ifndef fosls_contact_qp_tangential_pair_h
#define fosls_contact_qp_tangential_pair_h

namespace FoslsContact
{
  /**
   * The two local problems of 3D friction on the two tangential
   * coordinates of one contact vertex or face (doc/method.md section 7.7):
   * with a symmetric positive definite 2x2 matrix H = {h00, h01, h11},
   *
   * - slip (a vertex):  minimize 1/2 y^T H y - r^T y + w |y|,
   * - disc (a face):    minimize 1/2 z^T H z - r^T z  subject to |z| <= s,
   *
   * with |.| the Euclidean norm: the isotropic friction of a 3D contact.
   * Both minimizers are y = (H + mu I)^{-1} r for the one mu >= 0 at which
   * the norm term's slope w / |y|, or the disc's multiplier, balances it:
   * |(H + mu I)^{-1} r| is monotone in mu, so mu is found by bisection in
   * the eigenbasis of H, to the last bit. These are the pair blocks of the
   * smoother's patches (PatchSmoother), of projected Gauss-Seidel and of
   * the Newton step's tests (NewtonStep); they are the only places where
   * the two coordinates do not separate.
   */
  namespace TangentialPair
  {
    /** A vector of the plane (entries 0 and 1). */
    struct Vector2
    {
      double x0, x1;
      double operator[](const unsigned int k) const { return k == 0 ? x0 : x1; }
      double &operator[](const unsigned int k) { return k == 0 ? x0 : x1; }
    };
    /** A symmetric 2x2 matrix: entries 0, 1, 2 are h00, h01, h11. */
    struct Matrix2
    {
      double h00, h01, h11;
      double operator[](const unsigned int k) const { return k == 0 ? h00 : k == 1 ? h01 : h11; }
    };

    /** The Euclidean norm of @p y. */
    double norm(const Vector2 &y);

    /** The minimizer of 1/2 y^T H y - r^T y + w |y| (0 where |r| <= w). */
    Vector2 minimize_with_norm(const Matrix2 &H, const Vector2 &r, const double w);

    /**
     * The minimizer of 1/2 z^T H z - r^T z over |z| <= s (on the circle:
     * |z| = s exactly, up to the rounding of one scaling).
     */
    Vector2 minimize_in_disc(const Matrix2 &H, const Vector2 &r, const double s);

    /** @p z scaled onto the disc |z| <= s (unchanged inside it). */
    Vector2 project_to_disc(const Vector2 &z, const double s);

    /**
     * The t >= 0 at which z + t d leaves the disc |.| <= s (z in it;
     * infinity for d = 0).
     */
    double disc_exit(const Vector2 &z, const Vector2 &d, const double s);
  } // namespace TangentialPair
} // namespace FoslsContact

#endif
