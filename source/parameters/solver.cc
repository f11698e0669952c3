#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/solver.h>
#include <fosls_contact/parameters/value_parsing.h>

namespace FoslsContact
{
  namespace Parameters
  {
    namespace
    {
      /**
       * The entries of the subsection that change how a run is carried out
       * or checked, not what it computes: threads, diagnostics and the
       * definiteness check.
       */
      void
      declare_run_parameters(ParameterHandler &prm, const Solver &defaults)
      {
        prm.declare_entry("Threads",
                          std::to_string(defaults.threads),
                          Patterns::Integer(0, 1024),
                          "Threads per process for the patch smoother (patches of "
                          "one color are relaxed concurrently), the assembly and "
                          "deal.II's vector and matrix operations. 0: as many as "
                          "the machine has cores (or the environment variable "
                          "DEAL_II_NUM_THREADS says). The smoother's iterates do "
                          "not depend on the number of threads; deal.II's sums "
                          "(dot products in the Newton step's CG) are split by "
                          "thread count, so other results can differ in the last "
                          "digits (doc/parallel_results.md has by how much).");
        prm.declare_entry("Check coarse defects",
                          "false",
                          Patterns::Bool(),
                          "A diagnostic of the monotone multigrid for tests: the "
                          "second visit of a level in a W- or F-cycle takes its coarse "
                          "defect as r_H - alpha A_H c when the truncation is the first "
                          "visit's; with true, it is also recomputed as P~^T (r - A v) "
                          "and the largest difference, relative to |P~^T| (|A| |v| + "
                          "|r|) (max norms), is written to summary.json as "
                          "coarse_defect_difference (round-off, doc/method.md "
                          "section 7.3), with the number of such visits as "
                          "coarse_defect_checks. The iterates are the same; the solve "
                          "time and, on several processes, the communication include "
                          "the check's products with the level's matrix and P~^T.");
        prm.declare_entry("Cross check",
                          "false",
                          Patterns::Bool(),
                          "After each solve, solve the same problem again with the "
                          "active set method (a sparse direct solver) from the same "
                          "start, and print and write to summary.json (cross_check) "
                          "and adaptive_steps.csv how far the two solutions are apart: "
                          "J's relative difference and the largest difference of a DoF "
                          "value relative to the active set solution's largest. For "
                          "checking a solver on a mesh; the direct solves take time "
                          "and memory (timer section 'Cross check').");
        prm.declare_entry("Definiteness check max dofs",
                          std::to_string(defaults.definiteness_max_dofs),
                          Patterns::Integer(0),
                          "The definiteness check (paper eq. 10, section 7) forms "
                          "the Schur complement of the functional onto the contact "
                          "normal DoFs on the finest level with at most this many "
                          "DoFs; indefiniteness there implies indefiniteness on "
                          "every finer level (nested spaces). The largest definite "
                          "C_compl falls under refinement, so on a coarser level "
                          "than the finest C_compl is checked raised by 50% (doc/"
                          "method.md section 6). 0: skip the check.");
      }
    } // namespace

    void
    Solver::declare_parameters(ParameterHandler &prm)
    {
      // the counts' defaults are the members' initial values
      const Solver defaults;
      prm.enter_subsection("Solver");
      prm.declare_entry("Type",
                        "monotone multigrid",
                        Patterns::Selection(
                          "monotone multigrid|active set|projected gauss seidel"),
                        "monotone multigrid: the paper's method (default). "
                        "active set: primal-dual active set with a sparse direct "
                        "solve (the reference). projected gauss seidel: the "
                        "classic baseline.");
      prm.declare_entry("Tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "With Stopping criterion = tolerance (see there): stop "
                        "when the energy norm of the last correction, "
                        "times rho/(1-rho) where the rate rho of the last two "
                        "iterations is above 1/2 (the error of a slowly "
                        "converging run), is below Tolerance times that of the "
                        "first correction (an error reduction factor; in the "
                        "Coulomb fixed point's later Tresca problems, the "
                        "larger of that and the first correction of the load "
                        "step's first Tresca problem).");
      prm.declare_entry("Max iterations",
                        std::to_string(defaults.max_iterations),
                        Patterns::Integer(1),
                        "Maximal number of iterations (cycles, sweeps or "
                        "active-set steps).");
      prm.declare_entry("Stopping criterion",
                        "auto",
                        Patterns::Selection("auto|tolerance|discretization accuracy"),
                        "tolerance: as above. discretization accuracy: stop when "
                        "the estimated algebraic error is below Discretization "
                        "fraction times the least-squares functional's "
                        "estimate of the discretization error, sqrt(J): the "
                        "iterations after that change the answer by less than "
                        "its discretization error (not for projected "
                        "Gauss-Seidel, whose rate is not steady enough for the "
                        "estimate). auto: discretization accuracy for the "
                        "monotone multigrid, unless the scene sets Tolerance to "
                        "another value than 1e-8 or has Coulomb friction (then "
                        "tolerance: the Coulomb fixed point compares the "
                        "solutions of its Tresca problems to its Fixed point "
                        "tolerance); tolerance for "
                        "the other solvers.");
      prm.declare_entry("Discretization fraction",
                        "0.1",
                        Patterns::Double(0, 1),
                        "See Stopping criterion.");
      prm.declare_entry("Pre smoothing",
                        std::to_string(defaults.pre_smoothing),
                        Patterns::Integer(0, 100),
                        "Forward patch sweeps before the coarse correction (Pre and "
                        "Post smoothing must not both be 0).");
      prm.declare_entry("Post smoothing",
                        std::to_string(defaults.post_smoothing),
                        Patterns::Integer(0, 100),
                        "Backward patch sweeps after the coarse correction.");
      prm.declare_entry("Cycle",
                        "W",
                        Patterns::Selection("V|W|F"),
                        "Multigrid cycle: V, W, or F (an F-cycle on the coarser "
                        "level, then a V-cycle there).");
      prm.declare_entry("Projection",
                        "b",
                        Patterns::Selection("a|b|c|d"),
                        "Coarse obstacle for the normal displacement: a = eq. "
                        "(26), b = eq. (27), c = eq. (28), d = no coarse "
                        "constraint (infinity).");
      prm.declare_entry("Initial guess",
                        "coarse solution",
                        Patterns::Selection(
                          "zero|coarse solution|nested iteration|expression"),
                        "zero; coarse solution: the exact solution on level 1 "
                        "interpolated to level J (paper section 7); nested "
                        "iteration: solve on every level in turn; expression: "
                        "Data/Initial displacement.");
      prm.declare_entry("Krylov steps",
                        std::to_string(defaults.krylov_steps),
                        Patterns::Integer(0, 1000),
                        "0: the plain monotone multigrid cycle. k > 0: truncated "
                        "nonsmooth Newton multigrid: projected pre-smoothing on "
                        "the finest level, then conjugate gradient steps (at most k; "
                        "they stop at 1e-3 times the first residual of the Newton step) "
                        "preconditioned by the linear truncated cycle on the "
                        "current inactive set, a projected line search that "
                        "never increases J, and projected post-smoothing.");
      prm.declare_entry("Patch rows",
                        "copied",
                        Patterns::Selection("copied|matrix"),
                        "Where the patch smoother reads the matrix rows of a "
                        "vertex patch: copied (each patch keeps a copy of its rows "
                        "next to each other: the fastest sweeps) or matrix (the "
                        "sweeps read the rows of the level matrices: less memory, "
                        "most of all in 3D, where a face DoF's row is in the "
                        "patches of the face's four vertices, but slower sweeps; "
                        "doc/performance.md, section 5). The iterates are the "
                        "same to the bit.");
      declare_run_parameters(prm, defaults);
      prm.leave_subsection();
    }

