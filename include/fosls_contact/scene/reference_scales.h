#ifndef fosls_contact_scene_reference_scales_h
#define fosls_contact_scene_reference_scales_h

#include <cmath>

namespace FoslsContact
{
  /**
   * The reference length L and stress S of a scene (doc/method.md,
   * section 1). The program solves for the dimensionless x/L, u/L and
   * sigma/S, with the body force f L/S, the traction t/S and the gap g/L,
   * and the elastic constants mu/S and lambda/S. The three terms of the
   * functional have different physical dimensions (stress^2/length^2,
   * strain^2 and stress times length, per volume), so weights applied to
   * the physical terms would define a different functional in every unit
   * system, with a different definiteness limit; applied to the
   * dimensionless terms, C_eq, C_const and C_compl define one functional
   * for all of them. Every number the program reports is converted back
   * by the factors below.
   */
  struct ReferenceScales
  {
    double length = 1.; ///< L
    double stress = 1.; ///< S

    /**
     * The functional in the scene's units: J = L^dim J^, i.e.
     * C_eq (L/S)^2 |div sigma + f|^2 + C_const |A sigma - eps(u)|^2 +
     * C_compl/S <u.n - g, sigma_nn>, of dimension length^dim (a squared
     * strain times a volume).
     */
    double functional(const unsigned int dim) const { return std::pow(length, double(dim)); }
    /** A force (or a force per unit thickness in 2D): S L^(dim-1). */
    double force(const unsigned int dim) const
    {
      return stress * std::pow(length, double(dim) - 1.);
    }
  };
} // namespace FoslsContact

#endif
