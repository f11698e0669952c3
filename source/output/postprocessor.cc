#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/output/stress_measures.h>
#include <fosls_contact/output/vtu_output.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    /** The norms from the squares this process integrated, @p e. */
    ErrorNorms
    norms_of_squares(ErrorNorms e, const MPI_Comm comm)
    {
      e.u_l2      = std::sqrt(Utilities::MPI::sum(e.u_l2, comm));
      e.u_h1_semi = std::sqrt(Utilities::MPI::sum(e.u_h1_semi, comm));
      e.sigma_l2  = std::sqrt(Utilities::MPI::sum(e.sigma_l2, comm));
      e.sigma_div = std::sqrt(Utilities::MPI::sum(e.sigma_div, comm));
      return e;
    }


    /**
     * The derivative in direction @p k of component @p c of @p f at @p p,
     * by fourth-order central differences with step @p h. The error
     * integration takes h a thousandth of the cell, so that the stencil
     * stays in the cell and the step follows the mesh: the fixed step of
     * the data expressions (1e-8 L) loses the derivatives of a singular
     * exact solution on the small cells at its singularity (cells of a few
     * 1e-6 L at the re-entrant corner of prm/l_shape_singular.prm: the
     * H(div) error of a good solution came out several times too large,
     * tests/solver/singular_corner), and a stencil leaving the domain can
     * cross the branch cut of an angle.
     */
    template <int dim>
    double
    derivative_in_cell(const Function<dim> &f,
                       const Point<dim> &   p,
                       const unsigned int   c,
                       const unsigned int   k,
                       const double         h)
    {
      Tensor<1, dim> e;
      e[k] = h;
      return (8. * (f.value(p + e, c) - f.value(p - e, c)) -
              (f.value(p + 2. * e, c) - f.value(p - 2. * e, c))) /
             (12. * h);
    }
  } // namespace


  template <int dim>
  Postprocessor<dim>::Postprocessor(const Discretization<dim> &       discretization,
                                    const Parameters::AllParameters &parameters,
                                    const FrictionTerms *            friction)
    : discretization(discretization)
    , parameters(parameters)
    , scaling(discretization.get_scene().scaling())
    , mapping(dynamic_cast<const MappingQ<dim> &>(discretization.get_mapping()).get_degree(),
              scaling.length)
    , friction(friction)
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
  std::map<types::boundary_id, Tensor<1, dim>>
  Postprocessor<dim>::boundary_forces(const LevelVector &solution) const
  {
    // every id of the scene, on every process (a process may have no face
    // of an id, and each sum below is collective)
    const auto &                                 conditions = parameters.boundary_conditions;
    std::map<types::boundary_id, Tensor<1, dim>> forces;
    for (const auto &ids :
         {conditions.dirichlet_ids, conditions.neumann_ids, conditions.contact_ids})
      for (const unsigned int id : ids)
        forces[id] = Tensor<1, dim>();
    // sigma n is constant on a flat face (an RT0 flux); the third point
    // covers a curved face's mapping
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
        if (cell->at_boundary(f))
          {
            const auto force = forces.find(cell->face(f)->boundary_id());
            if (force == forces.end())
              continue;
            fe_face.reinit(cell, f);
            fe_face.get_function_values(solution, values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int m = 0; m < dim; ++m)
                for (unsigned int k = 0; k < dim; ++k)
                  force->second[m] += values[q][dim + m * dim + k] *
                                      fe_face.normal_vector(q)[k] * fe_face.JxW(q);
          }
    for (auto &[id, force] : forces)
      force = Utilities::MPI::sum(force, discretization.get_communicator());
    return forces;
  }


  template <int dim>
  Tensor<1, dim>
  Postprocessor<dim>::contact_force(
    const std::map<types::boundary_id, Tensor<1, dim>> &forces) const
  {
    const auto &   scene = discretization.get_scene();
    Tensor<1, dim> force;
    for (const auto &[id, part] : forces)
      if (scene.is_contact(id))
        force += part;
    return force;
  }


  template <int dim>
  ErrorNorms
  Postprocessor<dim>::difference(const LevelVector &a, const LevelVector &b) const
  {
    LevelVector d(a);
    d -= b;
    update_ghosts(d);
    // Q1 gradients and RT0 values and divergences, squared: degree 2 on
    // an affine cell, exact with 2 points per direction; the third covers
    // the curved cells' mapping
    const QGauss<dim> quadrature(3);
    struct Scratch
    {
      Scratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe, const Quadrature<dim> &q)
        : fe_values(mapping, fe, q, update_values | update_gradients | update_JxW_values)
        , u(q.size())
        , row(q.size())
        , grad_u(q.size())
        , div(q.size())
      {}
      Scratch(const Scratch &other)
        : Scratch(other.fe_values.get_mapping(),
                  other.fe_values.get_fe(),
                  other.fe_values.get_quadrature())
      {}
      FEValues<dim>               fe_values;
      std::vector<Tensor<1, dim>> u, row;
      std::vector<Tensor<2, dim>> grad_u;
      std::vector<double>         div;
    };
    // Cell by cell in parallel (WorkStream): every cell writes its own
    // squares, summed in cell order after the loop, so that the norms do
    // not depend on the threads.
    struct NoCopy
    {};
    std::vector<ErrorNorms> cells(discretization.get_triangulation().n_active_cells());
    const auto worker = [&](const auto &cell, Scratch &scratch, NoCopy &) {
      if (!cell->is_locally_owned())
        return;
      const FEValuesExtractors::Vector displacement(0);
      FEValues<dim> &                  fe_values = scratch.fe_values;
      ErrorNorms &                     e         = cells[cell->active_cell_index()];
      fe_values.reinit(cell);
      fe_values[displacement].get_function_values(d, scratch.u);
      fe_values[displacement].get_function_gradients(d, scratch.grad_u);
      for (unsigned int q = 0; q < scratch.u.size(); ++q)
        {
          e.u_l2 += scratch.u[q].norm_square() * fe_values.JxW(q);
          e.u_h1_semi += scratch.grad_u[q].norm_square() * fe_values.JxW(q);
        }
      // (one extractor per stress row: the Tensor extractor's divergence
      // is zero for this FESystem's RT components)
      for (unsigned int m = 0; m < dim; ++m)
        {
          const FEValuesExtractors::Vector sigma_row(dim + m * dim);
          fe_values[sigma_row].get_function_values(d, scratch.row);
          fe_values[sigma_row].get_function_divergences(d, scratch.div);
          for (unsigned int q = 0; q < scratch.u.size(); ++q)
            {
              e.sigma_l2 += scratch.row[q].norm_square() * fe_values.JxW(q);
              e.sigma_div += scratch.div[q] * scratch.div[q] * fe_values.JxW(q);
            }
        }
    };
    const auto &dof_handler = discretization.get_dof_handler();
    WorkStream::run(dof_handler.begin_active(),
                    dof_handler.end(),
                    worker,
                    [](const NoCopy &) {},
                    Scratch(mapping, discretization.get_fe(), quadrature),
                    NoCopy());
    ErrorNorms e;
    for (const ErrorNorms &c : cells)
      {
        e.u_l2 += c.u_l2;
        e.u_h1_semi += c.u_h1_semi;
        e.sigma_l2 += c.sigma_l2;
        e.sigma_div += c.sigma_div;
      }
    return norms_of_squares(e, discretization.get_communicator());
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
        // (the cell's size in the scene's units)
        const double step = 1e-3 * std::pow(cell->measure(), 1. / dim) * scaling.length;
        fe_values[displacement].get_function_values(solution, u);
        fe_values[displacement].get_function_gradients(solution, grad_u);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<dim> &p = fe_values.quadrature_point(q);
            for (unsigned int k = 0; k < dim; ++k)
              {
                const double du = scene.exact_displacement().value(p, k) - u[q][k];
                e.u_l2 += du * du * fe_values.JxW(q);
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const double dg =
                      derivative_in_cell(scene.exact_displacement(), p, k, j, step) -
                      grad_u[q][k][j];
                    e.u_h1_semi += dg * dg * fe_values.JxW(q);
                  }
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
                    exact_div += derivative_in_cell(*exact_sigma, p, m * dim + k, k, step);
                  }
                e.sigma_div += (exact_div - div[q]) * (exact_div - div[q]) *
                               fe_values.JxW(q);
              }
          }
      }
    return norms_of_squares(e, discretization.get_communicator());
  }


  template <int dim>
  FieldMaxima
  Postprocessor<dim>::field_maxima(const LevelVector &solution) const
  {
    // (at the cells' corners, cell by cell in parallel: a maximum does not
    // depend on the order of the cells; the copier sees the cells in their
    // order, so the first of equal maxima is the position taken)
    struct Scratch
    {
      Scratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
        : fe_values(mapping, fe, QTrapezoid<dim>(), update_values | update_quadrature_points)
        , u(fe_values.n_quadrature_points)
        , row(fe_values.n_quadrature_points)
        , sigma(fe_values.n_quadrature_points)
      {}
      Scratch(const Scratch &other)
        : Scratch(other.fe_values.get_mapping(), other.fe_values.get_fe())
      {}
      FEValues<dim>               fe_values;
      std::vector<Tensor<1, dim>> u, row;
      std::vector<Tensor<2, dim>> sigma;
    };
    struct CellMaxima
    {
      FieldMaxima maxima;
      Point<dim>  position;
      double      diameter = 0;
    };
    const FEValuesExtractors::Vector displacement(0);
    const double                     nu = parameters.material.poisson_ratio;
    CellMaxima                       here;
    const auto worker = [&](const auto &cell, Scratch &scratch, CellMaxima &cell_maxima) {
      cell_maxima = CellMaxima();
      if (!cell->is_locally_owned())
        return;
      auto &fe_values = scratch.fe_values;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_values(solution, scratch.u);
      for (unsigned int m = 0; m < dim; ++m)
        {
          fe_values[FEValuesExtractors::Vector(dim + m * dim)].get_function_values(solution,
                                                                                 scratch.row);
          for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
            scratch.sigma[q][m] = scratch.row[q];
        }
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          FieldMaxima &m = cell_maxima.maxima;
          m.displacement = std::max(m.displacement, scratch.u[q].norm());
          const double von_mises = StressMeasures::von_mises(scratch.sigma[q], nu);
          if (von_mises > m.von_mises)
            {
              m.von_mises            = von_mises;
              cell_maxima.position   = fe_values.quadrature_point(q);
              cell_maxima.diameter   = cell->diameter(mapping);
            }
        }
    };
    const auto copier = [&](const CellMaxima &cell_maxima) {
      here.maxima.displacement =
        std::max(here.maxima.displacement, cell_maxima.maxima.displacement);
      if (cell_maxima.maxima.von_mises > here.maxima.von_mises)
        {
          here.maxima.von_mises = cell_maxima.maxima.von_mises;
          here.position         = cell_maxima.position;
          here.diameter         = cell_maxima.diameter;
        }
    };
    const auto &dof_handler = discretization.get_dof_handler();
    WorkStream::run(dof_handler.begin_active(),
                    dof_handler.end(),
                    worker,
                    copier,
                    Scratch(mapping, discretization.get_fe()),
                    CellMaxima());
    const MPI_Comm comm = discretization.get_communicator();
    FieldMaxima    maxima;
    maxima.displacement = Utilities::MPI::max(here.maxima.displacement, comm);
    // the position from the process with the largest value (the lowest
    // rank of equal ones)
    const auto von_mises = Utilities::MPI::min_max_avg(here.maxima.von_mises, comm);
    maxima.von_mises     = von_mises.max;
    std::vector<double> where(here.position.begin_raw(), here.position.end_raw());
    where.push_back(here.diameter);
    where = Utilities::MPI::broadcast(comm, where, von_mises.max_index);
    maxima.von_mises_cell_diameter = where.back();
    where.pop_back();
    maxima.von_mises_position = where;
    return maxima;
  }


  template <int dim>
  std::string
  Postprocessor<dim>::write_step(const LevelVector &         x,
                                 const ErrorIndicators<dim> &indicators,
                                 const unsigned int          step,
                                 OutputDirectory &           output) const
  {
    // an adaptive run keeps every step's contact table too (contact.csv is
    // the last one's): the pressure on each mesh, for comparisons
    // (and returns every step's table, which an interrupted run publishes
    // as contact.csv of its last finished step, FoslsProblem::run())
    // (so does a load path, every load step's)
    const bool adaptive = parameters.adaptivity.enabled() || !parameters.data.load_steps.empty();
    const bool table    = adaptive && discretization.get_scene().has_contact();
    if (!parameters.output.write_vtu && !adaptive)
      return "";
    const std::string csv = adaptive ? ContactTable<dim>(discretization, friction).csv(x) : ""; // (collective)
    std::string       error;
    try
      {
        if (parameters.output.write_vtu)
          VtuOutput<dim>(discretization, parameters.material, mapping, friction)
            .write(x, solution_in_scene_units(x), indicators, output, step);
        if (table && Utilities::MPI::this_mpi_process(discretization.get_communicator()) == 0)
          output.write("contact_" + Utilities::int_to_string(step, 4) + ".csv",
                       [&](std::ostream &out) { out << csv; });
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    // (every process learns of a failure anywhere, and publishes nothing)
    if (Utilities::MPI::logical_or(!error.empty(), discretization.get_communicator()))
      output.publish(error);
    return csv;
  }


  template <int dim>
  void
  Postprocessor<dim>::write(const LevelVector &                        x,
                            const Monitor &                            monitor,
                            const std::map<std::string, std::string> &summary,
                            const std::string &                        used_parameters,
                            const std::map<std::string, std::string> &extra_files,
                            OutputDirectory &                          output) const
  {
    const std::string table = ContactTable<dim>(discretization, friction).csv(x); // (collective)
    write(table, monitor.csv(), summary, used_parameters, extra_files, output);
  }


  template <int dim>
  void
  Postprocessor<dim>::write(const std::string &                        table,
                            const std::string &                        convergence,
                            const std::map<std::string, std::string> &summary,
                            const std::string &                        used_parameters,
                            const std::map<std::string, std::string> &extra_files,
                            OutputDirectory &                          output) const
  {
    const MPI_Comm     comm = discretization.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    // every process writes its files into the staging directory; a
    // failure (a full disk) is collected, so that every process reaches
    // publish(), which then publishes nothing and stops all of them
    std::string error;
    try
      {
        if (rank == 0)
          {
            for (const auto &[name, contents] : extra_files)
              output.write(name, [&](std::ostream &out) { out << contents; });
            output.write("contact.csv", [&](std::ostream &out) { out << table; });
            output.write("convergence.csv", [&](std::ostream &out) { out << convergence; });
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


  template class Postprocessor<2>;
  template class Postprocessor<3>;
} // namespace FoslsContact
