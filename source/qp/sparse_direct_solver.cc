#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <fosls_contact/qp/sparse_direct_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <trilinos_klu_decl.h>

#include <algorithm>
#include <climits>
#include <limits>
#include <iomanip>
#include <sstream>


namespace FoslsContact
{
  namespace
  {
    const std::string singular_matrix_message =
      "the sparse direct solver (Amesos KLU) found the matrix singular in floating point; "
      "the functional is too badly conditioned for double precision: check that the "
      "'Functional weights' are not many orders of magnitude apart";

    /**
     * The eight-byte units that KLU allocates for the factors of the
     * largest block of a matrix on the pattern @p structure (n rows, all
     * here; symmetric, so its rows are its columns), as klu_factor()
     * computes them: for each diagonal block of its ordering (Amesos's
     * KLU's defaults: BTF and AMD), initmem_amd (1.2) times its estimate of
     * the block's entries in L, and as many in U, plus the block's size,
     * an index and a value each. KLU refuses a block of more than INT_MAX
     * units (its offsets into them are ints) as if it had run out of
     * memory. @p entries is the estimate of all entries of L and U. An
     * estimate past INT_MAX, which KLU keeps in an int, comes out
     * negative: infinitely many units. Negative if KLU cannot analyze the
     * pattern.
     */
    double
    klu_block_units(const SparsityPattern &structure, const unsigned int n, double &entries)
    {
      std::vector<int> starts(n + 1), rows;
      rows.reserve(structure.n_nonzero_elements());
      for (unsigned int i = 0; i < n; ++i)
        {
          for (auto e = structure.begin(i); e != structure.end(i); ++e)
            rows.push_back(e->column());
          starts[i + 1] = rows.size();
        }
      trilinos_klu_common common;
      trilinos_klu_defaults(&common);
      trilinos_klu_symbolic *symbolic = trilinos_klu_analyze(n, starts.data(), rows.data(), &common);
      if (symbolic == nullptr)
        return -1;
      entries      = symbolic->lnz + symbolic->unz;
      double units = 0;
      for (int b = 0; b < symbolic->nblocks; ++b)
        {
          const double size  = symbolic->R[b + 1] - symbolic->R[b];
          const double lnz   = symbolic->Lnz[b];
          const double lsize = common.initmem_amd * lnz + size;
          // (a block of one is no factorization)
          if (size > 1)
            units = std::max(units,
                             lnz < 0 ? std::numeric_limits<double>::infinity() :
                                       2 * lsize * (sizeof(int) + sizeof(double)) / sizeof(double));
        }
      if (entries < 0)
        units = std::numeric_limits<double>::infinity();
      trilinos_klu_free_symbolic(&symbolic, &common);
      return units;
    }
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
    // Trilinos' error -22 stands both for a zero pivot and for KLU's
    // refusal to allocate its factors; on one process (the matrix all
    // here) KLU's own estimate tells the two apart. On several, Amesos
    // factorizes on the first process, and only there returns the error:
    // every process takes the outcome, so that all stop with the same line
    // instead of the others waiting in the next collective call.
    const bool analyzed = Utilities::MPI::min(solver->SymbolicFactorization() == 0 ? 1 : 0, comm);
    const bool factorized =
      analyzed && Utilities::MPI::min(solver->NumericFactorization() == 0 ? 1 : 0, comm);
    if (factorized)
      return;
    AssertThrow(Utilities::MPI::n_mpi_processes(comm) == 1,
                ExcMessage("the sparse direct solver (Amesos KLU) cannot factorize the matrix of " +
                           std::to_string(p->size()) +
                           " DoFs: it is singular in floating point (the 'Functional weights' "
                           "many orders of magnitude apart), or its factors exceed what KLU can "
                           "hold (a large 3D mesh: use 'Solver/Type = monotone multigrid'); a "
                           "run on one process tells which"));
    double       entries = 0;
    const double units   = klu_block_units(structure, n, entries);
    std::ostringstream message;
    message << std::setprecision(2) << "the sparse direct solver (Amesos KLU) cannot factorize "
            << "the matrix of " << n << " DoFs: by KLU's estimate its factors hold " << entries
            << " entries, for which it would allocate " << units
            << " eight-byte units, more than its 32-bit offsets (" << double(INT_MAX)
            << ") allow; solve with 'Solver/Type = monotone multigrid' (and 'Solver/Cross "
            << "check = false'), or on fewer 'Geometry/Levels'";
    AssertThrow(!(units > INT_MAX), ExcMessage(message.str()));
    AssertThrow(false, ExcMessage(singular_matrix_message));
  }


  void
  SparseDirectSolver::solve(const std::vector<LevelVector *> &      x,
                            const std::vector<const LevelVector *> &b) const
  {
    // (the owned entries are the Epetra vectors' local ones, in the same
    // order)
    const unsigned int n       = partitioner->locally_owned_size();
    const int          columns = static_cast<int>(b.size());
    const auto &       A       = matrix->trilinos_matrix();
    Epetra_MultiVector X_t(A.DomainMap(), columns), B_t(A.RangeMap(), columns);
    for (int k = 0; k < columns; ++k)
      for (unsigned int i = 0; i < n; ++i)
        B_t[k][i] = b[k]->local_element(i);
    problem->SetLHS(&X_t);
    problem->SetRHS(&B_t);
    // (Amesos solves on the first process and returns its error only there:
    // every process takes the outcome, as after the factorization)
    const bool solved =
      Utilities::MPI::min(solver->Solve() == 0 ? 1 : 0, partitioner->get_mpi_communicator());
    AssertThrow(solved, ExcMessage(singular_matrix_message));
    for (int k = 0; k < columns; ++k)
      for (unsigned int i = 0; i < n; ++i)
        x[k]->local_element(i) = X_t[k][i];
  }


  void
  SparseDirectSolver::vmult(LevelVector &x, const LevelVector &b) const
  {
    solve({&x}, {&b});
  }


  void
  SparseDirectSolver::vmult(std::vector<LevelVector> &x, const std::vector<LevelVector> &b) const
  {
    AssertThrow(x.size() == b.size(), ExcDimensionMismatch(x.size(), b.size()));
    std::vector<LevelVector *>       to;
    std::vector<const LevelVector *> from;
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        to.push_back(&x[k]);
        from.push_back(&b[k]);
      }
    solve(to, from);
  }
} // namespace FoslsContact
