#include <fosls_contact/problem/friction_law.h>

#include <algorithm>
#include <cmath>

namespace FoslsContact
{
  template <int dim>
  FrictionLaw<dim>::FrictionLaw(const Scene<dim> &    scene,
                                const LevelData<dim> &fine,
                                const double          c_compl)
    : scene(scene)
    , fine(fine)
    , c_compl(c_compl)
  {}


  template <int dim>
  std::vector<double>
  FrictionLaw<dim>::slip_bounds(const LevelVector &x) const
  {
    std::vector<double> s;
    s.reserve(fine.friction_faces.size());
    const bool tresca = scene.friction_law() == Parameters::Friction::Law::tresca;
    for (const auto &face : fine.friction_faces)
      {
        const double data = scene.friction_data().value(face.center);
        s.push_back(tresca ? data : data * std::max(0., -x.local_element(face.normal)));
      }
    return s;
  }


  template <int dim>
  void
  FrictionLaw<dim>::set_bounds(ConstrainedQP &qp, const std::vector<double> &s) const
  {
    auto &friction = qp.friction;
    friction.traction_bounds.reinit(qp.partitioner);
    friction.slip_weights.reinit(qp.partitioner);
    if (friction.slip_references.size() != qp.size())
      friction.slip_references.reinit(qp.partitioner);
    // Every process sees all the faces at the vertices it owns (the ghost
    // layer), so their sums are complete; the ghost entries come from
    // their owners.
    // In 3D the two tangential coordinates of a face or vertex are a pair
    // (FrictionTerms::partner), on every process (a collective property).
    if (dim == 3)
      friction.partner.assign(qp.role.size(), FrictionTerms::no_partner);
    const auto pair = [&](const auto &dofs) {
      if (dim == 3 && dofs[0] != numbers::invalid_dof_index &&
          dofs[dim - 2] != numbers::invalid_dof_index)
        {
          friction.partner[dofs[0]]       = dofs[dim - 2];
          friction.partner[dofs[dim - 2]] = dofs[0];
        }
    };
    for (unsigned int f = 0; f < fine.friction_faces.size(); ++f)
      {
        const auto &face = fine.friction_faces[f];
        for (const auto dof : face.traction)
          friction.traction_bounds.local_element(dof) = s[f];
        pair(face.traction);
        for (const auto &slip : face.slips)
          {
            for (const auto dof : slip)
              if (dof != numbers::invalid_dof_index)
                friction.slip_weights.local_element(dof) += c_compl * face.weight * s[f];
            pair(slip);
          }
      }
    update_ghosts(friction.traction_bounds);
    update_ghosts(friction.slip_weights);
  }


  template <int dim>
  void
  FrictionLaw<dim>::set_reference(ConstrainedQP &qp, const LevelVector &reference) const
  {
    auto &p = qp.friction.slip_references;
    p.reinit(qp.partitioner);
    for (unsigned int i = 0; i < qp.role.size(); ++i)
      if (qp.role[i] == DoFRole::slip)
        p.local_element(i) = reference.local_element(i);
  }


  template <int dim>
  double
  FrictionLaw<dim>::relative_change(const std::vector<double> &s,
                                    const std::vector<double> &t) const
  {
    double change = 0, largest = 0;
    for (unsigned int f = 0; f < s.size(); ++f)
      {
        change  = std::max(change, std::abs(s[f] - t[f]));
        largest = std::max(largest, std::abs(t[f]));
      }
    const MPI_Comm comm = fine.partitioner->get_mpi_communicator();
    change  = Utilities::MPI::max(change, comm);
    largest = Utilities::MPI::max(largest, comm);
    return largest > 0 ? change / largest : 0.;
  }


  template class FrictionLaw<2>;
  template class FrictionLaw<3>;
} // namespace FoslsContact
