#ifndef fosls_contact_scene_scaled_function_h
#define fosls_contact_scene_scaled_function_h

#include <deal.II/base/function.h>

#include <mutex>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A data function of the scene, given in the scene's units, seen in the
   * dimensionless coordinates of the computation (ReferenceScales):
   * f^(x^) = factor f(L x^), e.g. factor = L/S for a body force, 1/S for
   * a traction, 1/L for a displacement or a gap, 1 for a direction.
   *
   * It records the values it returns, at the points where the program asks
   * for them (the Dirichlet vertices, the faces of a traction, the contact
   * vertices and faces, the quadrature points of the body): a value that is
   * not finite, or so large or so small against L and S that the
   * dimensionless problem overflows or underflows, shows only at some
   * points, and DataCheck names the parameter and the point from these
   * records instead of the NaN iterate it would become.
   */
  template <int dim>
  class ScaledFunction : public Function<dim>
  {
  public:
    /**
     * The values returned so far, in the scene's units (f, not factor f),
     * and where (in the scene's units).
     */
    struct Record
    {
      /** The largest |value| of a finite value, and where. */
      double     largest = 0;
      Point<dim> largest_at;
      /** The lowest value, and where. */
      double     lowest = 0;
      Point<dim> lowest_at;
      /** Whether every value is finite; else the first that is not, and where. */
      bool       finite = true;
      double     not_finite = 0;
      Point<dim> not_finite_at;
    };

    ScaledFunction(const Function<dim> &function, const double length, const double factor);

    double value(const Point<dim> &p, const unsigned int component = 0) const override;
    void   vector_value(const Point<dim> &p, Vector<double> &values) const override;
    Tensor<1, dim> gradient(const Point<dim> &p, const unsigned int component = 0) const override;

    /** The values returned so far. */
    Record record() const;

    /** The factor from the scene's units to the dimensionless ones. */
    double scale() const { return factor; }

  private:
    /** Add the value @p f (scene units) at the dimensionless point @p p. */
    void note(const Point<dim> &p, const double f) const;

    const Function<dim> &function;
    const double         length;
    const double         factor;

    /** (the assembly evaluates on several threads) */
    mutable std::mutex  mutex;
    mutable Record      values_seen;
    mutable bool        seen = false;
  };
} // namespace FoslsContact

#endif
