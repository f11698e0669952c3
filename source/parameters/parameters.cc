#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/parameters.h>

#include <sstream>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    AllParameters::declare_parameters(ParameterHandler &prm)
    {
      Geometry::declare_parameters(prm);
      Material::declare_parameters(prm);
      Scaling::declare_parameters(prm);
      Weights::declare_parameters(prm);
      Data::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      Friction::declare_parameters(prm);
      Solver::declare_parameters(prm);
      Output::declare_parameters(prm);
      HertzComparison::declare_parameters(prm);
      Adaptivity::declare_parameters(prm);
    }

    void
    AllParameters::parse_parameters(ParameterHandler &prm)
    {
      geometry.parse_parameters(prm);
      material.parse_parameters(prm);
      scaling.parse_parameters(prm);
      weights.parse_parameters(prm);
      // a positive bulk modulus: lambda + 2 mu / dim > 0 (always so for E
      // and nu in their ranges)
      {
        std::ostringstream text;
        text << "parameter 'Material/lambda' = " << material.lambda
             << " must be > -2 mu / dim = " << -2. * material.mu / geometry.dimension
             << " (a positive bulk modulus), or inf";
        AssertThrow(material.lambda > -2. * material.mu / geometry.dimension,
                    ExcMessage(text.str()));
      }
      data.parse_parameters(prm);
      boundary_conditions.parse_parameters(prm);
      solver.parse_parameters(prm);
      output.parse_parameters(prm);
      hertz.parse_parameters(prm);
      if (hertz.shape != HertzComparison::Shape::none)
        {
          AssertThrow(hertz.shape == HertzComparison::Shape::cylinder ||
                        geometry.dimension == 3,
                      ExcMessage("parameter 'Hertz comparison/Shape' = sphere needs "
                                 "Dimension = 3"));
          if (hertz.shape == HertzComparison::Shape::cylinder && geometry.dimension == 3)
            {
              AssertThrow(hertz.length > 0,
                          ExcMessage("parameter 'Hertz comparison/Length' must be > 0 "
                                     "for a cylinder in 3D (the length of its contact "
                                     "line)"));
              AssertThrow(hertz.axis[0] != 0 || hertz.axis[1] != 0 || hertz.axis[2] != 0,
                          ExcMessage("parameter 'Hertz comparison/Axis' is zero"));
            }
          AssertThrow(hertz.contact_point.size() == geometry.dimension,
                      ExcMessage("parameter 'Hertz comparison/Contact point' needs " +
                                 std::to_string(geometry.dimension) + " entries"));
        }

      adaptivity.parse_parameters(prm);
      AssertThrow(!adaptivity.enabled() || solver.type != Solver::Type::projected_gauss_seidel,
                  ExcMessage("parameter 'Adaptivity/Steps' > 0 needs 'Solver/Type' = monotone "
                             "multigrid or active set: projected gauss seidel sweeps the "
                             "uniformly refined levels only"));

      // (a load path adapts its mesh on its first step only, so that the
      // later steps' mesh does not depend on the path: the reference of
      // Reference refinements, the last mesh refined everywhere, would be
      // solved for the last step's data and the error of the first step's
      // meshes measured against it)
      AssertThrow(data.load_steps.empty() || adaptivity.reference_refinements == 0,
                  ExcMessage("parameter 'Adaptivity/Reference refinements' needs an empty "
                             "'Data/Load steps': the reference is a solve of one step's data"));

      boundary_conditions.parse_components(geometry.dimension);

      friction.parse_parameters(prm);
      if (friction.enabled())
        {
          const std::string law =
            "parameter 'Friction/Law' = " +
            std::string(friction.law == Friction::Law::tresca ? "Tresca" : "Coulomb");
          AssertThrow(!boundary_conditions.contact_ids.empty(),
                      ExcMessage(law + " needs a contact boundary ('Boundary conditions/"
                                       "Contact boundary ids'): friction acts on contact faces only"));
          AssertThrow(geometry.dimension == 2 || solver.type != Solver::Type::active_set,
                      ExcMessage(law + " in 3D with 'Solver/Type' = active set: its semismooth "
                                       "Newton method is built for the 2D bounds; take monotone "
                                       "multigrid or projected Gauss-Seidel"));
          // (the Coulomb fixed point stops when the slip bounds of two
          // Tresca solutions differ by less than its tolerance, so they must
          // be solved closer than that: stopped at the discretization
          // accuracy, the last step of the sliding block on 6 levels kept
          // changing them by 1e-5 .. 3e-3, doc/method.md section 7.7)
          if (friction.law == Friction::Law::coulomb && solver.automatic_stopping)
            solver.stopping = Solver::Stopping::tolerance;
          // (the plain cycle's one-sided coarse obstacles cannot hold the
          // two-sided traction bounds or the kinks: its coarse corrections
          // would leave the friction DoFs to the smoother alone)
          AssertThrow(solver.type != Solver::Type::monotone_multigrid || solver.krylov_steps > 0,
                      ExcMessage(law + " with 'Solver/Type' = monotone multigrid needs "
                                       "'Solver/Krylov steps' > 0: the plain cycle would leave the "
                                       "tangential contact DoFs to the smoother alone"));
        }
    }
  } // namespace Parameters
} // namespace FoslsContact
