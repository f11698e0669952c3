#ifndef fosls_contact_discretization_rt_signs_h
#define fosls_contact_discretization_rt_signs_h

#include <deal.II/fe/fe_values.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The signs deal.II gives the RT shape functions of @p cell (+-1 per
   * DoF, 1 for displacement DoFs). On meshes whose cells are not all
   * aligned (the half disc), FE_RaviartThomas flips the sign of a face's
   * shape function in one of the two cells so that the normal flux is
   * continuous; the reference embedding matrices know nothing of it, so
   * the prolongation must apply the child's and the parent's signs.
   * The sign is read off the normal component at the face center, whose
   * orientation without a flip is the reference one: outward on faces 1
   * and 3 (5), inward on faces 0 and 2 (4).
   */
  template <int dim, typename Iterator>
  std::vector<double>
  rt_signs(FEFaceValues<dim> &fe_face, const Iterator &cell)
  {
    const auto &        fe = fe_face.get_fe();
    std::vector<double> signs(fe.n_dofs_per_cell(), 1.);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto base = fe.system_to_base_index(i);
        if (base.first.first != 1)
          continue;
        const unsigned int f = base.second; // RT0: DoF j lives on face j
        fe_face.reinit(cell, f);
        const FEValuesExtractors::Vector row(dim + base.first.second * dim);
        const double normal =
          fe_face[row].value(i, 0) * fe_face.normal_vector(0);
        const double reference = (f % 2 == 1) ? 1. : -1.;
        signs[i] = (normal * reference > 0) ? 1. : -1.;
      }
    return signs;
  }
} // namespace FoslsContact

#endif
