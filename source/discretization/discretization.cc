#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/multigrid/mg_tools.h>

#include <fosls_contact/discretization/discretization.h>

#include <set>

namespace FoslsContact
{
  template <int dim>
  Discretization<dim>::Discretization(const Scene<dim> &scene,
                                      const unsigned int n_levels)
    : scene(scene)
    , triangulation(Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(1), dim, FE_RaviartThomas<dim>(0), dim)
    , mapping(1)
  {
    scene.make_coarse_mesh(triangulation);
    coarse_ratio = Scene<dim>::mesh_size_ratio(triangulation);
    triangulation.refine_global(n_levels - 1);

    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    dof_handler.distribute_mg_dofs();

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
    if (norm < 1e-12)
      return H;
    w /= norm;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H(i, j) -= 2. * w[i] * w[j];
    return H;
  }


  template <int dim>
  void
  Discretization<dim>::setup_level(const unsigned int l)
  {
    LevelData<dim> &data = levels[l];
    data.n_dofs          = dof_handler.n_dofs(l);
    data.role.assign(data.n_dofs, DoFRole::free);
    data.fixed_values.reinit(data.n_dofs);
    data.upper_bounds.reinit(data.n_dofs);
    data.upper_bounds.add(std::numeric_limits<double>::infinity());
    data.rotation_of_dof.assign(data.n_dofs, numbers::invalid_unsigned_int);

    {
      DynamicSparsityPattern dsp(data.n_dofs, data.n_dofs);
      MGTools::make_sparsity_pattern(dof_handler, dsp, l);
      data.sparsity.copy_from(dsp);
    }

    // Which DoF is which: the base element (0 = Q1^d, 1 = RT0^d), its copy
    // (displacement component or stress row) and the vertex or face.
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      {
        cell->get_mg_dof_indices(dofs);
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

    const QGauss<dim - 1>   face_quadrature(3);
    FEFaceValues<dim>       fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_normal_vectors |
                                update_quadrature_points | update_JxW_values);
    const std::vector<bool> &mask = scene.dirichlet_components();

    std::set<unsigned int>                     dirichlet_vertices;
    std::map<unsigned int, Point<dim>>         contact_vertex_points;
    Vector<double>                             values(dim);

    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->at_boundary(f))
            continue;
          const auto                    face = cell->face(f);
          const types::boundary_id      id   = face->boundary_id();
          const auto &face_rt = data.face_dofs.at(face->index());

          // RT DoF of stress row m on this face: its normal component times
          // the outward normal, at the face quadrature points.
          fe_face.reinit(cell, f);
          std::array<unsigned int, dim> local_rt;
          {
            std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
            cell->get_mg_dof_indices(cell_dofs);
            for (unsigned int m = 0; m < dim; ++m)
              local_rt[m] = std::find(cell_dofs.begin(), cell_dofs.end(),
                                      face_rt[m]) - cell_dofs.begin();
          }
          auto normal_component = [&](const unsigned int m,
                                      const unsigned int q) {
            const FEValuesExtractors::Vector row(dim + m * dim);
            return fe_face[row].value(local_rt[m], q) *
                   fe_face.normal_vector(q);
          };

          // Prescribed traction, component m, as the L2 projection onto the
          // face's normal-flux basis function: it is essential here.
          auto fix_traction = [&](const unsigned int m) {
            double num = 0, den = 0;
            for (unsigned int q = 0; q < face_quadrature.size(); ++q)
              {
                const double phi_n = normal_component(m, q);
                num += scene.traction().value(fe_face.quadrature_point(q), m) *
                       phi_n * fe_face.JxW(q);
                den += phi_n * phi_n * fe_face.JxW(q);
              }
            data.role[face_rt[m]]         = DoFRole::fixed;
            data.fixed_values[face_rt[m]] = num / den;
          };

