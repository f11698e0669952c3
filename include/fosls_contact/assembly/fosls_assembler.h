#ifndef fosls_contact_assembly_fosls_assembler_h
#define fosls_contact_assembly_fosls_assembler_h

#include <deal.II/base/tensor.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>

#include <functional>
#include <vector>

namespace FoslsContact
{
  template <int dim>
  struct AssemblyScratch;
  struct AssemblyCopy;

  /**
   * Assembles the augmented least-squares functional of paper eqs. (1)-(2),
   *
   *   J(u, sigma) = C_eq ||div sigma + f||^2 + C_const ||A sigma - eps(u)||^2
   *               + C_compl <u.n - g, (sigma n).n>_{Gamma_C},
   *
   * with friction plus the bilinear part of the friction term (the same
   * weight, friction_terms(); its |u_t - p_t| part is no quadratic: it is
   * ConstrainedQP::FrictionTerms),
   *
   * on one level, directly in the normal-tangential basis: the local matrix
   * of a cell that touches a rotated vertex or face is transformed as
   * R^T K R before it is added, so the global matrix never needs a
   * triple product. On an adaptively refined mesh the hanging nodes are
   * eliminated the same way, cell by cell, before the rotation
   * (eliminate_hanging_dofs_of_cell()).
   *
   * Only declared effects are assembled: the body force enters only if the
   * scene has one, and the face integral over Gamma_C only with contact.
   *
   * Everything is dimensionless (ReferenceScales): the mesh, the data and the
   * elastic constants come from the scene in units of L and S, so the
   * weights mean the same functional in every unit system.
   */
  template <int dim>
  class FoslsAssembler
  {
  public:
    /**
     * With friction, @p friction_reference is the displacement the load
     * step starts from (Cartesian, with ghost values; null: the undeformed
     * body): the friction term acts on the displacement relative to it.
     */
    FoslsAssembler(const Discretization<dim> &discretization,
                   const Parameters::Weights &weights,
                   const LevelVector *        friction_reference = nullptr);

    /**
     * Fill @p qp (sized with ConstrainedQP::reinit) on level @p level;
     * @p release_coupling_pattern as in ConstrainedQP::compress_matrices().
     */
    void assemble(const unsigned int           level,
                  ConstrainedQP &              qp,
                  const std::function<void()> &release_coupling_pattern = {}) const;

    /**
     * The compliance tensor A sigma = (sigma - kappa tr(sigma) I) / (2 mu)
     * with kappa = lambda / (d lambda + 2 mu), written as
     * 1 / (d + 2 mu / lambda) so that lambda = inf gives kappa = 1/d exactly
     * and lambda = 1e8 loses no digits.
     */
    static Tensor<2, dim> compliance(const Tensor<2, dim> &sigma,
                                     const double          mu,
                                     const double          lambda);

  private:
    /**
     * The worker of assemble(): the terms of @p cell of @p data, with its
     * hanging DoFs eliminated, rotated and sorted for the copier, in
     * @p copy (left invalid for a cell that reaches no owned row). A cell
     * of the active mesh or of a level (@p CellIterator), one per thread.
     */
    template <typename CellIterator>
    void local_terms(const LevelData<dim> &data,
                     const CellIterator &  cell,
                     AssemblyScratch<dim> &scratch,
                     AssemblyCopy &        copy) const;

    /** The volume terms of @p cell (equilibrium, constitutive, body force). */
    void cell_terms(const typename Triangulation<dim>::cell_iterator &cell,
                    AssemblyScratch<dim> &                           scratch,
                    AssemblyCopy &                                   copy) const;
    /** The complementarity term on the faces of @p cell on Gamma_C. */
    void contact_terms(const typename Triangulation<dim>::cell_iterator &cell,
                       AssemblyScratch<dim> &                           scratch,
                       AssemblyCopy &                                   copy) const;

    /**
     * With friction: the bilinear part of the friction term on the contact
     * face @p f of @p cell (whose face values @p scratch holds), added to
     * the complementarity part, and its part at the reference displacement.
     */
    void friction_terms(const typename Triangulation<dim>::cell_iterator &cell,
                        const unsigned int                               f,
                        AssemblyScratch<dim> &                           scratch,
                        AssemblyCopy &                                   copy) const;

    /** The cell's terms in the normal-tangential basis: R^T K R, R^T r. */
    void rotate(const LevelData<dim> &data, AssemblyCopy &copy) const;

    /**
     * The patterns on which the parts of J are summed (owned rows): the
     * equilibrium part couples two fluxes of one stress row in one cell
     * (all the fluxes of a cell with a rotated face, whose rotation mixes
     * its rows), the complementarity part the DoFs of a cell on Gamma_C;
     * both with the masters of their hanging DoFs. Summed on the DoF
     * coupling pattern instead, the two parts took two more matrices of
     * A's size until compress_matrices() (memory that the process kept:
     * doc/performance.md, "Figures behind the code"), and the copier added every cell's zeros to
     * them.
     */
    void part_patterns(const LevelData<dim> &data,
                       SparsityPattern &     eq,
                       SparsityPattern &     contact) const;

    const Discretization<dim> &discretization;
    const Parameters::Material material;
    const Parameters::Weights  weights;
    /**
     * The stress row of each shape function of a cell (an RT function of
     * row m is nonzero in that row only), -1 for a displacement function:
     * the other rows' values and divergences are exact zeros, which the
     * cell terms neither evaluate nor multiply.
     */
    std::vector<int> stress_row;
    const LevelVector *friction_reference;
  };
} // namespace FoslsContact

#endif
