#include <deal.II/base/numbers.h>

#include <fosls_contact/base/json.h>
#include <fosls_contact/output/hertz_pressure.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  HertzPressure<dim>::HertzPressure(const Parameters::HertzComparison &hertz,
                                    const Parameters::Material &       material,
                                    const Tensor<1, dim> &             normal)
    : hertz(hertz)
    , contact_modulus(material.youngs_modulus /
                      (1. - material.poisson_ratio * material.poisson_ratio))
    , normal(normal)
  {
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = hertz.contact_point[d];
    if (dim == 3 && hertz.shape == Parameters::HertzComparison::Shape::cylinder)
      {
        for (unsigned int d = 0; d < dim; ++d)
          axis[d] = hertz.axis[d];
        axis /= axis.norm();
      }
  }


  template <int dim>
  double
  HertzPressure<dim>::distance(const Tensor<1, dim> &p) const
  {
    Tensor<1, dim> d = p - center;
    // (axis is zero but for a cylinder in 3D, whose distance is from the
    // contact line)
    d -= (d * axis) * axis;
    return (d - (d * normal) * normal).norm();
  }


  template <int dim>
  double
  HertzPressure<dim>::pressure(const double r) const
  {
    return r < a ? p0 * std::sqrt(1. - r * r / (a * a)) : 0.;
  }


  template <int dim>
  void
  HertzPressure<dim>::evaluate(const Tensor<1, dim> &                           total_force,
                                 const std::vector<typename ContactRow<dim>::Values> &rows)
  {
    const double R = hertz.radius, pi = numbers::PI;
    // the full model's force (per unit length for a cylinder)
    force = hertz.force_factor * std::abs(total_force * normal);
    if (dim == 3 && hertz.shape == Parameters::HertzComparison::Shape::cylinder)
      force /= hertz.length;
    if (hertz.shape == Parameters::HertzComparison::Shape::cylinder)
      {
        a  = std::sqrt(4. * force * R / (pi * contact_modulus));
        p0 = a > 0 ? 2. * force / (pi * a) : 0.;
      }
    else
      {
        a  = std::cbrt(3. * force * R / (4. * contact_modulus));
        p0 = a > 0 ? 3. * force / (2. * pi * a * a) : 0.;
      }
    edge_inside  = 0;
    edge_outside = std::numeric_limits<double>::infinity();
    peak = peak_r = 0;
    double difference = 0, norm = 0, difference_boundary = 0, norm_boundary = 0;
    for (const auto &row : rows)
      {
        Tensor<1, dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = row[d];
        const double r = distance(p), p_h = -row[ContactRow<dim>::sigma_nn];
        if (row[ContactRow<dim>::in_contact] == 1)
          edge_inside = std::max(edge_inside, r);
        if (p_h > peak)
          {
            peak   = p_h;
            peak_r = r;
          }
        difference += (p_h - pressure(r)) * (p_h - pressure(r));
        norm += pressure(r) * pressure(r);
        const double w = row[ContactRow<dim>::share];
        difference_boundary += w * (p_h - pressure(r)) * (p_h - pressure(r));
        norm_boundary += w * pressure(r) * pressure(r);
      }
    for (const auto &row : rows)
      {
        Tensor<1, dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = row[d];
        if (row[ContactRow<dim>::in_contact] == 0 && distance(p) > edge_inside)
          edge_outside = std::min(edge_outside, distance(p));
      }
    // (where Hertz's pressure is 0 at every contact vertex, without a
    // force or with a zone between the vertices, a relative error is not
    // defined: it is NaN, null in summary.json, and not 0, which would
    // read as a perfect match)
    const double undefined  = std::numeric_limits<double>::quiet_NaN();
    pressure_error          = norm > 0 ? std::sqrt(difference / norm) : undefined;
    pressure_error_boundary = norm_boundary > 0 ? std::sqrt(difference_boundary / norm_boundary) :
                                                  undefined;
    // (a peak on the contact point itself, up to round-off)
    constexpr double round_off = 1e-12;
    if (peak_r < round_off * R)
      peak_r = 0;
  }


  template <int dim>
  std::string
  HertzPressure<dim>::report() const
  {
    std::ostringstream out;
    out << std::setprecision(4) << "Hertz ("
        << (cylinder() ? "cylinder, per unit length" : "sphere") << ", R = " << hertz.radius
        << ", E* = " << contact_modulus;
    if (hertz.force_factor != 1)
      out << ", force factor " << hertz.force_factor;
    out << "): F = " << force << ", a = " << a
        << ", p0 = " << p0 << "\n"
        << "       computed: contact edge between " << edge_inside << " and "
        << edge_outside << ", peak pressure " << peak << " at r = " << peak_r
        << std::setprecision(3);
    if (std::isnan(pressure_error))
      out << ", no pressure error (Hertz's pressure is 0 at every contact vertex)";
    else
      out << ", pressure error " << pressure_error << " (relative l2 at the contact vertices), "
          << pressure_error_boundary << " (relative L2 on the contact boundary)";
    return out.str();
  }


  template <int dim>
  std::string
  HertzPressure<dim>::json() const
  {
    const auto number = json_number;
    std::ostringstream out;
    out << "{\"shape\": \"" << (cylinder() ? "cylinder" : "sphere")
        << "\", \"radius\": " << number(hertz.radius)
        << ", \"force_factor\": " << number(hertz.force_factor) << ", \"contact_point\": [";
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? ", " : "") << number(center[d]);
    out << "], \"normal\": [";
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? ", " : "") << number(normal[d]);
    out << "], \"axis\": [";
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? ", " : "") << number(axis[d]);
    out << "], \"contact_modulus\": " << number(contact_modulus)
        << ", \"force\": " << number(force) << ", \"a\": " << number(a)
        << ", \"p0\": " << number(p0) << ", \"edge_inside\": " << number(edge_inside)
        << ", \"edge_outside\": " << number(edge_outside) << ", \"peak\": " << number(peak)
        << ", \"peak_r\": " << number(peak_r) << ", \"pressure_error\": " << number(pressure_error)
        << ", \"pressure_error_boundary\": " << number(pressure_error_boundary) << "}";
    return out.str();
  }

  template <int dim>
  bool
  HertzPressure<dim>::cylinder() const
  {
    return hertz.shape == Parameters::HertzComparison::Shape::cylinder;
  }

  template class HertzPressure<2>;
  template class HertzPressure<3>;
} // namespace FoslsContact
