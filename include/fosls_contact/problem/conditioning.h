#ifndef fosls_contact_problem_conditioning_h
#define fosls_contact_problem_conditioning_h

#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/scene.h>

#include <string>

namespace FoslsContact
{
  /**
   * What in a scene makes the functional too badly conditioned for double
   * precision, for the messages of the checks that meet it: a Cholesky
   * factorization that fails, a Schur complement singular to round-off, a
   * multigrid that stops at its round-off floor. These show the symptom,
   * whose cause is in the input: without this, a 1 x 1e-6 cell or a
   * reference stress of 1 Pa for steel was blamed on C_compl, which no
   * value of it cures.
   *
   * The measures, each named when it is past its limit:
   *  - the cells' aspect ratio (CellShapeCheck::aspect_ratio(), which
   *    refuses the worst up front): the entries of div sigma scale with
   *    the inverse thickness, those of the other terms with the edges;
   *  - the ratio of the largest to the smallest cell of the coarse mesh;
   *  - the shear modulus in units of 'Scaling/Reference stress', and the
   *    body's size in units of 'Scaling/Reference length', where the scene
   *    sets them (auto makes both 1);
   *  - the spread of the nonzero 'Functional weights'.
   * The coarse cells are the same on every process, so the text is too.
   */
  template <int dim>
  struct Conditioning
  {
    /** Aspect ratios from here on are named. */
    static constexpr double aspect_limit = 100;
    /** Ratios of cell sizes from here on are named. */
    static constexpr double size_ratio_limit = 1e4;
    /** Scaled moduli and sizes this far from 1 are named. */
    static constexpr double scale_limit = 1e3;
    /** Weights this far apart are named. */
    static constexpr double weight_spread_limit = 1e8;

    /**
     * The measures of @p scene (its coarse cells in @p tria) past their
     * limits, as "cells of aspect ratio 1e+06 (the most elongated at
     * (0.5, 5e-07))", joined by "; ", or "" if none is.
     */
    static std::string cause(const Parameters::AllParameters &parameters,
                             const Scene<dim> &               scene,
                             const Triangulation<dim> &       tria);

    /**
     * cause(), or if it names nothing, the advice to check the weights and
     * scaling: the end of a message that the functional is too badly
     * conditioned.
     */
    static std::string advice(const Parameters::AllParameters &parameters,
                              const Scene<dim> &               scene,
                              const Triangulation<dim> &       tria);
  };
} // namespace FoslsContact

#endif
