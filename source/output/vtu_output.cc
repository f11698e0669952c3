#include <deal.II/numerics/data_out.h>

#include <fosls_contact/output/active_fields_buffer.h>
#include <fosls_contact/output/contact_surface.h>
#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/stress_fields.h>
#include <fosls_contact/output/vtu_output.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    /**
     * Name the active fields of a pvtu record: VTK's filters (warp by
     * vector, glyphs) use the active vector, which deal.II leaves unset
     * (its header says Scalars="scalars", a field that does not exist).
     * The pieces get the same from ActiveFieldsBuffer.
     */
    std::string
    with_active_fields(std::string text, const std::string &active)
    {
      const std::string tag = "<PPointData Scalars=\"scalars\">";
      const auto        at  = text.find(tag);
      if (at != std::string::npos)
        text.replace(at, tag.size(), "<PPointData " + active + ">");
      return text;
    }
  } // namespace


  template <int dim>
  VtuOutput<dim>::VtuOutput(const Discretization<dim> &  discretization,
                            const Parameters::Material & material,
                            const PhysicalMapping<dim> & mapping,
                            const FrictionTerms *        friction)
    : discretization(discretization)
    , material(material)
    , scaling(discretization.get_scene().scaling())
    , mapping(mapping)
    , friction(friction)
  {}


  template <int dim>
  void
  VtuOutput<dim>::write(const LevelVector &         x,
                        const LevelVector &         solution,
                        const ErrorIndicators<dim> &indicators,
                        OutputDirectory &           output,
                        const unsigned int          step) const
  {
    const MPI_Comm    comm     = discretization.get_communicator();
    const auto &      scene    = discretization.get_scene();
    DataOut<dim>      data_out;
    data_out.attach_dof_handler(discretization.get_dof_handler());
    // u, and sigma as computed (not exactly symmetric: paper section 2)
    std::vector<std::string> names(dim, "u");
    names.resize(dim + dim * dim, "sigma");
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    interpretation.resize(dim + dim * dim, DataComponentInterpretation::component_is_part_of_tensor);
    data_out.add_data_vector(solution, names, DataOut<dim>::type_dof_data, interpretation);
    StressFields<dim> stress(scene, material);
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
    // (the rows of contact.csv at this process's contact vertices: one
    // decision of which vertex is in contact for the cells' status and
    // the contact surface)
    const auto rows = ContactTable<dim>(discretization, friction).local_rows(x);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto it = rows.find(cell->vertex_index(v));
            if (it != rows.end())
              status[cell->active_cell_index()] =
                std::max<float>(status[cell->active_cell_index()],
                                it->second[ContactRow<dim>::in_contact] == 1 ? 2.f : 1.f);
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
    DataOutBase::VtkFlags flags(step /* time */, step /* cycle */);
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    const auto numbered = [](const std::string &name, const unsigned int s) {
      return name + "_" + Utilities::int_to_string(s, 4);
    };
    write_pieces(data_out,
                 numbered("solution", step),
                 "Scalars=\"von_mises\" Vectors=\"u\" Tensors=\"stress\"",
                 output);
    // the series ParaView opens in one go: for each step (an adaptive
    // run's meshes, as time steps) the body and, as a second part of the
    // same step, the contact surface (a multiblock data set)
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      output.write("solution.pvd", [&](std::ostream &out) {
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n";
        for (unsigned int s = 0; s <= step; ++s)
          {
            out << "    <DataSet timestep=\"" << s << "\" group=\"\" part=\"0\" name=\"body\" "
                << "file=\"" << numbered("solution", s) << ".pvtu\"/>\n";
            if (scene.has_contact())
              out << "    <DataSet timestep=\"" << s
                  << "\" group=\"\" part=\"1\" name=\"contact surface\" "
                  << "file=\"" << numbered("contact_surface", s) << ".pvtu\"/>\n";
          }
        out << "  </Collection>\n</VTKFile>\n";
      });

    if (scene.has_contact())
      {
        ContactSurface<dim>                  surface(scene);
        typename ContactSurface<dim>::Fields fields(scene, rows, friction != nullptr);
        surface.attach_dof_handler(discretization.get_dof_handler());
        surface.add_data_vector(solution, fields);
        // (with the mapping of the computation)
        surface.build_patches(mapping);
        surface.set_flags(flags);
        write_pieces(surface,
                     numbered("contact_surface", step),
                     "Scalars=\"contact_pressure\"",
                     output);
      }
  }


  template <int dim>
  template <typename Writer>
  void
  VtuOutput<dim>::write_pieces(Writer &           writer,
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
      ActiveFieldsBuffer buffer(out, active);
      std::ostream       piece_stream(&buffer);
      writer.write_vtu(piece_stream);
      buffer.finish();
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


  template class VtuOutput<2>;
  template class VtuOutput<3>;
} // namespace FoslsContact
