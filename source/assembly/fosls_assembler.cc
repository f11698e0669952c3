#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/assembly/constitutive_products.h>
#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/assembly/worker_exceptions.h>
#include <fosls_contact/discretization/hanging_nodes.h>

#include <algorithm>
#include <numeric>

namespace FoslsContact
{
  template <int dim>
  FoslsAssembler<dim>::FoslsAssembler(const Discretization<dim> &discretization,
                                      const Parameters::Weights &weights,
                                      const LevelVector *        friction_reference)
    : discretization(discretization)
    , material(discretization.get_scene().material())
    , weights(weights)
    , friction_reference(friction_reference)
  {
    const auto &fe = discretization.get_fe();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int c = fe.get_nonzero_components(i).first_selected_component();
        stress_row.push_back(c < dim ? -1 : static_cast<int>((c - dim) / dim));
      }
  }


  template <int dim>
  Tensor<2, dim>
  FoslsAssembler<dim>::compliance(const Tensor<2, dim> &sigma,
                                  const double          mu,
                                  const double          lambda)
  {
    const double kappa = 1. / (dim + 2. * mu / lambda); // 1/dim for inf
    Tensor<2, dim> a   = sigma;
    const double   tr  = trace(sigma);
    for (unsigned int d = 0; d < dim; ++d)
      a[d][d] -= kappa * tr;
    return a / (2. * mu);
  }


  /** Per-thread evaluators and work arrays of the cell loop. */
  template <int dim>
  struct AssemblyScratch
    {
      AssemblyScratch(const Mapping<dim> &      mapping,
                      const FiniteElement<dim> &fe,
                      const Quadrature<dim> &   quadrature,
                      const Quadrature<dim - 1> &face_quadrature)
        : fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_quadrature_points |
                      update_JxW_values)
        , fe_face(mapping,
                  fe,
                  face_quadrature,
                  update_values | update_normal_vectors |
                    update_quadrature_points | update_JxW_values)
        , residual(fe.n_dofs_per_cell())
        , divergence(fe.n_dofs_per_cell())
        , un(fe.n_dofs_per_cell())
        , sn(fe.n_dofs_per_cell())
        , f(dim)
        , mean_traction(fe.n_dofs_per_cell())
        , k_friction(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
      {}

      AssemblyScratch(const AssemblyScratch &other)
        : fe_values(other.fe_values.get_mapping(),
                    other.fe_values.get_fe(),
                    other.fe_values.get_quadrature(),
                    other.fe_values.get_update_flags())
        , fe_face(other.fe_face.get_mapping(),
                  other.fe_face.get_fe(),
                  other.fe_face.get_quadrature(),
                  other.fe_face.get_update_flags())
        , residual(other.residual.size())
        , divergence(other.divergence.size())
        , un(other.un.size())
        , sn(other.sn.size())
        , f(dim)
        , mean_traction(other.mean_traction.size())
        , k_friction(other.k_friction.m(), other.k_friction.n())
      {}

      FEValues<dim>               fe_values;
      FEFaceValues<dim>           fe_face;
      std::vector<Tensor<2, dim>> residual; // A sigma_i - eps(u_i)
      /** scratch of add_constitutive_products() */
      std::vector<double>         residual_components;
      std::vector<Tensor<1, dim>> divergence;
      std::vector<double>         un, sn;
      Vector<double>              f;
      /** scratch of friction_terms() */
      std::vector<Tensor<1, dim>> mean_traction;
      FullMatrix<double>          k_friction;
    };

    /** What one cell adds to the functional (already rotated). */
  struct AssemblyCopy
    {
      explicit AssemblyCopy(const unsigned int n)
        : k_eq(n, n)
        , k_const(n, n)
        , k_compl(n, n)
        , k_total(n, n)
        , r_eq(n)
        , r_compl(n)
        , r_total(n)
        , dofs(n)
      {}

      FullMatrix<double>                   k_eq, k_const, k_compl, k_total;
      Vector<double>                       r_eq, r_compl, r_total;
      /** local indices */
      std::vector<types::global_dof_index> dofs;
      /**
       * dofs sorted, and the position in dofs of each: the copier adds a
       * row's entries in the order of the global rows' columns, one merge
       * instead of a search per entry (each entry of the global matrix
       * still gets one sum per cell, in the order of the cells)
       */
      std::vector<types::global_dof_index> sorted_dofs;
      std::vector<unsigned int>            order;
      double                               constant_eq     = 0;
      /** the cell is owned (its constant counts here) */
      bool                                 owned           = false;
      bool                                 touches_contact = false;
      bool                                 valid           = false;
    };


  template <int dim>
  void
  FoslsAssembler<dim>::cell_terms(const typename Triangulation<dim>::cell_iterator &cell,
                                  AssemblyScratch<dim> &                           scratch,
                                  AssemblyCopy &                                   copy) const
  {
    const auto &       scene = discretization.get_scene();
    const unsigned int n     = discretization.get_fe().n_dofs_per_cell();
    // One Vector extractor per stress row: the Tensor<2> extractor's
    // divergence is zero for these non-primitive RT components on
    // deal.II 9.4 (pinned by tests/unit/rt_row_divergence).
    const FEValuesExtractors::Vector displacement(0);
    auto &fe_values = scratch.fe_values;
    auto &k_eq = copy.k_eq, &k_const = copy.k_const;
    auto &r_eq = copy.r_eq;
    k_eq             = 0;
    k_const          = 0;
    r_eq             = 0;
    copy.constant_eq = 0;
    fe_values.reinit(cell);

    auto &residual   = scratch.residual;
    auto &divergence = scratch.divergence;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            // A sigma_i - eps(u_i) has one half zero: a stress function's
            // eps is zero, a displacement function's sigma (and A sigma:
            // compliance() of a zero tensor is +0) too. The half that is
            // not evaluated is the +0 tensor, whose subtraction left the
            // other half as it was, bit for bit.
            divergence[i] = Tensor<1, dim>();
            if (stress_row[i] >= 0)
              {
                Tensor<2, dim>                   sigma;
                const unsigned int               m = stress_row[i];
                const FEValuesExtractors::Vector row(dim + m * dim);
                const Tensor<1, dim>             r = fe_values[row].value(i, q);
                for (unsigned int k = 0; k < dim; ++k)
                  sigma[m][k] = r[k];
                divergence[i][m] = fe_values[row].divergence(i, q);
                residual[i]      = compliance(sigma, material.mu, material.lambda);
              }
            else
              residual[i] = Tensor<2, dim>() - fe_values[displacement].symmetric_gradient(i, q);
          }
        // div sigma_i . div sigma_j is a single product for two functions
        // of one stress row and an exact zero otherwise (which, added, left
        // every sum as it was: the same bits)
        for (unsigned int i = 0; i < n; ++i)
          if (stress_row[i] >= 0)
            for (unsigned int j = 0; j <= i; ++j)
              if (stress_row[i] == stress_row[j])
                {
                  const unsigned int m = stress_row[i];
                  k_eq(i, j) += weights.c_eq * (divergence[i][m] * divergence[j][m]) * JxW;
                }
        add_constitutive_products(
          residual.data(), n, weights.c_const, JxW, scratch.residual_components, k_const);
        if (scene.has_body_force())
          {
            scene.body_force().vector_value(fe_values.quadrature_point(q), scratch.f);
            Tensor<1, dim> ft;
            for (unsigned int d = 0; d < dim; ++d)
              ft[d] = scratch.f[d];
            for (unsigned int i = 0; i < n; ++i)
              r_eq(i) -= weights.c_eq * (ft * divergence[i]) * JxW;
            copy.constant_eq += weights.c_eq * (ft * ft) * JxW;
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        {
          k_eq(i, j)    = k_eq(j, i);
          k_const(i, j) = k_const(j, i);
        }
  }


  template <int dim>
  void
  FoslsAssembler<dim>::contact_terms(const typename Triangulation<dim>::cell_iterator &cell,
                                     AssemblyScratch<dim> &                           scratch,
                                     AssemblyCopy &                                   copy) const
  {
    // Complementarity term on Gamma_C, symmetrized:
    // C_compl/2 [(u_i.n)(sigma_j n_b.n) + (u_j.n)(sigma_i n_b.n)].
    const auto &                     scene = discretization.get_scene();
    const unsigned int               n     = discretization.get_fe().n_dofs_per_cell();
    const FEValuesExtractors::Vector displacement(0);
    const double                     c_compl = weights.c_compl;
    copy.k_compl                             = 0;
    copy.r_compl                             = 0;
    copy.touches_contact                     = false;
    if (!scene.has_contact())
      return;
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
        {
          copy.touches_contact = true;
          auto &fe_face        = scratch.fe_face;
          fe_face.reinit(cell, f);
          for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
            {
              const Point<dim>     p   = fe_face.quadrature_point(q);
              const Tensor<1, dim> n_o = scene.obstacle_normal(p);
              const Tensor<1, dim> n_b = fe_face.normal_vector(q);
              const double         g   = scene.gap().value(p);
              const double         JxW = fe_face.JxW(q);
              auto &               un  = scratch.un;
              auto &               sn  = scratch.sn;
              for (unsigned int i = 0; i < n; ++i)
                {
                  un[i] = fe_face[displacement].value(i, q) * n_o;
                  Tensor<1, dim> traction;
                  for (unsigned int m = 0; m < dim; ++m)
                    traction[m] = fe_face[FEValuesExtractors::Vector(dim + m * dim)].value(i, q) *
                                  n_b;
                  sn[i] = traction * n_o;
                }
              for (unsigned int i = 0; i < n; ++i)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    copy.k_compl(i, j) += 0.5 * c_compl * (un[i] * sn[j] + un[j] * sn[i]) * JxW;
                  copy.r_compl(i) += 0.5 * c_compl * g * sn[i] * JxW;
                }
            }
          if (scene.has_friction())
            friction_terms(cell, f, scratch, copy);
        }
  }


  template <int dim>
  void
  FoslsAssembler<dim>::friction_terms(const typename Triangulation<dim>::cell_iterator &cell,
                                      const unsigned int                               f,
                                      AssemblyScratch<dim> &                           scratch,
                                      AssemblyCopy &                                   copy) const
  {
    // The bilinear part of the friction term (doc/method.md section 7.7),
    //   C_compl sum_{v of F} |F| / 2^(dim-1) (P_F sigma_F n) . (P_v u(v)),
    // with sigma_F n the face's mean traction (the rotated coordinates of
    // the face, ContactEntities::add_rotations()) and P the projections
    // onto the tangent planes of the obstacle at the face's center and at
    // the vertex (those of the rotations): symmetrized like the normal
    // term. Its part linear in u is taken at the step's reference
    // displacement p, u = (u - p) + p: the right-hand side gets K p.
    const auto &       scene = discretization.get_scene();
    const auto &       fe    = discretization.get_fe();
    const unsigned int n     = fe.n_dofs_per_cell();
    auto &             fe_face = scratch.fe_face; // (reinit'ed on face f)
    double             area    = 0;
    std::vector<Tensor<1, dim>> &traction = scratch.mean_traction;
    std::fill(traction.begin(), traction.end(), Tensor<1, dim>());
    for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
      {
        const Tensor<1, dim> n_b = fe_face.normal_vector(q);
        area += fe_face.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          if (stress_row[i] >= 0)
            traction[i][stress_row[i]] +=
              fe_face[FEValuesExtractors::Vector(dim + stress_row[i] * dim)].value(i, q) * n_b *
              fe_face.JxW(q);
      }
    const Tensor<1, dim> n_F = scene.obstacle_normal(cell->face(f)->center());
    for (unsigned int i = 0; i < n; ++i)
      {
        traction[i] /= area;
        traction[i] -= (traction[i] * n_F) * n_F;
      }
    const double weight = weights.c_compl * area / GeometryInfo<dim>::vertices_per_face;
    FullMatrix<double> &k = scratch.k_friction;
    k = 0;
    for (unsigned int fv = 0; fv < GeometryInfo<dim>::vertices_per_face; ++fv)
      {
        const unsigned int   v   = GeometryInfo<dim>::face_to_cell_vertices(f, fv);
        const Tensor<1, dim> n_v = scene.obstacle_normal(cell->vertex(v));
        for (unsigned int c = 0; c < dim; ++c)
          {
            // u_j = e_c at vertex v: its tangential part
            const unsigned int j = fe.component_to_system_index(c, v);
            Tensor<1, dim>     e;
            e[c] = 1;
            e -= (e * n_v) * n_v;
            for (unsigned int i = 0; i < n; ++i)
              if (stress_row[i] >= 0)
                {
                  const double value = 0.5 * weight * (traction[i] * e);
                  k(i, j) += value;
                  k(j, i) += value;
                }
          }
      }
    copy.k_compl.add(1., k);
    if (friction_reference == nullptr)
      return;
    // (the reference's displacement DoFs only: K p with p zero on the
    // stress DoFs, whose couplings to the tractions are no part of it)
    for (unsigned int j = 0; j < n; ++j)
      if (stress_row[j] < 0)
        {
          const double p_j = friction_reference->local_element(copy.dofs[j]);
          if (p_j != 0)
            for (unsigned int i = 0; i < n; ++i)
              copy.r_compl(i) += k(i, j) * p_j;
        }
  }


  template <int dim>
  void
  FoslsAssembler<dim>::rotate(const LevelData<dim> &data, AssemblyCopy &copy) const
  {
    // Change of basis R^T K R for DoFs in rotation blocks (section 4.3).
    const unsigned int n    = copy.dofs.size();
    const auto &       dofs = copy.dofs;
    bool               rotated = false;
    for (unsigned int i = 0; i < n; ++i)
      rotated |= data.rotation_of_dof[dofs[i]] != numbers::invalid_unsigned_int;
    if (!rotated)
      return;
    FullMatrix<double> R(n, n), tmp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int b = data.rotation_of_dof[dofs[i]];
        if (b == numbers::invalid_unsigned_int)
          {
            R(i, i) = 1.;
            continue;
          }
        const auto &       block = data.rotations[b];
        const unsigned int ki =
          std::find(block.dofs.begin(), block.dofs.end(), dofs[i]) - block.dofs.begin();
        for (unsigned int j = 0; j < n; ++j)
          {
            const auto kj = std::find(block.dofs.begin(), block.dofs.end(), dofs[j]);
            if (kj != block.dofs.end())
              R(i, j) = block.matrix(ki, kj - block.dofs.begin());
          }
      }
    Vector<double> tmp_v(n);
    for (FullMatrix<double> *k : {&copy.k_eq, &copy.k_const, &copy.k_compl})
      {
        tmp = 0;
        tmp.triple_product(*k, R, R, true, false);
        *k = tmp;
      }
    for (Vector<double> *r : {&copy.r_eq, &copy.r_compl})
      {
        R.Tvmult(tmp_v, *r);
        *r = tmp_v;
      }
  }


  template <int dim>
  void
  FoslsAssembler<dim>::part_patterns(const LevelData<dim> &data,
                                     SparsityPattern &     eq,
                                     SparsityPattern &     contact) const
  {
    const auto &       scene   = discretization.get_scene();
    const unsigned int n_local = data.n_local();
    const unsigned int n_owned = data.n_owned();
    const unsigned int n       = discretization.get_fe().n_dofs_per_cell();
    DynamicSparsityPattern dsp_eq(n_local, n_local), dsp_contact(n_local, n_local);
    std::vector<types::global_dof_index> dofs, block;
    // the owned rows of @p block (with the masters of its hanging DoFs)
    // couple with all of it
    const auto add_block = [&](DynamicSparsityPattern &dsp) {
      sort_with_masters(data, block);
      for (const auto i : block)
        if (i < n_owned)
          dsp.add_entries(i, block.begin(), block.end(), true);
    };
    data.for_each_cell(discretization.get_dof_handler(), [&](const auto &cell) {
      data.get_local_dofs(cell, dofs);
      bool rotated = false;
      for (const auto dof : dofs)
        rotated |= data.rotation_of_dof[dof] != numbers::invalid_unsigned_int;
      for (int m = rotated ? -1 : 0; m < (rotated ? 0 : static_cast<int>(dim)); ++m)
        {
          block.clear();
          for (unsigned int i = 0; i < n; ++i)
            if (stress_row[i] >= 0 && (m < 0 || stress_row[i] == m))
              block.push_back(dofs[i]);
          add_block(dsp_eq);
        }
      if (scene.has_contact())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
            {
              block = dofs;
              add_block(dsp_contact);
              break;
            }
    });
    eq.copy_from(dsp_eq);
    contact.copy_from(dsp_contact);
  }


  namespace
  {
    /**
     * Whether a cell's terms reach an owned row: one of its DoFs, or a
     * master of one of its hanging DoFs, is owned. Only such cells (and the
     * owned ones, for J's constant) are computed: on a mesh held whole by
     * every process (Discretization::MeshDistribution) every cell is here,
     * and the others would be computed to be thrown away.
     */
    template <int dim>
    bool
    reaches_owned_row(const LevelData<dim> &                      data,
                      const std::vector<types::global_dof_index> &dofs)
    {
      const unsigned int n_owned = data.n_owned();
      for (const auto dof : dofs)
        {
          if (dof < n_owned)
            return true;
          const auto h = data.hanging.find(dof);
          if (h != data.hanging.end())
            for (const auto &master : h->second)
              if (master.first < n_owned)
                return true;
        }
      return false;
    }


    /**
     * The copier: the owned rows of one cell's terms added to @p qp. Only
     * the owned rows are summed here; every cell at an owned DoF is here
     * (owned or ghost), so they are complete. The ghost rows the patches
     * need come from their owners (compress_matrices()). @p row is the
     * copier's: a row of a cell's matrix, by sorted column.
     */
    void
    add_to_qp(const AssemblyCopy & copy,
              const unsigned int   n_owned,
              std::vector<double> &row,
              ConstrainedQP &      qp)
    {
      if (!copy.valid)
        return;
      const auto &       dofs = copy.dofs;
      const unsigned int n    = dofs.size();
      row.resize(n);
      // row i of @p k into @p matrix, its columns sorted
      const auto add_row = [&](SparseMatrix<double> &    matrix,
                               const FullMatrix<double> &k,
                               const unsigned int        i,
                               const bool                elide_zeros) {
        for (unsigned int j = 0; j < n; ++j)
          row[j] = k(i, copy.order[j]);
        matrix.add(dofs[i], n, copy.sorted_dofs.data(), row.data(), elide_zeros, true);
      };
      for (unsigned int i = 0; i < n; ++i)
        if (dofs[i] < n_owned)
          {
            // (k_eq is an exact zero outside its pattern: part_patterns())
            add_row(qp.matrix_eq, copy.k_eq, i, true);
            add_row(qp.matrix, copy.k_total, i, false);
            qp.rhs.local_element(dofs[i]) += copy.r_total(i);
            qp.rhs_eq.local_element(dofs[i]) += 2. * copy.r_eq(i);
            if (copy.touches_contact)
              {
                add_row(qp.matrix_compl, copy.k_compl, i, false);
                qp.rhs_compl.local_element(dofs[i]) += 2. * copy.r_compl(i);
              }
          }
      if (copy.owned)
        qp.constant_eq += copy.constant_eq;
    }
  } // namespace


  template <int dim>
  template <typename CellIterator>
  void
  FoslsAssembler<dim>::local_terms(const LevelData<dim> &data,
                                   const CellIterator &  cell,
                                   AssemblyScratch<dim> &scratch,
                                   AssemblyCopy &        copy) const
  {
    const unsigned int n = discretization.get_fe().n_dofs_per_cell();
    if (copy.dofs.size() != n) // (grown by eliminate_hanging() for another cell)
      copy = AssemblyCopy(n);
    copy.owned = data.owns(cell);
    data.get_local_dofs(cell, copy.dofs);
    if (!copy.owned && !reaches_owned_row(data, copy.dofs))
      return;
    const typename Triangulation<dim>::cell_iterator tria_cell(cell);
    cell_terms(tria_cell, scratch, copy);
    contact_terms(tria_cell, scratch, copy);
    if (eliminate_hanging_dofs_of_cell(data,
                                       copy.dofs,
                                       {&copy.k_eq, &copy.k_const, &copy.k_compl},
                                       {&copy.r_eq, &copy.r_compl}))
      {
        copy.k_total.reinit(copy.dofs.size(), copy.dofs.size());
        copy.r_total.reinit(copy.dofs.size());
      }
    rotate(data, copy);
    // J = 1/2 x^T A x - b^T x + c with A = 2 K and b = 2 r.
    copy.k_total = 0;
    copy.k_total.add(2., copy.k_eq);
    copy.k_total.add(2., copy.k_const);
    copy.r_total = 0;
    copy.r_total.add(2., copy.r_eq);
    if (copy.touches_contact)
      {
        copy.k_total.add(2., copy.k_compl);
        copy.r_total.add(2., copy.r_compl);
      }
    // the matrices of J's parts, 2 K_eq and 2 K_compl, summed doubled
    // (doubling is exact, so the sums are 2 times those of K): an
    // empty matrix (no DoFs of the level here) is never scaled, which
    // deal.II does not allow
    copy.k_eq *= 2.;
    if (copy.touches_contact)
      copy.k_compl *= 2.;
    const unsigned int n_kept = copy.dofs.size();
    copy.order.resize(n_kept);
    std::iota(copy.order.begin(), copy.order.end(), 0u);
    std::sort(copy.order.begin(), copy.order.end(), [&](const auto a, const auto b) {
      return copy.dofs[a] < copy.dofs[b];
    });
    copy.sorted_dofs.resize(n_kept);
    for (unsigned int k = 0; k < n_kept; ++k)
      copy.sorted_dofs[k] = copy.dofs[copy.order[k]];
    copy.valid = true;
  }


  template <int dim>
  void
  FoslsAssembler<dim>::assemble(const unsigned int           level,
                                ConstrainedQP &              qp,
                                const std::function<void()> &release_coupling_pattern) const
  {
    const auto &       fe   = discretization.get_fe();
    const auto &       data = discretization.level(level);
    const unsigned int n    = fe.n_dofs_per_cell();
    // (the parts' matrices are on these until compress_matrices() puts
    // them on their own patterns, below)
    SparsityPattern eq_pattern, contact_pattern;
    part_patterns(data, eq_pattern, contact_pattern);
    qp.matrix_eq.reinit(eq_pattern);
    qp.matrix_compl.reinit(contact_pattern);

    // The cell terms, in parallel (WorkStream); the copier adds them to
    // the global matrices one cell after the other in cell order, so the
    // result does not depend on the number of threads.
    //
    // An exception in a worker is kept and thrown after the loop
    // (WorkerExceptions).
    WorkerExceptions   errors;
    const unsigned int n_owned = data.n_owned();
    auto worker = [&](const auto &cell, AssemblyScratch<dim> &scratch, AssemblyCopy &copy) {
      copy.valid = false;
      if (data.active_mesh ? cell->is_artificial() : !Discretization<dim>::is_present(cell))
        return; // no DoFs on this process
      errors.guard([&]() { local_terms(data, cell, scratch, copy); });
    };
    std::vector<double> row;
    auto copier = [&](const AssemblyCopy &copy) { add_to_qp(copy, n_owned, row, qp); };

    const auto &               dof_handler = discretization.get_dof_handler();
    const AssemblyScratch<dim> scratch(discretization.get_mapping(),
                                       fe,
                                       QGauss<dim>(3),
                                       QGauss<dim - 1>(3));
    try
      {
        if (data.active_mesh)
          WorkStream::run(dof_handler.begin_active(),
                          dof_handler.end(),
                          worker,
                          copier,
                          scratch,
                          AssemblyCopy(n));
        else
          WorkStream::run(dof_handler.begin_mg(level),
                          dof_handler.end_mg(level),
                          worker,
                          copier,
                          scratch,
                          AssemblyCopy(n));
        errors.rethrow(qp.get_communicator());
      }
    catch (...)
      {
        // (they are on this function's patterns, which the exception
        // destroys)
        qp.matrix_eq.clear();
        qp.matrix_compl.clear();
        throw;
      }
    // an eliminated DoF keeps a unit diagonal (it is fixed at zero), so
    // that the matrix stays regular for the direct solvers
    for (const auto &hanging : data.hanging)
      if (hanging.first < n_owned)
        qp.matrix.set(hanging.first, hanging.first, 1.);
    qp.compress_matrices(release_coupling_pattern);
    qp.constant_eq = Utilities::MPI::sum(qp.constant_eq, qp.get_communicator());
    qp.constant    = qp.constant_eq;
  }


  template class FoslsAssembler<2>;
  template class FoslsAssembler<3>;
} // namespace FoslsContact
