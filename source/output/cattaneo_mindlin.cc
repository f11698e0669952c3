#include <fosls_contact/base/json.h>
#include <fosls_contact/output/cattaneo_mindlin.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  CattaneoMindlin<dim>::CattaneoMindlin(const HertzPressure<dim> &hertz, const double coefficient)
    : hertz(hertz)
    , f(coefficient)
  {}


  template <int dim>
  double
  CattaneoMindlin<dim>::traction(const double r) const
  {
    const double a = hertz.half_width(), p0 = hertz.maximum_pressure();
    if (r >= a)
      return 0.;
    double q = f * p0 * std::sqrt(1. - r * r / (a * a));
    if (r < c)
      q -= f * p0 * (c / a) * std::sqrt(1. - r * r / (c * c));
    return q;
  }


  template <int dim>
  void
  CattaneoMindlin<dim>::evaluate(const Tensor<1, dim> &                               force,
                                 const std::vector<typename ContactRow<dim>::Values> &rows)
  {
    using Row                = ContactRow<dim>;
    constexpr double inf     = std::numeric_limits<double>::infinity();
    const Tensor<1, dim> n   = hertz.contact_normal();
    const Tensor<1, dim> t   = force - (force * n) * n;
    const double         P   = hertz.normal_force();
    tangential_force         = hertz.force_factor() * t.norm();
    ratio                    = f > 0 && P > 0 ? tangential_force / (f * P) : inf;
    // (Johnson eqs. 7.33 and 7.42)
    c = ratio < 1 ?
          hertz.half_width() * std::pow(1. - ratio, hertz.cylinder() ? 1. / 2 : 1. / 3) :
          0.;
    // the direction of Q; without Q any tangent (q = 0 along all of them)
    Tensor<1, dim> e = t;
    if (e.norm() > 0)
      e /= e.norm();
    else
      {
        // (the coordinate axis least aligned with n, made orthogonal to it)
        unsigned int axis = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(n[d]) < std::abs(n[axis]))
            axis = d;
        e[axis] = 1;
        e -= (e * n) * n;
        e /= e.norm();
      }

    // (position along Q, stick) of every contact vertex on the line through
    // the contact point along Q, in order (in 2D every contact vertex; on
    // a sphere's contact the stick zone is a disc, and that line crosses
    // it along a diameter, so the ends found on it are at -c and c)
    const double                         off_line = 1e-6 * hertz.half_width();
    std::vector<std::pair<double, bool>> along;
    double                               difference = 0, norm_q = 0, norm_fp = 0;
    for (const auto &row : rows)
      {
        Tensor<1, dim> p, traction_t;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[d]          = row[Row::x + d];
            traction_t[d] = row[Row::traction_t + d];
          }
        const double r = hertz.distance(p), q = traction(r), q_h = traction_t * e;
        const double w = row[Row::share];
        difference += w * (q_h - q) * (q_h - q);
        norm_q += w * q * q;
        norm_fp += w * std::pow(f * hertz.pressure(r), 2);
        const Tensor<1, dim> from = p - hertz.contact_point();
        const Tensor<1, dim> across = from - (from * e) * e - (from * n) * n;
        if (across.norm() <= off_line)
          along.emplace_back(from * e, row[Row::in_contact] == 1 && row[Row::status] == 1);
      }
    // (without a tangential force beyond round-off q is 0, and so is a
    // norm relative to it)
    constexpr double round_off = 1e-6;
    error_of_q = ratio > round_off && norm_q > 0 ? std::sqrt(difference / norm_q) :
                                                   std::numeric_limits<double>::quiet_NaN();
    error_of_fp = norm_fp > 0 ? std::sqrt(difference / norm_fp) : inf;

    // each end of the stick zone midway between its outermost stick vertex
    // and the next vertex beyond it
    std::sort(along.begin(), along.end());
    const auto first = std::find_if(along.begin(), along.end(), [](const auto &v) { return v.second; });
    const auto last  = std::find_if(along.rbegin(), along.rend(), [](const auto &v) { return v.second; });
    sticks           = first != along.end();
    if (!sticks)
      return;
    const auto end_of = [&](const double stick, const double beyond, const double exact, double &end) {
      end = (stick + beyond) / 2;
      return std::abs(end - exact) / std::abs(beyond - stick);
    };
    if (first == along.begin())
      stick_from = first->first, from_error = inf;
    else
      from_error = end_of(first->first, std::prev(first)->first, -c, stick_from);
    if (last == along.rbegin())
      stick_to = last->first, to_error = inf;
    else
      to_error = end_of(last->first, std::prev(last)->first, c, stick_to);
  }


  template <int dim>
  std::string
  CattaneoMindlin<dim>::report() const
  {
    std::ostringstream out;
    out << std::setprecision(4) << "Cattaneo-Mindlin (f = " << f << ", Q = " << tangential_force
        << ", Q/(f P) = " << std::setprecision(3) << ratio << std::setprecision(4) << "): ";
    if (ratio < 1)
      out << (hertz.cylinder() ? "stick zone |x| < c = " : "stick disc r < c = ") << c
          << " along Q";
    else
      out << "the whole contact slips (c = 0)";
    out << "\n       computed: ";
    if (sticks)
      out << "stick zone from " << stick_from << " to " << stick_to << " (" << std::setprecision(2)
          << from_error << " and " << to_error << " vertex spacings from -c and c)";
    else
      out << "no vertex sticks";
    out << std::setprecision(3) << ", tangential traction error ";
    if (!std::isnan(error_of_q))
      out << error_of_q << " of |q|, ";
    out << error_of_fp << " of |f p| (relative L2 on the contact boundary)";
    return out.str();
  }


  template <int dim>
  std::string
  CattaneoMindlin<dim>::json() const
  {
    const auto         number = json_number;
    const double       nan    = std::numeric_limits<double>::quiet_NaN();
    std::ostringstream out;
    out << "{\"coefficient\": " << number(f) << ", \"tangential_force\": "
        << number(tangential_force) << ", \"ratio\": " << number(ratio)
        << ", \"c\": " << number(c) << ", \"stick_from\": " << number(sticks ? stick_from : nan)
        << ", \"stick_to\": " << number(sticks ? stick_to : nan)
        << ", \"stick_from_error\": " << number(sticks ? from_error : nan)
        << ", \"stick_to_error\": " << number(sticks ? to_error : nan)
        << ", \"traction_error\": " << number(error_of_q)
        << ", \"traction_error_of_slip_limit\": " << number(error_of_fp) << "}";
    return out.str();
  }

  template class CattaneoMindlin<2>;
  template class CattaneoMindlin<3>;
} // namespace FoslsContact
