#include <deal.II/base/memory_consumption.h>

#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/qp/tangential_pair.h>
#include <fosls_contact/solvers/energy_check.h>
#include <fosls_contact/solvers/patch_smoother.h>

#include <deal.II/base/memory_consumption.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace FoslsContact
{
  namespace
  {
    /**
     * Patches per task of a sweep: the patches of one color are
     * independent, so any split among threads gives the same result.
     * Pieces of 16 patches keep both threads busy on the small levels,
     * whose colors have some 70 patches (doc/performance.md, section 3).
     */
    constexpr unsigned int sweep_grain = 16;

    /**
     * The work arrays of a thread's relaxations (allocated per call they
     * cost a third of a smoothing step on the coarsest levels, 42 DoFs):
     * the defect g and the room to the bounds s on the patch, the
     * correction c, and the values of the neighbourhood.
     */
    struct RelaxationWork
    {
      std::vector<double>       g, s, c, near;
      std::vector<bool>         at_bound;
      std::vector<double>       lo, hi, q, w;
      std::vector<BoxQP::Bound> where;
      /**
       * 3D friction: the patch's pairs (entries a < b), which entries are
       * paired, the scalar block's data, the pairs' references and weights
       * (the scalar block's are zeroed), the scalar entries' bounds hit and
       * which slip pairs end at their kink
       */
      std::vector<std::array<unsigned int, 2>> pairs;
      std::vector<bool>                        paired, at_kink;
      std::vector<double>                      g_scalar, c_scalar, pair_q, pair_w;
      std::vector<BoxQP::Bound>                pair_where;
    };

    /**
     * The defect g = r - A v on the DoFs of patch k (its copied rows
     * against the values of its neighbourhood, or the rows of the level
     * matrix) and the room to their bounds, s = max(0, ub - v) (+inf where
     * unbounded).
     */
    void
    patch_defect(const PackedPatches &level,
                 const unsigned int   k,
                 const double *       v,
                 const double *       r,
                 const double *       ub,
                 RelaxationWork &     w)
    {
      const auto *       dofs = level.neighbors.data() + level.neighbor_start[k];
      const unsigned int m    = level.neighbor_start[k + 1] - level.neighbor_start[k];
      const unsigned int n    = level.start[k + 1] - level.start[k];
      w.g.resize(n);
      w.s.resize(n);
      w.c.resize(n);
      const auto room = [&](const unsigned int a, const types::global_dof_index i) {
        return level.roles[level.start[k] + a] == DoFRole::bounded ?
                 std::max(0., ub[i] - v[i]) :
                 std::numeric_limits<double>::infinity();
      };
      if (level.matrix != nullptr)
        {
          for (unsigned int a = 0; a < n; ++a)
            {
              w.g[a] = level.row_defect(dofs[a], v, r[dofs[a]]);
              w.s[a] = room(a, dofs[a]);
            }
          return;
        }
      w.near.resize(m);
      for (unsigned int j = 0; j < m; ++j)
        w.near[j] = v[dofs[j]];
      const std::uint16_t *column = level.columns.data();
      const double *       value  = level.values.data();
      for (unsigned int a = 0; a < n; ++a)
        {
          const auto        i     = dofs[a];
          const std::size_t first = level.row_start[level.start[k] + a];
          const std::size_t last  = level.row_start[level.start[k] + a + 1];
          double            gi    = r[i];
          for (std::size_t e = first; e < last; ++e)
            gi -= value[e] * w.near[column[e]];
          w.g[a] = gi;
          w.s[a] = room(a, i);
        }
    }


    /**
     * Patch k of the linear problem: the fixed DoFs stay, the others move
     * to the minimizer without bounds. Returns whether J increased.
     */
    bool
    relax_linear_patch(const PackedPatches &level,
                       const unsigned int   k,
                       double *             v,
                       RelaxationWork &     w)
    {
      const auto *       dofs     = level.neighbors.data() + level.neighbor_start[k];
      const auto &       patch    = level.linear_patch[level.box_qp[k]];
      const unsigned int n_moving = patch.moving.size();
      double             gc = 0, scale = 0;
      for (const auto &[a, i, j, k_ii, k_ij] : patch.pair_entries)
        w.g[a] -= k_ii * v[i] + k_ij * v[j];
      for (unsigned int a = 0; a < n_moving; ++a)
        {
          double ca = 0;
          for (unsigned int b = 0; b < n_moving; ++b)
            ca += patch.inverse[a * n_moving + b] * w.g[patch.moving[b]];
          w.c[a] = ca;
          gc += w.g[patch.moving[a]] * ca;
          scale += std::abs(w.g[patch.moving[a]] * ca);
        }
      for (unsigned int a = 0; a < n_moving; ++a)
        v[dofs[patch.moving[a]]] += w.c[a];
      return increases_energy(-0.5 * gc, scale);
    }


    /**
     * Patch k of the constrained problem: the exact minimizer within the
     * bounds. Returns whether J increased.
     */
    bool
    relax_patch(const PackedPatches &level,
                const unsigned int   k,
                double *             v,
                const double *       ub,
                RelaxationWork &     w)
    {
      // the unconstrained patch minimizer c = M^{-1} g (the upper
      // triangle of M^{-1} by rows), and the change of the objective,
      // 1/2 c^T M c - g^T c = -1/2 g^T c
      const auto *       dofs = level.neighbors.data() + level.neighbor_start[k];
      const unsigned int n    = level.start[k + 1] - level.start[k];
      const double *     inv  = level.inverse.data() + level.inverse_start[k];
      auto &             g = w.g, &s = w.s, &c = w.c;
      std::fill(c.begin(), c.end(), 0.);
      for (unsigned int a = 0; a < n; ++a)
        {
          double ca = c[a] + inv[0] * g[a];
          for (unsigned int b = a + 1; b < n; ++b)
            {
              ca += inv[b - a] * g[b];
              c[b] += inv[b - a] * g[a];
            }
          c[a] = ca;
          inv += n - a;
        }
      bool   feasible = true;
      double gc       = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          gc += g[a] * c[a];
          // (a NaN correction counts as feasible: only a patch with a
          // bounded DoF has a BoxQP, and the observer stops a run whose
          // iterate is not finite)
          feasible &= !(c[a] > s[a]);
        }
      double change = -0.5 * gc;
      if (feasible)
        w.at_bound.assign(n, false);
      else
        change = level.qps[level.box_qp[k]].solve(g.data(), s.data(), c.data(), w.at_bound);
      double scale = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          const auto i = dofs[a];
          v[i]         = w.at_bound[a] ? ub[i] : v[i] + c[a];
          scale += std::abs(g[a] * c[a]);
        }
      // exact minimization on the patch: the change is <= 0 up to
      // round-off relative to its own terms
      return increases_energy(change, scale);
    }


    /**
     * The new value of a patch entry of role @p role that the friction
     * patch problem (BoxQP::solve_with_friction()) ended @p where with the
     * correction @p c: exactly its obstacle @p ub, slip bound +-@p s or
     * kink @p p where it ended on one, v + c elsewhere.
     */
    double
    relaxed_value(const DoFRole      role,
                  const BoxQP::Bound where,
                  const double       c,
                  const double       v,
                  const double       ub,
                  const double       s,
                  const double       p)
    {
      switch (where)
        {
          case BoxQP::Bound::upper:
            return role == DoFRole::bounded ? ub : s;
          case BoxQP::Bound::lower:
            return -s;
          case BoxQP::Bound::kink:
            return p;
          default:
            return v + c;
        }
    }


    /**
     * relax_friction_patch() with the pairs of 3D friction
     * (FrictionTerms::partner): the patch's part of J is minimized by
     * block coordinate descent, the scalar entries together
     * (BoxQP::solve_with_friction() with the pairs held) and then each
     * pair with the others held (TangentialPair), until the pairs stop
     * moving or after max_rounds rounds. Each block step minimizes J
     * exactly over its block, so J never increases; the norms and discs
     * are separable by blocks, so the rounds converge to the patch's
     * minimizer (Tseng, J. Optim. Theory Appl. 109, 2001), and an iterate
     * that no patch changes is the minimizer of J. @p w holds the bounds,
     * kinks and weights of relax_friction_patch() on entry.
     */
    bool
    relax_friction_pairs_patch(const PackedPatches &level,
                               const unsigned int   k,
                               double *             v,
                               const double *       ub,
                               const FrictionTerms &friction,
                               RelaxationWork &     w)
    {
      using namespace TangentialPair;
      constexpr unsigned int max_rounds = 20;
      const auto *           dofs       = level.neighbors.data() + level.neighbor_start[k];
      const unsigned int     n          = level.start[k + 1] - level.start[k];
      const BoxQP &          qp         = level.qps[level.box_qp[k]];
      const auto             M = [&](const unsigned int a, const unsigned int b) {
        return qp.matrix_entry(a, b);
      };
      const auto role = [&](const unsigned int a) { return level.roles[level.start[k] + a]; };
      // the pairs, and their entries held in the scalar block
      w.pairs.clear();
      auto &paired = w.paired;
      paired.assign(n, false);
      for (unsigned int a = 0; a < n; ++a)
        {
          const unsigned int j = friction.partner_of(dofs[a]);
          if (j == FrictionTerms::no_partner ||
              (role(a) != DoFRole::traction && role(a) != DoFRole::slip))
            continue;
          unsigned int b = 0;
          while (b < n && dofs[b] != j)
            ++b;
          AssertThrow(b < n, ExcInternalError("a friction pair split between patches"));
          paired[a] = true;
          if (a < b)
            w.pairs.push_back({{a, b}});
        }
      w.pair_q = w.q;
      w.pair_w = w.w;
      const std::vector<double> &q = w.pair_q, &weight = w.pair_w;
      for (unsigned int a = 0; a < n; ++a)
        if (paired[a])
          w.lo[a] = w.hi[a] = w.w[a] = w.q[a] = 0.;
      std::vector<double> &c = w.c;
      std::fill(c.begin(), c.end(), 0.);
      w.g_scalar.resize(n);
      w.c_scalar.resize(n);
      auto &where = w.pair_where;
      where.assign(n, BoxQP::Bound::none);
      auto &at_kink = w.at_kink;
      at_kink.assign(w.pairs.size(), false);
      for (unsigned int round = 0; round < max_rounds; ++round)
        {
          // the scalar entries with the pairs at c
          for (unsigned int a = 0; a < n; ++a)
            {
              double ga = w.g[a];
              for (const auto &pair : w.pairs)
                ga -= M(a, pair[0]) * c[pair[0]] + M(a, pair[1]) * c[pair[1]];
              w.g_scalar[a] = ga;
            }
          qp.solve_with_friction(w.g_scalar.data(),
                                 w.lo.data(),
                                 w.hi.data(),
                                 w.q.data(),
                                 w.w.data(),
                                 w.c_scalar.data(),
                                 w.where,
                                 true);
          for (unsigned int a = 0; a < n; ++a)
            if (!paired[a])
              {
                c[a]     = w.c_scalar[a];
                where[a] = w.where[a];
              }
          // each pair with the rest at c
          double move = 0, size = 0;
          for (unsigned int p = 0; p < w.pairs.size(); ++p)
            {
              const auto [a, b] = w.pairs[p];
              Vector2     h{w.g[a], w.g[b]};
              for (unsigned int e = 0; e < n; ++e)
                {
                  h[0] -= M(a, e) * c[e];
                  h[1] -= M(b, e) * c[e];
                }
              const Matrix2 H{M(a, a), M(a, b), M(b, b)};
              const Vector2 now{c[a], c[b]};
              // h at c = 0 of the pair's own variable: + H now
              h[0] += H[0] * now[0] + H[1] * now[1];
              h[1] += H[1] * now[0] + H[2] * now[1];
              Vector2 next;
              if (role(a) == DoFRole::slip)
                {
                  // y = c - q: 1/2 y^T H y - (h - H q)^T y + w |y|
                  const Vector2 y = minimize_with_norm(
                    H, {h[0] - H[0] * q[a] - H[1] * q[b], h[1] - H[1] * q[a] - H[2] * q[b]}, weight[a]);
                  at_kink[p] = y[0] == 0 && y[1] == 0;
                  next       = {q[a] + y[0], q[b] + y[1]};
                  size       = std::max({size, std::abs(q[a]), std::abs(q[b])});
                }
              else
                {
                  // z = v + c in the disc: 1/2 z^T H z - (h + H v)^T z
                  const Vector2 vv{v[dofs[a]], v[dofs[b]]};
                  const Vector2 z = minimize_in_disc(H,
                                                     {h[0] + H[0] * vv[0] + H[1] * vv[1],
                                                      h[1] + H[1] * vv[0] + H[2] * vv[1]},
                                                     friction.traction_bounds.begin()[dofs[a]]);
                  next = {z[0] - vv[0], z[1] - vv[1]};
                  size = std::max({size, std::abs(vv[0]), std::abs(vv[1])});
                }
              move = std::max({move, std::abs(next[0] - now[0]), std::abs(next[1] - now[1])});
              size = std::max({size, std::abs(next[0]), std::abs(next[1])});
              c[a] = next[0];
              c[b] = next[1];
            }
          if (!(move > 1e-12 * size))
            break;
        }
      // the change of the patch's part of J against c = 0
      double change = 0, scale = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          double mc = 0;
          for (unsigned int b = 0; b < n; ++b)
            mc += M(a, b) * c[b];
          change += 0.5 * c[a] * mc - w.g[a] * c[a];
          scale += std::abs(w.g[a] * c[a]);
          if (!paired[a])
            {
              change += weight[a] * (std::abs(c[a] - q[a]) - std::abs(q[a]));
              scale += weight[a] * (std::abs(c[a] - q[a]) + std::abs(q[a]));
            }
        }
      for (unsigned int p = 0; p < w.pairs.size(); ++p)
        {
          const auto [a, b] = w.pairs[p];
          if (role(a) != DoFRole::slip)
            continue;
          const double now = std::hypot(c[a] - q[a], c[b] - q[b]), before = std::hypot(q[a], q[b]);
          change += weight[a] * (now - before);
          scale += weight[a] * (now + before);
        }
      const double *s_bound = friction.traction_bounds.begin();
      const double *p_ref   = friction.slip_references.begin();
      for (unsigned int a = 0; a < n; ++a)
        if (!paired[a])
          {
            const auto i = dofs[a];
            v[i] = relaxed_value(role(a), where[a], c[a], v[i], ub[i], s_bound[i], p_ref[i]);
          }
      for (unsigned int p = 0; p < w.pairs.size(); ++p)
        {
          const auto [a, b] = w.pairs[p];
          const auto i = dofs[a], j = dofs[b];
          if (role(a) == DoFRole::slip && at_kink[p])
            {
              v[i] = p_ref[i];
              v[j] = p_ref[j];
              continue;
            }
          Vector2 z{v[i] + c[a], v[j] + c[b]};
          if (role(a) == DoFRole::traction)
            z = project_to_disc(z, s_bound[i]);
          v[i] = z[0];
          v[j] = z[1];
        }
      return increases_energy(change, scale);
    }


    /**
     * Patch k of the constrained problem with the friction terms of J: the
     * exact minimizer (BoxQP::solve_with_friction()) of the patch's part
     * of J, with the obstacles of its bounded DoFs, the bounds
     * |x_i| <= s_i of its tangential tractions and the kinks
     * w_i |x_i - p_i| of its tangential displacements. An entry that ends
     * on its bound or kink is set to it exactly. Returns whether J
     * increased.
     */
    bool
    relax_friction_patch(const PackedPatches &  level,
                         const unsigned int     k,
                         double *               v,
                         const double *         ub,
                         const FrictionTerms &  friction,
                         RelaxationWork &       w)
    {
      const auto *       dofs     = level.neighbors.data() + level.neighbor_start[k];
      const unsigned int n        = level.start[k + 1] - level.start[k];
      const double       infinity = std::numeric_limits<double>::infinity();
      const double *     s_bound  = friction.traction_bounds.begin();
      const double *     weight   = friction.slip_weights.begin();
      const double *     p        = friction.slip_references.begin();
      w.lo.assign(n, -infinity);
      w.hi.assign(n, infinity);
      w.q.assign(n, 0.);
      w.w.assign(n, 0.);
      for (unsigned int a = 0; a < n; ++a)
        {
          const auto i = dofs[a];
          switch (level.roles[level.start[k] + a])
            {
              case DoFRole::bounded:
                w.hi[a] = std::max(0., ub[i] - v[i]);
                break;
              case DoFRole::traction:
                w.lo[a] = std::min(0., -s_bound[i] - v[i]);
                w.hi[a] = std::max(0., s_bound[i] - v[i]);
                break;
              case DoFRole::slip:
                w.q[a] = p[i] - v[i];
                w.w[a] = weight[i];
                break;
              default:
                break;
            }
        }
      if (friction.has_pairs())
        return relax_friction_pairs_patch(level, k, v, ub, friction, w);
      const double change = level.qps[level.box_qp[k]].solve_with_friction(
        w.g.data(), w.lo.data(), w.hi.data(), w.q.data(), w.w.data(), w.c.data(), w.where);
      double scale = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          scale += std::abs(w.g[a] * w.c[a]) + w.w[a] * (std::abs(w.c[a] - w.q[a]) + std::abs(w.q[a]));
          v[dofs[a]] = relaxed_value(level.roles[level.start[k] + a], w.where[a], w.c[a], v[dofs[a]],
                                     ub[dofs[a]], s_bound[dofs[a]], p[dofs[a]]);
        }
      return increases_energy(change, scale);
    }


  } // namespace


  PatchSmoother::PatchSmoother(const unsigned int n_levels,
                               const unsigned int steps,
                               const bool         transpose,
                               SectionTime *      time,
                               const PatchRows    rows)
    : MGSmoother<LevelVector>(steps, false, false, transpose)
    , shared(std::make_shared<Shared>(n_levels, rows))
    , time(time)
  {}


  PatchSmoother::PatchSmoother(const PatchSmoother &other,
                               const unsigned int   steps,
                               const bool           transpose)
    : MGSmoother<LevelVector>(steps, false, false, transpose)
    , shared(other.shared)
    , time(other.time)
  {}


  void
  PatchSmoother::initialize_level(
    const unsigned int                                       l,
    const SparseMatrix<double> &                             matrix,
    const std::vector<std::vector<types::global_dof_index>> &patches,
    const std::vector<unsigned int> &                        patch_color,
    const unsigned int                                       n_colors,
    const std::vector<DoFRole> &                             role,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    shared->obstacles[l] = nullptr;
    shared->friction[l]  = nullptr;
    shared->linear[l]    = false;
    shared->levels[l].build(
      matrix, patches, patch_color, n_colors, role, partitioner, shared->rows == PatchRows::copied);
  }


  void
  PatchSmoother::set_linear_roles(const unsigned int          l,
                                  const std::vector<DoFRole> &linear_role,
                                  const PairTerms *           pair_terms)
  {
    shared->levels[l].set_linear_roles(linear_role, pair_terms);
  }


  void
  PatchSmoother::use_linear_roles(const unsigned int l, const bool linear)
  {
    shared->linear[l] = linear;
  }


  void
  PatchSmoother::set_obstacles(const unsigned int l, const LevelVector &ub)
  {
    shared->obstacles[l] = &ub;
  }


  void
  PatchSmoother::set_friction(const unsigned int l, const FrictionTerms *friction)
  {
    shared->friction[l] = friction;
  }


  void
  PatchSmoother::relax_patches(const unsigned int l,
                               const unsigned int begin,
                               const unsigned int end,
                               LevelVector &      v_vector,
                               const LevelVector &r_vector) const
  {
    const PackedPatches &level = shared->levels[l];
    // local elements, owned and ghost
    double *                              v  = v_vector.begin();
    const double *                        r  = r_vector.begin();
    const double *                        ub = shared->obstacles[l]->begin();
    thread_local RelaxationWork           work;
    unsigned int                          increases = 0;
    const bool                            linear    = shared->linear[l];
    const FrictionTerms *                 friction  = shared->friction[l];
    for (unsigned int k = begin; k < end; ++k)
      {
        patch_defect(level, k, v, r, ub, work);
        const bool constrained = level.box_qp[k] != numbers::invalid_unsigned_int;
        const bool increased =
          constrained && linear ? relax_linear_patch(level, k, v, work) :
          constrained && friction != nullptr && level.friction[k] ?
                                  relax_friction_patch(level, k, v, ub, *friction, work) :
                                  relax_patch(level, k, v, ub, work);
        if (increased && level.counted[k])
          ++increases;
      }
    if (increases > 0)
      shared->n_increases += increases;
  }


  void
  PatchSmoother::sweep(const unsigned int l,
                       LevelVector &      v,
                       const LevelVector &r,
                       const bool         backward) const
  {
    const PackedPatches &level    = shared->levels[l];
    const unsigned int   n_colors = level.n_colors();
    for (unsigned int cc = 0; cc < n_colors; ++cc)
      {
        const unsigned int color = backward ? n_colors - 1 - cc : cc;
        for_subranges(
          level.color_start[color],
          level.color_start[color + 1],
          [&](const unsigned int begin, const unsigned int end) {
            relax_patches(l, begin, end, v, r);
          },
          sweep_grain);
        // the owners' new values to the other processes' ghost copies
        update_ghosts(v);
      }
  }


  void
  PatchSmoother::smooth(const unsigned int l, LevelVector &v, const LevelVector &r) const
  {
    AssertThrow(!shared->linear[l] ||
                  shared->levels[l].linear_patch.size() == shared->levels[l].qps.size(),
                ExcMessage("PatchSmoother: linear roles used before set_linear_roles()"));
    AssertThrow(!variable, ExcMessage("PatchSmoother: variable smoothing steps"));
    std::optional<ScopedTime> timing;
    if (time != nullptr)
      timing.emplace(*time);
    update_ghosts(r);
    update_ghosts(*shared->obstacles[l]);
    update_ghosts(v);
    // (as deal.II's MGSmootherRelaxation: symmetric alternates the
    // direction, starting forward for an even number of steps)
    bool backward = transpose && !(symmetric && steps % 2 == 0);
    for (unsigned int step = 0; step < steps; ++step)
      {
        sweep(l, v, r, backward);
        ++shared->sweeps[l];
        if (symmetric)
          backward = !backward;
      }
  }


  void
  PatchSmoother::clear()
  {
    const unsigned int n_levels = shared->levels.size();
    shared->levels.assign(n_levels, PackedPatches());
    shared->obstacles.assign(n_levels, nullptr);
    shared->friction.assign(n_levels, nullptr);
    shared->linear.assign(n_levels, false);
  }

  LevelBytes
  PatchSmoother::memory_consumption() const
  {
    LevelBytes bytes;
    for (const PackedPatches &level : shared->levels)
      bytes.push_back(level.memory_consumption());
    return bytes;
  }
} // namespace FoslsContact
