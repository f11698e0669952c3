#ifndef fosls_contact_parameters_adaptivity_h
#define fosls_contact_parameters_adaptivity_h

#include <deal.II/base/parameter_handler.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Adaptivity: the adaptive loop solve -> estimate -> mark ->
     * refine, driven by the cellwise parts eta_T^2 of the least-squares
     * functional (ErrorIndicators). With Steps = 0 (the default) the mesh
     * is refined uniformly, Geometry/Levels times, and nothing else.
     */
    struct Adaptivity
    {
      enum class Marking
      {
        /** Dörfler: the fewest cells whose eta_T^2 sum to Fraction * J. */
        bulk,
        /** The Fraction of the cells with the largest eta_T. */
        fixed_fraction,
      };

      unsigned int steps    = 0;
      Marking      marking  = Marking::bulk;
      double       fraction = 0.5;
      /** No refinement to a mesh of more DoFs than this (0: no limit). */
      unsigned int max_dofs = 0;
      /** Stop once sqrt(J) is at most this, in the scene's units (0: never). */
      double       target_root_functional = 0;
      /**
       * After the loop: refine every cell of the last mesh this many
       * times and solve there, the reference against which every step's
       * error is measured (0: no reference).
       */
      unsigned int reference_refinements = 0;

      bool enabled() const { return steps > 0; }

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
