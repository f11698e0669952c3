#ifndef fosls_contact_assembly_error_indicators_h
#define fosls_contact_assembly_error_indicators_h

#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/parameters/parameters.h>

namespace FoslsContact
{
  /**
   * The least-squares functional cell by cell: for every active cell T
   *
   *   eta_T^2 = C_eq ||div sigma + f||_T^2 + C_const ||A sigma - eps(u)||_T^2
   *           + C_compl <u.n - g, (sigma n_b).n>_{faces of T on Gamma_C},
   *
   * whose sum over the cells is J (paper eqs. 1-2). The functional of a
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
     * Evaluate the parts of eta_T^2 on the owned active cells for the
     * solution @p x_rotated (finest level, rotated basis, dimensionless).
     * Collective.
     */
    void compute(const LevelVector &x_rotated);

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

    /** total(), max_squared() and cells_for_half() from the parts. */
    void summarize();

    const Discretization<dim> &discretization;
    const Parameters::Weights  weights;
    double                     sum = 0, largest = 0;
    unsigned int               half_cells = 0;
  };
} // namespace FoslsContact

#endif
