#include <deal.II/lac/lapack_full_matrix.h>
#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/qp/definiteness_check.h>

namespace FoslsContact
{
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
      if (qp.role[i] == DoFRole::bounded)
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
    SparseDirectSolver direct;
    direct.initialize(M, qp.partitioner, qp.coupling_sparsity);

    const unsigned int       nc = contact.size();
    LAPACKFullMatrix<double> S(nc, nc);
    LevelVector column = qp.new_vector(), y = qp.new_vector(), Ay = qp.new_vector();
    for (unsigned int c = 0; c < nc; ++c)
      {
        // column = A_IC e_c
        column = 0;
        for (auto e = A.begin(contact[c]); e != A.end(contact[c]); ++e)
          if (qp.role[e->column()] == DoFRole::free)
            column.local_element(e->column()) = e->value(); // A symmetric
        direct.vmult(y, column);
        for (types::global_dof_index i = 0; i < n; ++i)
          if (qp.role[i] != DoFRole::free)
            y.local_element(i) = 0;
        vmult(A, Ay, y);
        for (unsigned int r = 0; r < nc; ++r)
          S(r, c) = A.el(contact[r], contact[c]) - Ay.local_element(contact[r]);
      }
    for (unsigned int r = 0; r < nc; ++r)
      for (unsigned int c = 0; c < nc; ++c)
        S(r, c) /= std::sqrt(A.diag_element(contact[r]) *
                             A.diag_element(contact[c]));
    // symmetrize the round-off
    for (unsigned int r = 0; r < nc; ++r)
      for (unsigned int c = 0; c < r; ++c)
        S(r, c) = S(c, r) = 0.5 * (S(r, c) + S(c, r));
    Vector<double> eigenvalues;
    FullMatrix<double> eigenvectors;
    S.compute_eigenvalues_symmetric(-1e300, 1e300, 0., eigenvalues, eigenvectors);
    result.min_relative_eigenvalue = eigenvalues.size() ? eigenvalues[0] : 1.;
    for (unsigned int i = 0; i < eigenvalues.size(); ++i)
      result.min_relative_eigenvalue =
        std::min(result.min_relative_eigenvalue, eigenvalues[i]);
    return result;
  }


  double
  DefinitenessCheck::least_mode_energy(const ConstrainedQP &     qp,
                                       std::vector<LevelVector> &modes,
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
        {
          G(a, b) = G(b, a) = 0.5 * (G(a, b) + G(b, a));
          M(a, b) = M(b, a) = 0.5 * (M(a, b) + M(b, a));
        }
    std::vector<Vector<double>> eigenvectors(k, Vector<double>(k));
    G.compute_generalized_eigenvalues_symmetric(M, eigenvectors);
    unsigned int least = 0;
    for (unsigned int a = 1; a < k; ++a)
      if (G.eigenvalue(a).real() < G.eigenvalue(least).real())
        least = a;
    coefficients = eigenvectors[least];
    coefficients /= coefficients.linfty_norm();
    return G.eigenvalue(least).real();
  }
} // namespace FoslsContact
