#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/assembly/worker_exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace FoslsContact
{
  template <int dim>
  ErrorIndicators<dim>::ErrorIndicators(const Discretization<dim> &discretization,
                                        const Parameters::Weights &weights)
    : discretization(discretization)
    , weights(weights)
  {}


  /** The evaluators and work arrays of one thread. */
  template <int dim>
  struct ErrorIndicators<dim>::Scratch
  {
    Scratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
      // the assembler's quadrature, so that the sum is the assembled J
      : fe_values(mapping,
                  fe,
                  QGauss<dim>(3),
                  update_values | update_gradients | update_quadrature_points | update_JxW_values)
      , fe_face(mapping,
                fe,
                QGauss<dim - 1>(3),
                update_values | update_normal_vectors | update_quadrature_points |
                  update_JxW_values)
      , eps(fe_values.n_quadrature_points)
      // (deal.II's get_function_values() fills as many points as the
      // vector has, so the face's values need a vector of the face's size:
      // one of the cell's size made it read shape values past the face's
      // points)
      , row(fe_values.n_quadrature_points)
      , face_row(fe_face.n_quadrature_points)
      , u(fe_face.n_quadrature_points)
      , divergence(fe_values.n_quadrature_points)
      , sigma(std::max(fe_values.n_quadrature_points, fe_face.n_quadrature_points))
      , div_sigma(fe_values.n_quadrature_points)
      , f(dim)
      , dofs(fe.n_dofs_per_cell())
    {}

    Scratch(const Scratch &other)
      : Scratch(other.fe_values.get_mapping(), other.fe_values.get_fe())
    {}

    FEValues<dim>                        fe_values;
    FEFaceValues<dim>                    fe_face;
    std::vector<SymmetricTensor<2, dim>> eps;
    std::vector<Tensor<1, dim>>          row, face_row, u;
    std::vector<double>                  divergence;
    std::vector<Tensor<2, dim>>          sigma;
    std::vector<Tensor<1, dim>>          div_sigma;
    Vector<double>                       f;
    std::vector<types::global_dof_index> dofs;
  };


  template <int dim>
  void
  ErrorIndicators<dim>::cell_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                    const LevelVector &                                   solution,
                                    Scratch &                                             scratch)
  {
    const auto &                     scene    = discretization.get_scene();
    const auto &                     material = scene.material();
    const FEValuesExtractors::Vector displacement(0);
    auto &                           fe_values = scratch.fe_values;
    auto &                           fe_face   = scratch.fe_face;
    auto &                           sigma     = scratch.sigma;
    auto &                           row       = scratch.row;
    const unsigned int nq = fe_values.n_quadrature_points, nf = fe_face.n_quadrature_points;
    const unsigned int i  = cell->active_cell_index();
    fe_values.reinit(cell);
    fe_values[displacement].get_function_symmetric_gradients(solution, scratch.eps);
    for (unsigned int m = 0; m < dim; ++m)
      {
        // one extractor per stress row (the Tensor<2> extractor's
        // divergence is zero for these RT components on deal.II 9.4)
        const FEValuesExtractors::Vector sigma_row(dim + m * dim);
        fe_values[sigma_row].get_function_values(solution, row);
        fe_values[sigma_row].get_function_divergences(solution, scratch.divergence);
        for (unsigned int q = 0; q < nq; ++q)
          {
            sigma[q][m]             = row[q];
            scratch.div_sigma[q][m] = scratch.divergence[q];
          }
      }
    for (unsigned int q = 0; q < nq; ++q)
      {
        Tensor<1, dim> residual = scratch.div_sigma[q];
        if (scene.has_body_force())
          {
            scene.body_force().vector_value(fe_values.quadrature_point(q), scratch.f);
            for (unsigned int d = 0; d < dim; ++d)
              residual[d] += scratch.f[d];
          }
        const Tensor<2, dim> r =
          FoslsAssembler<dim>::compliance(sigma[q], material.mu, material.lambda) -
          Tensor<2, dim>(scratch.eps[q]);
        eq[i] += weights.c_eq * (residual * residual) * fe_values.JxW(q);
        constitutive[i] += weights.c_const * scalar_product(r, r) * fe_values.JxW(q);
      }
    if (scene.has_contact())
      for (const unsigned int face : cell->face_indices())
        if (cell->at_boundary(face) && scene.is_contact(cell->face(face)->boundary_id()))
          {
            fe_face.reinit(cell, face);
            fe_face[displacement].get_function_values(solution, scratch.u);
            for (unsigned int m = 0; m < dim; ++m)
              {
                fe_face[FEValuesExtractors::Vector(dim + m * dim)].get_function_values(
                  solution, scratch.face_row);
                for (unsigned int q = 0; q < nf; ++q)
                  sigma[q][m] = scratch.face_row[q];
              }
            for (unsigned int q = 0; q < nf; ++q)
              {
                const Point<dim>     p   = fe_face.quadrature_point(q);
                const Tensor<1, dim> n_o = scene.obstacle_normal(p);
                const double         s_n = (sigma[q] * fe_face.normal_vector(q)) * n_o;
                complementarity[i] += weights.c_compl * (scratch.u[q] * n_o - scene.gap().value(p)) *
                                      s_n * fe_face.JxW(q);
              }
            if (slip_term != nullptr)
              {
                complementarity[i] += friction_bilinear(cell, face, solution, scratch);
                const auto term = slip_term->find(cell->face(face)->index());
                if (term != slip_term->end())
                  complementarity[i] += term->second;
              }
          }
  }


  template <int dim>
  double
  ErrorIndicators<dim>::friction_bilinear(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    f,
    const LevelVector &                                   solution,
    Scratch &                                             scratch) const
  {
    // FoslsAssembler::friction_terms()'s form at the solution: the face's
    // mean traction (scratch.sigma, fe_face on face f) projected onto the
    // obstacle's tangent plane at the face's center, against the
    // tangential increment of each vertex
    const auto &   scene   = discretization.get_scene();
    const auto &   fe      = discretization.get_fe();
    const auto &   fe_face = scratch.fe_face;
    Tensor<1, dim> traction;
    double         area = 0;
    for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
      {
        traction += scratch.sigma[q] * fe_face.normal_vector(q) * fe_face.JxW(q);
        area += fe_face.JxW(q);
      }
    traction /= area;
    const Tensor<1, dim> n_F = scene.obstacle_normal(cell->face(f)->center());
    traction -= (traction * n_F) * n_F;
    cell->get_dof_indices(scratch.dofs);
    double value = 0;
    for (unsigned int fv = 0; fv < GeometryInfo<dim>::vertices_per_face; ++fv)
      {
        const unsigned int v = GeometryInfo<dim>::face_to_cell_vertices(f, fv);
        Tensor<1, dim>     increment;
        for (unsigned int c = 0; c < dim; ++c)
          {
            const auto dof = scratch.dofs[fe.component_to_system_index(c, v)];
            increment[c]   = solution(dof) - (reference != nullptr ? (*reference)(dof) : 0.);
          }
        const Tensor<1, dim> n_v = scene.obstacle_normal(cell->vertex(v));
        increment -= (increment * n_v) * n_v;
        value += traction * increment;
      }
    return weights.c_compl * area / GeometryInfo<dim>::vertices_per_face * value;
  }


  template <int dim>
  std::unordered_map<unsigned int, double>
  ErrorIndicators<dim>::slip_terms(const LevelVector &x_rotated, const ConstrainedQP &qp) const
  {
    const auto &fine = discretization.level(discretization.finest_level());
    const auto &p    = qp.friction.slip_references;
    const auto  z    = [&](const types::global_dof_index i) {
      return i == numbers::invalid_dof_index ? 0. : x_rotated.local_element(i) - p.local_element(i);
    };
    std::unordered_map<unsigned int, double> terms;
    for (const auto &face : fine.friction_faces)
      {
        const double s = qp.friction.traction_bounds.local_element(face.traction[0]);
        double       sum = 0;
        for (const auto &slip : face.slips)
          sum += std::hypot(z(slip[0]), dim == 3 ? z(slip[dim - 2]) : 0.);
        terms[face.face_index] = weights.c_compl * face.weight * s * sum;
      }
    return terms;
  }


  template <int dim>
  void
  ErrorIndicators<dim>::compute(const LevelVector &x_rotated, const Friction *friction)
  {
    LevelVector x = x_rotated;
    discretization.rotate_to_cartesian(discretization.finest_level(), x);
    const LevelVector solution = discretization.to_active(x);
    std::unordered_map<unsigned int, double> terms;
    LevelVector                              reference_active;
    if (friction != nullptr)
      {
        // (the slip DoFs of a face may be ghosts)
        LevelVector x_ghosted = x_rotated;
        update_ghosts(x_ghosted);
        terms     = slip_terms(x_ghosted, friction->qp);
        slip_term = &terms;
        if (friction->reference != nullptr)
          {
            reference_active = discretization.to_active(*friction->reference);
            reference        = &reference_active;
          }
      }

    const unsigned int n_cells = discretization.get_triangulation().n_active_cells();
    eq.reinit(n_cells);
    constitutive.reinit(n_cells);
    complementarity.reinit(n_cells);

    // Cell by cell in parallel (WorkStream): every cell writes its own
    // entries, so the values do not depend on the threads, and their sums
    // (summarize()) are taken in cell order. The data functions were
    // evaluated at these points by the assembly already; an exception is
    // still carried out of the workers and thrown after the loop.
    WorkerExceptions errors;
    const auto       worker = [&](const auto &cell, Scratch &scratch, Empty &) {
      if (cell->is_locally_owned())
        errors.guard([&]() { cell_values(cell, solution, scratch); });
    };
    const auto &dof_handler = discretization.get_dof_handler();
    WorkStream::run(dof_handler.begin_active(),
                    dof_handler.end(),
                    worker,
                    [](const Empty &) {},
                    Scratch(discretization.get_mapping(), discretization.get_fe()),
                    Empty());
    slip_term = nullptr;
    reference = nullptr;
    errors.rethrow(discretization.get_communicator());
    summarize();
  }


  template <int dim>
  void
  ErrorIndicators<dim>::summarize()
  {
    const MPI_Comm      comm = discretization.get_communicator();
    std::vector<double> owned;
    double              local_sum = 0;
    for (const auto &cell : discretization.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          owned.push_back(squared(cell->active_cell_index()));
          local_sum += owned.back();
        }
    sum     = Utilities::MPI::sum(local_sum, comm);
    largest = Utilities::MPI::max(owned.empty() ? 0. : *std::max_element(owned.begin(),
                                                                        owned.end()),
                                  comm);
    // the cells for half of J: gathered (the values only), largest first
    const auto all = Utilities::MPI::all_gather(comm, owned);
    std::vector<double> values;
    for (const auto &part : all)
      values.insert(values.end(), part.begin(), part.end());
    std::sort(values.begin(), values.end(), std::greater<double>());
    double partial = 0;
    half_cells     = 0;
    while (half_cells < values.size() && partial < 0.5 * sum)
      partial += values[half_cells++];
  }

  template class ErrorIndicators<2>;
  template class ErrorIndicators<3>;
} // namespace FoslsContact
