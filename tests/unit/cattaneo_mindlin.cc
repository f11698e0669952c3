// Checks CattaneoMindlin (the comparison of a 2D cylinder's frictional
// contact with Cattaneo and Mindlin's solution) on contact tables made
// from the exact solution, P = 0.01, R = 2, E* = 4, f = 0.3, 101 vertices
// 0.004 apart:
//  - Q = 0.5 f P along +x and along -x: c = a sqrt(1 - Q/(f P)), the
//    traction error 0 (to 1e-12) against q and against f p, both ends of
//    the stick zone within half a vertex spacing of +-c (midway between
//    the outermost stick vertex and the next one);
//  - a traction 1% above q has the traction error 0.01;
//  - Q = f P: c = 0, no stick vertex, and summary.json's stick zone null;
//  - the screen report names c and the stick zone;
//  - a sphere in 3D (Q = 0.5 f P along +x, vertices on a 101 x 101 grid
//    0.004 apart): c = a (1 - Q/(f P))^(1/3), the traction error 0, the
//    stick disc's ends along Q within half a vertex spacing of -c and c.
// ctest: sanitize
#include <fosls_contact/output/cattaneo_mindlin.h>

#include "tests.h"

using namespace FoslsContactTests;

namespace
{
  constexpr double P = 0.01, R = 2, f = 0.3, h = 0.004;
  using Row = ContactRow<2>;

  Parameters::HertzComparison
  cylinder()
  {
    Parameters::HertzComparison hertz;
    hertz.shape         = Parameters::HertzComparison::Shape::cylinder;
    hertz.radius        = R;
    hertz.contact_point = {0, 0};
    hertz.axis          = {0, 0, 1};
    return hertz;
  }

  /**
   * The contact table of Hertz's pressure and Cattaneo-Mindlin's traction
   * for the tangential force @p Q along @p direction (+1 or -1), the
   * traction scaled by @p factor.
   */
  std::vector<Row::Values>
  table(const double Q, const double direction, const double factor)
  {
    const double a = std::sqrt(4 * P * R / (numbers::PI * 4)), p0 = 2 * P / (numbers::PI * a);
    const double c = Q < f * P ? a * std::sqrt(1 - Q / (f * P)) : 0.;
    std::vector<Row::Values> rows;
    for (int i = -50; i <= 50; ++i)
      {
        const double x = i * h, s = direction * x;
        const double p = std::abs(x) < a ? p0 * std::sqrt(1 - x * x / (a * a)) : 0.;
        const double q =
          f * p - (std::abs(x) < c ? f * p0 * (c / a) * std::sqrt(1 - x * x / (c * c)) : 0.);
        Row::Values row{};
        row[Row::x]              = x;
        row[Row::sigma_nn]       = -p;
        row[Row::share]          = h;
        row[Row::in_contact]     = p > 0 ? 1 : 0;
        row[Row::traction_t]     = direction * factor * q;
        row[Row::status]         = p == 0 ? 0 : std::abs(s) < c ? 1 : 2;
        rows.push_back(row);
      }
    return rows;
  }

  /**
   * CattaneoMindlin's JSON object and report for table(@p Q, @p direction,
   * @p factor), with the force (direction Q, P), E = 3 and nu = 1/2.
   */
  std::pair<std::string, std::string>
  compare(const double Q, const double direction, const double factor)
  {
    Parameters::Material material;
    material.youngs_modulus = 3;
    material.poisson_ratio  = 0.5;
    const auto         rows = table(Q, direction, factor);
    const Tensor<1, 2> force({direction * Q, P});
    HertzPressure<2>   hertz(cylinder(), material, Tensor<1, 2>({0., -1.}));
    hertz.evaluate(force, rows);
    CattaneoMindlin<2> cm(hertz, f);
    cm.evaluate(force, rows);
    return {cm.json(), cm.report()};
  }


