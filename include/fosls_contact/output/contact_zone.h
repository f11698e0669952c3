#ifndef fosls_contact_output_contact_zone_h
#define fosls_contact_output_contact_zone_h

#include <deal.II/base/point.h>

#include <fosls_contact/output/contact_table.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The contact zone in an engineer's terms, from the contact table
   * (ContactTable::rows(), the rows of contact.csv): its measure (a width
   * in 2D, an area in 3D), the mean and the peak contact pressure, in the
   * scene's units.
   *
   * The zone is where the contact vertices are in contact (u.n = g,
   * ContactTable::in_contact(), the `active` column): its measure is the
   * sum of the boundary shares of the vertices in contact (ContactRow::share,
   * each contact face's measure divided among its vertices). A face whose
   * vertices are all in contact counts whole, a face at the edge of the
   * zone with the fraction of its vertices in contact: the vertex rule
   * (trapezoidal rule) for the integral of the contact indicator over the
   * contact boundary. The true edge lies somewhere on the edge faces; this
   * puts it at their middle, within half a face of either end. The pressure
   * at a vertex is -sigma_nn, the mean over its contact faces (contact.csv);
   * the mean pressure is its integral over the zone by the same rule,
   * divided by the measure, and the peak pressure its largest value at a
   * contact vertex (the peak of the Hertz comparison). Where every vertex
   * is in contact, measure times mean pressure is the integral of the
   * pressure over the contact boundary: the contact force's normal part on
   * a flat obstacle.
   */
  template <int dim>
  class ContactZone
  {
  public:
    /** The zone of the contact table @p rows (of every process, gathered). */
    explicit ContactZone(const std::vector<typename ContactRow<dim>::Values> &rows);

    /** The width (2D) or area (3D) of the zone; length^(dim-1). */
    double measure() const { return zone_measure; }
    /** The mean contact pressure over the zone (0 for an empty zone); stress. */
    double mean_pressure() const { return mean; }
    /** The largest contact pressure -sigma_nn at a contact vertex (0 if none is > 0); stress. */
    double peak_pressure() const { return peak; }
    /** Where peak_pressure() is (the first such vertex by position). */
    const Point<dim> &peak_position() const { return peak_point; }
    /** The number of contact vertices in contact. */
    unsigned int vertices_in_contact() const { return n_in_contact; }
    /** The number of contact vertices. */
    unsigned int vertices() const { return n_vertices; }
    /**
     * Whether the mesh resolves the zone: no vertex in contact, or at
     * least 3 in 2D (two faces) and 5 in 3D (a vertex and its four
     * neighbours on a quadrilateral surface mesh). A zone of fewer is
     * decided by single vertices: an obstacle touching one vertex of the
     * square's bottom gives u.n = g there and a contact force of exactly 0
     * (one vertex carries no traction of its own: RT0's tractions live on
     * faces), and a finer mesh changes the figures by their whole size.
     */
    bool resolved() const
    {
      return n_in_contact == 0 || n_in_contact >= (dim == 2 ? 3u : 5u);
    }

  private:
    double       zone_measure = 0, mean = 0, peak = 0;
    Point<dim>   peak_point;
    unsigned int n_in_contact = 0, n_vertices = 0;
  };
} // namespace FoslsContact

#endif
