// GalerkinProduct and the patch smoother's level scheduling.
//
// 1. deal.II 9.4's SparseMatrix::mmult / Tmmult with
//    rebuild_sparsity_pattern = false ADD the product to the result instead
//    of overwriting it (pinned here: if a later deal.II changes that, this
//    line changes). A solver that called them on reused matrices would make
//    every Galerkin operator after the first change of the truncation the
//    sum of all earlier ones.
// 2. GalerkinProduct::compute overwrites: P~^T A P~ for a truncated P~,
//    computed twice with different truncations, equals deal.II's product
//    (into zeroed matrices) to round-off, with 1 and with 2 threads (and
//    the same bits). The result lies on the pattern given to initialize()
//    (here that of deal.II's compute_Tmmult_pattern, which holds it).
//    zero_round_off(drop) sets exactly the entries below drop relative to the
//    diagonal to 0.
// 3. VertexPatches::level_schedule keeps the order of every coupled
//    pair of patches, so a smoothing step relaxed color by color in
//    parallel gives the same bits as the sequential sweep over the patches
//    in their order (checked against a hand-written sequential sweep on a
//    1D chain of overlapping patches); PatchSmoother::initialize_level
//    refuses colors under which the matrix couples two patches of one
//    color, also where the coupling is a nonzero on one side only.
// The 1D problems are not tied to a mesh: their vectors (LevelVector) and
// the level scheduling live on serial_partitioner(), all indices owned by
// the one process.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/galerkin_product.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/patch_smoother.h>

#include "tests.h"

using namespace FoslsContactTests;

