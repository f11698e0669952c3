#ifndef fosls_contact_parameters_weights_h
#define fosls_contact_parameters_weights_h

#include <deal.II/base/parameter_handler.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /** subsection Functional weights: C_eq, C_const, C_compl of eq. (1)-(2). */
    struct Weights
    {
      double c_eq    = 1e2;
      double c_const = 1.;
      /**
       * With #c_compl_auto the largest value the program takes
       * (auto_compl_cap) until ProblemChecks::check_definiteness() chooses
       * it on the scene's mesh.
       */
      double c_compl = auto_compl_cap;
      /** C_compl = auto: the program chooses C_compl (doc/method.md section 6). */
      bool c_compl_auto = true;

      /**
       * The largest C_compl that auto chooses: the weight of the solvers'
       * convergence studies and the shipped scenes' results (doc/method.md
       * section 6); a larger weight only brings the problem closer to
       * indefinite.
       */
      static constexpr double auto_compl_cap = 0.1;
      /**
       * The fraction of the largest definite C_compl on the checked level
       * that auto chooses, where that is below auto_compl_cap: the limit goes
       * down under refinement (by how much from one level to the next:
       * doc/method.md section 6), and a check on a coarser level
       * than the finest raises the weight by
       * ProblemChecks::coarse_level_margin (50%).
       */
      static constexpr double auto_compl_fraction = 0.5;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
