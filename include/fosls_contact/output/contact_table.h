#ifndef fosls_contact_output_contact_table_h
#define fosls_contact_output_contact_table_h

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/qp/constrained_qp.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * A row of the contact table (ContactTable::rows(), contact.csv):
   * the positions of its entries.
   */
  template <int dim>
  struct ContactRow
  {
    static constexpr unsigned int x        = 0;       ///< position (dim)
    static constexpr unsigned int u        = dim;     ///< displacement (dim)
    static constexpr unsigned int u_n      = 2 * dim; ///< normal displacement
    /** The initial gap g (Data/Gap) along the obstacle normal. */
    static constexpr unsigned int gap           = 2 * dim + 1;
    /** The remaining gap g - u_n: 0 where the body touches the obstacle. */
    static constexpr unsigned int remaining_gap = 2 * dim + 2;
    static constexpr unsigned int sigma_nn      = 2 * dim + 3; ///< mean normal traction
    /**
     * The vertex's share of the contact boundary: the measure of its
     * contact faces, each divided among its vertices (in the scene's units,
     * length^(dim-1)); the weights of a quadrature over the contact
     * boundary.
     */
    static constexpr unsigned int share      = 2 * dim + 4;
    static constexpr unsigned int in_contact = 2 * dim + 5; ///< 1 in contact, else 0
    /**
     * With friction (else 0): the tangential displacement of the load step
     * (u_t - p_t, relative to the displacement it starts from: what
     * friction resists), Cartesian (dim); the tangential traction on the
     * body, the mean over the contact faces at the vertex (dim); and the
     * status: 0 separated, 1 stick (no slip in the step, or a tangential
     * displacement prescribed), 2 slip.
     */
    static constexpr unsigned int slip       = 2 * dim + 6;
    static constexpr unsigned int traction_t = 3 * dim + 6;
    static constexpr unsigned int status     = 4 * dim + 6;
    static constexpr unsigned int size       = 4 * dim + 7;
    using Values                           = std::array<double, size>;
  };


  /**
   * The solution at the contact vertices of the finest level, one row per
   * vertex in the scene's units, gathered on the first process and sorted
   * by position so that contact.csv and the Hertz comparison are the same
   * on any number of processes. Which vertex counts as in contact is
   * decided here (in_contact()), for the table and the VTU's contact
   * status alike.
   */
  template <int dim>
  class ContactTable
  {
  public:
    /**
     * With @p friction (the problem's friction terms) the rows have the
     * friction columns too.
     */
    explicit ContactTable(const Discretization<dim> &discretization,
                          const FrictionTerms *      friction = nullptr);

    /**
     * One row per contact vertex of the finest level, sorted by position,
     * in the scene's units (ContactRow): the position, the displacement,
     * u_n, the gap, sigma_nn (the mean over the contact faces at the
     * vertex), its share of the contact boundary, and 1 if the vertex is
     * in contact (u_n = g), else 0. On the first process; collective.
     */
    std::vector<typename ContactRow<dim>::Values> rows(const LevelVector &x_rotated) const;
    /**
     * The rows of every contact vertex of this process's owned and ghost
     * cells, by vertex index (the pressure of a vertex of an owned cell is
     * complete: every face at it belongs to an owned or a ghost cell): what
     * the contact surface shows at the vertices, so that it has
     * contact.csv's values. Not collective.
     */
    std::map<unsigned int, typename ContactRow<dim>::Values>
    local_rows(const LevelVector &x_rotated) const;

    /** rows() as CSV text (on the first process; collective). */
    std::string csv(const LevelVector &x_rotated) const;

    /**
     * Whether a contact vertex with normal displacement @p u_n is in
     * contact with the obstacle at gap @p gap: the solvers leave an active
     * DoF at its bound up to round-off, relative to the gap and to 1 (a
     * gap of 0).
     */
    static bool in_contact(const double u_n, const double gap);

  private:
    /**
     * The friction columns of the rows @p rows (by vertex index) at
     * @p x (rotated, its local elements @p x_local).
     */
    void add_friction(const LocalElements &                          x_local,
                      std::map<unsigned int, typename ContactRow<dim>::Values> &rows) const;

    const Discretization<dim> &discretization;
    const FrictionTerms *      friction;
  };
} // namespace FoslsContact

#endif
