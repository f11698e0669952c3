// gather_all (qp/level_algebra.h), run on 2 MPI processes: every process gets every process's object, in the
// order of the ranks, and the same as from Utilities::MPI::all_gather(),
// for the three ways it takes:
// - a trivially copyable object (an int, a std::array) as bytes with
//   MPI_Allgather;
// - a std::vector of trivially copyable elements (the coarse solve's and
//   the Galerkin updates' entries and DoF lists) as bytes with
//   MPI_Allgatherv, also where one process's vector is empty;
// - anything else (a std::string) through Utilities::MPI::all_gather();
// and on MPI_COMM_SELF the object itself. Only the first process prints;
// a check holds if it holds on every process.
// ctest: sanitize
#include <deal.II/base/mpi.h>

#include <fosls_contact/qp/level_algebra.h>

#include <array>
#include <string>

#include "tests.h"

using namespace FoslsContactTests;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int               rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int               size = Utilities::MPI::n_mpi_processes(comm);
  const bool                       first = rank == 0;
  auto everywhere = [&](const bool condition, const std::string &what) {
    check_everywhere(comm, condition, what);
  };
  if (first)
    std::cout << "processes: " << size << std::endl;

  // a trivially copyable object
  const int         number = 10 * int(rank) + 1;
  const auto        numbers = gather_all(comm, number);
  bool              numbers_ok = numbers.size() == size;
  for (unsigned int p = 0; p < size && numbers_ok; ++p)
    numbers_ok = numbers[p] == 10 * int(p) + 1;
  everywhere(numbers_ok, "int: one per process, in rank order");
  const std::array<double, 2> pair{{0.5 + rank, -1. / (rank + 3.)}};
  everywhere(gather_all(comm, pair) == Utilities::MPI::all_gather(comm, pair),
             "std::array<double, 2>: as Utilities::MPI::all_gather");

  // vectors of plain data, of different lengths (the first process's empty)
  std::vector<std::array<double, 3>> entries;
  for (unsigned int k = 0; k < 3 * rank; ++k)
    entries.push_back({{double(rank), double(k), 1. / (k + 7.)}});
  const auto all_entries = gather_all(comm, entries);
  bool       entries_ok  = all_entries.size() == size;
  for (unsigned int p = 0; p < size && entries_ok; ++p)
    {
      entries_ok = all_entries[p].size() == 3 * p;
      for (unsigned int k = 0; k < all_entries[p].size() && entries_ok; ++k)
        entries_ok = all_entries[p][k][0] == p && all_entries[p][k][1] == k &&
                     all_entries[p][k][2] == 1. / (k + 7.);
    }
  everywhere(entries_ok, "vector of std::array<double, 3>: lengths 0, 3, ... and values by rank");
  everywhere(all_entries == Utilities::MPI::all_gather(comm, entries),
             "vector of std::array<double, 3>: as Utilities::MPI::all_gather");
  const std::vector<types::global_dof_index> dofs(rank + 1, 100 + rank);
  everywhere(gather_all(comm, dofs) == Utilities::MPI::all_gather(comm, dofs),
             "vector of DoF indices: as Utilities::MPI::all_gather");

  // not plain data: serialized
  const std::string text(rank + 2, char('a' + rank));
  everywhere(gather_all(comm, text) == Utilities::MPI::all_gather(comm, text),
             "std::string: as Utilities::MPI::all_gather");

  // one process: the object itself
  const auto alone = gather_all(MPI_COMM_SELF, entries);
  everywhere(alone.size() == 1 && alone[0] == entries, "MPI_COMM_SELF: the object itself");

  return first ? exit_code() : (n_failures() > 0 ? 1 : 0);
}
