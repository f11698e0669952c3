// Helpers shared by the unit tests in tests/unit: building parameters from
// text, and a check() that prints one deterministic line per assertion and
// remembers failures (main returns a nonzero exit code if one failed, so a
// test fails even if someone regenerates its .output file carelessly).
#ifndef fosls_contact_tests_h
#define fosls_contact_tests_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fosls_contact/parameters/parameters.h>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace FoslsContactTests
{
  using namespace dealii;
  using namespace FoslsContact;

  inline unsigned int &
  n_failures()
  {
    static unsigned int n = 0;
    return n;
  }

  /** Print "what: ok" or "what: FAILED" and count failures. */
  inline bool
  check(const bool condition, const std::string &what)
  {
    std::cout << what << ": " << (condition ? "ok" : "FAILED") << std::endl;
    if (!condition)
      ++n_failures();
    return condition;
  }

  /**
   * check() on several processes: @p condition must hold on every process
   * of @p comm; the first process prints the line, another counts a
   * failure where it does not hold everywhere. Collective.
   */
  inline bool
  check_everywhere(const MPI_Comm comm, const bool condition, const std::string &what)
  {
    const bool all = Utilities::MPI::min(condition ? 1u : 0u, comm) == 1u;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      check(all, what);
    else if (!all)
      ++n_failures();
    return all;
  }

  /** The exit code of main(). */
  inline int
  exit_code()
  {
    if (n_failures() > 0)
      std::cout << n_failures() << " check(s) FAILED" << std::endl;
    return n_failures() > 0 ? 1 : 0;
  }

  /** A number rounded to @p digits significant digits, as text. */
  inline std::string
  rounded(const double value, const int digits = 6)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << value;
    return s.str();
  }

  /**
   * Parameters from a parameter file @p file (may be empty) with
   * overrides "Section/Name" -> value applied afterwards, like --set.
   */
  inline Parameters::AllParameters
  make_parameters(const std::string &file,
                  const std::vector<std::pair<std::string, std::string>>
                    &overrides = {},
                  const std::string &text = "")
  {
    ParameterHandler prm;
    Parameters::AllParameters::declare_parameters(prm);
    if (!file.empty())
      prm.parse_input(file);
    if (!text.empty())
      prm.parse_input_from_string(text);
    for (const auto &[path, value] : overrides)
      {
        const auto slash = path.rfind('/');
        const auto sections =
          Utilities::split_string_list(path.substr(0, slash), '/');
        for (const auto &s : sections)
          prm.enter_subsection(s);
        prm.set(path.substr(slash + 1), value);
        for (unsigned int i = 0; i < sections.size(); ++i)
          prm.leave_subsection();
      }
    Parameters::AllParameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }

  /** The path of a scene file in prm/ of the source tree. */
  inline std::string
  scene_file(const std::string &name)
  {
    return std::string(FOSLS_SOURCE_DIR) + "/prm/" + name;
  }

  /**
   * A portable pseudo-random number in [-1, 1) (a 64-bit LCG): the same
   * sequence with every compiler and standard library, unlike <random>'s
   * distributions.
   */
  class Random
  {
  public:
    explicit Random(const std::uint64_t seed = 42)
      : state(seed)
    {}
    double
    operator()()
    {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<double>(state >> 11) / 4503599627370496.0 - 1.0;
    }

  private:
    std::uint64_t state;
  };
} // namespace FoslsContactTests

#endif
