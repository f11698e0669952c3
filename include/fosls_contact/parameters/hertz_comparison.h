#ifndef fosls_contact_parameters_hertz_comparison_h
#define fosls_contact_parameters_hertz_comparison_h

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Hertz comparison: a scene that is a Hertz contact (a
     * cylinder, per unit length in 2D, or a sphere, in 3D, of radius R
     * against a plane, one of them rigid) declares it here, and the run
     * compares its contact pressure with Hertz's (HertzPressure).
     */
    struct HertzComparison
    {
      enum class Shape
      {
        none,
        cylinder,
        sphere,
      };
      Shape               shape  = Shape::none;
      double              radius = 0;
      /** The first point of contact, where Hertz's pressure peaks. */
      std::vector<double> contact_point;
      /**
       * The full contact's force per computed force: 4 for a quarter model
       * of a sphere, 2 for a half model; Hertz's formulas get the full
       * force.
       */
      double              force_factor = 1.;
      /** A cylinder in 3D: the direction of its axis. */
      std::vector<double> axis;
      /** A cylinder in 3D: the length of the contact line (of the full model). */
      double              length = 0.;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
