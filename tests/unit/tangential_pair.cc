// Checks TangentialPair, the two local problems of 3D friction on a pair
// of tangential coordinates, on 400 pseudo-random problems each (a random
// SPD 2x2 H, every tenth with a condition number of 1e8; r of random size
// around the norm's weight w or the disc's radius s, some with |r| within
// 1e-9 of w):
//  - minimize_with_norm(): y = 0 exactly where |r| <= w; elsewhere
//    H y + w y / |y| = r (to 1e-10 of the size of the terms, |H| |y| +
//    |r| + w);
//  - minimize_in_disc(): |z| <= s exactly; inside the circle H z = r, on
//    it r - H z = mu z / |z| with mu >= 0 (to 1e-10 of the terms);
//  - no point of a ring of 64 trial points around the result (radius 1e-6
//    of the result's scale, kept in the disc) lowers the objective (to the
//    rounding of its terms).
// ctest: sanitize
#include <fosls_contact/qp/tangential_pair.h>

#include "tests.h"

#include <cmath>
#include <random>

using namespace FoslsContactTests;
using namespace FoslsContact::TangentialPair;

int
main()
{
  const unsigned int               n_problems = 400;
  std::mt19937                     random(7);
  std::uniform_real_distribution<> uniform(-1., 1.);
  unsigned int n_zero = 0, n_norm = 0, n_norm_local = 0, n_on_circle = 0, n_disc = 0,
               n_disc_local = 0;
  const auto random_matrix = [&](const unsigned int k) -> Matrix2 {
    // H = Q diag(l1, l2) Q^T
    const double angle = 3.2 * uniform(random), l1 = 1 + uniform(random);
    const double l2    = k % 10 == 0 ? 1e-8 * l1 : l1 * (0.55 + 0.45 * uniform(random));
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2};
  };
  const auto product = [](const Matrix2 &H, const Vector2 &y) -> Vector2 {
    return {H[0] * y[0] + H[1] * y[1], H[1] * y[0] + H[2] * y[1]};
  };
  const auto quadratic = [&](const Matrix2 &H, const Vector2 &r, const Vector2 &y) {
    const Vector2 Hy = product(H, y);
    return 0.5 * (y[0] * Hy[0] + y[1] * Hy[1]) - r[0] * y[0] - r[1] * y[1];
  };
  for (unsigned int k = 0; k < n_problems; ++k)
    {
      const Matrix2 H = random_matrix(k);
      const double  w = 0.5 * (1 + uniform(random)) + 0.01;
      double        direction = 3.2 * uniform(random);
      const double  length    = k % 7 == 0 ? w * (1 + 1e-9) : 2 * w * (1 + uniform(random));
      const Vector2 r{length * std::cos(direction), length * std::sin(direction)};

      // the norm term
      const Vector2 y         = minimize_with_norm(H, r, w);
      const auto    objective = [&](const Vector2 &v) { return quadratic(H, r, v) + w * norm(v); };
      if (norm(r) <= w)
        n_zero += y[0] == 0 && y[1] == 0;
      else
        {
          // (relative to the size of the terms, |H| |y| + |r| + w: with a
          // condition number of 1e8 the rounding of H moves y by 1e-8)
          const Vector2 Hy    = product(H, y);
          const double  ny    = norm(y);
          const double  scale = norm(r) + (std::abs(H[0]) + 2 * std::abs(H[1]) + std::abs(H[2])) * ny + w;
          n_norm += ny > 0 && std::abs(Hy[0] + w * y[0] / ny - r[0]) <= 1e-10 * scale &&
                    std::abs(Hy[1] + w * y[1] / ny - r[1]) <= 1e-10 * scale;
        }
      {
        // (to the rounding of the objective's terms, |H| |y|^2 / 2 + |r| |y| + w |y|)
        const double radius = 1e-6 * (norm(y) + norm(r));
        const double terms  = 0.5 * (std::abs(H[0]) + 2 * std::abs(H[1]) + std::abs(H[2])) *
                               (norm(y) + radius) * (norm(y) + radius) +
                             (norm(r) + w) * (norm(y) + radius);
        bool local = true;
        for (unsigned int t = 0; t < 64; ++t)
          {
            const double a = 2 * M_PI * t / 64;
            local &= objective({y[0] + radius * std::cos(a), y[1] + radius * std::sin(a)}) >=
                     objective(y) - 1e-14 * terms;
          }
        n_norm_local += local;
      }

      // the disc
      const double  s = 0.5 * (1 + uniform(random)) + 0.01;
      direction       = 3.2 * uniform(random);
      const double  size = 3 * s * (1 + uniform(random));
      const Vector2 b{size * std::cos(direction), size * std::sin(direction)};
      const Vector2 z  = minimize_in_disc(H, b, s);
      const Vector2 Hz = product(H, z);
      const double  nz = norm(z), scale = norm(b) + (std::abs(H[0]) + 2 * std::abs(H[1]) + std::abs(H[2])) * nz;
      bool          ok = nz <= s;
      if (nz < s * (1 - 1e-12))
        ok &= std::abs(Hz[0] - b[0]) <= 1e-10 * scale && std::abs(Hz[1] - b[1]) <= 1e-10 * scale;
      else
        {
          ++n_on_circle;
          // r - H z = mu z / |z|: no part across z, mu >= 0
          const Vector2 m{b[0] - Hz[0], b[1] - Hz[1]};
          ok &= std::abs(m[0] * z[1] - m[1] * z[0]) / nz <= 1e-10 * scale &&
                (m[0] * z[0] + m[1] * z[1]) / nz >= -1e-10 * scale;
        }
      n_disc += ok;
      const double radius = 1e-6 * s;
      bool         local  = true;
      for (unsigned int t = 0; t < 64; ++t)
        {
          const double  a     = 2 * M_PI * t / 64;
          const Vector2 trial = project_to_disc({z[0] + radius * std::cos(a), z[1] + radius * std::sin(a)}, s);
          local &= quadratic(H, b, trial) >= quadratic(H, b, z) - 1e-14 * (1 + std::abs(quadratic(H, b, z)));
        }
      n_disc_local += local;
    }
  std::cout << n_problems << " problems: the norm's minimizer is 0 in " << n_zero << ", the disc's on its circle in "
            << n_on_circle << std::endl;
  check(n_zero + n_norm == n_problems, "the norm: 0 where |r| <= w, else H y + w y / |y| = r (to 1e-10)");
  check(n_norm_local == n_problems, "the norm: no point of a ring around y lowers the objective");
  check(n_disc == n_problems, "the disc: |z| <= s, H z = r inside, r - H z = mu z / |z|, mu >= 0 on the circle");
  check(n_disc_local == n_problems, "the disc: no point of a ring around z in the disc lowers the objective");
  // the line from (0.3, 0.4) along (1, 0) leaves the unit disc at
  // t = sqrt(0.84) - 0.3; from its circle outwards at once; never along 0
  const double t = disc_exit({0.3, 0.4}, {1., 0.}, 1.);
  check(std::abs(t - (std::sqrt(0.84) - 0.3)) <= 1e-15 && norm({0.3 + t, 0.4}) <= 1 + 1e-15 &&
          disc_exit({0.6, 0.8}, {1., 1.}, 1.) == 0 && std::isinf(disc_exit({0.3, 0.4}, {0., 0.}, 1.)),
        "disc_exit: where the line leaves the disc");
  return exit_code();
}
