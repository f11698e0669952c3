#ifndef fosls_contact_output_hertz_pressure_h
#define fosls_contact_output_hertz_pressure_h

#include <deal.II/base/tensor.h>

#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/parameters/parameters.h>

#include <array>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Hertz's solution for the scene's contact (Parameters::HertzComparison)
   * with the computed force, against the computed contact pressure.
   *
   * One body is rigid, the other elastic with E and nu, so the contact
   * modulus is E* = E / (1 - nu^2). With F the normal component of the
   * computed contact force times the Force factor (the full model's force,
   * of a model that is a symmetric part of it), per unit length for a
   * cylinder (in 3D divided by the contact line's Length):
   *   cylinder: a = sqrt(4 F R / (pi E*)),  p0 = 2 F / (pi a),
   *   sphere:   a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2),
   * and p(r) = p0 sqrt(1 - r^2 / a^2) for r < a, with r the distance from
   * the contact point in the plane of contact (orthogonal to the obstacle
   * normal there; for a cylinder in 3D, from the contact line through the
   * contact point along the Axis). Hertz assumes a half-space and a contact small against
   * R; the scenes are bodies of finite size, so expect agreement to a few
   * percent, improving with the mesh.
   */
  template <int dim>
  class HertzPressure
  {
  public:
    /**
     * @p normal: the unit obstacle normal at the contact point; the
     * material's E and nu are in the scene's units.
     */
    HertzPressure(const Parameters::HertzComparison &hertz,
                  const Parameters::Material &       material,
                  const Tensor<1, dim> &             normal);

    /**
     * Compare with @p force and the contact table @p rows
     * (ContactTable::rows()).
     */
    void evaluate(const Tensor<1, dim> &                           force,
                  const std::vector<typename ContactRow<dim>::Values> &rows);

    /** Hertz's pressure at distance @p r from the contact point. */
    double pressure(const double r) const;
    /** The distance of @p p from the contact point, in the plane of contact. */
    double distance(const Tensor<1, dim> &p) const;

    /** @{ After evaluate(): Hertz's F (the full model's), a and p0. */
    double normal_force() const { return force; }
    double half_width() const { return a; }
    double maximum_pressure() const { return p0; }
    /** @} */
    double force_factor() const { return hertz.force_factor; }
    const Tensor<1, dim> &contact_point() const { return center; }
    /** The unit obstacle normal at the contact point. */
    const Tensor<1, dim> &contact_normal() const { return normal; }
    /** Whether the obstacle is a cylinder (else a sphere). */
    bool cylinder() const;

    /**
     * The relative l2 error of the computed pressure at the contact
     * vertices against Hertz's (after evaluate()).
     */
    double relative_pressure_error() const { return pressure_error; }
    /**
     * The same weighted by the vertices' shares of the contact boundary
     * (ContactRow::share): the relative L2 error on the contact boundary,
     * by the vertex rule. The unweighted error weights every vertex alike,
     * so a mesh refined at the edge of the contact zone counts the edge,
     * where the pressure has its square-root behaviour, many times.
     */
    double relative_pressure_error_boundary() const { return pressure_error_boundary; }

    /** Two lines for the screen. */
    std::string report() const;
    /** The JSON object for summary.json. */
    std::string json() const;

  private:
    const Parameters::HertzComparison hertz;
    double                            contact_modulus; ///< E*
    Tensor<1, dim>                    normal, center;
    /** The unit axis of a cylinder in 3D, else zero. */
    Tensor<1, dim>                    axis;

    double force = 0, a = 0, p0 = 0;
    /** Largest r of a vertex in contact, smallest r of one beyond it. */
    double edge_inside = 0, edge_outside = 0;
    double peak = 0, peak_r = 0, pressure_error = 0, pressure_error_boundary = 0;
  };
} // namespace FoslsContact

#endif
