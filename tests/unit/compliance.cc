// Checks FoslsAssembler<dim>::compliance, the compliance tensor
// A sigma = (sigma - lambda/(d lambda + 2 mu) tr(sigma) I) / (2 mu) of paper
// section 2, in 2D and 3D for lambda = 1, 1e8 and inf:
//  - A is the inverse of the elasticity tensor C eps = 2 mu eps +
//    lambda tr(eps) I for finite lambda: A(C eps) = eps;
//  - lambda = 1e8 agrees with lambda = inf to about 2 mu / lambda (no digits
//    lost in the quotient);
//  - lambda = inf is deviatoric: A sigma = dev(sigma) / (2 mu), tr(A sigma) = 0
//    and A(p I) = 0 for a pressure p;
//  - A is linear and symmetric: A(sigma) : tau = sigma : A(tau).
#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>

#include "tests.h"

#include <limits>

using namespace FoslsContactTests;

template <int dim>
Tensor<2, dim>
random_tensor(Random &random)
{
  Tensor<2, dim> t;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      t[i][j] = random();
  return t;
}

template <int dim>
Tensor<2, dim>
elasticity(const Tensor<2, dim> &eps, const double mu, const double lambda)
{
  Tensor<2, dim> sigma = 2. * mu * eps;
  for (unsigned int d = 0; d < dim; ++d)
    sigma[d][d] += lambda * trace(eps);
  return sigma;
}

template <int dim>
void
test()
{
  std::cout << "--- dim = " << dim << std::endl;
  Random       random(dim);
  const double inf = std::numeric_limits<double>::infinity();
  const auto   A   = [](const Tensor<2, dim> &s, const double mu, const double lambda) {
    return FoslsAssembler<dim>::compliance(s, mu, lambda);
  };

  for (const double mu : {1., 2.5})
    {
      // A(C eps) = eps for symmetric and non-symmetric eps
      for (const double lambda : {1., 1e8})
        {
          double max_error = 0;
          for (unsigned int k = 0; k < 10; ++k)
            {
              const Tensor<2, dim> eps = random_tensor<dim>(random);
              max_error = std::max(max_error,
                                   (A(elasticity(eps, mu, lambda), mu, lambda) - eps)
                                       .norm() /
                                     eps.norm());
            }
          // C has norm ~ lambda: round-off allows ~ 1e-16 * lambda / mu
          const double tol = 1e-14 * std::max(1., lambda / mu);
          check(max_error < tol,
                "mu = " + rounded(mu) + ", lambda = " + rounded(lambda) +
                  ": A(C eps) = eps");
        }

      // lambda = 1e8 against lambda = inf
      {
        double max_difference = 0;
        for (unsigned int k = 0; k < 10; ++k)
          {
            Tensor<2, dim> s = random_tensor<dim>(random);
            for (unsigned int d = 0; d < dim; ++d)
              s[d][d] += 3.; // a sizable trace
            max_difference =
              std::max(max_difference,
                       (A(s, mu, 1e8) - A(s, mu, inf)).norm() / (s.norm() / (2 * mu)));
          }
        // kappa(inf) - kappa(1e8) = 2 mu / (d^2 lambda) + O(lambda^-2)
        check(max_difference < 1e-8 * std::max(1., mu) && max_difference > 1e-12,
              "mu = " + rounded(mu) + ": lambda = 1e8 agrees with inf to ~2 mu/lambda");
      }

      // lambda = inf: deviatoric
      {
        double max_error = 0, max_trace = 0;
        for (unsigned int k = 0; k < 10; ++k)
          {
            const Tensor<2, dim> s   = random_tensor<dim>(random);
            Tensor<2, dim>       dev = s;
            for (unsigned int d = 0; d < dim; ++d)
              dev[d][d] -= trace(s) / dim;
            max_error = std::max(max_error, (A(s, mu, inf) - dev / (2 * mu)).norm());
            max_trace = std::max(max_trace, std::abs(trace(A(s, mu, inf))));
          }
        Tensor<2, dim> pressure;
        for (unsigned int d = 0; d < dim; ++d)
          pressure[d][d] = 7.;
        check(max_error < 1e-15 && max_trace < 1e-15,
              "mu = " + rounded(mu) + ", lambda = inf: A sigma = dev(sigma)/(2 mu)");
        check(A(pressure, mu, inf).norm() < 1e-15,
              "mu = " + rounded(mu) + ", lambda = inf: A(p I) = 0");
      }

      // symmetry of the quadratic form (the FOSLS matrix relies on it)
      for (const double lambda : {1., 1e8, inf})
        {
          const Tensor<2, dim> s = random_tensor<dim>(random);
          const Tensor<2, dim> t = random_tensor<dim>(random);
          check(std::abs(scalar_product(A(s, mu, lambda), t) -
                         scalar_product(s, A(t, mu, lambda))) < 1e-14,
                "mu = " + rounded(mu) + ", lambda = " + rounded(lambda) +
                  ": A is symmetric");
        }
    }

  // a value to pin the formula, mu = 1: A(I) = (1 - d kappa)/2 I with
  // kappa = lambda / (d lambda + 2 mu)
  Tensor<2, dim> identity;
  for (unsigned int d = 0; d < dim; ++d)
    identity[d][d] = 1.;
  for (const double lambda : {1., 1e8, inf})
    std::cout << "A(I)[0][0] for mu = 1, lambda = " << lambda << ": "
              << rounded(A(identity, 1., lambda)[0][0], 8) << std::endl;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  test<2>();
  test<3>();
  return exit_code();
}
