#ifndef fosls_contact_assembly_error_indicators_h
#define fosls_contact_assembly_error_indicators_h

#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>

#include <unordered_map>

namespace FoslsContact
{
  /**
   * The least-squares functional cell by cell: for every active cell T
   *
   *   eta_T^2 = C_eq ||div sigma + f||_T^2 + C_const ||A sigma - eps(u)||_T^2
   *           + C_compl <u.n - g, (sigma n_b).n>_{faces of T on Gamma_C}
   *           + (with friction) the friction term of its contact faces,
   *
   * whose sum over the cells is J (paper eqs. 1-2; doc/method.md section
   * 7.7 for the friction term, C_compl sum_{v of F} |F|/2^(dim-1)
   * [(P_F sigma_F n).(P_v (u(v) - p(v))) + s_F |P_v (u(v) - p(v))|], which
   * is >= 0 where the tangential traction is within its bound s_F, and 0
   * where the friction law holds). The functional of a
   * least-squares method bounds the error from above and below (paper
   * section 1: "a reliable and efficient a posteriori error estimator"),
   * and its cellwise parts show where the error is: these are the error
   * indicators written to the VTU and summarized in summary.json.
   *
   * Computed in the dimensionless form the solvers minimize (ReferenceScales), with
   * the same quadrature as FoslsAssembler, so that their sum is the J of
   * ConstrainedQP up to round-off; ReferenceScales::functional() converts to the
   * scene's units.
   */
  template <int dim>
  class ErrorIndicators
  {
  public:
    ErrorIndicators(const Discretization<dim> &discretization,
                    const Parameters::Weights &weights);

    /**
     * With friction: the problem whose friction terms J holds (its slip
     * bounds s_F and references p in the rotated basis), and the step's
     * reference displacement in Cartesian coordinates on the finest level,
     * as the assembly took it (nullptr in a path's first step: zero).
     */
    struct Friction
    {
      const ConstrainedQP &qp;
      const LevelVector *  reference;
    };

    /**
     * Evaluate the parts of eta_T^2 on the owned active cells for the
     * solution @p x_rotated (finest level, rotated basis, dimensionless),
     * with the friction terms of @p friction where it is given. Collective.
     */
    void compute(const LevelVector &x_rotated, const Friction *friction = nullptr);

    /** The parts, indexed by active_cell_index() (0 on cells not owned). */
    Vector<double> eq, constitutive, complementarity;

    /** eta_T^2 of cell @p i. */
    double squared(const unsigned int i) const
    {
      return eq[i] + constitutive[i] + complementarity[i];
    }
    /** The sum of eta_T^2 over all cells and processes: J. */
    double total() const { return sum; }
    /** The largest eta_T^2 over all cells and processes. */
    double max_squared() const { return largest; }
    /**
     * The smallest number of cells whose eta_T^2 make up half of J (all
     * processes): few cells against many shows an error concentrated at
     * singularities, where adaptive refinement pays.
     */
    unsigned int cells_for_half() const { return half_cells; }

  private:
    struct Scratch;
    /** No data goes from a cell to a copier: a cell writes its own entries. */
    struct Empty
    {};

    /** The parts of eta_T^2 of one owned @p cell, for the Cartesian @p solution. */
    void cell_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     const LevelVector &                                   solution,
                     Scratch &                                             scratch);

    /**
     * The term s_F |P_v (u(v) - p(v))| of every friction face of the finest
     * level, by face index, from the slip DoFs of ConstrainedQP::friction
     * as ConstrainedQP::friction_term() sums them (per DoF there, per face
     * here: the same sum). A vertex whose tangential displacement is
     * prescribed has no slip DoF and no term (a constant of J left out).
     */
    std::unordered_map<unsigned int, double> slip_terms(const LevelVector &  x_rotated,
                                                        const ConstrainedQP &qp) const;

    /** C_compl (P_F sigma_F n).(P_v (u(v) - p(v))) of contact face @p f of @p cell. */
    double friction_bilinear(const typename DoFHandler<dim>::active_cell_iterator &cell,
                             const unsigned int                                    f,
                             const LevelVector &                                   solution,
                             Scratch &                                             scratch) const;

    /** total(), max_squared() and cells_for_half() from the parts. */
    void summarize();

    const Discretization<dim> &discretization;
    const Parameters::Weights  weights;
    /** During compute() with friction: slip_terms() and p (Cartesian, active DoFs). */
    const std::unordered_map<unsigned int, double> *slip_term = nullptr;
    const LevelVector *                             reference = nullptr;
    double                     sum = 0, largest = 0;
    unsigned int               half_cells = 0;
  };
} // namespace FoslsContact

#endif
