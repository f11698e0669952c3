// Checks the change to normal-tangential coordinates of paper section 4.3:
//  - NormalTangentialBasis<dim>::householder(n) for tilted normals (and the
//    special cases n = +-e_1) in 2D and 3D: H is symmetric, orthogonal and
//    H e_1 = n;
//  - on a square / cube / half disc with a tilted obstacle (Obstacle normal
//    "0.3; -1" resp. "0.3; 0.2; -1", normalized by the program), and on a
//    square with contact on its right side (normal "1; 0.3"), on every
//    level and for every contact face: the block is Q_phi = H/c with c the
//    mean normal component of the face's RT basis function, computed here
//    with FEFaceValues (c < 0 on bottom faces, c > 0 on the right side,
//    where the basis functions point outward); for a constant stress
//    sigma_0 whose face coefficients reproduce sigma_0 n_body on the face
//    (checked by evaluating the field), the rotated coordinates are the
//    normal traction
//    (sigma_0 n_body).n_o and the tangential ones (sigma_0 n_body).(H e_k);
//  - every contact vertex block is H(n_o) with the bound u.n_o <= g;
//  - roles and bounds: the normal face DoF is bounded by 0, the tangential
//    face DoFs are fixed at 0, the normal vertex DoF is bounded by the gap;
//  - rotate_to_cartesian o rotate_to_normal_tangential = identity (on
//    LevelVectors).
// Runs on one MPI process, which owns every DoF (local indices of LevelData
// = global ones).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/normal_tangential_basis.h>

#include "tests.h"

using namespace FoslsContactTests;

template <int dim>
double
matrix_difference(const FullMatrix<double> &a, const FullMatrix<double> &b)
{
  double d = 0;
  for (unsigned int i = 0; i < a.m(); ++i)
    for (unsigned int j = 0; j < a.n(); ++j)
      d = std::max(d, std::abs(a(i, j) - b(i, j)));
  return d;
}

template <int dim>
void
test_householder(const Tensor<1, dim> &direction)
{
  const Tensor<1, dim>     n = direction / direction.norm();
  const FullMatrix<double> H = NormalTangentialBasis<dim>::householder(n);
  FullMatrix<double>       HtH(dim, dim), identity(dim, dim);
  H.Tmmult(HtH, H);
  for (unsigned int i = 0; i < dim; ++i)
    identity(i, i) = 1;
  double asymmetry = 0, he1 = 0;
  for (unsigned int i = 0; i < dim; ++i)
    {
      he1 = std::max(he1, std::abs(H(i, 0) - n[i]));
      for (unsigned int j = 0; j < dim; ++j)
        asymmetry = std::max(asymmetry, std::abs(H(i, j) - H(j, i)));
    }
  std::ostringstream name;
  name << "householder(" << direction << ")";
  check(asymmetry < 1e-15 && matrix_difference<dim>(HtH, identity) < 1e-14 &&
          he1 < 1e-15,
        name.str() + ": symmetric, orthogonal, H e_1 = n");
}


