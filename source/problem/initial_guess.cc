#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/base/json.h>
#include <fosls_contact/problem/initial_guess.h>
#include <fosls_contact/problem/solver_choice.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monitor.h>

#include <algorithm>
#include <iomanip>

namespace FoslsContact
{
  std::string
  InitialGuessRecord::level_solves_json() const
  {
    std::vector<std::string> items;
    for (const auto &s : level_solves)
      items.push_back("{\"level\": " + std::to_string(s.level + 1) +
                      ", \"dofs\": " + std::to_string(s.dofs) +
                      ", \"iterations\": " + std::to_string(s.iterations) +
                      ", \"cycles\": " + std::to_string(s.cycles) + ", \"stop_reason\": \"" +
                      s.stop_reason + "\", \"converged\": " + (s.converged ? "true" : "false") +
                      ", \"linear_rate\": " + json_number(s.linear_rate) +
                      ", \"energy_increases\": " + std::to_string(s.energy_increases) + "}");
    return json_array(items);
  }


  template <int dim>
  InitialGuess<dim>::InitialGuess(const Parameters::AllParameters &parameters,
                                  const Scene<dim> &               scene,
                                  const Discretization<dim> &      discretization,
                                  const LevelTransfer<dim> &       transfer,
                                  const ConditionalOStream &       pcout)
    : parameters(parameters)
    , scene(scene)
    , discretization(discretization)
    , transfer(transfer)
    , pcout(pcout)
  {}


  template <int dim>
  LevelVector
  InitialGuess<dim>::prolongate_rotated(const unsigned int to_level,
                                        const LevelVector &coarse) const
  {
    // (a rotation block is the DoFs of one vertex or face, of one owner:
    // the product brings the owners' rotated values to the ghost copies;
    // the owned entries of the result are valid)
    LevelVector cartesian(coarse), fine(discretization.level(to_level).partitioner);
    discretization.rotate_to_cartesian(to_level - 1, cartesian);
    transfer.prolongate(to_level, fine, cartesian);
    discretization.rotate_to_normal_tangential(to_level, fine);
    return fine;
  }


  template <int dim>
  LevelVector
  InitialGuess<dim>::solve_on_level(const unsigned int level, const LevelVector *start)
  {
    ConstrainedQP level_qp;
    level_qp.reinit(discretization.level(level));
    FoslsAssembler<dim>(discretization, parameters.weights)
      .assemble(level, level_qp);
    LevelVector x = level_qp.new_vector();
    if (start)
      x = *start;
    ConditionalOStream quiet(std::cout, false);
    Monitor            level_monitor(level_qp,
                                parameters.solver,
                                quiet,
                                "initial guess (the solution on level " +
                                  std::to_string(level + 1) + ")");
    // (each level carries the rates its coarser levels measured on: see
    // StoppingRules::at_discretization_accuracy())
    level_monitor.set_rate_floor(guess_record.rate);
    level_monitor.require_rates(2);
    if (level == 0)
      ActiveSetDirect().solve(level_qp, x, level_monitor);
    else
      {
        const auto solver =
          SolverChoice<dim>::make(parameters.solver, discretization, transfer, level_qp, level);
        solver->solve(level_qp, x, level_monitor);
        guess_record.rate = std::max(guess_record.rate, level_monitor.linear_rate());
        guess_record.level_solves.push_back({level,
                          level_qp.size(),
                          level_monitor.iterations(),
                          level_monitor.cycles(),
                          level_monitor.stop_reason(),
                          level_monitor.linear_rate(),
                          level_monitor.energy_increases(),
                          level_monitor.converged()});
        // (the level's work units times its DoFs: sweeps times DoFs)
        if (const auto &mg = solver->statistics().multilevel)
          guess_record.work_units += mg->work_units() * double(mg->level_dofs.back());
      }
    return x;
  }


  template <int dim>
  void
  InitialGuess<dim>::compute(const ConstrainedQP &qp, LevelVector &solution)
  {
    const unsigned int L = discretization.finest_level();
    solution.reinit(qp.partitioner);
    guess_record = {};
    using IG = Parameters::Solver::InitialGuess;
    switch (parameters.solver.initial_guess)
      {
        case IG::zero:
          break;
        case IG::coarse_solution:
          {
            // paper section 7: the exact level-1 solution, interpolated
            LevelVector x = solve_on_level(0, nullptr);
            for (unsigned int l = 1; l <= L; ++l)
              x = prolongate_rotated(l, x);
            solution = x;
            break;
          }
        case IG::nested_iteration:
          {
            LevelVector x = solve_on_level(0, nullptr);
            for (unsigned int l = 1; l < L; ++l)
              {
                x = prolongate_rotated(l, x);
                x = solve_on_level(l, &x);
              }
            if (L > 0)
              solution = prolongate_rotated(L, x);
            else
              solution = x;
            break;
          }
        case IG::expression:
          {
            const auto &fine = discretization.level(L);
            Vector<double> values(dim);
            fine.for_each_cell(discretization.get_dof_handler(), [&](const auto &cell) {
              for (const unsigned int v : cell->vertex_indices())
                {
                  scene.initial_displacement()->vector_value(cell->vertex(v), values);
                  const auto &dofs = fine.vertex_dofs.at(cell->vertex_index(v));
                  for (unsigned int k = 0; k < dim; ++k)
                    solution.local_element(dofs[k]) = values[k];
                }
            });
            for (const auto &hanging : fine.hanging)
              solution.local_element(hanging.first) = 0.;
            discretization.rotate_to_normal_tangential(L, solution);
            AssertThrow(std::isfinite(solution.l2_norm()),
                        ExcMessage("parameter 'Data/Initial displacement' is not finite (NaN "
                                   "or Inf) at a vertex"));
            break;
          }
      }
    guess_record.work_units /= double(discretization.level(L).n_dofs);
    // fixed values are simply set; a penetrating start is worth a note
    double penetration = 0;
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      if (qp.role[i] == DoFRole::bounded)
        penetration = std::max(penetration,
                               solution.local_element(i) - qp.upper_bounds.local_element(i));
    penetration = Utilities::MPI::max(penetration, qp.get_communicator());
    // (a start on its bounds up to round-off is no news)
    constexpr double round_off = 1e-12;
    if (penetration > round_off)
      pcout << "Initial guess violates the contact constraints by "
            << std::scientific << std::setprecision(3)
            << penetration * scene.scaling().length
            << std::defaultfloat << ": projected onto the feasible set"
            << std::endl;
  }


  template class InitialGuess<2>;
  template class InitialGuess<3>;
} // namespace FoslsContact
