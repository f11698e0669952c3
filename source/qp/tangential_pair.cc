#include <fosls_contact/qp/tangential_pair.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FoslsContact
{
  namespace TangentialPair
  {
    namespace
    {
      /** H = Q diag(lambda) Q^T, Q = [q, q_perp] (a rotation). */
      struct Eigen2
      {
        double lambda[2];
        double c, s; ///< the first eigenvector (c, s), the second (-s, c)

        explicit Eigen2(const Matrix2 &H)
        {
          const double mean = 0.5 * (H[0] + H[2]), half = 0.5 * (H[0] - H[2]);
          const double radius = std::hypot(half, H[1]);
          lambda[0]           = mean + radius;
          lambda[1]           = mean - radius;
          // (the smaller one without the cancellation of mean - radius)
          const double det = H[0] * H[2] - H[1] * H[1];
          if (lambda[0] > 0)
            lambda[1] = det / lambda[0];
          const double angle = 0.5 * std::atan2(2 * H[1], H[0] - H[2]);
          c                  = std::cos(angle);
          s                  = std::sin(angle);
        }
        Vector2 to_eigen(const Vector2 &r) const { return {c * r[0] + s * r[1], -s * r[0] + c * r[1]}; }
        Vector2 from_eigen(const Vector2 &y) const { return {c * y[0] - s * y[1], s * y[0] + c * y[1]}; }
      };

      /** |(H + mu I)^{-1} r| in the eigenbasis (r_hat), squared. */
      double
      shifted_norm_square(const Eigen2 &e, const Vector2 &r_hat, const double mu)
      {
        const double a = r_hat[0] / (e.lambda[0] + mu), b = r_hat[1] / (e.lambda[1] + mu);
        return a * a + b * b;
      }

      /**
       * The root of a monotone function of mu on [lo, hi] by bisection to
       * the last bit: @p below(mu) tells whether mu lies below the root.
       */
      template <typename Below>
      double
      bisect(double lo, double hi, const Below &below)
      {
        for (unsigned int k = 0; k < 200; ++k)
          {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi))
              break;
            (below(mid) ? lo : hi) = mid;
          }
        return 0.5 * (lo + hi);
      }
    } // namespace


    double
    norm(const Vector2 &y)
    {
      return std::hypot(y[0], y[1]);
    }


    Vector2
    minimize_with_norm(const Matrix2 &H, const Vector2 &r, const double w)
    {
      // 0 is the minimizer iff r lies in w times the unit disc (the
      // subdifferential of w|y| at 0); otherwise (H + w/|y| I) y = r, and
      // mu = w / |y| solves mu |(H + mu I)^{-1} r| = w, whose left side
      // grows from 0 to |r| > w: below the root it is < w. The root is at
      // most w lambda_max / (|r| - w), where the left side is >= w.
      const double r_norm = norm(r);
      if (!(r_norm > w))
        return {0., 0.};
      const Eigen2  e(H);
      const Vector2 r_hat = e.to_eigen(r);
      const double  hi    = 2 * w * e.lambda[0] / (r_norm - w) + 1e-300;
      const double  mu    = bisect(0., hi, [&](const double m) {
        return m * m * shifted_norm_square(e, r_hat, m) < w * w;
      });
      return e.from_eigen({r_hat[0] / (e.lambda[0] + mu), r_hat[1] / (e.lambda[1] + mu)});
    }


    Vector2
    minimize_in_disc(const Matrix2 &H, const Vector2 &r, const double s)
    {
      // the unconstrained minimizer H^{-1} r if it lies in the disc;
      // otherwise (H + mu I) z = r with |z| = s, mu > 0, and
      // |(H + mu I)^{-1} r| falls from |H^{-1} r| > s to 0: below the root
      // it is > s. At mu = |r| / s it is <= s.
      if (!(s > 0))
        return {0., 0.};
      const Eigen2  e(H);
      const Vector2 r_hat = e.to_eigen(r);
      if (shifted_norm_square(e, r_hat, 0.) <= s * s)
        return e.from_eigen({r_hat[0] / e.lambda[0], r_hat[1] / e.lambda[1]});
      const double mu = bisect(0., norm(r) / s, [&](const double m) {
        return shifted_norm_square(e, r_hat, m) > s * s;
      });
      return project_to_disc(
        e.from_eigen({r_hat[0] / (e.lambda[0] + mu), r_hat[1] / (e.lambda[1] + mu)}), s);
    }


    Vector2
    project_to_disc(const Vector2 &z, const double s)
    {
      const double length = norm(z);
      if (length <= s)
        return z;
      // (s / |z| rounded, the product may lie an ulp outside the circle:
      // scaled down by an ulp until it does not)
      double  scale = s / length;
      Vector2 result{z[0] * scale, z[1] * scale};
      for (unsigned int k = 0; k < 4 && norm(result) > s; ++k)
        {
          scale  = std::nextafter(scale, 0.);
          result = {z[0] * scale, z[1] * scale};
        }
      return result;
    }


    double
    disc_exit(const Vector2 &z, const Vector2 &d, const double s)
    {
      const double a = d[0] * d[0] + d[1] * d[1], b = z[0] * d[0] + z[1] * d[1];
      const double c = z[0] * z[0] + z[1] * z[1] - s * s;
      if (!(a > 0))
        return std::numeric_limits<double>::infinity();
      return std::max(0., (-b + std::sqrt(std::max(0., b * b - a * c))) / a);
    }
  } // namespace TangentialPair
} // namespace FoslsContact
