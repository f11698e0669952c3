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
    fixed,   ///< Dirichlet u, Neumann sigma n, tangential contact traction
    bounded, ///< contact: normal displacement <= g or normal stress <= 0
  };
} // namespace FoslsContact

#endif
