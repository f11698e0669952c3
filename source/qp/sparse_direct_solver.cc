#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <fosls_contact/qp/sparse_direct_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

#include <algorithm>

namespace FoslsContact
{
  namespace
  {
    const std::string singular_matrix_message =
      "the sparse direct solver (Amesos KLU) found the matrix singular in floating point; "
      "the functional is too badly conditioned for double precision: check that the "
      "'Functional weights' are not many orders of magnitude apart";
  } // namespace

  SparseDirectSolver::SparseDirectSolver() = default;
  SparseDirectSolver::~SparseDirectSolver() = default;


  void
  SparseDirectSolver::initialize(const SparseMatrix<double> &                               A,
                                 const std::shared_ptr<const Utilities::MPI::Partitioner> &p,
                                 const SparsityPattern *pattern)
  {
    partitioner              = p;
    const MPI_Comm     comm  = p->get_mpi_communicator();
    const IndexSet &   owned = p->locally_owned_range();
    const unsigned int n     = p->locally_owned_size();
    const SparsityPattern &structure = pattern ? *pattern : A.get_sparsity_pattern();

    TrilinosWrappers::SparsityPattern sp(owned, owned, comm);
    std::vector<types::global_dof_index> columns;
    for (unsigned int i = 0; i < n; ++i)
      {
        columns.clear();
        for (auto e = structure.begin(i); e != structure.end(i); ++e)
          columns.push_back(p->local_to_global(e->column()));
        sp.add_entries(p->local_to_global(i), columns.begin(), columns.end());
      }
    sp.compress();
    matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    matrix->reinit(sp);
    std::vector<double> values;
    for (unsigned int i = 0; i < n; ++i)
      {
        columns.clear();
        values.clear();
        for (auto e = A.begin(i); e != A.end(i); ++e)
          // (exact zeros only: the round-off entries are zero already,
          // ConstrainedQP::compress_matrices(); an absolute drop tolerance of
          // 1e-13 removed the constitutive couplings of mu = 1e7, whose
          // compliance is 1/(2 mu), and KLU found the matrix singular)
          if (e->value() != 0.)
            {
              columns.push_back(p->local_to_global(e->column()));
              values.push_back(e->value());
            }
        matrix->set(p->local_to_global(i), columns.size(), columns.data(), values.data());
      }
    matrix->compress(VectorOperation::insert);
    // (what deal.II's TrilinosWrappers::SolverDirect does, with the solver
    // kept here for solves with several columns at once)
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix->trilinos_matrix()));
    Amesos factory;
    solver.reset(factory.Create("Amesos_Klu", *problem));
    AssertThrow(solver, ExcMessage("Trilinos' Amesos has no KLU"));
    // (a nonzero error is Trilinos' -22: KLU found a zero pivot)
    AssertThrow(solver->SymbolicFactorization() == 0 && solver->NumericFactorization() == 0,
                ExcMessage(singular_matrix_message));
    x_t.reinit(owned, comm);
    b_t.reinit(owned, comm);
  }


  void
  SparseDirectSolver::solve(Epetra_MultiVector &X_t, Epetra_MultiVector &B_t) const
  {
    problem->SetLHS(&X_t);
    problem->SetRHS(&B_t);
    AssertThrow(solver->Solve() == 0, ExcMessage(singular_matrix_message));
  }


  void
  SparseDirectSolver::vmult(LevelVector &x, const LevelVector &b) const
  {
    const unsigned int n = partitioner->locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      b_t[partitioner->local_to_global(i)] = b.local_element(i);
    b_t.compress(VectorOperation::insert);
    solve(x_t.trilinos_vector(), b_t.trilinos_vector());
    for (unsigned int i = 0; i < n; ++i)
      x.local_element(i) = x_t[partitioner->local_to_global(i)];
  }


  void
  SparseDirectSolver::vmult(std::vector<LevelVector> &x, const std::vector<LevelVector> &b) const
  {
    // blocks of columns, so that the work vectors stay small next to A's
    // factors (the owned entries are the Epetra vectors' local ones, in
    // the same order)
    constexpr unsigned int block = 64;
    const unsigned int     n     = partitioner->locally_owned_size();
    const Epetra_BlockMap &map  = x_t.trilinos_vector().Map();
    AssertThrow(x.size() == b.size(), ExcDimensionMismatch(x.size(), b.size()));
    for (std::size_t first = 0; first < b.size(); first += block)
      {
        const auto         columns = static_cast<int>(std::min<std::size_t>(block, b.size() - first));
        Epetra_MultiVector X_t(map, columns), B_t(map, columns);
        for (int k = 0; k < columns; ++k)
          for (unsigned int i = 0; i < n; ++i)
            B_t[k][i] = b[first + k].local_element(i);
        solve(X_t, B_t);
        for (int k = 0; k < columns; ++k)
          for (unsigned int i = 0; i < n; ++i)
            x[first + k].local_element(i) = X_t[k][i];
      }
  }
} // namespace FoslsContact
