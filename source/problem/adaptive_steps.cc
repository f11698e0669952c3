#include <fosls_contact/base/json.h>
#include <fosls_contact/problem/adaptive_steps.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  double
  AdaptiveSteps::Step::efficiency_index() const
  {
    // (both in the norm of the dimensionless problem: the figure of the
    // norm equivalence of the least-squares functional, independent of
    // the units; in the scene's units an H1 norm in mm and an H(div) norm
    // in MPa mm would be added)
    return std::sqrt(std::max(0., functional_dimensionless)) / reference_error_scaled;
  }


  bool
  AdaptiveSteps::singular_stress(const std::string &stress_unit, std::string &text) const
  {
    // Near a singular point the stress grows like r^(alpha - 1), alpha < 1, and
    // its largest nodal value by 2^(1 - alpha) whenever the cells there are
    // halved (the edge of the bonded punch of prm/punch.prm,
    // doc/performance.md, "Figures behind the code"). A smooth field's peak
    // converges instead. Taken as singular: the peak rose by more than 5% at
    // each of the last two refinements and stayed within the diameter of the
    // cells of the first of them, where the cells got smaller.
    const unsigned int n = steps.size();
    if (n < 3 || steps.back().reference)
      return false;
    const Step &a = steps[n - 3], &b = steps[n - 2], &c = steps[n - 1];
    if (a.von_mises_position.empty() || !(b.max_von_mises > 1.05 * a.max_von_mises) ||
        !(c.max_von_mises > 1.05 * b.max_von_mises) ||
        !(c.von_mises_cell_diameter < a.von_mises_cell_diameter))
      return false;
    double distance_ab = 0, distance_ac = 0;
    for (unsigned int d = 0; d < a.von_mises_position.size(); ++d)
      {
        distance_ab += std::pow(b.von_mises_position[d] - a.von_mises_position[d], 2);
        distance_ac += std::pow(c.von_mises_position[d] - a.von_mises_position[d], 2);
      }
    if (std::sqrt(std::max(distance_ab, distance_ac)) > a.von_mises_cell_diameter)
      return false;
    std::ostringstream out;
    out << "the largest von Mises stress grows under refinement at (";
    for (unsigned int d = 0; d < c.von_mises_position.size(); ++d)
      out << (d > 0 ? ", " : "") << std::setprecision(6) << c.von_mises_position[d];
    out << "): " << std::setprecision(4) << a.max_von_mises << " -> " << b.max_von_mises
        << " -> " << c.max_von_mises << (stress_unit.empty() ? "" : " " + stress_unit)
        << " in the last three steps, a singular stress (a corner, the edge of a bonded "
           "or rigid part, where the boundary conditions change); its peak value depends on "
           "the mesh, while forces and the stress away from the point converge";
    text = out.str();
    return true;
  }


  bool
  AdaptiveSteps::go_on(const Parameters::Adaptivity &adaptivity, std::string &why) const
  {
    if (!adaptivity.enabled())
      return false;
    const unsigned int step = steps.size() - 1;
    if (!steps.back().converged)
      why = "the solve did not converge";
    else if (step == adaptivity.steps)
      why = "Adaptivity/Steps = " + std::to_string(adaptivity.steps) + " done";
    else if (adaptivity.target_root_functional > 0 &&
             std::sqrt(std::max(0., steps.back().functional)) <=
               adaptivity.target_root_functional)
      why = "sqrt(J) at most Adaptivity/Target sqrt(J)";
    return why.empty();
  }


  std::string
  AdaptiveSteps::json(const unsigned int n) const
  {
    std::vector<std::string> items;
    for (unsigned int s = 0; s < std::min<std::size_t>(n, steps.size()); ++s)
      {
        const Step &             step = steps[s];
        std::vector<std::string> force;
        for (const double f : step.force)
          force.push_back(json_number(f));
        std::ostringstream item;
        item << "{\"step\": " << s << ", \"cells\": " << step.cells << ", \"dofs\": " << step.dofs
             << ", \"iterations\": " << step.iterations
             << ", \"converged\": " << (step.converged ? "true" : "false")
             << ", \"functional\": " << json_number(step.functional)
             << ", \"functional_start\": " << json_number(step.functional_start)
             << ", \"contact_force\": " << json_array(force)
             << ", \"time_solve_s\": " << json_number(step.time_solve_s)
             << ", \"time_step_s\": " << json_number(step.time_step_s)
             << ", \"hertz_pressure_error\": " << json_number(step.hertz_pressure_error)
             << ", \"hertz_pressure_error_boundary\": "
             << json_number(step.hertz_pressure_error_boundary)
             << ", \"error_u_h1\": " << json_number(step.error_u_h1)
             << ", \"error_sigma_hdiv\": " << json_number(step.error_sigma_hdiv)
             << ", \"cycles\": " << step.cycles
             << ", \"energy_increases\": " << step.energy_increases
             << ", \"cross_check_functional\": " << json_number(step.cross_check_functional)
             << ", \"cross_check_solution\": " << json_number(step.cross_check_solution)
             << ", \"time_cross_check_s\": " << json_number(step.time_cross_check_s)
             << ", \"reference\": " << (step.reference ? "true" : "false")
             << ", \"reference_error_u_h1\": " << json_number(step.reference_error_u_h1)
             << ", \"reference_error_sigma_hdiv\": "
             << json_number(step.reference_error_sigma_hdiv)
             << ", \"efficiency_index\": " << json_number(step.efficiency_index())
             << ", \"relative_error_estimate\": " << json_number(step.relative_error_estimate)
             << ", \"max_von_mises\": " << json_number(step.max_von_mises) << "}";
        items.push_back(item.str());
      }
    return json_array(items);
  }


  std::string
  AdaptiveSteps::csv(const unsigned int n) const
  {
    std::ostringstream out;
    out << "step,cells,dofs,iterations,converged,functional,sqrt_functional,functional_start";
    const unsigned int n_force = steps.empty() ? 0 : steps[0].force.size();
    for (unsigned int d = 0; d < n_force; ++d)
      out << ",force_" << "xyz"[d];
    out << ",time_solve_s,time_step_s,hertz_pressure_error,hertz_pressure_error_boundary,"
           "error_u_h1,error_sigma_hdiv,cycles,energy_increases,cross_check_functional,"
           "cross_check_solution,time_cross_check_s,reference,reference_error_u_h1,"
           "reference_error_sigma_hdiv,efficiency_index,relative_error_estimate,"
           "max_von_mises\n";
    out << std::setprecision(10);
    for (unsigned int s = 0; s < std::min<std::size_t>(n, steps.size()); ++s)
      {
        const Step &step = steps[s];
        out << s << ',' << step.cells << ',' << step.dofs << ',' << step.iterations << ','
            << (step.converged ? 1 : 0) << ',' << step.functional << ','
            << std::sqrt(std::max(0., step.functional)) << ',' << step.functional_start;
        for (const double f : step.force)
          out << ',' << f;
        out << ',' << step.time_solve_s << ',' << step.time_step_s << ','
            << step.hertz_pressure_error << ',' << step.hertz_pressure_error_boundary << ','
            << step.error_u_h1 << ',' << step.error_sigma_hdiv << ',' << step.cycles << ','
            << step.energy_increases << ',' << step.cross_check_functional << ','
            << step.cross_check_solution << ',' << step.time_cross_check_s << ','
            << (step.reference ? 1 : 0) << ',' << step.reference_error_u_h1 << ','
            << step.reference_error_sigma_hdiv << ',' << step.efficiency_index() << ','
            << step.relative_error_estimate << ',' << step.max_von_mises << '\n';
      }
    return out.str();
  }
} // namespace FoslsContact
