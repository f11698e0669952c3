#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/data.h>
#include <fosls_contact/parameters/value_parsing.h>

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
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace FoslsContact
