#ifndef fosls_contact_qp_dof_role_h
#define fosls_contact_qp_dof_role_h

namespace FoslsContact
{
  /**
   * The role of one degree of freedom in the constrained quadratic problem
   * (ConstrainedQP): what the solvers may do with it. The discretization
   * decides it from the boundary conditions (Discretization::setup_level),
   * in the normal-tangential basis of the contact DoFs.
   */
  enum class DoFRole : unsigned char
  {
    free,    ///< unconstrained
    fixed,   ///< Dirichlet u, Neumann sigma n, frictionless tangential traction
    bounded, ///< contact: normal displacement <= g or normal stress <= 0
    /**
     * friction: a tangential contact traction, |x_i| <= its slip bound
     * (ConstrainedQP::FrictionTerms)
     */
    traction,
    /**
     * friction: a tangential displacement of a contact vertex, with the
     * term w_i |x_i - p_i| in J (ConstrainedQP::FrictionTerms)
     */
    slip,
  };
} // namespace FoslsContact

#endif
