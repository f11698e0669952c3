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
   *    Measured with the push of the square (prm/square.prm, 6 levels),
   *    the contact force against the push's 1e-2 L: 2e-11 off at 1e-150 L,
   *    3e-8 at 1e-155 L, 5% at 1e-160 L (after 2 iterations), and 1e-170 L
   *    "converged" after one iteration with a largest displacement of 0;
   *    the cube on 4 levels: 1e-13 off at 1e-150 L, 2e-7 at 1e-155 L. The
   *    decline is steep and comes earlier on finer meshes, hence the
   *    margin of 1e5 from the first measured loss.
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
