#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <fosls_contact/qp/sparse_direct_solver.h>

namespace FoslsContact
{
  namespace
  {
    const std::string singular_matrix_message =
      "the sparse direct solver (Amesos KLU) found the matrix singular in floating point; "
      "the functional is too badly conditioned for double precision: check that the "
      "'Functional weights' are not many orders of magnitude apart";
  } // namespace

  SparseDirectSolver::SparseDirectSolver()
    : control(1, 0)
  {}


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
    solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
    try
      {
        solver->initialize(*matrix);
      }
    catch (const ExceptionBase &)
      {
        // (deal.II's message is Trilinos' error number, -22: KLU found a
        // zero pivot)
        AssertThrow(false, ExcMessage(singular_matrix_message));
      }
    x_t.reinit(owned, comm);
    b_t.reinit(owned, comm);
  }


  void
  SparseDirectSolver::vmult(LevelVector &x, const LevelVector &b) const
  {
    const unsigned int n = partitioner->locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      b_t[partitioner->local_to_global(i)] = b.local_element(i);
    b_t.compress(VectorOperation::insert);
    try
      {
        solver->solve(x_t, b_t);
      }
    catch (const ExceptionBase &)
      {
        AssertThrow(false, ExcMessage(singular_matrix_message));
      }
    for (unsigned int i = 0; i < n; ++i)
      x.local_element(i) = x_t[partitioner->local_to_global(i)];
  }
} // namespace FoslsContact
