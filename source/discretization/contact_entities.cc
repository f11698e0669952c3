#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/discretization/contact_entities.h>
#include <fosls_contact/discretization/normal_tangential_basis.h>

#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  ContactEntities<dim>::ContactEntities(const Scene<dim> &        scene,
                                        const Triangulation<dim> &triangulation)
    : scene(scene)
    , triangulation(triangulation)
  {}


  template <int dim>
  void
  ContactEntities<dim>::set_contact_vertices(LevelData<dim> &    data,
                                             const BoundaryData &boundary) const
  {
    // Contact vertices: those of contact faces that are not Dirichlet
    // vertices. At a vertex of both, the prescribed displacement wins; it
    // must not be prescribed into the obstacle, where u.n <= g cannot hold
    // (a corner of the square with Dirichlet value u_y = -0.01 and gap
    // -0.02 would keep a penetration of 0.03, silently). A roller vertex
    // (u.n not prescribed) stays a contact vertex if n is orthogonal to its
    // prescribed components: vertex_rotation(n) then has +-e_k as a column
    // for each of them, so u_k is one rotated coordinate, fixed, beside the
    // bounded u.n (roller_contact_vertex()). Any other roller vertex is
    // refused: a box constraint cannot hold u.n <= g and a Cartesian
    // component together.
    double          penetration = 0;
    Vector<double>  values(dim);
    // (the normal, the gap and the Dirichlet values at this process's
    // vertices: an error there, or the first unsupported roller vertex of
    // the first process that has one, stops every process, CollectiveError)
    CollectiveError::run(data.partitioner->get_mpi_communicator(), [&]() {
      for (const auto &[vi, p] : boundary.contact_vertex_points)
        {
          const auto dofs = data.vertex_dofs.at(vi);
          const auto d    = boundary.dirichlet_vertices.find(vi);
          if (d == boundary.dirichlet_vertices.end())
            {
              data.role[dofs[0]]                       = DoFRole::bounded;
              data.upper_bounds.local_element(dofs[0]) = scene.gap().value(p);
              if (scene.has_friction())
                for (unsigned int k = 1; k < dim; ++k)
                  data.role[dofs[k]] = DoFRole::slip;
              continue;
            }
          const auto &         mask = d->second;
          const Tensor<1, dim> n    = scene.obstacle_normal(p);
          const double         gap  = scene.gap().value(p);
          scene.dirichlet_values().vector_value(p, values);
          bool   prescribed = true; // u.n: n has no part along a free component
          double normal_u   = 0;
          for (unsigned int k = 0; k < dim; ++k)
            {
              prescribed = prescribed && (mask[k] || n[k] == 0.);
              if (mask[k])
                normal_u += values[k] * n[k];
            }
          if (prescribed)
            {
              // (relative to 1 too: sin(pi) = 1.2e-16 against a gap of 0
              // must pass)
              if (normal_u - gap >
                  penetration_round_off * (1. + std::abs(normal_u) + std::abs(gap)))
                penetration = std::max(penetration, normal_u - gap);
              continue;
            }
          if (!roller_contact_vertex(data, dofs, mask, n, gap, values))
            {
              std::ostringstream where;
              where << p;
              AssertThrow(false,
                          ExcMessage("a vertex at (" + where.str() + ")" +
                                     " of both a roller ('Boundary conditions/Dirichlet "
                                     "components') and the contact boundary has an obstacle "
                                     "normal with a part along a prescribed component "
                                     "('Data/Obstacle normal'): u.n <= g and the prescribed "
                                     "components cannot be held together there"));
            }
        }
    });
    check_penetration(data, penetration);
  }


  template <int dim>
  bool
  ContactEntities<dim>::roller_contact_vertex(LevelData<dim> &                                data,
                                             const std::array<types::global_dof_index, dim> &dofs,
                                             const std::array<bool, dim> &                   mask,
                                             const Tensor<1, dim> &                          n,
                                             const double                                    gap,
                                             const Vector<double> &values) const
  {
    // n has no part along a prescribed component
    for (unsigned int k = 0; k < dim; ++k)
      if (mask[k] && n[k] != 0.)
        return false;
    // rotated coordinate i: free, or u_k = R(k, i) x_i fixed
    const FullMatrix<double> R = NormalTangentialBasis<dim>::vertex_rotation(n);
    std::array<bool, dim>    fixed{};
    for (unsigned int i = 0; i < dim; ++i)
      data.fixed_values.local_element(dofs[i]) = 0.;
    for (unsigned int k = 0; k < dim; ++k)
      if (mask[k])
        {
          unsigned int i = 1;
          while (i < dim && std::abs(std::abs(R(k, i)) - 1.) > 1e-14)
            ++i;
          if (i == dim)
            return false;
          fixed[i]                                 = true;
          data.fixed_values.local_element(dofs[i]) = R(k, i) * values[k];
        }
    for (unsigned int i = 1; i < dim; ++i)
      data.role[dofs[i]] = fixed[i]              ? DoFRole::fixed :
                           scene.has_friction() ? DoFRole::slip :
                                                  DoFRole::free;
    data.role[dofs[0]]                       = DoFRole::bounded;
    data.upper_bounds.local_element(dofs[0]) = gap;
    return true;
  }


  template <int dim>
  void
  ContactEntities<dim>::check_penetration(const LevelData<dim> &data, double penetration) const
  {
    penetration = Utilities::MPI::max(penetration, data.partitioner->get_mpi_communicator());
    if (penetration > 0)
      {
        std::ostringstream message;
        message << "parameter 'Data/Dirichlet values' prescribes a vertex of both the Dirichlet "
                << "and the contact boundary " << std::setprecision(3) << penetration
                << " into the obstacle ('Data/Gap', 'Data/Obstacle normal'): u.n <= g cannot "
                << "hold there";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }


  template <int dim>
  void
  ContactEntities<dim>::add_rotations(LevelData<dim> &data, const BoundaryData &boundary) const
  {
    // The rotations (paper section 4.3) of the contact faces and vertices.
    // A face: Q_phi = H_phi / c with c the mean normal component of the
    // face's basis function (+-1/|face|): then the first rotated coordinate
    // is the mean normal traction (sigma n).n on the face, whatever the
    // sign of the RT orientation.
    const unsigned int n_owned = data.n_owned();
    for (const auto &face : boundary.contact_faces)
      {
        RotationBlock<dim> block;
        block.dofs    = face.dofs;
        block.matrix  = NormalTangentialBasis<dim>::householder(face.normal);
        block.inverse = block.matrix;
        block.matrix *= 1. / face.c;
        block.inverse *= face.c;
        const unsigned int b = data.rotations.size();
        data.rotations.push_back(block);
        for (unsigned int m = 0; m < dim; ++m)
          data.rotation_of_dof[face.dofs[m]] = b;
        data.contact_faces.push_back({face.face_index,
                                      face.dofs[0],
                                      face.center,
                                      face.normal,
                                      face.area,
                                      face.dofs[0] < n_owned});
      }
    // (every local vertex the owner made a contact vertex, also one whose
    // contact face is in a cell that is not here)
    for (const auto &[vi, vertex] : data.vertex_dofs)
      {
        if (data.role[vertex[0]] != DoFRole::bounded)
          continue;
        const Point<dim>     p = triangulation.get_vertices()[vi];
        const Tensor<1, dim> n = scene.obstacle_normal(p);
        RotationBlock<dim>   block;
        block.dofs   = vertex;
        block.matrix = NormalTangentialBasis<dim>::vertex_rotation(n);
        block.inverse.copy_transposed(block.matrix);
        const unsigned int b = data.rotations.size();
        data.rotations.push_back(block);
        for (unsigned int k = 0; k < dim; ++k)
          data.rotation_of_dof[block.dofs[k]] = b;
        data.contact_vertices.push_back({vi,
                                         vertex[0],
                                         p,
                                         n,
                                         data.upper_bounds.local_element(vertex[0]),
                                         vertex[0] < n_owned});
      }
  }


  template <int dim>
  void
  ContactEntities<dim>::add_friction_faces(LevelData<dim> &data, const BoundaryData &boundary) const
  {
    // The trapezoidal rule on a face gives each of its 2^(dim-1) vertices
    // the weight |F| / 2^(dim-1); a vertex whose tangential displacement is
    // prescribed (a Dirichlet or roller vertex) has no slip DoF, and its
    // term w |x - p| is a constant of J, left out. A 3D roller vertex with
    // one tangential coordinate prescribed keeps the other as a slip DoF
    // alone (the other entry no DoF): its term is w |x_i - p_i|, exact
    // where the prescribed coordinate does not move in the step (a
    // symmetry plane).
    for (const auto &face : boundary.contact_faces)
      {
        FrictionFace<dim> friction;
        friction.face_index = face.face_index;
        friction.normal     = face.dofs[0];
        for (unsigned int k = 1; k < dim; ++k)
          friction.traction[k - 1] = face.dofs[k];
        friction.weight = face.area / GeometryInfo<dim>::vertices_per_face;
        friction.center = face.center;
        for (const unsigned int vi : face.vertices)
          {
            const auto vertex = data.vertex_dofs.find(vi);
            if (vertex == data.vertex_dofs.end())
              continue;
            std::array<types::global_dof_index, dim - 1> slip;
            bool                                         slips = false;
            for (unsigned int k = 1; k < dim; ++k)
              {
                const bool free_k = data.role[vertex->second[k]] == DoFRole::slip;
                slip[k - 1]       = free_k ? vertex->second[k] : numbers::invalid_dof_index;
                slips             = slips || free_k;
              }
            if (slips)
              friction.slips.push_back(slip);
          }
        data.friction_faces.push_back(friction);
      }
  }


  template class ContactEntities<2>;
  template class ContactEntities<3>;
} // namespace FoslsContact