namespace
{
  // A 1D Laplacian-like SPD matrix (n x n, bandwidth 2) and a linear
  // interpolation P from m = (n + 1) / 2 coarse points.
  void
  make_problem(const unsigned int    n,
               SparsityPattern &     A_pattern,
               SparseMatrix<double> &A,
               SparsityPattern &     P_pattern,
               SparseMatrix<double> &P)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i >= 2 ? i - 2 : 0); j < std::min(n, i + 3); ++j)
        dsp.add(i, j);
    A_pattern.copy_from(dsp);
    A.reinit(A_pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i >= 2 ? i - 2 : 0); j < std::min(n, i + 3); ++j)
        A.set(i, j, i == j ? 6. + 0.01 * i : (std::abs(int(i) - int(j)) == 1 ? -2. : 0.5));
    const unsigned int     m = (n + 1) / 2;
    DynamicSparsityPattern pdsp(n, m);
    for (unsigned int i = 0; i < n; ++i)
      {
        pdsp.add(i, i / 2);
        if (i % 2 == 1 && i / 2 + 1 < m)
          pdsp.add(i, i / 2 + 1);
      }
    P_pattern.copy_from(pdsp);
    P.reinit(P_pattern);
    for (unsigned int i = 0; i < n; ++i)
      if (i % 2 == 0)
        P.set(i, i / 2, 1.);
      else
        {
          P.set(i, i / 2, 0.5);
          if (i / 2 + 1 < m)
            P.set(i, i / 2 + 1, 0.5);
        }
  }


  /** The (owned) entries of @p v as a serial vector. */
  Vector<double>
  to_vector(const LevelVector &v)
  {
    return Vector<double>(v.begin(), v.end());
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  // large enough for several parallel subranges of every loop
  const unsigned int   n = 20001;
  const unsigned int   n_coarse = (n + 1) / 2; // the m of make_problem
  SparsityPattern      A_pattern, P_pattern, product_pattern, galerkin_pattern;
  SparseMatrix<double> A, P;
  make_problem(n, A_pattern, A, P_pattern, P);
  {
    DynamicSparsityPattern product_dsp, galerkin_dsp;
    product_dsp.compute_mmult_pattern(A_pattern, P_pattern);
    product_pattern.copy_from(product_dsp);
    galerkin_dsp.compute_Tmmult_pattern(P_pattern, product_pattern);
    galerkin_pattern.copy_from(galerkin_dsp);
  }

  // 1. deal.II's mmult accumulates
  {
    SparseMatrix<double> product(product_pattern);
    A.mmult(product, P, Vector<double>(), false);
    const double once = product.frobenius_norm();
    A.mmult(product, P, Vector<double>(), false);
    std::cout << "deal.II mmult twice / once (Frobenius norm): "
              << rounded(product.frobenius_norm() / once) << std::endl;
  }

  // 2. GalerkinProduct overwrites and is exact
  GalerkinProduct galerkin_product;
  galerkin_product.initialize(
    P_pattern, A_pattern, serial_partitioner(n), galerkin_pattern, serial_partitioner(n_coarse));
  SparseMatrix<double> Pt(P_pattern), galerkin(galerkin_pattern);
  std::vector<double> results;
  for (const unsigned int threads : {1u, 2u})
    {
      MultithreadInfo::set_thread_limit(threads);
      for (const unsigned int truncate_every : {7u, 3u})
        {
          Pt.copy_from(P);
          for (unsigned int i = 0; i < n; i += truncate_every)
            for (auto e = Pt.begin(i); e != Pt.end(i); ++e)
              e->value() = 0.;
          galerkin_product.compute(A, Pt, galerkin);
          // the reference: deal.II's products into zeroed matrices
          SparseMatrix<double> product_ref(product_pattern), galerkin_ref(galerkin_pattern);
          A.mmult(product_ref, Pt, Vector<double>(), false);
          Pt.Tmmult(galerkin_ref, product_ref, Vector<double>(), false);
          galerkin_ref.add(-1., galerkin);
          check(galerkin_ref.linfty_norm() <= 1e-13 * galerkin.linfty_norm(),
                "threads " + std::to_string(threads) + ", fine DoFs 0, k, 2k, ... "
                "truncated (k = " + std::to_string(truncate_every) +
                  "): P~^T A P~ equals deal.II's product");
          for (auto e = galerkin.begin(); e != galerkin.end(); ++e)
            results.push_back(e->value());
        }
    }
  check(std::equal(results.begin(),
                   results.begin() + results.size() / 2,
                   results.begin() + results.size() / 2),
        "the same bits with 1 and 2 threads");

  // 2b. the drop rule (zero_round_off, applied to the Galerkin products):
  // entries with |g_ij| <= drop sqrt(g_ii g_jj) become 0, the others are
  // untouched (drop = 0.05 is far above round-off: it takes out the weak
  // couplings of this matrix, to see the rule work)
  {
    Pt.copy_from(P);
    SparseMatrix<double> reference(galerkin_pattern);
    galerkin_product.compute(A, Pt, reference);
    galerkin_product.compute(A, Pt, galerkin);
    zero_round_off(galerkin, serial_partitioner(n_coarse), 0.05);
    unsigned int n_dropped = 0, n_wrong = 0;
    for (unsigned int i = 0; i < galerkin.m(); ++i)
      for (auto e = galerkin.begin(i); e != galerkin.end(i); ++e)
        {
          const unsigned int j     = e->column();
          const double       ref   = reference.el(i, j);
          const double       bound = 0.05 * std::sqrt(reference.diag_element(i) *
                                                        reference.diag_element(j));
          if (std::abs(ref) <= bound)
            {
              n_dropped += ref != 0.;
              n_wrong += e->value() != 0.;
            }
          else
            n_wrong += e->value() != ref;
        }
    check(n_dropped > 0 && n_wrong == 0,
          "drop 0.05: the weak entries are 0, the others unchanged");
  }

  // 3. level scheduling of overlapping patches {i, i+1, i+2} of A
  std::vector<std::vector<types::global_dof_index>> patches;
  for (unsigned int i = 0; i + 2 < n; i += 1)
    patches.push_back({i, i + 1, i + 2});
  // a scattered order, as the vertex order of a refined mesh is: patches
  // k = 0, 5, 10, ... (independent: A couples DoFs at most 2 apart), then
  // 1, 6, 11, ..., then 2, 7, ... and the last group in reverse
  std::vector<std::vector<types::global_dof_index>> ordered;
  for (unsigned int start = 0; start < 4; ++start)
    for (unsigned int k = start; k < patches.size(); k += 5)
      ordered.push_back(patches[k]);
  for (unsigned int k = patches.size() - 1; k + 1 > 0; --k)
    if (k % 5 == 4)
      ordered.push_back(patches[k]);
  // patches starting at a and b are coupled if |a - b| <= 4
  std::vector<unsigned int> position(patches.size());
  for (unsigned int p = 0; p < ordered.size(); ++p)
    position[ordered[p][0]] = p;
  std::vector<std::vector<unsigned int>> coupled(ordered.size());
  for (unsigned int a = 0; a < patches.size(); ++a)
    for (unsigned int b = 0; b < patches.size(); ++b)
      if (a != b && a + 4 >= b && b + 4 >= a)
        coupled[position[a]].push_back(position[b]);
  // (one process: patch p carries its color in DoF p of its own partitioner)
  std::vector<types::global_dof_index> color_dof(ordered.size());
  for (unsigned int p = 0; p < ordered.size(); ++p)
    color_dof[p] = p;
  const auto color =
    VertexPatches<2>::level_schedule(coupled, color_dof, serial_partitioner(ordered.size()));
  const unsigned int n_colors = *std::max_element(color.begin(), color.end()) + 1;
  bool order_kept = true;
  for (unsigned int a = 0; a < patches.size(); ++a)
    for (unsigned int b = a + 1; b < std::min<unsigned int>(patches.size(), a + 5); ++b)
      {
        const unsigned int p = position[a], q = position[b];
        order_kept &= (p < q) == (color[p] < color[q]) && color[p] != color[q];
      }
  check(order_kept, "level scheduling: every coupled pair keeps its order");
  std::cout << "colors of " << ordered.size() << " patches: " << n_colors << std::endl;

  // two patches of one color that the matrix couples are refused, also by
  // a nonzero on one side only (an entry dropped on one side): patch {0}
  // reads DoF 1 of patch {1} (a_01 != 0), which does not read DoF 0
  for (const unsigned int first : {0u, 1u})
    {
      DynamicSparsityPattern dsp(2, 2);
      dsp.add(0, 0), dsp.add(0, 1), dsp.add(1, 0), dsp.add(1, 1);
      SparsityPattern pattern;
      pattern.copy_from(dsp);
      SparseMatrix<double> B(pattern);
      B.set(0, 0, 2.), B.set(1, 1, 2.), B.set(0, 1, -1.);
      PatchSmoother smoother(1);
      const std::vector<std::vector<types::global_dof_index>> two =
        first == 0 ? std::vector<std::vector<types::global_dof_index>>{{0}, {1}} :
                     std::vector<std::vector<types::global_dof_index>>{{1}, {0}};
      bool refused = false;
      try
        {
          smoother.initialize_level(
            0, B, two, {0, 0}, 1, {DoFRole::free, DoFRole::free}, serial_partitioner(2));
        }
      catch (const ExceptionBase &)
        {
          refused = true;
        }
      check(refused, "coupled patches in one color are refused (patch order " +
                       std::to_string(first) + ", 1)");
      smoother.initialize_level(
        0, B, two, {0, 1}, 2, {DoFRole::free, DoFRole::free}, serial_partitioner(2));
      check(smoother.n_colors(0) == 2, "and accepted in two colors");
    }

  // the colored sweep against a sequential one, forward and backward
  const auto           partitioner = serial_partitioner(n);
  std::vector<DoFRole> role(n, DoFRole::free);
  LevelVector          r(partitioner), ub(partitioner);
  for (unsigned int i = 0; i < n; ++i)
    r.local_element(i) = std::sin(1. + i);
  ub = 1e300;
  for (const bool backward : {false, true})
    {
      Vector<double> colored(n), sequential(n);
      for (const unsigned int threads : {1u, 2u})
        {
          MultithreadInfo::set_thread_limit(threads);
          PatchSmoother smoother(1);
          smoother.initialize_level(0, A, ordered, color, n_colors, role, partitioner);
          smoother.set_obstacles(0, ub);
          smoother.set_transpose(backward);
          smoother.set_steps(2);
          LevelVector v(partitioner);
          smoother.smooth(0, v, r);
          if (threads == 1)
            colored = to_vector(v);
          else
            check(to_vector(v) == colored,
                  std::string(backward ? "backward" : "forward") +
                    ": the same bits with 1 and 2 threads");
        }
      // sequential block Gauss-Seidel over the patches in their order
      for (unsigned int step = 0; step < 2; ++step)
        for (unsigned int kk = 0; kk < ordered.size(); ++kk)
          {
            const auto &       patch = ordered[backward ? ordered.size() - 1 - kk : kk];
            const unsigned int m     = patch.size();
            FullMatrix<double> M(m, m);
            Vector<double>     g(m), c(m);
            for (unsigned int a = 0; a < m; ++a)
              {
                g[a] = r.local_element(patch[a]);
                for (auto e = A.begin(patch[a]); e != A.end(patch[a]); ++e)
                  g[a] -= e->value() * sequential[e->column()];
                for (unsigned int b = 0; b < m; ++b)
                  M(a, b) = A.el(patch[a], patch[b]);
              }
            M.gauss_jordan();
            M.vmult(c, g);
            for (unsigned int a = 0; a < m; ++a)
              sequential[patch[a]] += c[a];
          }
      Vector<double> difference(colored);
      difference -= sequential;
      check(difference.linfty_norm() <= 1e-14 * sequential.linfty_norm(),
            std::string(backward ? "backward" : "forward") +
              ": colored sweep = sequential sweep in patch order");
    }
  return exit_code();
}
