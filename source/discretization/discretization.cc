#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/discretization/discretization.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <set>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  Discretization<dim>::Discretization(const Scene<dim> &scene,
                                      const unsigned int n_levels,
                                      const MPI_Comm     comm)
    : scene(scene)
    , triangulation(comm,
                    Triangulation<dim>::limit_level_difference_at_vertices,
                    parallel::distributed::Triangulation<dim>::construct_multigrid_hierarchy)
    , fe(FE_Q<dim>(1), dim, FE_RaviartThomas<dim>(0), dim)
    , mapping(1)
  {
    {
      // the coarse mesh is built serially (on every process, identically)
      // and handed to p4est
      Triangulation<dim> coarse;
      scene.make_coarse_mesh(coarse);
      coarse_ratio = Scene<dim>::mesh_size_ratio(coarse);
      triangulation.copy_triangulation(coarse);
    }
    triangulation.refine_global(n_levels - 1);
    scene.check_cell_shapes(triangulation, comm);

    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    dof_handler.distribute_mg_dofs();
    for (unsigned int l = 0; l < triangulation.n_global_levels(); ++l)
      renumber_level(l);
    active_partitioner = std::make_shared<const Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      DoFTools::extract_locally_relevant_dofs(dof_handler),
      comm);

    levels.resize(triangulation.n_global_levels());
    for (unsigned int l = 0; l < levels.size(); ++l)
      setup_level(l);
  }


  template <int dim>
  FullMatrix<double>
  Discretization<dim>::householder(const Tensor<1, dim> &n)
  {
    // H = I - 2 w w^T with w = (n - e_1)/|n - e_1|: symmetric, orthogonal,
    // and H e_1 = n, so the first rotated coordinate is the normal one.
    FullMatrix<double> H(dim, dim);
    Tensor<1, dim>     w = n;
    w[0] -= 1.;
    const double norm = w.norm();
    for (unsigned int i = 0; i < dim; ++i)
      H(i, i) = 1.;
    if (norm < householder_tolerance)
      return H;
    w /= norm;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H(i, j) -= 2. * w[i] * w[j];
    return H;
  }


  template <int dim>
  FullMatrix<double>
  Discretization<dim>::vertex_rotation(const Tensor<1, dim> &n)
  {
    if (dim == 1 || n[0] != 0.)
      return householder(n);
    // n _|_ e_1: columns n, sign(n_j) e_1 at j = argmax |n_j| and, in 3D,
    // the unit part of e_k orthogonal to n at the other k. For n = +-e_j
    // this is H(n); in general e_1, and every e_k with n_k = 0, is a column
    // (H(n) would mix u_1 into every rotated coordinate).
    unsigned int j = 1;
    for (unsigned int k = 2; k < dim; ++k)
      if (std::abs(n[k]) > std::abs(n[j]))
        j = k;
    FullMatrix<double> R(dim, dim);
    for (unsigned int i = 0; i < dim; ++i)
      R(i, 0) = n[i];
    R(0, j) = (n[j] > 0 ? 1. : -1.);
    for (unsigned int k = 1; k < dim; ++k)
      if (k != j)
        {
          Tensor<1, dim> t;
          t[k] = 1.;
          t -= n[k] * n;
          t /= t.norm();
          for (unsigned int i = 0; i < dim; ++i)
            R(i, k) = t[i];
        }
    return R;
  }


  template <int dim>
  std::vector<std::array<double, dim + 3>>
  Discretization<dim>::owned_dof_keys(const unsigned int l) const
  {
    const IndexSet &                         owned = dof_handler.locally_owned_mg_dofs(l);
    std::vector<std::array<double, dim + 3>> keys;
    std::vector<bool>                        seen(owned.n_elements(), false);
    std::vector<types::global_dof_index>     dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (is_present(cell))
        {
          cell->get_mg_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (owned.is_element(dofs[i]) && !seen[owned.index_within_set(dofs[i])])
              {
                seen[owned.index_within_set(dofs[i])] = true;
                const auto       base  = fe.system_to_base_index(i);
                const Point<dim> point = base.first.first == 0 ?
                                           cell->vertex(base.second) :
                                           cell->face(base.second)->center();
                std::array<double, dim + 3> key;
                for (unsigned int d = 0; d < dim; ++d)
                  key[d] = point[d];
                key[dim]     = base.first.first;
                key[dim + 1] = base.first.second;
                key[dim + 2] = dofs[i];
                keys.push_back(key);
              }
        }
    AssertThrow(keys.size() == owned.n_elements(),
                ExcMessage("Discretization: an owned DoF without a cell here"));
    std::sort(keys.begin(), keys.end());
    return keys;
  }


  template <int dim>
  void
  Discretization<dim>::renumber_level(const unsigned int l)
  {
    // (the gain is in the cache: about 6-8% less time per cycle per DoF
    // on the square's levels 8 and 9, none measurable on the small levels;
    // bench/compare.py against p4est's numbering)
    const IndexSet &                     owned = dof_handler.locally_owned_mg_dofs(l);
    const auto                           keys  = owned_dof_keys(l);
    std::vector<types::global_dof_index> new_numbers(owned.n_elements());
    for (unsigned int k = 0; k < keys.size(); ++k)
      new_numbers[owned.index_within_set(types::global_dof_index(keys[k][dim + 2]))] =
        owned.nth_index_in_set(k);
    dof_handler.renumber_dofs(l, new_numbers);
  }


  template <int dim>
  std::vector<types::global_dof_index>
  Discretization<dim>::sweep_order(const unsigned int l) const
  {
    std::vector<double> mine;
    for (const auto &key : owned_dof_keys(l))
      mine.insert(mine.end(), key.begin(), key.end());
    const auto all = Utilities::MPI::gather(get_communicator(), mine, 0);
    std::vector<std::array<double, dim + 3>> keys;
    for (const auto &part : all)
      for (std::size_t k = 0; k < part.size(); k += dim + 3)
        {
          keys.emplace_back();
          std::copy(part.begin() + k, part.begin() + k + dim + 3, keys.back().begin());
        }
    std::sort(keys.begin(), keys.end());
    std::vector<types::global_dof_index> order;
    for (const auto &key : keys)
      order.push_back(types::global_dof_index(key[dim + 2]));
    return order;
  }


  template <int dim>
  void
  Discretization<dim>::setup_level(const unsigned int l)
  {
    map_level_dofs(l);
    const BoundaryData boundary = apply_boundary_faces(l);
    set_contact_vertices(l, boundary);
    // The owner decides: a ghost vertex on the edge of the ghost layer may
    // miss a Dirichlet face of a cell that is not here.
    LevelData<dim> &data = levels[l];
    exchange_ghosts(data.partitioner, data.role);
    update_ghosts(data.fixed_values);
    update_ghosts(data.upper_bounds);
    add_rotations(l, boundary);
    set_coupling_pattern(l);
  }


  template <int dim>
  template <typename Iterator>
  void
  Discretization<dim>::get_local_dofs(const unsigned int                    l,
                                      const Iterator &                      cell,
                                      std::vector<types::global_dof_index> &dofs) const
  {
    dofs.resize(fe.n_dofs_per_cell());
    cell->get_mg_dof_indices(dofs);
    for (auto &dof : dofs)
      dof = levels[l].partitioner->global_to_local(dof);
  }


  template <int dim>
  void
  Discretization<dim>::map_level_dofs(const unsigned int l)
  {
    LevelData<dim> &data = levels[l];
    data.n_dofs          = dof_handler.n_dofs(l);
    data.partitioner     = std::make_shared<const Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_mg_dofs(l),
      DoFTools::extract_locally_relevant_level_dofs(dof_handler, l),
      get_communicator());
    const unsigned int n_local = data.n_local();
    data.role.assign(n_local, DoFRole::free);
    data.fixed_values.reinit(data.partitioner);
    data.upper_bounds.reinit(data.partitioner);
    data.upper_bounds.add(std::numeric_limits<double>::infinity());
    data.rotation_of_dof.assign(n_local, numbers::invalid_unsigned_int);

    // Which DoF is which: the base element (0 = Q1^d, 1 = RT0^d), its copy
    // (displacement component or stress row) and the vertex or face, for
    // the cells with DoFs here (owned and ghost).
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (is_present(cell))
        {
          get_local_dofs(l, cell, dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto base = fe.system_to_base_index(i);
              if (base.first.first == 0)
                data.vertex_dofs[cell->vertex_index(base.second)]
                                [base.first.second] = dofs[i];
              else
                data.face_dofs[cell->face(base.second)->index()]
                              [base.first.second] = dofs[i];
            }
        }
  }


  template <int dim>
  typename Discretization<dim>::BoundaryData
  Discretization<dim>::apply_boundary_faces(const unsigned int l)
  {
    LevelData<dim> &      data = levels[l];
    BoundaryData          boundary;
    const QGauss<dim - 1> face_quadrature(3);
    FEFaceValues<dim>     fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_normal_vectors |
                                update_quadrature_points | update_JxW_values);
    Vector<double>                       values(dim);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (is_present(cell))
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const auto               face    = cell->face(f);
            const types::boundary_id id      = face->boundary_id();
            const auto &             face_rt = data.face_dofs.at(face->index());

            // RT DoF of stress row m on this face: its normal component
            // times the outward normal, at the face quadrature points.
            fe_face.reinit(cell, f);
            std::array<unsigned int, dim> local_rt;
            get_local_dofs(l, cell, dofs);
            for (unsigned int m = 0; m < dim; ++m)
              local_rt[m] = std::find(dofs.begin(), dofs.end(), face_rt[m]) - dofs.begin();
            auto normal_component = [&](const unsigned int m, const unsigned int q) {
              const FEValuesExtractors::Vector row(dim + m * dim);
              return fe_face[row].value(local_rt[m], q) * fe_face.normal_vector(q);
            };

            // Prescribed traction, component m, as the L2 projection onto
            // the face's normal-flux basis function: it is essential here.
            auto fix_traction = [&](const unsigned int m) {
              double num = 0, den = 0;
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  const double phi_n = normal_component(m, q);
                  num += scene.traction().value(fe_face.quadrature_point(q), m) *
                         phi_n * fe_face.JxW(q);
                  den += phi_n * phi_n * fe_face.JxW(q);
                }
              data.role[face_rt[m]]                       = DoFRole::fixed;
              data.fixed_values.local_element(face_rt[m]) = num / den;
            };

            if (scene.is_dirichlet(id))
              {
                const std::vector<bool> &mask = scene.dirichlet_components(id);
                for (const unsigned int v : face->vertex_indices())
                  {
                    const unsigned int vi = face->vertex_index(v);
                    auto &vertex_mask = boundary.dirichlet_vertices.try_emplace(vi).first->second;
                    scene.dirichlet_values().vector_value(face->vertex(v), values);
                    for (unsigned int k = 0; k < dim; ++k)
                      if (mask[k])
                        {
                          vertex_mask[k]                       = true;
                          const auto dof                       = data.vertex_dofs.at(vi)[k];
                          data.role[dof]                       = DoFRole::fixed;
                          data.fixed_values.local_element(dof) = values[k];
                        }
                  }
                for (unsigned int m = 0; m < dim; ++m)
                  if (!mask[m])
                    fix_traction(m);
              }
            else if (scene.is_neumann(id))
              {
                for (unsigned int m = 0; m < dim; ++m)
                  fix_traction(m);
              }
            else if (scene.is_contact(id))
              {
                for (const unsigned int v : face->vertex_indices())
                  boundary.contact_vertex_points[face->vertex_index(v)] = face->vertex(v);
                // the mean normal component of the face's basis function
                double area = 0, c = 0;
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    area += fe_face.JxW(q);
                    c += normal_component(0, q) * fe_face.JxW(q);
                  }
                bound_contact_face(data, face_rt);
                boundary.contact_faces.push_back({static_cast<unsigned int>(face->index()),
                                                  face_rt,
                                                  face->center(),
                                                  scene.obstacle_normal(face->center()),
                                                  area,
                                                  c / area});
              }
          }
    return boundary;
  }


  template <int dim>
  void
  Discretization<dim>::bound_contact_face(LevelData<dim> &                                data,
                                          const std::array<types::global_dof_index, dim> &face_rt)
  {
    // the tangential tractions are 0, the normal one (the first rotated
    // coordinate, see add_rotations()) is bounded by 0
    for (unsigned int m = 0; m < dim; ++m)
      {
        data.role[face_rt[m]]                       = DoFRole::fixed;
        data.fixed_values.local_element(face_rt[m]) = 0;
      }
    data.role[face_rt[0]]                       = DoFRole::bounded;
    data.upper_bounds.local_element(face_rt[0]) = 0.;
  }


  template <int dim>
  void
  Discretization<dim>::set_contact_vertices(const unsigned int l, const BoundaryData &boundary)
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
    LevelData<dim> &data        = levels[l];
    double          penetration = 0;
    std::string     unsupported;
    Vector<double>  values(dim);
    for (const auto &[vi, p] : boundary.contact_vertex_points)
      {
        const auto dofs = data.vertex_dofs.at(vi);
        const auto d    = boundary.dirichlet_vertices.find(vi);
        if (d == boundary.dirichlet_vertices.end())
          {
            data.role[dofs[0]]                       = DoFRole::bounded;
            data.upper_bounds.local_element(dofs[0]) = scene.gap().value(p);
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
            unsupported = where.str();
          }
      }
    check_contact_vertices(data, unsupported, penetration);
  }


  template <int dim>
  bool
  Discretization<dim>::roller_contact_vertex(LevelData<dim> &                                data,
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
    const FullMatrix<double> R = vertex_rotation(n);
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
      data.role[dofs[i]] = fixed[i] ? DoFRole::fixed : DoFRole::free;
    data.role[dofs[0]]                       = DoFRole::bounded;
    data.upper_bounds.local_element(dofs[0]) = gap;
    return true;
  }


  template <int dim>
  void
  Discretization<dim>::check_contact_vertices(const LevelData<dim> &data,
                                              std::string           unsupported,
                                              double                penetration) const
  {
    // (the first such vertex of any process: the message is printed by
    // process 0)
    for (const auto &where :
         Utilities::MPI::all_gather(data.partitioner->get_mpi_communicator(), unsupported))
      if (unsupported.empty())
        unsupported = where;
    AssertThrow(unsupported.empty(),
                ExcMessage("a vertex at (" + unsupported + ")" +
                           " of both a roller ('Boundary conditions/Dirichlet components') "
                           "and the contact boundary has an obstacle normal with a part along "
                           "a prescribed component ('Data/Obstacle normal'): u.n <= g and the "
                           "prescribed components cannot be held together there"));
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
  Discretization<dim>::add_rotations(const unsigned int l, const BoundaryData &boundary)
  {
    // The rotations (paper section 4.3) of the contact faces and vertices.
    // A face: Q_phi = H_phi / c with c the mean normal component of the
    // face's basis function (+-1/|face|): then the first rotated coordinate
    // is the mean normal traction (sigma n).n on the face, whatever the
    // sign of the RT orientation.
    LevelData<dim> &   data    = levels[l];
    const unsigned int n_owned = data.n_owned();
    for (const auto &face : boundary.contact_faces)
      {
        RotationBlock<dim> block;
        block.dofs    = face.dofs;
        block.matrix  = householder(face.normal);
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
        block.matrix = vertex_rotation(n);
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
  Discretization<dim>::set_coupling_pattern(const unsigned int l)
  {
    // The rows held here: the owned DoFs, and the DoFs of the patches at
    // the vertices of owned cells (the vertex's displacement, the faces at
    // it), whose cells are all here.
    LevelData<dim> &   data    = levels[l];
    const unsigned int n_local = data.n_local();
    const unsigned int n_owned = data.n_owned();
    std::vector<bool>  held(n_local, false);
    for (unsigned int i = 0; i < n_owned; ++i)
      held[i] = true;
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (cell->is_locally_owned_on_level())
        for (const unsigned int v : cell->vertex_indices())
          data.owned_cell_vertices.insert(cell->vertex_index(v));
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (is_present(cell))
        for (const unsigned int v : cell->vertex_indices())
          if (data.owned_cell_vertices.count(cell->vertex_index(v)))
            for_patch_dofs_in_cell(data, cell, v, [&](const auto dof) { held[dof] = true; });
    {
      std::vector<types::global_dof_index> dofs;
      DynamicSparsityPattern               dsp(n_local, n_local);
      for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
        if (is_present(cell))
          {
            get_local_dofs(l, cell, dofs);
            for (const auto i : dofs)
              if (held[i])
                for (const auto j : dofs)
                  dsp.add(i, j);
          }
      data.sparsity.copy_from(dsp);
    }
    std::vector<MatrixEntryImport::Entry> requests;
    for (unsigned int i = n_owned; i < n_local; ++i)
      if (held[i])
        for (auto e = data.sparsity.begin(i); e != data.sparsity.end(i); ++e)
          requests.emplace_back(data.global(i), data.global(e->column()));
    data.ghost_rows.reinit(requests, data.sparsity, data.partitioner);
  }


  template <int dim>
  void
  Discretization<dim>::apply_rotations(const unsigned int l,
                                       LevelVector &      x,
                                       const bool         inverse) const
  {
    Vector<double> in(dim), out(dim);
    for (const auto &block : levels[l].rotations)
      {
        for (unsigned int k = 0; k < dim; ++k)
          in[k] = x.local_element(block.dofs[k]);
        (inverse ? block.inverse : block.matrix).vmult(out, in);
        for (unsigned int k = 0; k < dim; ++k)
          x.local_element(block.dofs[k]) = out[k];
      }
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_cartesian(const unsigned int l, LevelVector &x) const
  {
    apply_rotations(l, x, false);
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_normal_tangential(const unsigned int l,
                                                   LevelVector &      x) const
  {
    apply_rotations(l, x, true);
  }


  template <int dim>
  LevelVector
  Discretization<dim>::to_active(const LevelVector &level_vector) const
  {
    // every owned active DoF is a DoF of an owned active cell, whose level
    // DoFs (owned or ghost) are here
    const unsigned int                   L = finest_level();
    const auto &                         level_partitioner = *levels[L].partitioner;
    LevelVector                          active(active_partitioner);
    std::vector<types::global_dof_index> level_dofs(fe.n_dofs_per_cell()),
      active_dofs(fe.n_dofs_per_cell());
    update_ghosts(level_vector);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const typename DoFHandler<dim>::level_cell_iterator level_cell(
            &triangulation, cell->level(), cell->index(), &dof_handler);
          level_cell->get_mg_dof_indices(level_dofs);
          cell->get_dof_indices(active_dofs);
          for (unsigned int i = 0; i < level_dofs.size(); ++i)
            if (active_partitioner->in_local_range(active_dofs[i]))
              active[active_dofs[i]] = level_vector.local_element(
                level_partitioner.global_to_local(level_dofs[i]));
        }
    // (kept ghosted: for FEValues and DataOut)
    active.update_ghost_values();
    return active;
  }

  template class Discretization<2>;
  template class Discretization<3>;
} // namespace FoslsContact