  /**
   * A sphere's contact: the table of Hertz's pressure and Mindlin's
   * traction for Q along +x on the vertices of a grid in the plane z = 0,
   * and CattaneoMindlin's JSON object and report for it.
   */
  std::pair<std::string, std::string>
  compare_sphere(const double Q)
  {
    using Row3 = ContactRow<3>;
    const double a = std::cbrt(3 * P * R / (4 * 4)), p0 = 3 * P / (2 * numbers::PI * a * a);
    const double c = a * std::cbrt(1 - Q / (f * P));
    std::vector<Row3::Values> rows;
    for (int i = -50; i <= 50; ++i)
      for (int j = -50; j <= 50; ++j)
        {
          const double x = i * h, y = j * h, r = std::hypot(x, y);
          const double p = r < a ? p0 * std::sqrt(1 - r * r / (a * a)) : 0.;
          const double q = f * p - (r < c ? f * p0 * (c / a) * std::sqrt(1 - r * r / (c * c)) : 0.);
          Row3::Values row{};
          row[Row3::x]          = x;
          row[Row3::x + 1]      = y;
          row[Row3::sigma_nn]   = -p;
          row[Row3::share]      = h * h;
          row[Row3::in_contact] = p > 0 ? 1 : 0;
          row[Row3::traction_t] = q;
          row[Row3::status]     = p == 0 ? 0 : r < c ? 1 : 2;
          rows.push_back(row);
        }
    Parameters::HertzComparison sphere;
    sphere.shape         = Parameters::HertzComparison::Shape::sphere;
    sphere.radius        = R;
    sphere.contact_point = {0, 0, 0};
    Parameters::Material material;
    material.youngs_modulus = 3;
    material.poisson_ratio  = 0.5;
    const Tensor<1, 3> force({Q, 0., P});
    HertzPressure<3>   hertz(sphere, material, Tensor<1, 3>({0., 0., -1.}));
    hertz.evaluate(force, rows);
    CattaneoMindlin<3> cm(hertz, f);
    cm.evaluate(force, rows);
    return {cm.json(), cm.report()};
  }


  /** The JSON's number after "key": (null as NaN). */
  double
  json_value(const std::string &json, const std::string &key)
  {
    const auto at = json.find("\"" + key + "\": ");
    if (at == std::string::npos)
      return -1;
    const std::string value = json.substr(at + key.size() + 4);
    return value.rfind("null", 0) == 0 ? std::nan("") : std::stod(value);
  }
} // namespace

int
main()
{
  const double a = std::sqrt(4 * P * R / (numbers::PI * 4));
  for (const double direction : {1., -1.})
    {
      const auto [json, report] = compare(0.5 * f * P, direction, 1.);
      const std::string along   = direction > 0 ? "+x" : "-x";
      check(std::abs(json_value(json, "c") - a * std::sqrt(0.5)) <= 1e-12 * a,
            "Q = f P / 2 along " + along + ": c = a sqrt(1/2)");
      check(json_value(json, "traction_error") <= 1e-12 &&
              json_value(json, "traction_error_of_slip_limit") <= 1e-12,
            "Q = f P / 2 along " + along + ": the exact traction has error 0");
      check(json_value(json, "stick_from") < 0 && json_value(json, "stick_to") > 0 &&
              json_value(json, "stick_from_error") <= 0.5 &&
              json_value(json, "stick_to_error") <= 0.5,
            "Q = f P / 2 along " + along +
              ": the stick zone's ends within half a vertex spacing of -c and c");
      if (direction > 0)
        check(report.find("stick zone |x| < c = ") != std::string::npos &&
                report.find("computed: stick zone from ") != std::string::npos,
              "the report names c and the computed stick zone");
    }
  check(std::abs(json_value(compare(0.5 * f * P, 1., 1.01).first, "traction_error") - 0.01) <=
          1e-12,
        "a traction 1% above q: traction error 0.01");
  const auto [json, report] = compare(f * P, 1., 1.);
  check(json_value(json, "c") == 0 && std::isnan(json_value(json, "stick_from")) &&
          json_value(json, "traction_error") <= 1e-12 &&
          report.find("the whole contact slips") != std::string::npos &&
          report.find("no vertex sticks") != std::string::npos,
        "Q = f P: c = 0, no stick vertex, the whole contact slips");
  {
    const auto [json, report] = compare_sphere(0.5 * f * P);
    const double a_sphere     = std::cbrt(3 * P * R / (4 * 4));
    // (summary.json's numbers have 12 significant digits)
    check(std::abs(json_value(json, "c") - a_sphere * std::cbrt(0.5)) <= 1e-11 * a_sphere,
          "sphere, Q = f P / 2: c = a (1/2)^(1/3)");
    check(json_value(json, "traction_error") <= 1e-12 &&
            json_value(json, "traction_error_of_slip_limit") <= 1e-12,
          "sphere, Q = f P / 2: the exact traction has error 0");
    check(json_value(json, "stick_from_error") <= 0.5 && json_value(json, "stick_to_error") <= 0.5,
          "sphere, Q = f P / 2: the stick disc's ends along Q within half a vertex spacing of "
          "-c and c");
    check(report.find("stick disc r < c = ") != std::string::npos,
          "sphere: the report names the stick disc");
  }
  return exit_code();
}
