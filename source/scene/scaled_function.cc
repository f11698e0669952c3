#include <deal.II/lac/vector.h>

#include <fosls_contact/scene/scaled_function.h>

namespace FoslsContact
{
  template <int dim>
  ScaledFunction<dim>::ScaledFunction(const Function<dim> &function,
                                      const double         length,
                                      const double         factor)
    : Function<dim>(function.n_components)
    , function(function)
    , length(length)
    , factor(factor)
  {}


  template <int dim>
  double
  ScaledFunction<dim>::value(const Point<dim> &p, const unsigned int component) const
  {
    return factor * function.value(length * p, component);
  }


  template <int dim>
  void
  ScaledFunction<dim>::vector_value(const Point<dim> &p, Vector<double> &values) const
  {
    function.vector_value(length * p, values);
    values *= factor;
  }


  template <int dim>
  Tensor<1, dim>
  ScaledFunction<dim>::gradient(const Point<dim> &p, const unsigned int component) const
  {
    return (factor * length) * function.gradient(length * p, component);
  }

  template class ScaledFunction<2>;
  template class ScaledFunction<3>;
} // namespace FoslsContact
