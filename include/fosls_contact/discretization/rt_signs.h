#ifndef fosls_contact_discretization_rt_signs_h
#define fosls_contact_discretization_rt_signs_h

#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The faces of a cell on which deal.II flips the sign of the RT shape
   * functions, as a bit mask (bit f for face f). On meshes whose cells are
   * not all aligned (the half disc), FE_RaviartThomas flips the sign of a
   * face's shape function in one of the two cells so that the normal flux
   * is continuous; the reference embedding matrices know nothing of it, so
   * the prolongation must apply the child's and the parent's signs.
   *
   * The flips are read from what deal.II computes, not from its rule (the
   * rule is an implementation detail of FE_PolyTensor and differs between
   * 2D and 3D): the RT0 shape function of face f, evaluated at the face's
   * center and pulled back by the inverse Jacobian, is the reference
   * function (whose component f/2 is positive there) times the sign divided
   * by det J > 0. One FEValues of a lone FE_RaviartThomas(0) with the face
   * centers as its points reads all faces of a cell with one reinit(): all
   * copies of RT0 in the FESystem (the stress rows) share a face's flip,
   * and the FESystem computes each copy's values as the lone element does.
   * This is a few times cheaper than one FEFaceValues reinit() of the whole
   * FESystem per face, which was a visible part of the set-up
   * (doc/performance.md, section 3).
   */
  template <int dim>
  class RtFaceFlips
  {
  public:
    /** Reads the flips of cells mapped by @p mapping. */
    explicit RtFaceFlips(const Mapping<dim> &mapping);

    /** The bit mask of the flipped faces of @p cell (any cell of any level). */
    unsigned int
    operator()(const typename Triangulation<dim>::cell_iterator &cell);

  private:
    /** The points: face f's center on the reference cell. */
    static Quadrature<dim>
    face_centers();

    const FE_RaviartThomas<dim> rt;
    FEValues<dim>               fe_values;
  };


  /**
   * The signs deal.II gives the RT shape functions of a cell whose flipped
   * faces are @p flips (RtFaceFlips): +-1 per DoF of @p fe, 1 for the
   * displacement DoFs.
   */
  template <int dim>
  std::vector<double>
  rt_signs(const FiniteElement<dim> &fe, const unsigned int flips)
  {
    std::vector<double> signs(fe.n_dofs_per_cell(), 1.);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto base = fe.system_to_base_index(i);
        if (base.first.first == 1 && (flips & (1u << base.second)))
          signs[i] = -1.;
      }
    return signs;
  }
} // namespace FoslsContact

#endif
