// Checks the DoF roles, fixed values and upper bounds that
// Discretization<dim> sets up on every level (the constraints of K_J,
// paper section 4.1), for prm/square.prm at 3 levels:
//  - the number of fixed / bounded / free DoFs on each level against the
//    counts for an n x n mesh (top Dirichlet vertices, left/right Neumann
//    faces, bottom contact vertices and faces);
//  - upper bounds: the gap at contact vertices, 0 for the normal stress of
//    contact faces, +inf for every other DoF;
//  - fixed values: the Dirichlet data at Dirichlet vertices, the face mean
//    of the traction on Neumann faces (value times the basis function's
//    mean normal component), 0 for tangential contact stresses;
// with the data of square.prm and with non-constant data (linear Dirichlet
// values, traction and gap), and for a roller (Dirichlet components = 1).
// Runs on one MPI process, which owns every DoF (local indices of LevelData
// = global ones): the counts are those of the whole mesh.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <fosls_contact/discretization/discretization.h>

#include "tests.h"

using namespace FoslsContactTests;

void
test(const std::string &                                     name,
     const std::vector<std::pair<std::string, std::string>> &overrides,
     const bool                                              roller)
{
  std::cout << "--- " << name << std::endl;
  auto all = overrides;
  all.emplace_back("Geometry/Levels", "3");
  const auto              parameters = make_parameters(scene_file("square.prm"), all);
  const Scene<2>          scene(parameters);
  const Discretization<2> discretization(scene, 3, MPI_COMM_WORLD);
  const auto &            fe = discretization.get_fe();

  const QGauss<1> face_quadrature(3);
  FEFaceValues<2> fe_face(discretization.get_mapping(),
                          fe,
                          face_quadrature,
                          update_values | update_normal_vectors |
                            update_quadrature_points | update_JxW_values);
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  Vector<double>                       values(2);

  for (unsigned int l = 0; l < discretization.n_levels(); ++l)
    {
      const auto &       data = discretization.level(l);
      const unsigned int n    = 1u << l;
      unsigned int       n_fixed = 0, n_bounded = 0, n_free = 0;
      for (const auto r : data.role)
        (r == DoFRole::fixed ? n_fixed : r == DoFRole::bounded ? n_bounded : n_free)++;
      std::cout << "level " << l + 1 << ": " << data.n_dofs << " DoFs, "
                << n_fixed << " fixed, " << n_bounded << " bounded, " << n_free
                << " free" << std::endl;
      const unsigned int n_vertices = (n + 1) * (n + 1), n_faces = 2 * n * (n + 1);
      // top: 2 (roller: 1) components at n+1 vertices, and for the
      // roller the x traction on n faces; left/right: 2 rows on 2n faces;
      // bottom: the tangential row on n faces
      const unsigned int expected_fixed =
        (roller ? (n + 1) + n : 2 * (n + 1)) + 4 * n + n;
      const unsigned int expected_bounded = n + (n + 1);
      check(data.n_dofs == 2 * n_vertices + 2 * n_faces && n_fixed == expected_fixed &&
              n_bounded == expected_bounded &&
              n_free == data.n_dofs - expected_fixed - expected_bounded,
            "level " + std::to_string(l + 1) + ": role counts");

      // upper bounds and fixed values, DoF by DoF
      // (LevelData: roles, bounds, fixed values and DoF maps in local indices)
      std::vector<bool> seen_bound(data.n_local(), false), seen_fixed(data.n_local(), false);
      double            bound_error = 0, dirichlet_error = 0, traction_error = 0,
             tangential_error = 0;
      for (const auto &cv : data.contact_vertices)
        {
          bound_error = std::max(bound_error,
                                 std::abs(data.upper_bounds.local_element(cv.normal_dof) -
                                          scene.gap().value(cv.point)));
          seen_bound[cv.normal_dof] = true;
        }
      for (const auto &cf : data.contact_faces)
        {
          bound_error =
            std::max(bound_error, std::abs(data.upper_bounds.local_element(cf.normal_dof)));
          seen_bound[cf.normal_dof] = true;
        }
      for (const auto &cell :
           discretization.get_dof_handler().mg_cell_iterators_on_level(l))
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const auto face = cell->face(f);
            const auto id   = face->boundary_id();
            cell->get_mg_dof_indices(cell_dofs);
            const auto &face_rt = data.face_dofs.at(face->index());
            if (scene.is_dirichlet(id))
              for (const unsigned int v : face->vertex_indices())
                {
                  scene.dirichlet_values().vector_value(face->vertex(v), values);
                  const auto &dofs = data.vertex_dofs.at(face->vertex_index(v));
                  for (unsigned int k = (roller ? 1 : 0); k < 2; ++k)
                    {
                      dirichlet_error = std::max(
                        dirichlet_error,
                        std::abs(data.fixed_values.local_element(dofs[k]) - values[k]));
                      seen_fixed[dofs[k]] = true;
                    }
                }
            if (scene.is_neumann(id) || (roller && scene.is_dirichlet(id)))
              {
                // the face mean of the traction, from the fixed value
                fe_face.reinit(cell, f);
                for (unsigned int m = 0; m < (scene.is_neumann(id) ? 2 : 1); ++m)
                  {
                    // (the cell's DoF indices are global ones)
                    const unsigned int local =
                      std::find(cell_dofs.begin(), cell_dofs.end(), data.global(face_rt[m])) -
                      cell_dofs.begin();
                    const FEValuesExtractors::Vector row(2 + 2 * m);
                    double mean_phi_n = 0, mean_t = 0, area = 0;
                    for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                      {
                        mean_phi_n += fe_face[row].value(local, q) *
                                      fe_face.normal_vector(q) * fe_face.JxW(q);
                        mean_t += scene.traction().value(fe_face.quadrature_point(q), m) *
                                  fe_face.JxW(q);
                        area += fe_face.JxW(q);
                      }
                    traction_error =
                      std::max(traction_error,
                               std::abs(data.fixed_values.local_element(face_rt[m]) *
                                          mean_phi_n / area -
                                        mean_t / area));
                    seen_fixed[face_rt[m]] = true;
                  }
              }
            if (scene.is_contact(id))
              {
                tangential_error =
                  std::max(tangential_error,
                           std::abs(data.fixed_values.local_element(face_rt[1])));
                seen_fixed[face_rt[1]] = true;
              }
          }
      bool bounds_ok = true, fixed_ok = true;
      for (unsigned int i = 0; i < data.n_local(); ++i)
        {
          bounds_ok &= seen_bound[i] == (data.role[i] == DoFRole::bounded);
          if (!seen_bound[i])
            bounds_ok &= std::isinf(data.upper_bounds.local_element(i)) &&
                         data.upper_bounds.local_element(i) > 0;
          fixed_ok &= seen_fixed[i] == (data.role[i] == DoFRole::fixed);
        }
      check(bounds_ok && bound_error < 1e-15,
            "level " + std::to_string(l + 1) +
              ": bounds: gap at contact vertices, 0 at contact faces, inf elsewhere");
      check(fixed_ok, "level " + std::to_string(l + 1) +
                        ": fixed DoFs are exactly the Dirichlet, traction and "
                        "tangential contact DoFs");
      check(dirichlet_error < 1e-15,
            "level " + std::to_string(l + 1) + ": fixed displacements = Dirichlet data");
      check(traction_error < 1e-13 && tangential_error == 0.,
            "level " + std::to_string(l + 1) +
              ": fixed stresses = face mean of the traction, 0 tangential on Gamma_C");
    }
}


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  test("square.prm", {}, false);
  test("square.prm with linear data",
       {{"Data/Dirichlet values", "0.002*x; -0.01 + 0.003*x"},
        {"Data/Traction", "0.1*y; -0.2*y + 0.05"},
        {"Data/Gap", "0.001 + 0.002*x"}},
       false);
  test("square.prm with a roller on top (Dirichlet components = 1)",
       {{"Boundary conditions/Dirichlet components", "1"},
        {"Data/Dirichlet values", "0.5; -0.01 + 0.003*x"},
        {"Data/Traction", "0.1*y + 0.2*x; -0.2*y + 0.05"}},
       true);
  return exit_code();
}
