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

      bool enabled() const { return law != Law::none; }

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
