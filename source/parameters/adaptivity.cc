#include <fosls_contact/parameters/adaptivity.h>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Adaptivity::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      prm.declare_entry("Steps",
                        "0",
                        Patterns::Integer(0, 40),
                        "The number of adaptive refinements after the first solve on the "
                        "uniform mesh of Geometry/Levels levels: each step estimates the "
                        "error by the cellwise parts eta_T^2 of the functional J (their sum "
                        "is J), marks cells, refines them (hanging nodes, at most one level "
                        "of difference at a vertex), carries the solution over to the new "
                        "mesh (projected onto its contact constraints) and solves from it. "
                        "0: uniform refinement only. Needs one MPI process and Solver/Type = "
                        "monotone multigrid (on one level per mesh level of the adaptive "
                        "mesh) or active set.");
      prm.declare_entry("Marking",
                        "bulk",
                        Patterns::Selection("bulk|fixed fraction"),
                        "bulk (Dörfler): refine the fewest cells whose eta_T^2 sum to at "
                        "least Fraction times J; fixed fraction: refine the Fraction of the "
                        "cells with the largest eta_T (rounded up: at least one cell).");
      prm.declare_entry("Fraction",
                        "0.5",
                        Patterns::Double(0, 1),
                        "Bulk: the share theta of J the marked cells carry; fixed "
                        "fraction: the share of the cells marked. In (0, 1].");
      prm.declare_entry("Max DoFs",
                        "0",
                        Patterns::Integer(0),
                        "Stop before a refinement that could give the mesh more DoFs than "
                        "this (bounded by the vertices and faces the marked cells add); 0: "
                        "no limit.");
      prm.declare_entry("Target sqrt(J)",
                        "0",
                        Patterns::Double(0),
                        "Stop once sqrt(J) (in the scene's units, J as printed) is at most "
                        "this; 0: no target.");
      prm.leave_subsection();
    }

    void
    Adaptivity::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptivity");
      steps                  = prm.get_integer("Steps");
      marking                = prm.get("Marking") == "bulk" ? Marking::bulk : Marking::fixed_fraction;
      fraction               = prm.get_double("Fraction");
      max_dofs               = prm.get_integer("Max DoFs");
      target_root_functional = prm.get_double("Target sqrt(J)");
      prm.leave_subsection();
      AssertThrow(fraction > 0,
                  ExcMessage("parameter 'Adaptivity/Fraction' must be in (0, 1]"));
    }
  } // namespace Parameters
} // namespace FoslsContact
