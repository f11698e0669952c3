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
      prm.declare_entry("Tresca accuracy",
                        "0",
                        Patterns::Double(0, 1),
                        "Coulomb, with the monotone multigrid and Solver/Stopping "
                        "criterion = tolerance (its "
                        "auto choice): the Tresca problems of a load step are solved "
                        "to the larger of Solver/Tolerance and this factor times the "
                        "relative change of the slip bounds that started them (1 for "
                        "the step's first); the one whose bounds the fixed point "
                        "accepts is then solved on to Solver/Tolerance. 0: every "
                        "Tresca problem to Solver/Tolerance (the default: 0.01 saved a "
                        "quarter of the time in 2D, but lost the stick zones of "
                        "prm/cattaneo_mindlin_3d_fine.prm, doc/method.md section 7.7).");
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
      tresca_accuracy        = prm.get_double("Tresca accuracy");
      prm.leave_subsection();
      AssertThrow(fixed_point_tolerance > 0,
                  ExcMessage("parameter 'Friction/Fixed point tolerance' must be > 0"));
    }
  } // namespace Parameters
} // namespace FoslsContact
