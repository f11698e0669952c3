#ifndef fosls_contact_discretization_normal_tangential_basis_h
#define fosls_contact_discretization_normal_tangential_basis_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The orthogonal matrices that turn the Cartesian coordinates of a
   * contact face or vertex into the normal-tangential ones of paper section
   * 4.3, in which the contact constraints are bounds on single coordinates
   * (box constraints). Functions of the normal alone, so every process that
   * holds an entity builds the same matrix, and the unit test checks them
   * without a mesh.
   */
  template <int dim>
  class NormalTangentialBasis
  {
  public:
    /** The Householder reflection H with H e_1 = n (paper section 4.3). */
    static FullMatrix<double> householder(const Tensor<1, dim> &n);

    /**
     * The rotation R (x_cart = R x_rot) of a contact vertex with obstacle
     * normal @p n: R e_1 = n, and e_k (up to sign) is a column for every k
     * with n_k = 0, so a roller's prescribed components stay single
     * rotated coordinates. H(n) when n_1 != 0; when n_1 = 0 an orthogonal
     * matrix that equals H(n) for n = +-e_j. A function of n alone: every
     * process that holds the vertex builds the same.
     */
    static FullMatrix<double> vertex_rotation(const Tensor<1, dim> &n);

  private:
    /** |n - e_1| below which the Householder reflection of n is I. */
    static constexpr double householder_tolerance = 1e-12;
  };
} // namespace FoslsContact

#endif
