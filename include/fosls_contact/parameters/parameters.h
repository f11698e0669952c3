#ifndef fosls_contact_parameters_parameters_h
#define fosls_contact_parameters_parameters_h

#include <fosls_contact/parameters/adaptivity.h>
#include <fosls_contact/parameters/boundary_conditions.h>
#include <fosls_contact/parameters/data.h>
#include <fosls_contact/parameters/friction.h>
#include <fosls_contact/parameters/geometry.h>
#include <fosls_contact/parameters/hertz_comparison.h>
#include <fosls_contact/parameters/material.h>
#include <fosls_contact/parameters/output.h>
#include <fosls_contact/parameters/scaling.h>
#include <fosls_contact/parameters/solver.h>
#include <fosls_contact/parameters/value_parsing.h>
#include <fosls_contact/parameters/weights.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * All run-time parameters, one struct per subsection of the input file.
   *
   * Every struct has the same two functions: `declare_parameters()` adds its
   * entries (with a Patterns object, so that ParameterHandler rejects a bad
   * value with the name of the entry) and `parse_parameters()` reads them back
   * and performs the checks that a Pattern cannot express (e.g. `lambda =
   * inf`). Errors are thrown as ExcMessage with a one-line text that names the
   * parameter; main() adds the file name.
   */
  namespace Parameters
  {
    /**
     * All subsections together: what the program reads from an input file.
     * The subsection structs check their own entries; this struct checks
     * what relates two subsections (lambda against the dimension, the Hertz
     * shape against the dimension, the Dirichlet components) and is what
     * the rest of the program is given, as `const AllParameters &`.
     */
    struct AllParameters
    {
      Geometry           geometry;
      Material           material;
      Scaling            scaling;
      Weights            weights;
      Data               data;
      BoundaryConditions boundary_conditions;
      Friction           friction;
      Solver             solver;
      Output             output;
      HertzComparison    hertz;
      Adaptivity         adaptivity;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
