#include <deal.II/base/memory_consumption.h>

#include <fosls_contact/qp/accurate_sums.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/qp/tangential_pair.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FoslsContact
{
  void
  ConstrainedQP::reinit(const AlgebraicLevel &level)
  {
    matrix.reinit(level.sparsity);
    // (matrix_eq and matrix_compl: sized by the assembler on the
    // couplings of their terms)
    matrix_eq.clear();
    matrix_compl.clear();
    partitioner = level.partitioner;
    ghost_rows  = &level.ghost_rows;
    rhs.reinit(partitioner);
    rhs_eq.reinit(partitioner);
    rhs_compl.reinit(partitioner);
    constant = constant_eq = 0;
    coupling_sparsity = &level.sparsity;
    role         = level.role;
    dimension    = level.dimension;
    refinement_ratio = level.refinement_ratio;
    fixed_values = level.fixed_values;
    upper_bounds = level.upper_bounds;
    update_ghosts(fixed_values);
    update_ghosts(upper_bounds);
    // (FrictionLaw sets them for the friction law of the scene)
    friction = FrictionTerms();
  }


  double
  ConstrainedQP::friction_term(const LevelVector &x) const
  {
    if (!has_friction())
      return 0;
    double term = 0;
    for (unsigned int i = 0; i < n_owned(); ++i)
      if (role[i] == DoFRole::slip)
        {
          // (a 3D pair once, by its first entry: the Euclidean norm)
          const unsigned int j = friction.partner_of(i);
          if (j != FrictionTerms::no_partner && j < i)
            continue;
          const double z = x.local_element(i) - friction.slip_references.local_element(i);
          const double z_j =
            j == FrictionTerms::no_partner ?
              0. :
              x.local_element(j) - friction.slip_references.local_element(j);
          term += friction.slip_weights.local_element(i) * std::hypot(z, z_j);
        }
    return Utilities::MPI::sum(term, get_communicator());
  }


  void
  ConstrainedQP::compress_matrices(const std::function<void()> &release_coupling_pattern)
  {
    zero_round_off(matrix, partitioner, round_off_drop, &matrix_eq);
    ghost_rows->import_into(matrix);
    // the small parts first: what their compression frees (blocks under
    // 32 MB stay on the heap, app/main.cc) can take A's new pattern
    compress_to_nonzeros(matrix_eq, sparsity_eq);
    compress_to_nonzeros(matrix_compl, sparsity_compl);
    compress_to_nonzeros(matrix, sparsity, release_coupling_pattern);
    if (release_coupling_pattern)
      coupling_sparsity = nullptr;
  }


  double
  ConstrainedQP::value(const LevelVector &x) const
  {
    return accurate_quadratic(matrix, x, rhs, constant) + friction_term(x);
  }


  FunctionalValue
  ConstrainedQP::parts(const LevelVector &x) const
  {
    return parts_with_total(x, value(x));
  }


  FunctionalValue
  ConstrainedQP::parts_with_total(const LevelVector &x, const double total) const
  {
    FunctionalValue v;
    v.total = total;
    v.eq    = accurate_quadratic(matrix_eq, x, rhs_eq, constant_eq);
    // (with friction: the tangential term's bilinear part is in
    // matrix_compl, its |u_t - p_t| part is friction_term())
    v.complementarity = accurate_quadratic(matrix_compl, x, rhs_compl, 0.) + friction_term(x);
    v.constitutive    = v.total - v.eq - v.complementarity;
    return v;
  }


  void
  ConstrainedQP::project_to_feasible(LevelVector &x) const
  {
    // (the ghost entries too: see LocalElements)
    const LocalElements fixed(fixed_values), ub(upper_bounds);
    for (unsigned int i = 0; i < role.size(); ++i)
      if (role[i] == DoFRole::fixed)
        x.local_element(i) = fixed(i);
      else if (role[i] == DoFRole::bounded)
        x.local_element(i) = std::min(x.local_element(i), ub(i));
      else if (role[i] == DoFRole::traction && has_friction())
        {
          const double       s = friction.traction_bounds.local_element(i);
          const unsigned int j = friction.partner_of(i);
          if (j == FrictionTerms::no_partner)
            x.local_element(i) = std::max(-s, std::min(x.local_element(i), s));
          else if (i < j)
            {
              const auto z =
                TangentialPair::project_to_disc({x.local_element(i), x.local_element(j)}, s);
              x.local_element(i) = z[0];
              x.local_element(j) = z[1];
            }
        }
  }


  double
  ConstrainedQP::max_violation(const LevelVector &x) const
  {
    double v = 0;
    for (unsigned int i = 0; i < n_owned(); ++i)
      if (role[i] == DoFRole::fixed)
        v = std::max(v, std::abs(x.local_element(i) - fixed_values.local_element(i)));
      else if (role[i] == DoFRole::bounded)
        v = std::max(v, x.local_element(i) - upper_bounds.local_element(i));
      else if (role[i] == DoFRole::traction && has_friction())
        {
          const unsigned int j = friction.partner_of(i);
          v = std::max(v,
                       std::hypot(x.local_element(i),
                                  j == FrictionTerms::no_partner ? 0. : x.local_element(j)) -
                         friction.traction_bounds.local_element(i));
        }
    return Utilities::MPI::max(v, get_communicator());
  }


  std::vector<bool>
  ConstrainedQP::active_set(const LevelVector &x) const
  {
    std::vector<bool> active(n_owned(), false);
    for (unsigned int i = 0; i < n_owned(); ++i)
      active[i] = role[i] == DoFRole::bounded &&
                  x.local_element(i) >= upper_bounds.local_element(i);
    return active;
  }


  unsigned int
  ConstrainedQP::n_active(const std::vector<bool> &active) const
  {
    return Utilities::MPI::sum(
      static_cast<unsigned int>(std::count(active.begin(), active.end(), true)),
      get_communicator());
  }


  unsigned int
  ConstrainedQP::n_active(const LevelVector &x) const
  {
    return n_active(active_set(x));
  }


  KKTResidual
  ConstrainedQP::kkt_residual(const LevelVector &x) const
  {
    // For x_i <= ub_i the multiplier is mu_i = (b - A x)_i >= 0; it must
    // vanish where the bound is not attained.
    LevelVector g = new_vector();
    vmult(matrix, g, x);
    g -= rhs;
    // relative to the size of the terms of each row, sum_j |A_ij x_j|, so
    // that the residual is meaningful also when b = 0 (pure Dirichlet data)
    double scale = rhs.linfty_norm();
    double              local_scale = 0, bound_scale = 1;
    const LocalElements x_local(x); // (ghost entries updated by vmult())
    for (unsigned int i = 0; i < n_owned(); ++i)
      {
        if (role[i] != DoFRole::fixed)
          {
            double row = 0;
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              row += std::abs(e->value() * x_local(e->column()));
            local_scale = std::max(local_scale, row);
          }
        if (role[i] == DoFRole::bounded)
          bound_scale = std::max(bound_scale, std::abs(upper_bounds.local_element(i)));
      }
    const MPI_Comm comm = get_communicator();
    scale       = std::max(std::max(scale, Utilities::MPI::max(local_scale, comm)), 1e-300);
    bound_scale = Utilities::MPI::max(bound_scale, comm);

    KKTResidual r;
    for (unsigned int i = 0; i < n_owned(); ++i)
      {
        const double gi = g.local_element(i), xi = x.local_element(i);
        // (a problem without friction terms whose roles have them, a
        // level of an initial guess: those DoFs are free)
        const bool friction_role = role[i] == DoFRole::traction || role[i] == DoFRole::slip;
        switch (friction_role && !has_friction() ? DoFRole::free : role[i])
          {
            case DoFRole::free:
              r.stationarity = std::max(r.stationarity, std::abs(gi));
              break;
            case DoFRole::fixed:
              r.feasibility = std::max(r.feasibility,
                                       std::abs(xi - fixed_values.local_element(i)) / bound_scale);
              break;
            case DoFRole::bounded:
              {
                const double ub = upper_bounds.local_element(i);
                const double mu = std::max(0., -gi);
                r.stationarity  = std::max(r.stationarity, std::max(0., gi));
                r.feasibility =
                  std::max(r.feasibility, std::max(0., xi - ub) / bound_scale);
                r.complementarity =
                  std::max(r.complementarity, mu * std::abs(ub - xi) / bound_scale);
                break;
              }
            case DoFRole::traction:
              {
                const double       s = friction.traction_bounds.local_element(i);
                const unsigned int j = friction.partner_of(i);
                if (j != FrictionTerms::no_partner)
                  {
                    // |(x_i, x_j)| <= s: g = -mu x / |x| with mu >= 0 on
                    // the circle, g = 0 inside it (per entry: g_i less
                    // its part along x, and the multiplier's sign)
                    const double length = std::hypot(xi, x.local_element(j));
                    r.feasibility = std::max(r.feasibility, std::max(0., length - s) / bound_scale);
                    if (length < s * (1 - 1e-12))
                      {
                        r.stationarity = std::max(r.stationarity, std::abs(gi));
                        break;
                      }
                    // (a disc of radius 0 holds the pair at 0 with any multiplier)
                    if (length == 0)
                      break;
                    const double along = (gi * xi + g.local_element(j) * x.local_element(j)) / length;
                    r.stationarity =
                      std::max({r.stationarity, std::abs(gi - along * xi / length), std::max(0., along)});
                    break;
                  }
                // -s <= x_i <= s: a multiplier of either sign, each of
                // which must vanish away from its bound
                r.feasibility  = std::max(r.feasibility, std::max(0., std::abs(xi) - s) / bound_scale);
                r.complementarity =
                  std::max({r.complementarity,
                            std::max(0., -gi) * std::abs(s - xi) / bound_scale,
                            std::max(0., gi) * std::abs(xi + s) / bound_scale});
                break;
              }
            case DoFRole::slip:
              {
                // 0 in g_i + w_i d|x_i - p_i|: g_i = -w_i sign(x_i - p_i), or
                // |g_i| <= w_i at x_i = p_i
                const double       w = friction.slip_weights.local_element(i);
                const double       d = xi - friction.slip_references.local_element(i);
                const unsigned int j = friction.partner_of(i);
                if (j != FrictionTerms::no_partner)
                  {
                    // 0 in g + w d|z| for the pair z: g = -w z / |z|, or
                    // |g| <= w at z = 0
                    const double d_j    = x.local_element(j) - friction.slip_references.local_element(j);
                    const double length = std::hypot(d, d_j);
                    r.stationarity =
                      std::max(r.stationarity,
                               length > 0 ? std::abs(gi + w * d / length) :
                                            std::max(0., std::hypot(gi, g.local_element(j)) - w));
                    break;
                  }
                r.stationarity = std::max(r.stationarity,
                                          d > 0 ? std::abs(gi + w) :
                                          d < 0 ? std::abs(gi - w) :
                                                  std::max(0., std::abs(gi) - w));
                break;
              }
          }
      }
    r.stationarity    = Utilities::MPI::max(r.stationarity, comm) / scale;
    r.feasibility     = Utilities::MPI::max(r.feasibility, comm);
    r.complementarity = Utilities::MPI::max(r.complementarity, comm) / scale;
    return r;
  }


  double
  ConstrainedQP::energy_norm(const LevelVector &d) const
  {
    return std::sqrt(std::max(0., matrix_norm_square(matrix, d)));
  }


  double
  ConstrainedQP::round_off_correction(const LevelVector &x) const
  {
    update_ghosts(x);
    const LocalElements x_local(x);
    const auto          partial = sum_over_row_blocks<double>(
      n_owned(), [&](double &sum, const unsigned int i) {
        if (role[i] != DoFRole::fixed && matrix.diag_element(i) > 0)
          {
            double s = std::abs(rhs.local_element(i));
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              s += std::abs(e->value() * x_local(e->column()));
            sum += s * s / matrix.diag_element(i);
          }
      });
    double sum = 0;
    for (const double p : partial)
      sum += p;
    return round_off_from(sum, x.size());
  }


  double
  ConstrainedQP::round_off_from(const double local_sum, const types::global_dof_index n) const
  {
    const double sum = Utilities::MPI::sum(local_sum, get_communicator());
    return std::numeric_limits<double>::epsilon() * std::sqrt(sum) *
           std::pow(double(n), 1. / dimension) * refinement_ratio;
  }


  IterateMeasures
  ConstrainedQP::measure(const LevelVector &x, const LevelVector &d) const
  {
    update_ghosts(x);
    update_ghosts(d);
    const LocalElements x_local(x), d_local(d);
    const unsigned int  n = n_owned();
    // Each row's terms as value(), energy_norm() (matrix_norm_square())
    // and round_off_correction() compute them. Their sums, too: value()'s
    // and round_off_correction()'s by the same blocks of rows, in order;
    // energy_norm()'s row by row, so its terms are kept.
    struct Partial
    {
      CompensatedSum value;
      double         round_off = 0;
      double         scale     = 0; // of J's terms: sum |x_i| (|A||x| / 2 + |b|)_i
    };
    std::vector<double> d_terms(n);
    const auto          partial =
      sum_over_row_blocks<Partial>(n, [&](Partial &p, const unsigned int i) {
        CompensatedSum Ax;
        double         Ad = 0, s = std::abs(rhs.local_element(i));
        for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
          {
            const double a = e->value(), x_j = x_local(e->column());
            Ax.add_product(a, x_j);
            Ad += a * d_local(e->column());
            s += std::abs(a * x_j);
          }
        add_quadratic_row(p.value, x.local_element(i), Ax, rhs.local_element(i));
        d_terms[i] = d.local_element(i) * Ad;
        if (role[i] != DoFRole::fixed && matrix.diag_element(i) > 0)
          p.round_off += s * s / matrix.diag_element(i);
        p.scale += std::abs(x.local_element(i)) * 0.5 * (s + std::abs(rhs.local_element(i)));
      });
    CompensatedSum value;
    double         round_off = 0, d_norm_square = 0, scale = 0;
    for (const auto &p : partial)
      {
        value.add(p.value);
        round_off += p.round_off;
        scale += p.scale;
      }
    for (const double t : d_terms)
      d_norm_square += t;

    IterateMeasures m;
    m.functional = parts_with_total(x,
                                    accurate_total(value, get_communicator(), constant) +
                                      friction_term(x));
    m.correction =
      std::sqrt(std::max(0., Utilities::MPI::sum(d_norm_square, get_communicator())));
    m.round_off = round_off_from(round_off, x.size());
    m.functional_round_off =
      std::numeric_limits<double>::epsilon() *
      (Utilities::MPI::sum(scale, get_communicator()) + std::abs(constant));
    return m;
  }
  std::size_t
  ConstrainedQP::memory_consumption() const
  {
    return matrix.memory_consumption() + sparsity.memory_consumption() +
           matrix_eq.memory_consumption() + sparsity_eq.memory_consumption() +
           matrix_compl.memory_consumption() + sparsity_compl.memory_consumption() +
           rhs.memory_consumption() + rhs_eq.memory_consumption() +
           rhs_compl.memory_consumption() + role.capacity() * sizeof(DoFRole) +
           fixed_values.memory_consumption() + upper_bounds.memory_consumption() +
           friction.traction_bounds.memory_consumption() +
           friction.slip_weights.memory_consumption() +
           friction.slip_references.memory_consumption();
  }

} // namespace FoslsContact
