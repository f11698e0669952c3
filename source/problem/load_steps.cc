#include <fosls_contact/base/json.h>
#include <fosls_contact/problem/load_steps.h>

#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  std::string
  LoadSteps<dim>::json() const
  {
    std::vector<std::string> items;
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        const Step &       step = steps[s];
        std::ostringstream item;
        item << "{\"step\": " << step.output_index << ", \"constants\": {";
        bool first = true;
        for (const auto &[name, value] : step.constants)
          {
            item << (first ? "" : ", ") << '"' << name << "\": " << json_number(value);
            first = false;
          }
        item << "}, \"iterations\": " << step.iterations << ", \"cycles\": " << step.cycles
             << ", \"linear_rate\": " << json_number(step.linear_rate)
             << ", \"iteration_rate\": " << json_number(step.iteration_rate)
             << ", \"converged\": " << (step.converged ? "true" : "false")
             << ", \"functional\": " << json_number(step.functional)
             << ", \"contact_force\": " << json_vector<dim>(step.force)
             << ", \"normal_force\": " << json_number(step.normal_force)
             << ", \"tangential_force\": " << json_number(step.tangential_force) << ", \""
             << (dim == 2 ? "contact_width" : "contact_area")
             << "\": " << json_number(step.contact_measure)
             << ", \"peak_pressure\": " << json_number(step.peak_pressure)
             << ", \"vertices_in_contact\": " << step.vertices_in_contact;
        if (step.friction)
          item << ", \"stick_vertices\": " << step.stick_vertices
               << ", \"slip_vertices\": " << step.slip_vertices;
        item << ", \"reactions\": {";
        first = true;
        for (const auto &[id, force] : step.reactions)
          {
            item << (first ? "" : ", ") << '"' << static_cast<unsigned int>(id)
                 << "\": " << json_vector<dim>(force);
            first = false;
          }
        item << "}}";
        items.push_back(item.str());
      }
    return json_array(items);
  }


  template <int dim>
  std::string
  LoadSteps<dim>::csv() const
  {
    std::ostringstream out;
    if (steps.empty())
      return "";
    const char *xyz = "xyz";
    out << "step";
    for (const auto &constant : steps[0].constants)
      out << ',' << constant.first;
    out << ",iterations,cycles,linear_rate,iteration_rate,converged,functional";
    for (unsigned int d = 0; d < dim; ++d)
      out << ",force_" << xyz[d];
    out << ",normal_force,tangential_force," << (dim == 2 ? "contact_width" : "contact_area")
        << ",peak_pressure,vertices_in_contact";
    if (steps[0].friction)
      out << ",stick_vertices,slip_vertices";
    for (const auto &reaction : steps[0].reactions)
      for (unsigned int d = 0; d < dim; ++d)
        out << ",reaction_" << static_cast<unsigned int>(reaction.first) << '_' << xyz[d];
    out << '\n' << std::setprecision(10);
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        const Step &step = steps[s];
        out << step.output_index;
        for (const auto &constant : step.constants)
          out << ',' << constant.second;
        out << ',' << step.iterations << ',' << step.cycles << ',' << step.linear_rate << ','
            << step.iteration_rate << ','
            << (step.converged ? 1 : 0)
            << ',' << step.functional;
        for (unsigned int d = 0; d < dim; ++d)
          out << ',' << step.force[d];
        out << ',' << step.normal_force << ',' << step.tangential_force << ','
            << step.contact_measure << ',' << step.peak_pressure << ','
            << step.vertices_in_contact;
        if (step.friction)
          out << ',' << step.stick_vertices << ',' << step.slip_vertices;
        for (const auto &reaction : step.reactions)
          for (unsigned int d = 0; d < dim; ++d)
            out << ',' << reaction.second[d];
        out << '\n';
      }
    return out.str();
  }


  template <int dim>
  std::pair<unsigned int, unsigned int>
  LoadSteps<dim>::count_status(const std::vector<typename ContactRow<dim>::Values> &rows)
  {
    std::pair<unsigned int, unsigned int> counts{0, 0};
    for (const auto &row : rows)
      {
        counts.first += row[ContactRow<dim>::status] == 1;
        counts.second += row[ContactRow<dim>::status] == 2;
      }
    return counts;
  }


  template class LoadSteps<2>;
  template class LoadSteps<3>;
} // namespace FoslsContact