template <int dim>
void
test_tilted_scene(const std::string &                              file,
                  const std::string &                              normal,
                  const unsigned int                               n_levels,
                  const bool                                       box,
                  std::vector<std::pair<std::string, std::string>> overrides = {},
                  const double                                     gap_shift = 0)
{
  std::cout << "--- " << dim << "D, " << file << ", tilted obstacle, normal "
            << normal << (overrides.empty() ? "" : ", contact on the right side")
            << std::endl;
  overrides.emplace_back("Geometry/Levels", std::to_string(n_levels));
  overrides.emplace_back("Data/Obstacle normal", normal);
  overrides.emplace_back("Data/Gap", std::to_string(gap_shift) + " + 0.001*x");
  const auto parameters = make_parameters(scene_file(file), overrides);
  const Scene<dim>          scene(parameters);
  const Discretization<dim> discretization(scene, n_levels, MPI_COMM_WORLD);
  const auto &              fe = discretization.get_fe();

  Tensor<1, dim> n_o;
  {
    const auto c = Utilities::split_string_list(normal, ';');
    for (unsigned int d = 0; d < dim; ++d)
      n_o[d] = Utilities::string_to_double(c[d]);
    n_o /= n_o.norm();
  }
  const FullMatrix<double> H = NormalTangentialBasis<dim>::householder(n_o);

  // a constant, non-symmetric stress
  Tensor<2, dim> sigma_0;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      sigma_0[i][j] = (i == j ? -1. - i : 0.1 * (i + 1) + 0.05 * j);

  const QGauss<dim - 1> face_quadrature(2);
  FEFaceValues<dim>     fe_face(discretization.get_mapping(),
                            fe,
                            face_quadrature,
                            update_values | update_normal_vectors |
                              update_JxW_values);
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());

  for (unsigned int l = 0; l < discretization.n_levels(); ++l)
    {
      const auto &data = discretization.level(l);
      const unsigned int n = 1u << l; // cells per side
      const unsigned int expected_faces    = dim == 2 ? n : n * n;
      const unsigned int expected_vertices = dim == 2 ? n + 1 : (n + 1) * (n + 1);
      std::cout << "level " << l + 1 << ": " << data.contact_faces.size()
                << " contact faces, " << data.contact_vertices.size()
                << " contact vertices, " << data.rotations.size()
                << " rotation blocks" << std::endl;
      if (box)
        check(data.contact_faces.size() == expected_faces &&
                data.contact_vertices.size() == expected_vertices &&
                data.rotations.size() == expected_faces + expected_vertices,
              "level " + std::to_string(l + 1) + ": contact entity counts");
      else // half disc: an arc of F faces, its two end vertices Dirichlet
        check(data.contact_vertices.size() == data.contact_faces.size() - 1 &&
                data.rotations.size() ==
                  data.contact_faces.size() + data.contact_vertices.size(),
              "level " + std::to_string(l + 1) + ": contact entity counts");

      double max_block_error = 0, max_traction_error = 0,
             max_field_error = 0, max_normal_error = 0;
      bool         roles_ok   = true;
      unsigned int faces_seen = 0, negative_c = 0;
      for (const auto &cell :
           discretization.get_dof_handler().mg_cell_iterators_on_level(l))
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
            {
              ++faces_seen;
              fe_face.reinit(cell, f);
              cell->get_mg_dof_indices(cell_dofs);
              const auto &face_rt = data.face_dofs.at(cell->face(f)->index());
              const unsigned int b = data.rotation_of_dof[face_rt[0]];
              if (b == numbers::invalid_unsigned_int)
                {
                  roles_ok = false;
                  continue;
                }
              const auto &block = data.rotations[b];

              // c_m: mean normal component of the basis function of row m
              std::array<double, dim> c;
              std::array<unsigned int, dim> local;
              double area = 0;
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                area += fe_face.JxW(q);
              for (unsigned int m = 0; m < dim; ++m)
                {
                  // (the cell's DoF indices are global, face_rt local ones)
                  local[m] = std::find(cell_dofs.begin(),
                                       cell_dofs.end(),
                                       data.global(face_rt[m])) -
                             cell_dofs.begin();
                  const FEValuesExtractors::Vector row(dim + m * dim);
                  c[m] = 0;
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    c[m] += fe_face[row].value(local[m], q) *
                            fe_face.normal_vector(q) * fe_face.JxW(q);
                  c[m] /= area;
                  // RT0 normalization: |c| = 1/|face|
                  max_block_error =
                    std::max(max_block_error, std::abs(std::abs(c[m]) * area - 1.));
                }
              const Tensor<1, dim> n_b = fe_face.normal_vector(0);
              negative_c += (c[0] < 0);

              // block = H / c
              FullMatrix<double> expected(H);
              expected *= 1. / c[0];
              max_block_error =
                std::max(max_block_error,
                         matrix_difference<dim>(block.matrix, expected) * std::abs(c[0]));
              max_normal_error = std::max(max_normal_error,
                                          (data.rotations[b].dofs[0] == face_rt[0] ? 0. : 1.));

              // Cartesian coefficients of sigma_0 on this face, checked by
              // evaluating sigma n_b with all local shape functions
              const Tensor<1, dim> t = sigma_0 * n_b;
              Vector<double>       local_values(fe.n_dofs_per_cell());
              for (unsigned int m = 0; m < dim; ++m)
                local_values[local[m]] = t[m] / c[m];
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int m = 0; m < dim; ++m)
                  {
                    const FEValuesExtractors::Vector row(dim + m * dim);
                    double value = 0;
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      value += local_values[i] * (fe_face[row].value(i, q) *
                                                  fe_face.normal_vector(q));
                    max_field_error = std::max(max_field_error, std::abs(value - t[m]));
                  }

              // rotated: (t.n_o, t.(H e_2), ...)
              LevelVector x(data.partitioner);
              for (unsigned int m = 0; m < dim; ++m)
                x.local_element(face_rt[m]) = local_values[local[m]];
              discretization.rotate_to_normal_tangential(l, x);
              for (unsigned int k = 0; k < dim; ++k)
                {
                  double expected_k = 0;
                  for (unsigned int d = 0; d < dim; ++d)
                    expected_k += H(d, k) * t[d];
                  max_traction_error =
                    std::max(max_traction_error,
                             std::abs(x.local_element(face_rt[k]) - expected_k));
                }

              // roles and bounds
              roles_ok &= data.role[face_rt[0]] == DoFRole::bounded &&
                          data.upper_bounds.local_element(face_rt[0]) == 0.;
              for (unsigned int m = 1; m < dim; ++m)
                roles_ok &= data.role[face_rt[m]] == DoFRole::fixed &&
                            data.fixed_values.local_element(face_rt[m]) == 0.;
            }
      std::cout << "level " << l + 1 << ": " << negative_c << " of " << faces_seen
                << " contact faces with c < 0" << std::endl;
      check(faces_seen == data.contact_faces.size() && roles_ok,
            "level " + std::to_string(l + 1) +
              ": faces: normal DoF bounded by 0, tangential DoFs fixed at 0");
      check(max_block_error < 1e-12 && max_normal_error == 0,
            "level " + std::to_string(l + 1) + ": face blocks are H/c, |c| = 1/|face|");
      check(max_field_error < 1e-12,
            "level " + std::to_string(l + 1) +
              ": face coefficients t_m/c reproduce sigma_0 n_body");
      check(max_traction_error < 1e-12,
            "level " + std::to_string(l + 1) +
              ": rotated face coordinates = ((sigma_0 n_b).n_o, (sigma_0 n_b).H e_k)");

      // vertices
      double max_vertex_error = 0;
      bool   vertex_roles_ok  = true;
      for (const auto &cv : data.contact_vertices)
        {
          const auto &block = data.rotations[data.rotation_of_dof[cv.normal_dof]];
          max_vertex_error =
            std::max(max_vertex_error, matrix_difference<dim>(block.matrix, H));
          max_vertex_error = std::max(max_vertex_error, (cv.normal - n_o).norm());
          vertex_roles_ok &= data.role[cv.normal_dof] == DoFRole::bounded &&
                             std::abs(data.upper_bounds.local_element(cv.normal_dof) -
                                      (gap_shift + 0.001 * cv.point[0])) < 1e-15;
          for (unsigned int k = 1; k < dim; ++k)
            vertex_roles_ok &= data.role[block.dofs[k]] == DoFRole::free;
          // u.n_o is the first rotated coordinate
          Tensor<1, dim> u;
          for (unsigned int k = 0; k < dim; ++k)
            u[k] = 0.01 * (k + 1);
          LevelVector x(data.partitioner);
          for (unsigned int k = 0; k < dim; ++k)
            x.local_element(block.dofs[k]) = u[k];
          discretization.rotate_to_normal_tangential(l, x);
          max_vertex_error =
            std::max(max_vertex_error, std::abs(x.local_element(cv.normal_dof) - u * n_o));
        }
      check(max_vertex_error < 1e-15,
            "level " + std::to_string(l + 1) +
              ": vertex blocks are H(n_o), first rotated coordinate u.n_o");
      check(vertex_roles_ok,
            "level " + std::to_string(l + 1) +
              ": vertices: normal DoF bounded by the gap, tangential DoFs free");

      // round trip
      Random      random(l + 1);
      LevelVector x(data.partitioner), y(data.partitioner);
      for (auto &v : x)
        v = random();
      y = x;
      discretization.rotate_to_normal_tangential(l, y);
      const bool changed = (LevelVector(y) -= x).linfty_norm() > 1e-3;
      discretization.rotate_to_cartesian(l, y);
      y -= x;
      check(changed && y.linfty_norm() < 1e-13 * x.linfty_norm() * (1 << (l * (dim - 1))),
            "level " + std::to_string(l + 1) +
              ": rotate_to_cartesian o rotate_to_normal_tangential = identity");
    }
}


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  test_householder<2>(Point<2>(0.3, -1.));
  test_householder<2>(Point<2>(0., -1.));
  test_householder<2>(Point<2>(1., 0.));
  test_householder<2>(Point<2>(-1., 0.));
  test_householder<2>(Point<2>(-1., 1e-9));
  test_householder<3>(Point<3>(0.3, 0.2, -1.));
  test_householder<3>(Point<3>(0., 0., -1.));
  test_householder<3>(Point<3>(1., 0., 0.));
  test_householder<3>(Point<3>(-1., 0., 0.));
  test_householder<3>(Point<3>(-0.5, 2., 1.));

  test_tilted_scene<2>("square.prm", "0.3; -1", 3, true);
  test_tilted_scene<3>("cube3d.prm", "0.3; 0.2; -1", 3, true);
  // contact on the right side: the RT basis functions point outward (c > 0)
  test_tilted_scene<2>("square.prm",
                       "1; 0.3",
                       3,
                       true,
                       {{"Boundary conditions/Dirichlet boundary ids", "0"},
                        {"Boundary conditions/Neumann boundary ids", "2, 3"},
                        {"Boundary conditions/Contact boundary ids", "1"}});
  // The half disc's Dirichlet ends (0, -0.01) lie on the contact boundary:
  // a gap of 0.001 x would put them into the obstacle, which Discretization
  // refuses.
  test_tilted_scene<2>("hertz.prm", "0.3; -1", 2, false, {}, 0.5);
  return exit_code();
}
