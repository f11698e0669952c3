#ifndef fosls_contact_parameters_solver_h
#define fosls_contact_parameters_solver_h

#include <deal.II/base/parameter_handler.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Solver: which solver (the monotone multigrid, the active
     * set reference or projected Gauss-Seidel) and how it runs: stopping,
     * cycle, smoothing, coarse obstacle projection, initial guess, Newton
     * acceleration, threads. The defaults of the counts are the members'
     * initial values, stated once.
     */
    struct Solver
    {
      enum class Type
      {
        monotone_multigrid,
        active_set,
        projected_gauss_seidel,
      };
      enum class Projection
      {
        a,
        b,
        c,
        d,
      };
      enum class InitialGuess
      {
        zero,
        coarse_solution,
        nested_iteration,
        expression,
      };
      enum class Stopping
      {
        tolerance,
        discretization_accuracy,
      };
      /**
       * V: one visit of the coarser level per visit; W: two; F: an F-cycle
       * on the coarser level, then a V-cycle there (level l - k is visited
       * k + 1 times instead of 2^k).
       */
      enum class Cycle
      {
        V,
        W,
        F,
      };

      /**
       * Where the patch smoother reads the matrix rows of a patch from:
       * copied next to each other per patch (PackedPatches: the fastest
       * sweeps) or the level matrices themselves (a row of a face DoF is
       * then stored once instead of once per patch of the face's
       * vertices, the largest saving of memory in 3D). The iterates are
       * the same to the bit.
       */
      enum class PatchRows
      {
        copied,
        matrix,
      };

      /** The default of Tolerance ("auto" stopping takes another value as a wish). */
      static constexpr double default_tolerance = 1e-8;

      Type         type                = Type::monotone_multigrid;
      double       tolerance           = default_tolerance;
      unsigned int max_iterations      = 200;
      Stopping     stopping            = Stopping::tolerance;
      /** Whether the stopping criterion was chosen by "auto". */
      bool         automatic_stopping  = false;
      double       discretization_fraction = 0.1;
      unsigned int pre_smoothing       = 3;
      unsigned int post_smoothing      = 3;
      Cycle        cycle               = Cycle::W;
      Projection   projection          = Projection::b;
      InitialGuess initial_guess       = InitialGuess::coarse_solution;
      unsigned int definiteness_max_dofs = 20000;
      unsigned int krylov_steps          = 50;
      PatchRows    patch_rows            = PatchRows::copied;
      /** 0: as many threads as cores (or DEAL_II_NUM_THREADS). */
      unsigned int threads               = 0;
      /**
       * A diagnostic: recompute the coarse defects a W- or F-cycle's
       * second visit takes from the first (MonotoneCycle) and
       * report the largest difference.
       */
      bool         check_coarse_defects  = false;
      /**
       * Solve each problem again with the active set method and report
       * the difference (FoslsProblem::cross_check()).
       */
      bool         cross_check           = false;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
