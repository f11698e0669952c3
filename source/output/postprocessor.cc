#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fosls_contact/output/contact_surface.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/output/stress_fields.h>
#include <fosls_contact/output/stress_measures.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace FoslsContact
{


  template <int dim>
  Postprocessor<dim>::Postprocessor(const Discretization<dim> &       discretization,
                                    const Parameters::AllParameters &parameters)
    : discretization(discretization)
    , parameters(parameters)
    , scaling(discretization.get_scene().scaling())
    , mapping(dynamic_cast<const MappingQ<dim> &>(discretization.get_mapping()).get_degree(),
              scaling.length)
  {}


  template <int dim>
  LevelVector
  Postprocessor<dim>::solution_in_scene_units(const LevelVector &x_rotated) const
  {
    // (a rotation block is the DoFs of one vertex or face, of one owner:
    // to_active() brings the owners' rotated values to the ghost copies)
    LevelVector x = x_rotated;
    discretization.rotate_to_cartesian(discretization.finest_level(), x);
    LevelVector active = discretization.to_active(x);
    if (scaling.length == 1. && scaling.stress == 1.)
      return active;
    // with the PhysicalMapping: displacements (nodal values) times L,
    // stresses (Raviart-Thomas fluxes) times S L^(dim-1)
    const auto &    dof_handler = discretization.get_dof_handler();
    const IndexSet  displacement_dofs =
      DoFTools::extract_dofs(dof_handler,
                             discretization.get_fe().component_mask(
                               FEValuesExtractors::Vector(0)));
    const double    u_factor = scaling.length, sigma_factor = scaling.force(dim);
    const IndexSet &owned    = dof_handler.locally_owned_dofs();
    for (const auto i : owned)
      active[i] *= displacement_dofs.is_element(i) ? u_factor : sigma_factor;
    active.update_ghost_values();
    return active;
  }


  template <int dim>
  Tensor<1, dim>
  Postprocessor<dim>::contact_force(const LevelVector &solution) const
  {
    const auto &          scene = discretization.get_scene();
    Tensor<1, dim>        force;
    if (!scene.has_contact())
      return force;
    const QGauss<dim - 1> quadrature(3);
    FEFaceValues<dim>     fe_face(mapping,
                              discretization.get_fe(),
                              quadrature,
                              update_values | update_normal_vectors |
                                update_JxW_values);
    std::vector<Vector<double>> values(quadrature.size(),
                                       Vector<double>(dim + dim * dim));
    for (const auto &cell :
         discretization.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
          {
            fe_face.reinit(cell, f);
            fe_face.get_function_values(solution, values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int m = 0; m < dim; ++m)
                for (unsigned int k = 0; k < dim; ++k)
                  force[m] += values[q][dim + m * dim + k] *
                              fe_face.normal_vector(q)[k] * fe_face.JxW(q);
          }
    return Utilities::MPI::sum(force, discretization.get_communicator());
  }


  template <int dim>
  ErrorNorms
  Postprocessor<dim>::errors(const LevelVector &solution) const
  {
    const auto &scene = discretization.get_scene();
    ErrorNorms  e;
    if (!scene.has_exact_solution())
      return e;
    const QGauss<dim> quadrature(4);
    FEValues<dim>     fe_values(mapping,
                            discretization.get_fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               nq = quadrature.size();
    std::vector<Tensor<1, dim>>      u(nq);
    std::vector<Tensor<2, dim>>      grad_u(nq);
    std::vector<Tensor<1, dim>>      row(nq);
    std::vector<double>              div(nq);
    const Function<dim> *            exact_sigma = scene.exact_stress();

    for (const auto &cell :
         discretization.get_dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, u);
        fe_values[displacement].get_function_gradients(solution, grad_u);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<dim> &p = fe_values.quadrature_point(q);
            for (unsigned int k = 0; k < dim; ++k)
              {
                const double           du = scene.exact_displacement().value(p, k) - u[q][k];
                const Tensor<1, dim> dg =
                  scene.exact_displacement().gradient(p, k) - grad_u[q][k];
                e.u_l2 += du * du * fe_values.JxW(q);
                e.u_h1_semi += dg * dg * fe_values.JxW(q);
              }
          }
        if (exact_sigma == nullptr)
          continue;
        for (unsigned int m = 0; m < dim; ++m)
          {
            const FEValuesExtractors::Vector sigma_row(dim + m * dim);
            fe_values[sigma_row].get_function_values(solution, row);
            fe_values[sigma_row].get_function_divergences(solution, div);
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<dim> &p         = fe_values.quadrature_point(q);
                double            exact_div = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  {
                    const double ds =
                      exact_sigma->value(p, m * dim + k) - row[q][k];
                    e.sigma_l2 += ds * ds * fe_values.JxW(q);
                    exact_div += exact_sigma->gradient(p, m * dim + k)[k];
                  }
                e.sigma_div += (exact_div - div[q]) * (exact_div - div[q]) *
                               fe_values.JxW(q);
              }
          }
      }
    const MPI_Comm comm = discretization.get_communicator();
    e.u_l2      = std::sqrt(Utilities::MPI::sum(e.u_l2, comm));
    e.u_h1_semi = std::sqrt(Utilities::MPI::sum(e.u_h1_semi, comm));
    e.sigma_l2  = std::sqrt(Utilities::MPI::sum(e.sigma_l2, comm));
    e.sigma_div = std::sqrt(Utilities::MPI::sum(e.sigma_div, comm));
    return e;
  }


  template <int dim>
  FieldMaxima
  Postprocessor<dim>::field_maxima(const LevelVector &solution) const
  {
    const QTrapezoid<dim>            corners;
    FEValues<dim>                    fe_values(mapping,
                            discretization.get_fe(),
                            corners,
                            update_values);
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = corners.size();
    std::vector<Tensor<1, dim>>      u(n), row(n);
    std::vector<Tensor<2, dim>>      sigma(n);
    FieldMaxima                      maxima;
    for (const auto &cell : discretization.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(solution, u);
          for (unsigned int m = 0; m < dim; ++m)
            {
              fe_values[FEValuesExtractors::Vector(dim + m * dim)].get_function_values(solution,
                                                                                     row);
              for (unsigned int q = 0; q < n; ++q)
                sigma[q][m] = row[q];
            }
          for (unsigned int q = 0; q < n; ++q)
            {
              maxima.displacement = std::max(maxima.displacement, u[q].norm());
              maxima.von_mises =
                std::max(maxima.von_mises,
                         StressMeasures::von_mises(sigma[q], parameters.material.poisson_ratio));
            }
        }
    const MPI_Comm comm = discretization.get_communicator();
    maxima.displacement = Utilities::MPI::max(maxima.displacement, comm);
    maxima.von_mises    = Utilities::MPI::max(maxima.von_mises, comm);
    return maxima;
  }


  template <int dim>
  std::vector<typename ContactRow<dim>::Values>
  Postprocessor<dim>::contact_rows(const LevelVector &x) const
  {
    using Row         = ContactRow<dim>;
    const auto &level = discretization.level(discretization.finest_level());
    update_ghosts(x);
    // the displacement in Cartesian coordinates, at the vertices
    LevelVector cartesian = x;
    discretization.rotate_to_cartesian(discretization.finest_level(), cartesian);
    // sigma_nn at a vertex: mean over the contact faces that contain it
    // (all of them are here for an owned vertex)
    std::map<unsigned int, std::pair<double, unsigned int>> face_mean;
    for (const auto &cell : discretization.get_dof_handler()
                              .mg_cell_iterators_on_level(discretization.finest_level()))
      if (Discretization<dim>::is_present(cell))
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              discretization.get_scene().is_contact(cell->face(f)->boundary_id()))
            {
              const auto   face = cell->face(f);
              const double s = x.local_element(level.face_dofs.at(face->index())[0]);
              for (const unsigned int v : face->vertex_indices())
                {
                  auto &entry = face_mean[face->vertex_index(v)];
                  entry.first += s;
                  entry.second += 1;
                }
            }
    std::vector<typename Row::Values> rows;
    for (const auto &cv : level.contact_vertices)
      if (cv.owned)
        {
          const double un = x.local_element(cv.normal_dof);
          const auto   it = face_mean.find(cv.vertex_index);
          const double snn =
            it == face_mean.end() ? 0. : it->second.first / it->second.second;
          const auto &          dofs = level.vertex_dofs.at(cv.vertex_index);
          typename Row::Values row;
          for (unsigned int d = 0; d < dim; ++d)
            {
              row[Row::x + d] = scaling.length * cv.point[d];
              row[Row::u + d] = scaling.length * cartesian.local_element(dofs[d]);
            }
          row[Row::u_n]      = scaling.length * un;
          row[Row::gap]      = scaling.length * cv.gap;
          row[Row::sigma_nn] = scaling.stress * snn;
          row[Row::active]   = un >= cv.gap - 1e-12 * std::max(1., std::abs(cv.gap)) ? 1 : 0;
          rows.push_back(row);
        }
    const auto all = Utilities::MPI::gather(discretization.get_communicator(), rows, 0);
    rows.clear();
    for (const auto &part : all)
      rows.insert(rows.end(), part.begin(), part.end());
    std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) {
      return std::lexicographical_compare(a.begin(), a.begin() + dim, b.begin(), b.begin() + dim);
    });
    return rows;
  }


  template <int dim>
  std::string
  Postprocessor<dim>::contact_table(const LevelVector &x) const
  {
    const auto         rows = contact_rows(x);
    std::ostringstream out;
    if (Utilities::MPI::this_mpi_process(discretization.get_communicator()) != 0)
      return out.str();
    out << (dim == 2 ? "x,y,u_x,u_y" : "x,y,z,u_x,u_y,u_z") << ",u_n,gap,sigma_nn,active\n";
    out << std::setprecision(10);
    for (const auto &row : rows)
      {
        for (unsigned int d = 0; d < ContactRow<dim>::active; ++d)
          out << row[d] << ',';
        out << int(row[ContactRow<dim>::active]) << '\n';
      }
    return out.str();
  }


  template <int dim>
  void
  Postprocessor<dim>::write(const LevelVector &                        x,
                            const Monitor &                            monitor,
                            const std::map<std::string, std::string> &summary,
                            const std::string &                        used_parameters,
                            const ErrorIndicators<dim> &               indicators,
                            OutputDirectory &                          output) const
  {
    const MPI_Comm     comm  = discretization.get_communicator();
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const std::string  table = contact_table(x); // (collective)
    // every process writes its files into the staging directory; a
    // failure (a full disk) is collected, so that every process reaches
    // publish(), which then publishes nothing and stops all of them
    std::string error;
    try
      {
        if (parameters.output.write_vtu)
          write_vtu(x, indicators, output);
        if (rank == 0)
          {
            output.write("contact.csv", [&](std::ostream &out) { out << table; });
            output.write("convergence.csv", [&](std::ostream &out) { out << monitor.csv(); });
            output.write("used_parameters.prm",
                         [&](std::ostream &out) { out << used_parameters; });
            output.write("summary.json", [&](std::ostream &out) {
              out << "{\n";
              bool first = true;
              for (const auto &[key, value] : summary)
                {
                  out << (first ? "" : ",\n") << "  \"" << key << "\": " << value;
                  first = false;
                }
              out << "\n}\n";
            });
          }
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    output.publish(error);
  }


  namespace
  {
    /**
     * Name the active fields of a VTU piece or record: VTK's filters (warp
     * by vector, glyphs) use the active vector, which deal.II leaves unset
     * (its header says Scalars="scalars", a field that does not exist).
     */
    std::string
    with_active_fields(std::string text, const std::string &active)
    {
      for (const std::string tag : {"<PPointData Scalars=\"scalars\">",
                                    "<PointData Scalars=\"scalars\">"})
        {
          const auto at = text.find(tag);
          if (at != std::string::npos)
            {
              const std::string element = tag.substr(0, tag.find(' '));
              text.replace(at, tag.size(), element + " " + active + ">");
              break;
            }
        }
      return text;
    }
  } // namespace


  template <int dim>
  void
  Postprocessor<dim>::write_vtu(const LevelVector &           x,
                                const ErrorIndicators<dim> &indicators,
                                OutputDirectory &             output) const
  {
    const MPI_Comm    comm     = discretization.get_communicator();
    const auto &      scene    = discretization.get_scene();
    const LevelVector solution = solution_in_scene_units(x);
    DataOut<dim>      data_out;
    data_out.attach_dof_handler(discretization.get_dof_handler());
    // u, and sigma as computed (not exactly symmetric: paper section 2)
    std::vector<std::string> names(dim, "u");
    names.resize(dim + dim * dim, "sigma");
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    interpretation.resize(dim + dim * dim, DataComponentInterpretation::component_is_part_of_tensor);
    data_out.add_data_vector(solution, names, DataOut<dim>::type_dof_data, interpretation);
    StressFields<dim> stress(scene, parameters.material);
    data_out.add_data_vector(solution, stress);

    // cell data: the error indicator eta_T (ErrorIndicators, in the
    // scene's units: the eta_T^2 sum to J) and the contact status
    const auto &  tria = discretization.get_triangulation();
    Vector<float> eta(tria.n_active_cells()), status(tria.n_active_cells());
    const double  unit = scaling.functional(dim);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        eta[cell->active_cell_index()] =
          std::sqrt(std::max(0., unit * indicators.squared(cell->active_cell_index())));
    {
      const auto &                 level = discretization.level(discretization.finest_level());
      std::map<unsigned int, bool> active_vertex;
      // (x's ghost values: from contact_table() before)
      for (const auto &cv : level.contact_vertices)
        active_vertex[cv.vertex_index] =
          x.local_element(cv.normal_dof) >= cv.gap - 1e-12 * std::max(1., std::abs(cv.gap));
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto it = active_vertex.find(cell->vertex_index(v));
              if (it != active_vertex.end())
                status[cell->active_cell_index()] =
                  std::max<float>(status[cell->active_cell_index()], it->second ? 2.f : 1.f);
            }
    }
    data_out.add_data_vector(eta, "error_indicator", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(status, "contact_status", DataOut<dim>::type_cell_data);

    // a curved boundary (a manifold other than the flat one) is drawn
    // with a quadratic mapping of each cell, subdivided once: the
    // solution is that of the linear mapping, shown on the curved shape
    const auto manifolds = tria.get_manifold_ids();
    const bool curved    = std::any_of(manifolds.begin(), manifolds.end(), [](const auto id) {
      return id != numbers::flat_manifold_id;
    });
    const PhysicalMapping<dim> drawing(curved ? 2 : 1, scaling.length);
    data_out.build_patches(drawing, curved ? 2 : 0, DataOut<dim>::curved_boundary);
    // zlib's default level spent more time than the solve on large
    // meshes (13% of a level-8 run); best_speed files are ~10% larger
    DataOutBase::VtkFlags flags(0. /* time */, 0 /* cycle */);
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    write_pieces(data_out,
                 "solution_0000",
                 "Scalars=\"von_mises\" Vectors=\"u\" Tensors=\"stress\"",
                 output);
    // the series ParaView opens in one go: the body and, as a second part
    // of the same step, the contact surface (a multiblock data set)
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      output.write("solution.pvd", [&](std::ostream &out) {
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n"
            << "    <DataSet timestep=\"0\" group=\"\" part=\"0\" name=\"body\" "
               "file=\"solution_0000.pvtu\"/>\n";
        if (scene.has_contact())
          out << "    <DataSet timestep=\"0\" group=\"\" part=\"1\" name=\"contact surface\" "
                 "file=\"contact_surface_0000.pvtu\"/>\n";
        out << "  </Collection>\n</VTKFile>\n";
      });

    if (scene.has_contact())
      {
        ContactSurface<dim>                 surface(scene);
        typename ContactSurface<dim>::Fields fields(scene);
        surface.attach_dof_handler(discretization.get_dof_handler());
        surface.add_data_vector(solution, fields);
        // (with the mapping of the computation: the gap g - u.n is that of
        // the solution's own geometry, 0 where the body touches)
        surface.build_patches(mapping);
        surface.set_flags(flags);
        write_pieces(surface, "contact_surface_0000", "Scalars=\"contact_pressure\"", output);
      }
  }


  template <int dim>
  template <typename Writer>
  void
  Postprocessor<dim>::write_pieces(Writer &           writer,
                                   const std::string &name,
                                   const std::string &active,
                                   OutputDirectory &  output) const
  {
    // one piece per process, listed by the record the first process writes
    const MPI_Comm     comm  = discretization.get_communicator();
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const auto         piece = [&](const unsigned int p) {
      return name + "." + std::to_string(p) + ".vtu";
    };
    output.write(piece(rank), [&](std::ostream &out) {
      std::ostringstream text;
      writer.write_vtu(text);
      out << with_active_fields(text.str(), active);
    });
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int p = 0; p < Utilities::MPI::n_mpi_processes(comm); ++p)
          pieces.push_back(piece(p));
        output.write(name + ".pvtu", [&](std::ostream &out) {
          std::ostringstream text;
          writer.write_pvtu_record(text, pieces);
          out << with_active_fields(text.str(), active);
        });
      }
  }


  template class Postprocessor<2>;
  template class Postprocessor<3>;
} // namespace FoslsContact