          if (scene.is_dirichlet(id))
            {
              for (const unsigned int v : face->vertex_indices())
                {
                  const unsigned int vi = face->vertex_index(v);
                  dirichlet_vertices.insert(vi);
                  scene.dirichlet_values().vector_value(face->vertex(v), values);
                  for (unsigned int k = 0; k < dim; ++k)
                    if (mask[k])
                      {
                        const auto dof        = data.vertex_dofs.at(vi)[k];
                        data.role[dof]         = DoFRole::fixed;
                        data.fixed_values[dof] = values[k];
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
                contact_vertex_points[face->vertex_index(v)] = face->vertex(v);

              // Q_phi = H_phi / c with c the mean normal component of the
              // face's basis function (+-1/|face|): then the first rotated
              // coordinate is the mean normal traction (sigma n).n on the
              // face, whatever the sign of the RT orientation.
              double area = 0, c = 0;
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  area += fe_face.JxW(q);
                  c += normal_component(0, q) * fe_face.JxW(q);
                }
              c /= area;
              const Tensor<1, dim> n = scene.obstacle_normal(face->center());
              RotationBlock<dim>   block;
              block.dofs   = face_rt;
              block.matrix = householder(n);
              block.inverse = block.matrix;
              block.matrix *= 1. / c;
              block.inverse *= c;
              const unsigned int b = data.rotations.size();
              data.rotations.push_back(block);
              for (unsigned int m = 0; m < dim; ++m)
                {
                  data.rotation_of_dof[face_rt[m]] = b;
                  data.role[face_rt[m]]            = DoFRole::fixed; // tangential
                  data.fixed_values[face_rt[m]]    = 0;
                }
              data.role[face_rt[0]]         = DoFRole::bounded;
              data.upper_bounds[face_rt[0]] = 0.;
              data.contact_faces.push_back(
                {face->index(), face_rt[0], face->center(), n, area});
            }
        }

    // Contact vertices: those of contact faces that are not Dirichlet
    // vertices (where the prescribed displacement wins).
    for (const auto &[vi, p] : contact_vertex_points)
      {
        if (dirichlet_vertices.count(vi))
          continue;
        const Tensor<1, dim> n = scene.obstacle_normal(p);
        RotationBlock<dim>   block;
        block.dofs    = data.vertex_dofs.at(vi);
        block.matrix  = householder(n);
        block.inverse = block.matrix;
        const unsigned int b = data.rotations.size();
        data.rotations.push_back(block);
        for (unsigned int k = 0; k < dim; ++k)
          data.rotation_of_dof[block.dofs[k]] = b;
        data.role[block.dofs[0]]         = DoFRole::bounded;
        const double g                   = scene.gap().value(p);
        data.upper_bounds[block.dofs[0]] = g;
        data.contact_vertices.push_back({vi, block.dofs[0], p, n, g});
      }
  }


  template <int dim>
  void
  Discretization<dim>::apply_rotations(const unsigned int l,
                                       Vector<double> &   x,
                                       const bool         inverse) const
  {
    Vector<double> in(dim), out(dim);
    for (const auto &block : levels[l].rotations)
      {
        for (unsigned int k = 0; k < dim; ++k)
          in[k] = x[block.dofs[k]];
        (inverse ? block.inverse : block.matrix).vmult(out, in);
        for (unsigned int k = 0; k < dim; ++k)
          x[block.dofs[k]] = out[k];
      }
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_cartesian(const unsigned int l,
                                           Vector<double> &   x) const
  {
    apply_rotations(l, x, false);
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_normal_tangential(const unsigned int l,
                                                   Vector<double> &   x) const
  {
    apply_rotations(l, x, true);
  }


  template <int dim>
  Vector<double>
  Discretization<dim>::to_active(const Vector<double> &level_vector) const
  {
    const unsigned int                   L = finest_level();
    Vector<double>                       active(dof_handler.n_dofs());
    std::vector<types::global_dof_index> level_dofs(fe.n_dofs_per_cell()),
      active_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(L))
      {
        const typename DoFHandler<dim>::active_cell_iterator active_cell(
          &triangulation, cell->level(), cell->index(), &dof_handler);
        cell->get_mg_dof_indices(level_dofs);
        active_cell->get_dof_indices(active_dofs);
        for (unsigned int i = 0; i < level_dofs.size(); ++i)
          active[active_dofs[i]] = level_vector[level_dofs[i]];
      }
    return active;
  }

  template class Discretization<2>;
  template class Discretization<3>;
} // namespace FoslsContact
