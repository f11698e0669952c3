#ifndef fosls_contact_discretization_rt_signs_h
#define fosls_contact_discretization_rt_signs_h

#include <deal.II/fe/fe_values.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The faces of @p cell on which deal.II flips the sign of the RT shape
   * functions, as a bit mask (bit f for face f). On meshes whose cells are
   * not all aligned (the half disc), FE_RaviartThomas flips the sign of a
   * face's shape function in one of the two cells so that the normal flux
   * is continuous; the reference embedding matrices know nothing of it, so
   * the prolongation must apply the child's and the parent's signs.
   * The sign is read off the normal component at the face center, whose
   * orientation without a flip is the reference one: outward on faces 1
   * and 3 (5), inward on faces 0 and 2 (4). All copies of RT0 in the
   * FESystem (the stress rows) share a face's flip, so one reinit() per
   * face reads it (the copies' DoFs on the face are the same function).
   */
  template <int dim, typename Iterator>
  unsigned int
  rt_face_flips(FEFaceValues<dim> &fe_face, const Iterator &cell)
  {
    const auto & fe = fe_face.get_fe();
    unsigned int flips = 0;
    unsigned int read  = 0;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto base = fe.system_to_base_index(i);
        if (base.first.first != 1)
          continue;
        const unsigned int f = base.second; // RT0: DoF j lives on face j
        if (read & (1u << f))
          continue;
        read |= 1u << f;
        fe_face.reinit(cell, f);
        const FEValuesExtractors::Vector row(dim + base.first.second * dim);
        const double normal    = fe_face[row].value(i, 0) * fe_face.normal_vector(0);
        const double reference = (f % 2 == 1) ? 1. : -1.;
        if (normal * reference <= 0)
          flips |= 1u << f;
      }
    return flips;
  }


  /**
   * The signs deal.II gives the RT shape functions of a cell whose flipped
   * faces are @p flips (rt_face_flips()): +-1 per DoF of @p fe, 1 for the
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


  /** The signs deal.II gives the RT shape functions of @p cell. */
  template <int dim, typename Iterator>
  std::vector<double>
  rt_signs(FEFaceValues<dim> &fe_face, const Iterator &cell)
  {
    return rt_signs(fe_face.get_fe(), rt_face_flips(fe_face, cell));
  }
} // namespace FoslsContact

#endif
