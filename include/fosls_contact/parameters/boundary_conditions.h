#ifndef fosls_contact_parameters_boundary_conditions_h
#define fosls_contact_parameters_boundary_conditions_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Boundary conditions: which boundary ids are Dirichlet,
     * Neumann and contact boundaries. Every boundary id of the mesh must be
     * named exactly once. On a Dirichlet id, the components not listed in
     * `Dirichlet components` get the traction of the Neumann data instead
     * (a roller), component by component. The components may differ per
     * id ("0: 0; 3: all"): a symmetry plane beside a clamped side, whose
     * rigid motions the clamped side fixes.
     */
    struct BoundaryConditions
    {
      /**
       * The largest boundary id the parameters accept: the ids of the box
       * and the curved bodies are 0 to 4, and a mesh file's ids are its
       * physical groups or surfaces, which a scene numbers from 0. (deal.II
       * itself takes ids to 2^32 - 2.)
       */
      static constexpr unsigned int max_id = 255;

      std::vector<unsigned int> dirichlet_ids;
      /// per Dirichlet id: which components are prescribed (size dim);
      /// filled by parse_components(), once the dimension is known
      std::map<unsigned int, std::vector<bool>> dirichlet_components;
      std::string               dirichlet_components_text = "all";
      std::vector<unsigned int> neumann_ids;
      std::vector<unsigned int> contact_ids;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
      /**
       * Read `Dirichlet components` into dirichlet_components: 'all', a
       * component list for every Dirichlet id, or one list per id. A
       * separate step because the valid components depend on
       * Geometry/Dimension, which AllParameters passes in.
       */
      void parse_components(const unsigned int dimension);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
