#include <deal.II/lac/vector.h>

#include <fosls_contact/scene/scaled_function.h>

#include <cmath>

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
    const double f = function.value(length * p, component);
    note(p, f);
    return factor * f;
  }


  template <int dim>
  void
  ScaledFunction<dim>::vector_value(const Point<dim> &p, Vector<double> &values) const
  {
    function.vector_value(length * p, values);
    for (const double f : values)
      note(p, f);
    values *= factor;
  }


  template <int dim>
  Tensor<1, dim>
  ScaledFunction<dim>::gradient(const Point<dim> &p, const unsigned int component) const
  {
    return (factor * length) * function.gradient(length * p, component);
  }


  template <int dim>
  typename ScaledFunction<dim>::Record
  ScaledFunction<dim>::record() const
  {
    std::lock_guard<std::mutex> lock(mutex);
    return values_seen;
  }


  template <int dim>
  void
  ScaledFunction<dim>::note(const Point<dim> &p, const double f) const
  {
    std::lock_guard<std::mutex> lock(mutex);
    Record &r = values_seen;
    if (!std::isfinite(f))
      {
        if (r.finite)
          {
            r.finite        = false;
            r.not_finite    = f;
            r.not_finite_at = length * p;
          }
        return;
      }
    if (!seen || std::abs(f) > r.largest)
      {
        r.largest    = std::abs(f);
        r.largest_at = length * p;
      }
    if (!seen || f < r.lowest)
      {
        r.lowest    = f;
        r.lowest_at = length * p;
      }
    seen = true;
  }

  template class ScaledFunction<2>;
  template class ScaledFunction<3>;
} // namespace FoslsContact
