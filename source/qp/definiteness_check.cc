#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <fosls_contact/qp/sparse_cholesky.h>

#include <fosls_contact/qp/definiteness_check.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FoslsContact
{
  namespace
  {
    /**
     * The eigenvalues and eigenvectors of @p M after averaging away the
     * round-off asymmetry of its entries.
     */
    void
    symmetric_eigenpairs(LAPACKFullMatrix<double> &M,
                         Vector<double> &          values,
                         FullMatrix<double> &      vectors)
    {
      for (unsigned int r = 0; r < M.m(); ++r)
        for (unsigned int c = 0; c < r; ++c)
          M(r, c) = M(c, r) = 0.5 * (M(r, c) + M(c, r));
      M.compute_eigenvalues_symmetric(-1e300, 1e300, 0., values, vectors);
    }

    /**
     * Whether the Cholesky factorization of @p M succeeds: the test sygv
     * makes before its eigenvalues, made here first because deal.II's
     * sygv prints a line to stderr when it fails, beside the one line of
     * the error that names the cause.
     */
    bool
    cholesky_succeeds(const LAPACKFullMatrix<double> &M)
    {
      const unsigned int  n = M.m();
      FullMatrix<double>  factor(n, n);
      for (unsigned int r = 0; r < n; ++r)
        {
          for (unsigned int c = 0; c <= r; ++c)
            {
              double sum = M(r, c);
              for (unsigned int k = 0; k < c; ++k)
                sum -= factor(r, k) * factor(c, k);
              if (c < r)
                factor(r, c) = sum / factor(c, c);
              else if (!(sum > 0))
                return false;
              else
                factor(r, r) = std::sqrt(sum);
            }
        }
      return true;
    }

    /**
     * DefinitenessCheck::limit_factor of the scaled Schur complement
     * @p S on the @p contact DoFs of @p qp: M_CC, the complementarity part
     * on them, scaled as S is (its diagonal is zero: the term couples a
     * displacement with a stress DoF, so the scaling by diag(A_CC) does not
     * depend on the weight).
     */
    double
    complementarity_limit(const ConstrainedQP &                        qp,
                          const std::vector<types::global_dof_index> &contact,
                          const LAPACKFullMatrix<double> &             S)
    {
      const unsigned int nc = contact.size();
      if (qp.matrix_compl.m() == 0)
        return std::numeric_limits<double>::infinity();
      std::vector<int> position(qp.size(), -1);
      for (unsigned int r = 0; r < nc; ++r)
        position[contact[r]] = r;
      LAPACKFullMatrix<double> minus_M(nc, nc), S0(S);
      for (unsigned int r = 0; r < nc; ++r)
        for (auto e = qp.matrix_compl.begin(contact[r]); e != qp.matrix_compl.end(contact[r]);
             ++e)
          if (position[e->column()] >= 0)
            minus_M(r, position[e->column()]) =
              -e->value() / std::sqrt(qp.matrix.diag_element(contact[r]) *
                                      qp.matrix.diag_element(e->column()));
      for (unsigned int r = 0; r < nc; ++r)
        for (unsigned int c = 0; c < nc; ++c)
          {
            // (symmetric to the last bit, as sygv reads one triangle)
            minus_M(r, c) = minus_M(c, r) = 0.5 * (minus_M(r, c) + minus_M(c, r));
            S0(r, c) += minus_M(r, c);
          }
      for (unsigned int r = 0; r < nc; ++r)
        for (unsigned int c = 0; c < r; ++c)
          S0(r, c) = S0(c, r) = 0.5 * (S0(r, c) + S0(c, r));
      // (S_0 itself indefinite in floating point)
      if (!cholesky_succeeds(S0))
        return std::numeric_limits<double>::quiet_NaN();
      std::vector<Vector<double>> no_vectors;
      try
        {
          minus_M.compute_generalized_eigenvalues_symmetric(S0, no_vectors);
        }
      catch (...)
        {
          // sygv's Cholesky factorization of S_0 failed
          return std::numeric_limits<double>::quiet_NaN();
        }
      double largest = 0;
      for (unsigned int i = 0; i < nc; ++i)
        largest = std::max(largest, minus_M.eigenvalue(i).real());
      return largest > 0 ? 1. / largest : std::numeric_limits<double>::infinity();
    }
  } // namespace

  DefinitenessCheck
  DefinitenessCheck::run(const ConstrainedQP &qp)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(qp.get_communicator()) == 1,
                ExcMessage("DefinitenessCheck: a problem of one process (GatheredQP)"));
    DefinitenessCheck result;
    const auto &      A = qp.matrix;
    const auto        n = qp.size();
    std::vector<types::global_dof_index> contact;
    for (types::global_dof_index i = 0; i < n; ++i)
      // (with friction the complementarity term couples the tangential
      // tractions and displacements of the contact boundary too)
      if (qp.role[i] == DoFRole::bounded || qp.role[i] == DoFRole::traction ||
          qp.role[i] == DoFRole::slip)
        contact.push_back(i);
    result.n_contact_dofs = contact.size();
    if (contact.empty())
      return result;

    // A_II with identity rows and columns on fixed and contact DoFs.
    SparseMatrix<double> M(A.get_sparsity_pattern());
    M.copy_from(A);
    for (types::global_dof_index i = 0; i < n; ++i)
      for (auto e = M.begin(i); e != M.end(i); ++e)
        if (qp.role[i] != DoFRole::free || qp.role[e->column()] != DoFRole::free)
          e->value() = (i == e->column()) ? 1. : 0.;
    SparseCholesky cholesky;
    if (!cholesky.factorize(M, qp.coupling_sparsity))
      {
        result.interior_definite = false;
        return result;
      }

    // the columns of S in blocks, each block solved at once
    constexpr unsigned int   block = 64;
    const unsigned int       nc    = contact.size();
    LAPACKFullMatrix<double> S(nc, nc);
    std::vector<LevelVector> columns(std::min(block, nc), qp.new_vector()), ys(columns);
    for (unsigned int first = 0; first < nc; first += block)
      {
        const unsigned int n_columns = std::min(block, nc - first);
        columns.resize(n_columns);
        ys.resize(n_columns);
        for (unsigned int k = 0; k < n_columns; ++k)
          {
            // column = A_IC e_c
            columns[k] = 0;
            for (auto e = A.begin(contact[first + k]); e != A.end(contact[first + k]); ++e)
              if (qp.role[e->column()] == DoFRole::free)
                columns[k].local_element(e->column()) = e->value(); // A symmetric
          }
        cholesky.solve(ys, columns);
        for (unsigned int k = 0; k < n_columns; ++k)
          {
            LevelVector &y = ys[k];
            for (types::global_dof_index i = 0; i < n; ++i)
              if (qp.role[i] != DoFRole::free)
                y.local_element(i) = 0;
            // (A y)_r on the contact rows only, each summed as vmult()
            // sums it
            for (unsigned int r = 0; r < nc; ++r)
              {
                double Ay = 0;
                for (auto e = A.begin(contact[r]); e != A.end(contact[r]); ++e)
                  Ay += e->value() * y.local_element(e->column());
                S(r, first + k) = A.el(contact[r], contact[first + k]) - Ay;
              }
          }
      }
    for (unsigned int r = 0; r < nc; ++r)
      for (unsigned int c = 0; c < nc; ++c)
        S(r, c) /= std::sqrt(A.diag_element(contact[r]) *
                             A.diag_element(contact[c]));
    result.limit_factor = complementarity_limit(qp, contact, S);
    Vector<double> eigenvalues;
    FullMatrix<double> eigenvectors;
    symmetric_eigenpairs(S, eigenvalues, eigenvectors);
    result.min_relative_eigenvalue = eigenvalues.size() ? eigenvalues[0] : 1.;
    for (unsigned int i = 0; i < eigenvalues.size(); ++i)
      result.min_relative_eigenvalue =
        std::min(result.min_relative_eigenvalue, eigenvalues[i]);
    return result;
  }


  double
  DefinitenessCheck::least_mode_energy(const ConstrainedQP &     qp,
                                       std::vector<LevelVector> &modes,
                                       const double              threshold,
                                       Vector<double> &          coefficients)
  {
    const unsigned int k = modes.size();
    const auto &       A = qp.matrix;
    LevelVector        diagonal = qp.new_vector();
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      diagonal.local_element(i) = A.diag_element(i);
    for (auto &mode : modes)
      for (unsigned int i = 0; i < qp.role.size(); ++i)
        if (qp.role[i] == DoFRole::fixed)
          mode.local_element(i) = 0;
    LAPACKFullMatrix<double> G(k, k), M(k, k);
    LevelVector              product = qp.new_vector();
    for (unsigned int a = 0; a < k; ++a)
      {
        vmult(A, product, modes[a]);
        for (unsigned int b = 0; b < k; ++b)
          G(a, b) = modes[b] * product;
        product = modes[a];
        product.scale(diagonal);
        for (unsigned int b = 0; b < k; ++b)
          M(a, b) = modes[b] * product;
      }
    for (unsigned int a = 0; a < k; ++a)
      for (unsigned int b = 0; b < a; ++b)
        G(a, b) = G(b, a) = 0.5 * (G(a, b) + G(b, a));
    // The generalized problem G c = q M c, with M only semidefinite where
    // the fixed DoFs hold a whole mode (every vertex of a one-cell mesh
    // with Dirichlet sides): on the range of M, M = V L V^T, with
    // W = V L^{-1/2}, the least eigenvalue of W^T G W (LAPACK's sygv
    // refuses a singular M)
    Vector<double>     m_values;
    FullMatrix<double> m_vectors;
    symmetric_eigenpairs(M, m_values, m_vectors);
    // the modes the matrix moves: eigenvalues above its round-off
    constexpr double relative_round_off = 1e-12;
    double           largest            = 0;
    for (unsigned int a = 0; a < m_values.size(); ++a)
      largest = std::max(largest, m_values[a]);
    std::vector<unsigned int> range;
    for (unsigned int a = 0; a < m_values.size(); ++a)
      if (m_values[a] > relative_round_off * largest)
        range.push_back(a);
    coefficients.reinit(k);
    if (range.empty())
      return std::numeric_limits<double>::infinity(); // no mode can move
    const unsigned int r = range.size();
    FullMatrix<double> W(k, r);
    for (unsigned int a = 0; a < k; ++a)
      for (unsigned int b = 0; b < r; ++b)
        W(a, b) = m_vectors(a, range[b]) / std::sqrt(m_values[range[b]]);
    LAPACKFullMatrix<double> H(r, r);
    for (unsigned int a = 0; a < r; ++a)
      for (unsigned int b = 0; b < r; ++b)
        {
          double h = 0;
          for (unsigned int i = 0; i < k; ++i)
            for (unsigned int j = 0; j < k; ++j)
              h += W(i, a) * G(i, j) * W(j, b);
          H(a, b) = h;
        }
    Vector<double>     h_values;
    FullMatrix<double> h_vectors;
    symmetric_eigenpairs(H, h_values, h_vectors);
    unsigned int least = 0;
    for (unsigned int a = 1; a < h_values.size(); ++a)
      if (h_values[a] < h_values[least])
        least = a;
    // the modes in the combinations with an energy up to the threshold
    // (several where more than one motion is free), or in the least one
    for (unsigned int a = 0; a < h_values.size(); ++a)
      if (a == least || h_values[a] <= threshold)
        {
          Vector<double> combination(k);
          for (unsigned int i = 0; i < k; ++i)
            for (unsigned int b = 0; b < r; ++b)
              combination[i] += W(i, b) * h_vectors(b, a);
          combination /= combination.linfty_norm();
          for (unsigned int i = 0; i < k; ++i)
            coefficients[i] = std::max(coefficients[i], std::abs(combination[i]));
        }
    return h_values[least];
  }
} // namespace FoslsContact