    void
    Solver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      const std::string t = prm.get("Type");
      type = (t == "monotone multigrid" ? Type::monotone_multigrid :
              t == "active set"         ? Type::active_set :
                                          Type::projected_gauss_seidel);
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
      const std::string stop = prm.get("Stopping criterion");
      // auto: the multigrid stops where further iterations cannot change the
      // answer beyond its discretization error, in a third of the iterations of
      // the tolerance stop (doc/performance.md, "Figures behind the code"); a
      // scene that asks for a tolerance of its own gets it
      stopping = stop == "tolerance" ? Stopping::tolerance :
                 stop == "discretization accuracy" ?
                                       Stopping::discretization_accuracy :
                 type == Type::monotone_multigrid && tolerance == default_tolerance ?
                                       Stopping::discretization_accuracy :
                                       Stopping::tolerance;
      automatic_stopping      = stop == "auto";
      discretization_fraction = prm.get_double("Discretization fraction");
      pre_smoothing           = prm.get_integer("Pre smoothing");
      post_smoothing          = prm.get_integer("Post smoothing");
      const std::string c     = prm.get("Cycle");
      cycle                   = (c == "V" ? Cycle::V : c == "W" ? Cycle::W : Cycle::F);
      const std::string p     = prm.get("Projection");
      projection              = (p == "a" ? Projection::a :
                                 p == "b" ? Projection::b :
                                 p == "c" ? Projection::c :
                                            Projection::d);
      const std::string g     = prm.get("Initial guess");
      initial_guess = (g == "zero"             ? InitialGuess::zero :
                       g == "coarse solution"  ? InitialGuess::coarse_solution :
                       g == "nested iteration" ? InitialGuess::nested_iteration :
                                                 InitialGuess::expression);
      definiteness_max_dofs = prm.get_integer("Definiteness check max dofs");
      krylov_steps          = prm.get_integer("Krylov steps");
      patch_rows   = prm.get("Patch rows") == "copied" ? PatchRows::copied : PatchRows::matrix;
      threads               = prm.get_integer("Threads");
      check_coarse_defects  = prm.get_bool("Check coarse defects");
      cross_check           = prm.get_bool("Cross check");
      prm.leave_subsection();
      // the estimate of the algebraic error takes the rate as steady; that
      // of projected Gauss-Seidel keeps growing, and the run stopped with
      // the contact force far off (doc/performance.md, "Figures behind the code")
      AssertThrow(type != Type::projected_gauss_seidel ||
                    stopping != Stopping::discretization_accuracy,
                  ExcMessage("parameter 'Solver/Stopping criterion' = discretization accuracy "
                             "is not available for Solver/Type = projected gauss seidel, whose "
                             "rate is not steady: use Stopping criterion = tolerance"));
      // without smoothing the cycle never changes the finest level's
      // oscillating part: the first correction is the coarse one, and the
      // run stopped at once at the wrong answer (doc/performance.md, "Figures behind the code")
      AssertThrow(type != Type::monotone_multigrid || pre_smoothing + post_smoothing > 0,
                  ExcMessage("parameters 'Solver/Pre smoothing' and 'Solver/Post smoothing' are "
                             "both 0: the monotone multigrid needs at least one smoothing step"));
    }
  } // namespace Parameters
} // namespace FoslsContact
