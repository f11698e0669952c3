#include <deal.II/base/index_set.h>

#include <fosls_contact/qp/sparse_direct_solver.h>

namespace FoslsContact
{
  SparseDirectSolver::SparseDirectSolver()
    : control(1, 0)
  {}


  void
  SparseDirectSolver::initialize(const SparseMatrix<double> &A,
                                 const SparsityPattern *     pattern)
  {
    matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    // (deal.II's default drop tolerance of the copy, 1e-13, on the values)
    matrix->reinit(A, 1e-13, true, pattern);
    solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
    solver->initialize(*matrix);
    const IndexSet all = complete_index_set(A.m());
    x_t.reinit(all, MPI_COMM_SELF);
    b_t.reinit(all, MPI_COMM_SELF);
  }


  void
  SparseDirectSolver::vmult(Vector<double> &x, const Vector<double> &b) const
  {
    for (types::global_dof_index i = 0; i < b.size(); ++i)
      b_t[i] = b[i];
    b_t.compress(VectorOperation::insert);
    solver->solve(x_t, b_t);
    x.reinit(b.size());
    for (types::global_dof_index i = 0; i < b.size(); ++i)
      x[i] = x_t[i];
  }
} // namespace FoslsContact
