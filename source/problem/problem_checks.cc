#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/base/json.h>
#include <fosls_contact/problem/conditioning.h>
#include <fosls_contact/problem/data_check.h>
#include <fosls_contact/problem/problem_checks.h>
#include <fosls_contact/qp/definiteness_check.h>
#include <fosls_contact/qp/gathered_qp.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  ProblemChecks<dim>::ProblemChecks(const Parameters::AllParameters &parameters,
                                    const Scene<dim> &               scene,
                                    const Discretization<dim> &      discretization,
                                    const ConstrainedQP &            qp,
                                    const ConditionalOStream &       pcout)
    : parameters(parameters)
    , scene(scene)
    , discretization(discretization)
    , qp(qp)
    , pcout(pcout)
  {}


  template <int dim>
  void
  ProblemChecks<dim>::check_data() const
  {
    // The data enter the problem as fixed values (Dirichlet values at the
    // vertices, tractions at the faces), bounds (the gap at the contact
    // vertices) and the right-hand side (the body force); a data
    // expression that is NaN or Inf somewhere shows there, and is named
    // here instead of as a NaN iterate later: by the parameter, its value
    // and the point, from the values recorded where they are evaluated
    // (DataCheck), which also refuses data too large or too small for
    // double precision; the assembled values are checked for what the
    // records cannot see.
    DataCheck<dim>::check(parameters, scene, discretization.get_communicator());
    const auto &       fine = discretization.level(discretization.finest_level());
    std::vector<bool>  displacement(fine.n_local(), false);
    for (const auto &[vertex, dofs] : fine.vertex_dofs)
      for (const auto dof : dofs)
        displacement[dof] = true;
    enum : unsigned int
    {
      dirichlet = 1,
      traction  = 2,
      gap       = 4,
      load      = 8
    };
    unsigned int bad = 0;
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      {
        if (qp.role[i] == DoFRole::fixed && !std::isfinite(qp.fixed_values.local_element(i)))
          bad |= displacement[i] ? dirichlet : traction;
        if (qp.role[i] == DoFRole::bounded && !std::isfinite(qp.upper_bounds.local_element(i)))
          bad |= gap;
        if (!std::isfinite(qp.rhs.local_element(i)))
          bad |= load;
      }
    if (!std::isfinite(qp.constant))
      bad |= load;
    // (every process takes the same decision)
    for (unsigned int flag = 1; flag <= load; flag *= 2)
      if (Utilities::MPI::max(bad & flag, discretization.get_communicator()) != 0)
        bad |= flag;
    const std::string what = (bad & dirichlet) ? "Data/Dirichlet values" :
                             (bad & traction)  ? "Data/Traction" :
                             (bad & gap)       ? "Data/Gap" :
                                                 "Data/Body force";
    AssertThrow(bad == 0,
                ExcMessage("parameter '" + what + "' is not finite (NaN or Inf) " +
                           ((bad & dirichlet) ? "at a vertex of the Dirichlet boundary" :
                            (bad & traction)  ? "on a face of the Neumann boundary" :
                            (bad & gap)       ? "at a vertex of the contact boundary" :
                                                "somewhere in the body")));
  }


  template <int dim>
  void
  ProblemChecks<dim>::check_rigid_motions() const
  {
    // The rigid motions: translations and rotations about the centre of
    // the coarse mesh, with stress 0, in the DoF basis of the finest
    // level (normal-tangential at the contact DoFs).
    const unsigned int L    = discretization.finest_level();
    const auto &       fine = discretization.level(L);
    // (the coarse cells are the same on every process)
    Point<dim>   centre;
    unsigned int n_vertices = 0;
    for (const auto &cell : discretization.get_triangulation().cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        {
          centre += cell->vertex(v);
          ++n_vertices;
        }
    centre /= n_vertices;
    std::vector<std::string> names;
    const char *             axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back(std::string("translation in ") + axis[d]);
    std::vector<std::pair<unsigned int, unsigned int>> rotations; // (i, j): u_i = -x_j, u_j = x_i
    if (dim == 2)
      rotations = {{0, 1}};
    else
      rotations = {{1, 2}, {2, 0}, {0, 1}};
    for (unsigned int r = 0; r < rotations.size(); ++r)
      names.push_back(std::string("rotation about ") +
                      (dim == 2 ? "the centre" : axis[3 - rotations[r].first - rotations[r].second]));
    std::vector<LevelVector> modes(names.size(), qp.new_vector());
    fine.for_each_cell(discretization.get_dof_handler(), [&](const auto &cell) {
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto &dofs = fine.vertex_dofs.at(cell->vertex_index(v));
            const auto  x    = cell->vertex(v) - centre;
            for (unsigned int d = 0; d < dim; ++d)
              modes[d].local_element(dofs[d]) = 1.;
            for (unsigned int r = 0; r < rotations.size(); ++r)
              {
                const auto [i, j] = rotations[r];
                modes[dim + r].local_element(dofs[i]) = -x[j];
                modes[dim + r].local_element(dofs[j]) = x[i];
              }
          }
    });
    for (auto &mode : modes)
      {
        // (an eliminated DoF of a hanging node follows its masters)
        for (const auto &hanging : fine.hanging)
          mode.local_element(hanging.first) = 0.;
        discretization.rotate_to_normal_tangential(L, mode);
      }
    // free: round-off; held: the energy of the cut-off boundary layer, O(h),
    // orders of magnitude above the threshold on every scene
    // (doc/performance.md, "Figures behind the code")
    const double   threshold = 1e-10;
    Vector<double> coefficients;
    const double   energy =
      DefinitenessCheck::least_mode_energy(qp, modes, threshold, coefficients);
    if (energy > threshold)
      return;
    std::string free_modes;
    for (unsigned int m = 0; m < names.size(); ++m)
      if (std::abs(coefficients[m]) > 0.1)
        free_modes += (free_modes.empty() ? "" : " + ") + names[m];
    AssertThrow(false,
                ExcMessage("the boundary conditions leave a rigid motion free (" + free_modes +
                           ", relative energy " + json_number(energy) +
                           "): the functional's quadratic form does not change along it "
                           "and its matrix is singular, which contact, one-sided, does not "
                           "cure; prescribe the motion on some boundary ('Boundary "
                           "conditions/Dirichlet boundary ids' and 'Dirichlet components')"));
  }


  template <int dim>
  DefinitenessCheck
  ProblemChecks<dim>::check_level(const int level, const Parameters::Weights &weights,
                                  const bool use_assembled) const
  {
    DefinitenessCheck result;
    auto              check = [&](const ConstrainedQP &level_qp) {
      const GatheredQP gathered(level_qp);
      // The first process alone factorizes: its refusal of A_II, or an
      // error there (memory, CHOLMOD), stops every process with the same
      // line (CollectiveError).
      CollectiveError::run(discretization.get_communicator(), [&]() {
        if (!gathered.here())
          return;
        result = DefinitenessCheck::run(gathered.qp());
        AssertThrow(result.interior_definite,
                    ExcMessage("the functional's matrix without its contact DoFs is not "
                               "positive definite in floating point on level " +
                               std::to_string(level + 1) +
                               " (its Cholesky factorization failed): the functional is too "
                               "badly conditioned for double precision: " +
                               Conditioning<dim>::advice(parameters, scene,
                                                         discretization.get_triangulation())));
      });
      // (every process learns the outcome, so that every process stops
      // with the same line)
      const MPI_Comm comm = discretization.get_communicator();
      result.min_relative_eigenvalue =
        Utilities::MPI::broadcast(comm, result.min_relative_eigenvalue, 0);
      result.limit_factor = Utilities::MPI::broadcast(comm, result.limit_factor, 0);
    };
    if (use_assembled)
      check(qp);
    else
      {
        ConstrainedQP level_qp;
        level_qp.reinit(discretization.level(level));
        FoslsAssembler<dim>(discretization, weights).assemble(level, level_qp);
        check(level_qp);
      }
    return result;
  }


  template <int dim>
  std::string
  ProblemChecks<dim>::limit_text(const double limit, const int level) const
  {
    std::ostringstream text;
    if (std::isnan(limit))
      text << "unknown";
    else if (std::isinf(limit))
      text << "none";
    else
      text << std::setprecision(4) << limit;
    text << " on level " << level + 1;
    return text.str();
  }


  template <int dim>
  typename ProblemChecks<dim>::ComplWeight
  ProblemChecks<dim>::choose_compl_weight(TimerOutput &timer, std::set<unsigned int> &passed) const
  {
    const auto &w   = parameters.weights;
    const auto  cap = Parameters::Weights::auto_compl_cap;
    if (!scene.has_contact())
      return {cap};
    const int level = definiteness_level(discretization, parameters.solver);
    if (level < 0)
      {
        pcout << "Functional weights: C_compl = auto: " << cap
              << " (the definiteness check is off or even level 1 is larger than its cap: "
                 "not checked)"
              << std::endl;
        return {cap};
      }
    TimerOutput::Scope t(timer, "Definiteness check");
    // the check as check_definiteness() makes it with the weight cap
    const bool coarser = static_cast<unsigned int>(level) < discretization.finest_level();
    Parameters::Weights checked = w;
    checked.c_compl             = cap * (coarser ? 1. + coarse_level_margin : 1.);
    DefinitenessCheck result;
    try
      {
        result = check_level(level, checked, false);
      }
    catch (const std::exception &)
      {
        // A_II not definite: not a question of C_compl (a free rigid
        // motion, a badly conditioned functional); the checks that follow
        // name the cause
        return {cap};
      }
    const double limit  = checked.c_compl * result.limit_factor;
    const double chosen = std::min(cap, Parameters::Weights::auto_compl_fraction * limit);
    pcout << "Functional weights: C_compl = auto: " << std::setprecision(4) << chosen << " ("
          << (chosen < cap ? "half the largest definite value " : "the cap; the largest definite value ")
          << limit_text(limit, level) << ")" << std::endl;
    // (the check with the weight taken is made: it need not be made again)
    if (chosen == cap && result.definite() && !discretization.level(level).active_mesh)
      passed.insert(level);
    // (NaN: S_0 itself indefinite, which the check at the cap then names)
    return {std::isnan(chosen) ? cap : chosen, limit, level};
  }


  template <int dim>
  double
  ProblemChecks<dim>::check_definiteness(TimerOutput &timer, std::set<unsigned int> *passed) const
  {
    const auto &w = parameters.weights;
    if (!scene.has_contact() || w.c_compl == 0 ||
        parameters.solver.definiteness_max_dofs == 0)
      return 0;
    TimerOutput::Scope t(timer, "Definiteness check");
    Timer              wall;
    const int          level = definiteness_level(discretization, parameters.solver);
    if (level < 0)
      {
        pcout << "Definiteness check skipped: even level 1 has more than "
              << parameters.solver.definiteness_max_dofs << " DoFs" << std::endl;
        return 0;
      }
    // On a coarser level, C_compl with the margin for the finer ones.
    const bool          coarser = static_cast<unsigned int>(level) < discretization.finest_level();
    const bool uniform = !discretization.level(level).active_mesh;
    if (passed && uniform && passed->count(level))
      {
        pcout << "Definiteness check on level " << level + 1
              << ": passed on this level before" << std::endl;
        return 0;
      }
    Parameters::Weights checked = w;
    if (coarser)
      checked.c_compl *= 1. + coarse_level_margin;
    const DefinitenessCheck result  = check_level(level, checked, !coarser);
    const double            seconds = wall.wall_time();
    std::ostringstream margin;
    if (coarser)
      margin << " with C_compl = " << checked.c_compl << " (" << 100 * coarse_level_margin
             << "% margin for the finer levels)";
    // the largest C_compl accepted: the limit, less the margin on a
    // coarser level
    const double accepted = checked.c_compl * result.limit_factor / (coarser ? 1. + coarse_level_margin : 1.);
    pcout << "Definiteness check on level " << level + 1 << margin.str()
          << ": smallest relative eigenvalue of the contact Schur complement = "
          << std::setprecision(4) << result.min_relative_eigenvalue
          << "; largest definite C_compl " << limit_text(checked.c_compl * result.limit_factor, level)
          << std::endl;
    // No C_compl makes a Schur complement definite whose least eigenvalue
    // is at the round-off of its entries, or which the complementarity
    // term does not lower (no finite limit): the cause is the conditioning
    // of the rest of the functional.
    AssertThrow(result.definite() ||
                  (std::isfinite(accepted) && accepted > 0 &&
                   std::abs(result.min_relative_eigenvalue) > round_off_eigenvalue),
                ExcMessage("the functional's contact Schur complement is " +
                           std::string(std::abs(result.min_relative_eigenvalue) <=
                                           round_off_eigenvalue ?
                                         "singular to round-off" :
                                         "indefinite without its complementarity term") +
                           " on level " + std::to_string(level + 1) +
                           " (smallest relative eigenvalue " +
                           json_number(result.min_relative_eigenvalue) +
                           ", which no value of C_compl changes): " + singular_cause()));
    std::ostringstream weights;
    weights << "C_eq = " << w.c_eq << ", C_const = " << w.c_const
            << ", C_compl = " << w.c_compl;
    std::ostringstream advice;
    if (std::isfinite(accepted) && accepted > 0)
      {
        // (4 digits, rounded down: the value named is accepted)
        const double unit = std::pow(10., std::floor(std::log10(accepted)) - 3);
        advice << "decrease 'Functional weights/C_compl' (the largest accepted value on this "
                  "mesh is "
               << std::setprecision(4) << std::floor(accepted / unit) * unit
               << "; 'auto' chooses one) or ";
      }
    else
      advice << "decrease 'Functional weights/C_compl' or ";
    AssertThrow(result.definite(),
                ExcMessage("the functional is indefinite" +
                           std::string(coarser ? ", or within the margin of it," : "") +
                           " for " + weights.str() +
                           " (smallest relative eigenvalue of the contact "
                           "Schur complement " +
                           json_number(result.min_relative_eigenvalue) + " on level " +
                           std::to_string(level + 1) + margin.str() +
                           "): " + advice.str() + "increase C_eq/C_const (paper eq. 10)"));
    if (passed && uniform)
      passed->insert(level);
    return seconds;
  }


  template <int dim>
  int
  ProblemChecks<dim>::definiteness_level(const Discretization<dim> &discretization,
                                         const Parameters::Solver & solver)
  {
    if (solver.definiteness_max_dofs == 0)
      return -1;
    // The finest level small enough; indefinite there means indefinite on
    // all finer levels, as the spaces are nested.
    int level = discretization.finest_level();
    while (level >= 0 && discretization.level(level).n_dofs > solver.definiteness_max_dofs)
      --level;
    return level;
  }


  template <int dim>
  std::string
  ProblemChecks<dim>::singular_cause() const
  {
    // With friction the tangential tractions of the contact boundary are
    // free, and the pressure sigma = p I of an incompressible body costs
    // nothing in the functional (A sigma and div sigma vanish): its
    // traction p n has a tangential part where the contact boundary is
    // curved against the obstacle normal, so nothing but the
    // complementarity term holds it (doc/method.md section 10)
    if (scene.has_friction() && std::isinf(parameters.material.lambda))
      return "with friction the pressure of an incompressible body (Material/lambda = inf) "
             "is free on a curved contact boundary; give a finite lambda (nu < 0.5)";
    return "the functional is too badly conditioned for double precision: " +
           Conditioning<dim>::advice(parameters, scene, discretization.get_triangulation());
  }


  template class ProblemChecks<2>;
  template class ProblemChecks<3>;
} // namespace FoslsContact
