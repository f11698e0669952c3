// SameInput (input/same_input.h), run on 2 MPI processes: the processes
// compare the parts of their input in order, and all throw the same
// InputError naming the first part that differs:
// - the same parts everywhere: check() returns on every process;
// - a mesh file that differs on the second process (the same name, other
//   bytes, as on a node with another file): "another mesh file";
// - the second process with one part less (a process started with
//   --help reads no scene): the part the first process has beyond it,
//   named alike on both;
// - on one process nothing is compared.
// Only the first process prints; a check holds if it holds on every
// process.
#include <deal.II/base/mpi.h>

#include <fosls_contact/base/input_error.h>
#include <fosls_contact/input/same_input.h>

#include <string>

#include "tests.h"

using namespace FoslsContactTests;
using FoslsContact::InputError;
using FoslsContact::SameInput;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
  const bool         first = rank == 0;
  if (first)
    std::cout << "processes: " << Utilities::MPI::n_mpi_processes(comm) << std::endl;
  // what check() throws on this process ("" if nothing)
  const auto outcome = [&](const SameInput &input, const MPI_Comm c) -> std::string {
    try
      {
        input.check(c);
      }
    catch (const InputError &e)
      {
        return e.where() + ": " + e.what();
      }
    return "";
  };
  const auto everywhere = [&](const bool condition, const std::string &what) {
    check_everywhere(comm, condition, what);
  };

  SameInput same;
  same.add("command line", "scene.prm");
  same.add("mesh file (body.msh)", "$MeshFormat 2.2 0 8");
  everywhere(outcome(same, comm).empty(), "the same input: check() returns");

  SameInput mesh;
  mesh.add("command line", "scene.prm");
  mesh.add("mesh file (body.msh)", first ? "$MeshFormat 2.2 0 8" : "$MeshFormat 2.2 0 8\n");
  const std::string error = outcome(mesh, comm);
  if (first)
    std::cout << error << std::endl;
  everywhere(error.find("process 1 was started with another mesh file (body.msh)") !=
               std::string::npos,
             "a mesh file that differs: named on every process");

  SameInput fewer;
  fewer.add("command line", "--help");
  if (first)
    fewer.add("scene (its parameter values)", "set Levels = 3");
  everywhere(outcome(fewer, comm).find("another scene (its parameter values)") !=
               std::string::npos,
             "a process with a part less: the part it lacks named");

  everywhere(outcome(mesh, MPI_COMM_SELF).empty(), "one process: nothing compared");
  return n_failures() > 0;
}
