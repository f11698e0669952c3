#include <fosls_contact/parameters/friction.h>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Friction::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Friction");
      prm.declare_entry("Law",
                        "none",
                        Patterns::Selection("none|Tresca|Coulomb"),
                        "none (frictionless contact), Tresca (the tangential traction "
                        "is at most Bound, and the body slips where it reaches it) or "
                        "Coulomb (at most Coefficient times the contact pressure: a "
                        "fixed point of Tresca problems). Friction acts on the "
                        "tangential displacement of a load step relative to the step "
                        "before (Data/Load steps), the first step's relative to the "
                        "undeformed body. In 3D the friction is isotropic: the "
                        "tangential traction lies in a disc, the slip enters by its "
                        "length. Needs a contact boundary; the monotone multigrid takes "
                        "it with Solver/Krylov steps > 0 (its Newton step), projected "
                        "gauss seidel as it is, the active set method in 2D.");
      prm.declare_entry("Bound",
                        "0",
                        Patterns::Anything(),
                        "Tresca: the slip bound s >= 0, a stress in the scene's units: "
                        "an expression in x, y (and z) that may use Data/Constants.");
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Anything(),
                        "Coulomb: the friction coefficient f >= 0: an expression in x, y "
                        "(and z) that may use Data/Constants.");
      prm.declare_entry("Fixed point iterations",
                        "50",
                        Patterns::Integer(1),
                        "Coulomb: the most Tresca problems per load step (s = f times the "
                        "pressure of the last one).");
      prm.declare_entry("Fixed point tolerance",
                        "1e-6",
                        Patterns::Double(0),
                        "Coulomb: the fixed point stops when no slip bound changes by more "
                        "than this times the largest one.");
      prm.leave_subsection();
    }

    void
    Friction::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Friction");
      const std::string l = prm.get("Law");
      law         = l == "none" ? Law::none : l == "Tresca" ? Law::tresca : Law::coulomb;
      bound       = prm.get("Bound");
      coefficient = prm.get("Coefficient");
      fixed_point_iterations = prm.get_integer("Fixed point iterations");
      fixed_point_tolerance  = prm.get_double("Fixed point tolerance");
      prm.leave_subsection();
      AssertThrow(fixed_point_tolerance > 0,
                  ExcMessage("parameter 'Friction/Fixed point tolerance' must be > 0"));
    }
  } // namespace Parameters
} // namespace FoslsContact
