#ifndef fosls_contact_scene_scaled_function_h
#define fosls_contact_scene_scaled_function_h

#include <deal.II/base/function.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A data function of the scene, given in the scene's units, seen in the
   * dimensionless coordinates of the computation (Scaling):
   * f^(x^) = factor f(L x^), e.g. factor = L/S for a body force, 1/S for
   * a traction, 1/L for a displacement or a gap, 1 for a direction.
   */
  template <int dim>
  class ScaledFunction : public Function<dim>
  {
  public:
    ScaledFunction(const Function<dim> &function, const double length, const double factor);

    double value(const Point<dim> &p, const unsigned int component = 0) const override;
    void   vector_value(const Point<dim> &p, Vector<double> &values) const override;
    Tensor<1, dim> gradient(const Point<dim> &p, const unsigned int component = 0) const override;

  private:
    const Function<dim> &function;
    const double         length;
    const double         factor;
  };
} // namespace FoslsContact

#endif
