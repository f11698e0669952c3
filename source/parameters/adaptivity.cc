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
                        "0: uniform refinement only. A load path (Data/Load steps) runs "
                        "the loop on its first step and solves the later steps on the "
                        "last mesh. Needs Solver/Type = monotone multigrid "
                        "(on one level per mesh level of the adaptive mesh) or active set. "
                        "On several MPI processes every process holds the whole mesh and "
                        "works on its share of the cells (doc/parallel.md).");
      prm.declare_entry("Marking",
                        "bulk",
                        Patterns::Selection("bulk|fixed fraction"),
                        "bulk (Dörfler): refine the fewest cells whose eta_T^2 sum to at "
                        "least Fraction times J; fixed fraction: refine the Fraction of the "
                        "cells with the largest eta_T (rounded up: at least one cell). Either "
                        "way the cells whose eta_T^2 is within 0.1% of the smallest one "
                        "marked are marked too, so that mirror images are refined together "
                        "and indicators that differ only in their last digits (runs on "
                        "different numbers of processes) mark the same cells.");
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
      prm.declare_entry("Reference refinements",
                        "0",
                        Patterns::Integer(0, 3),
                        "For scenes without an exact solution: once the loop has stopped, "
                        "refine every cell of the last mesh this many times and solve "
                        "there (the reference, the last row of the step table, not limited "
                        "by Max DoFs: about 2^(dim R) times the last mesh's DoFs). Every "
                        "step's solution is carried over to the reference mesh, which "
                        "contains every earlier mesh, and its error against the reference "
                        "is reported: |u_ref - u_h|_H1, |sigma_ref - sigma_h|_Hdiv and the "
                        "efficiency index sqrt(J) / sqrt(|..|_H1^2 + |..|_Hdiv^2). The "
                        "reference's own error is in these figures, most for the last "
                        "steps. 0: no reference.");
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
      reference_refinements  = prm.get_integer("Reference refinements");
      prm.leave_subsection();
      AssertThrow(fraction > 0,
                  ExcMessage("parameter 'Adaptivity/Fraction' must be in (0, 1]"));
      AssertThrow(reference_refinements == 0 || steps > 0,
                  ExcMessage("parameter 'Adaptivity/Reference refinements' > 0 needs "
                             "'Adaptivity/Steps' > 0 (the reference ends an adaptive run)"));
    }
  } // namespace Parameters
} // namespace FoslsContact
