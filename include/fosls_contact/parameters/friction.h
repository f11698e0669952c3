#ifndef fosls_contact_parameters_friction_h
#define fosls_contact_parameters_friction_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Friction: the friction law on the contact boundary
     * (doc/method.md section 7.7). With Law = none (the default) the
     * contact is frictionless and nothing of this subsection is read,
     * assembled or stored.
     *
     * Friction acts on the tangential displacement increment of a load
     * step, relative to the previous step's solution (Data/Load steps), so
     * a load path gives the answer of that path; the first step's
     * reference is the undeformed body.
     */
    struct Friction
    {
      enum class Law
      {
        none,
        tresca,
        coulomb,
      };
      Law law = Law::none;
      /** Tresca's slip bound s >= 0 (a stress), an expression of position. */
      std::string bound = "0";
      /** Coulomb's coefficient f >= 0, an expression of position. */
      std::string coefficient = "0";
      /**
       * Coulomb: the most Tresca problems of the fixed point s = f |p| in
       * one load step, and the relative change of the slip bounds at which
       * it stops.
       */
      unsigned int fixed_point_iterations = 50;
      double       fixed_point_tolerance  = 1e-6;
      /**
       * Coulomb, with the monotone multigrid and the tolerance stop: the
       * Tresca problems of a load step are solved to the
       * larger of Solver/Tolerance and this factor times the relative
       * change of the slip bounds that started them (1 for the first), the
       * one whose bounds the fixed point accepts to Solver/Tolerance: an
       * inexact fixed point, since a problem whose bounds are still that
       * change away from their limit needs no more digits. 0 (the
       * default): every one to Solver/Tolerance; doc/method.md, section
       * 7.7, "Inexact Tresca problems", has what 0.01 gains in 2D and
       * loses on the fine 3D Cattaneo-Mindlin mesh.
       */
      double tresca_accuracy = 0;

      bool enabled() const { return law != Law::none; }

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
