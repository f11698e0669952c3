#ifndef fosls_contact_problem_data_check_h
#define fosls_contact_problem_data_check_h

#include <deal.II/base/mpi.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/scene.h>

#include <string>

namespace FoslsContact
{
  /**
   * The check of the data values the program has evaluated (the Dirichlet
   * values at the Dirichlet vertices, the traction on the faces where it
   * acts, the gap at the contact vertices and faces, the body force at the
   * quadrature points; ScaledFunction records them), against what double
   * precision can solve with:
   *  - a value that is not finite (a NaN or Inf at one point);
   *  - a value whose dimensionless size (u/L, t/S, g/L, f L/S) is above
   *    #largest: the squares of the functional overflow (without this
   *    check, a gap of 1e154 L gives a NaN iterate, a traction of 1e200 S a
   *    starting iterate that is not finite);
   *  - data that are all so small that the dimensionless solution's
   *    squares underflow (nonzero, but the largest load below #smallest).
   *    The contact force of a tiny push loses its digits steeply below
   *    about 1e-155 L, earlier on finer meshes, and a push of 1e-170 L
   *    "converges" to nothing; hence the margin of 1e5 from the first
   *    loss (doc/performance.md, "Figures behind the code").
   * Each is refused in one line that names the parameter, its value and the
   * point (in the scene's units), decided by all processes together.
   */
  template <int dim>
  struct DataCheck
  {
    /** The largest dimensionless data value accepted. */
    static constexpr double largest = 1e100;
    /**
     * The dimensionless load below which nonzero data are refused: the
     * largest of |u|/L (Dirichlet values), |t|/S, |f| L/S and the
     * penetration -g/L where the gap is negative (a positive gap loads
     * nothing). Its square, times the weights and the cells' measures, is
     * what the energy norm adds up; double precision ends at 2e-308.
     */
    static constexpr double smallest = 1e-150;

    /**
     * Refuse the data of @p scene (with the expressions of @p parameters)
     * that are not finite, too large or too small, in one line. Collective
     * on @p comm.
     */
    static void check(const Parameters::AllParameters &parameters,
                      const Scene<dim> &               scene,
                      const MPI_Comm                   comm);
  };
} // namespace FoslsContact

#endif
