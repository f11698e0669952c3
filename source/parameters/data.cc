#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/data.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <cmath>
#include <set>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Data::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Data");
      prm.declare_entry("Constants",
                        "",
                        Patterns::Anything(),
                        "Named constants for all expressions, e.g. "
                        "'push=0.01, R=0.5' (pi is always defined). Names: letters, "
                        "digits and _, not starting with a digit, not x, y (z in "
                        "3D) and each once.");
      prm.declare_entry("Load steps",
                        "",
                        Patterns::Anything(),
                        "A quasi-static load path: steps separated by ';', each "
                        "a ','-separated list name=value of constants of "
                        "'Data/Constants' that change at that step, e.g. "
                        "'push=0.005; push=0.01; shift=0.002' (a constant keeps "
                        "its value until a step changes it). Each step starts from "
                        "the previous step's solution; every step is a time step "
                        "of solution.pvd and a row of load_steps.csv. With "
                        "'Adaptivity/Steps' > 0 the first step runs the adaptive "
                        "loop and the later steps are solved on its last mesh. "
                        "Empty: one step with the constants as given.");
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Body force f, components separated by ';'. Empty: the "
                        "scene has no body force and no term is assembled.");
      prm.declare_entry("Dirichlet values",
                        "0; 0",
                        Patterns::Anything(),
                        "Displacement u^D on the Dirichlet boundary.");
      prm.declare_entry("Traction",
                        "0; 0",
                        Patterns::Anything(),
                        "Traction t^N = sigma n on the Neumann boundary.");
      prm.declare_entry("Gap",
                        "0",
                        Patterns::Anything(),
                        "Gap g: the contact constraint is u.n <= g.");
      prm.declare_entry("Obstacle normal",
                        "0; -1",
                        Patterns::Anything(),
                        "Direction n of the contact constraints u.n <= g and "
                        "(sigma n_body).n <= 0: it points from the body into "
                        "the obstacle and is normalized by the program.");
      prm.declare_entry("Exact displacement",
                        "",
                        Patterns::Anything(),
                        "Optional exact u, for error norms.");
      prm.declare_entry("Exact stress",
                        "",
                        Patterns::Anything(),
                        "Optional exact sigma, row by row (dim*dim entries).");
      prm.declare_entry("Initial displacement",
                        "",
                        Patterns::Anything(),
                        "Used with Solver/Initial guess = expression: the "
                        "starting displacement, projected onto the feasible set.");
      prm.leave_subsection();
    }

    void
    Data::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Data");
      constants            = prm.get("Constants");
      body_force           = prm.get("Body force");
      dirichlet_values     = prm.get("Dirichlet values");
      traction             = prm.get("Traction");
      gap                  = prm.get("Gap");
      obstacle_normal      = prm.get("Obstacle normal");
      exact_displacement   = prm.get("Exact displacement");
      exact_stress         = prm.get("Exact stress");
      initial_displacement = prm.get("Initial displacement");
      parse_load_steps(prm.get("Load steps"));
      prm.leave_subsection();
    }


    void
    Data::parse_load_steps(const std::string &text)
    {
      load_steps.clear();
      if (Utilities::trim(text).empty())
        return;
      // (the names of Data/Constants; the Scene checks them as names)
      std::set<std::string> defined;
      for (const auto &entry : Utilities::split_string_list(constants, ','))
        defined.insert(Utilities::trim(entry.substr(0, entry.find('='))));
      const auto steps = Utilities::split_string_list(text, ';');
      for (unsigned int s = 0; s < steps.size(); ++s)
        {
          const std::string where = "parameter 'Data/Load steps', step " + std::to_string(s + 1);
          AssertThrow(!steps[s].empty(),
                      ExcMessage(where + " is empty; expected name=value, ... (a constant of "
                                         "'Data/Constants' and its value at that step)"));
          std::map<std::string, double> values;
          for (const auto &entry : Utilities::split_string_list(steps[s], ','))
            {
              const auto pair = Utilities::split_string_list(entry, '=');
              AssertThrow(pair.size() == 2,
                          ExcMessage(where + " has entry '" + entry + "'; expected name=value"));
              const std::string name = Utilities::trim(pair[0]);
              AssertThrow(defined.count(name) > 0,
                          ExcMessage(where + " names '" + name +
                                     "', which 'Data/Constants' does not define" +
                                     (constants.empty() ? " (it is empty)" :
                                                          " ('" + constants + "')")));
              AssertThrow(values.count(name) == 0,
                          ExcMessage(where + " gives '" + name + "' twice"));
              double value = 0;
              try
                {
                  value = Utilities::string_to_double(pair[1]);
                }
              catch (...)
                {
                  AssertThrow(false,
                              ExcMessage(where + ": '" + Utilities::trim(pair[1]) +
                                         "' is not a number (the value of '" + name + "')"));
                }
              AssertThrow(std::isfinite(value),
                          ExcMessage(where + ": the value of '" + name + "' is not finite"));
              values[name] = value;
            }
          load_steps.push_back(values);
        }
    }


    std::map<std::string, double>
    Data::step_overrides(const unsigned int step) const
    {
      std::map<std::string, double> values;
      for (unsigned int s = 0; s <= step && s < load_steps.size(); ++s)
        for (const auto &[name, value] : load_steps[s])
          values[name] = value;
      return values;
    }
  } // namespace Parameters
} // namespace FoslsContact
