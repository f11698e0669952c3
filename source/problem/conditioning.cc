#include <deal.II/base/geometry_info.h>

#include <fosls_contact/problem/conditioning.h>
#include <fosls_contact/scene/cell_shape_check.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace FoslsContact
{
  namespace
  {
    std::string
    rounded(const double x)
    {
      std::ostringstream text;
      text.precision(2);
      text << x;
      return text.str();
    }

    /** How a reference compares with a quantity that is @p ratio of it. */
    std::string
    times(const double ratio)
    {
      return ratio > 1 ? rounded(ratio) + " times smaller than" :
                         rounded(1. / ratio) + " times larger than";
    }
  } // namespace


  template <int dim>
  std::string
  Conditioning<dim>::cause(const Parameters::AllParameters &parameters,
                           const Scene<dim> &               scene,
                           const Triangulation<dim> &       tria)
  {
    const double             L = scene.scaling().length;
    std::vector<std::string> causes;

    double     aspect = 0, smallest = 0, largest = 0;
    Point<dim> elongated, lower, upper;
    bool       first = true;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        const double cell_aspect = CellShapeCheck<dim>::aspect_ratio(cell);
        if (std::isfinite(cell_aspect) && cell_aspect > aspect)
          {
            aspect    = cell_aspect;
            elongated = cell->center();
          }
        const double diameter = cell->diameter();
        smallest = first ? diameter : std::min(smallest, diameter);
        largest  = std::max(largest, diameter);
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = first ? cell->vertex(v)[d] : std::min(lower[d], cell->vertex(v)[d]);
              upper[d] = first ? cell->vertex(v)[d] : std::max(upper[d], cell->vertex(v)[d]);
            }
        first = false;
      }
    if (aspect >= aspect_limit)
      {
        std::ostringstream where;
        where << "cells of aspect ratio " << rounded(aspect) << " (the most elongated at (";
        for (unsigned int d = 0; d < dim; ++d)
          where << (d ? ", " : "") << rounded(elongated[d] * L);
        where << "); split their long edges, e.g. with more 'Geometry/Box subdivisions' "
                 "along them)";
        causes.push_back(where.str());
      }
    if (smallest > 0 && largest / smallest >= size_ratio_limit)
      causes.push_back("coarse cells whose sizes are " + rounded(largest / smallest) +
                       " apart (grade the mesh more gently)");

    const auto &scaling = parameters.scaling;
    const double mu     = scene.material().mu;
    if (scaling.reference_stress > 0 && (mu > scale_limit || mu < 1. / scale_limit))
      causes.push_back("'Scaling/Reference stress' = " + rounded(scaling.reference_stress) +
                       " is " + times(mu) +
                       " the shear modulus (use auto, or a stress of the order of the "
                       "body's stresses)");
    double size = 0;
    for (unsigned int d = 0; d < dim; ++d)
      size = std::max(size, upper[d] - lower[d]);
    if (scaling.reference_length > 0 && (size > scale_limit || size < 1. / scale_limit))
      causes.push_back("'Scaling/Reference length' = " + rounded(scaling.reference_length) +
                       " is " + times(size) +
                       " the body's size (use auto, or a length of the order of the "
                       "body's size)");

    const auto &w = parameters.weights;
    double      w_min = 0, w_max = 0;
    for (const double c : {w.c_eq, w.c_const, w.c_compl})
      if (c > 0)
        {
          w_min = w_min > 0 ? std::min(w_min, c) : c;
          w_max = std::max(w_max, c);
        }
    if (w_min > 0 && w_max / w_min >= weight_spread_limit)
      causes.push_back("'Functional weights' " + rounded(w_max / w_min) + " apart");

    std::string text;
    for (const auto &c : causes)
      text += (text.empty() ? "" : "; ") + c;
    return text;
  }


  template <int dim>
  std::string
  Conditioning<dim>::advice(const Parameters::AllParameters &parameters,
                            const Scene<dim> &               scene,
                            const Triangulation<dim> &       tria)
  {
    const std::string named = cause(parameters, scene, tria);
    if (!named.empty())
      return named;
    const auto &scaling = parameters.scaling;
    return scaling.reference_length > 0 || scaling.reference_stress > 0 ?
             "check that 'Scaling/Reference length' and 'Reference stress' are of the "
             "order of the body's size and stresses (or auto), and that the 'Functional "
             "weights' are not many orders of magnitude apart" :
             "check that the 'Functional weights' are not many orders of magnitude apart";
  }


  template struct Conditioning<2>;
  template struct Conditioning<3>;
} // namespace FoslsContact
