// CollectiveError (base/collective_error.h), run on 2 MPI processes: an
// error that some processes meet in their own work stops every process
// with the error of the first (lowest rank) that failed, and a run where
// none failed goes on on every process:
// - nobody fails: run() returns everywhere;
// - only the second process fails (a deal.II exception): both throw, with
//   its text, as deal.II exceptions;
// - both fail with different texts: both throw the first process's text;
// - only the second process fails with an InputError: both throw an
//   InputError with its place and text, so main() prints the same line;
// - something that is no std::exception: "unknown error" everywhere;
// - on MPI_COMM_SELF the work's own exception leaves as it is (a
//   std::runtime_error stays one).
// Only the first process prints; a check holds if it holds on every
// process.
// ctest: sanitize
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/input_error.h>

#include <stdexcept>
#include <string>

#include "tests.h"

using namespace FoslsContactTests;
using FoslsContact::CollectiveError;
using FoslsContact::ErrorLine;
using FoslsContact::InputError;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  deal_II_exceptions::disable_abort_on_exception();
  deal_II_exceptions::suppress_stacktrace_in_exceptions();
  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
  const bool         first = rank == 0;
  auto everywhere = [&](const bool condition, const std::string &what) {
    check_everywhere(comm, condition, what);
  };
  if (first)
    std::cout << "processes: " << Utilities::MPI::n_mpi_processes(comm) << std::endl;

  // what run() throws on this process: "" if nothing, else its one line
  // text ("input: <where>: <what>" for an InputError)
  const auto outcome = [&](const MPI_Comm c, const auto &work) -> std::string {
    try
      {
        CollectiveError::run(c, work);
      }
    catch (const InputError &e)
      {
        return std::string("input: ") + e.where() + ": " + e.what();
      }
    catch (const ExceptionBase &e)
      {
        return "deal.II: " + ErrorLine::text(e);
      }
    catch (const std::exception &e)
      {
        return std::string("std: ") + e.what();
      }
    return "";
  };

  int done = 0;
  everywhere(outcome(comm, [&]() { ++done; }).empty() && done == 1,
             "nobody fails: the work ran once and run() returned on every process");
  everywhere(outcome(comm,
                     [&]() {
                       AssertThrow(rank == 0, ExcMessage("bad normal at rank 1"));
                     }) == "deal.II: bad normal at rank 1",
             "only the second process fails: both throw its text");
  everywhere(outcome(comm,
                     [&]() {
                       throw std::runtime_error("failure of rank " + std::to_string(rank));
                     }) == "deal.II: failure of rank 0",
             "both fail: both throw the first process's text");
  everywhere(outcome(comm,
                     [&]() {
                       if (rank == 1)
                         throw InputError("scene.prm:3", "no such file");
                     }) == "input: scene.prm:3: no such file",
             "an InputError of the second process: an InputError with its place everywhere");
  everywhere(outcome(comm,
                     [&]() {
                       if (rank == 1)
                         throw 42;
                     }) == "deal.II: unknown error",
             "no std::exception: \"unknown error\" everywhere");
  everywhere(outcome(MPI_COMM_SELF, [&]() { throw std::runtime_error("alone"); }) ==
               "std: alone",
             "MPI_COMM_SELF: the work's own exception");

  return first ? exit_code() : (n_failures() > 0 ? 1 : 0);
}
