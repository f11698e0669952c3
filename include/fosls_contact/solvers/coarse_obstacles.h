#ifndef fosls_contact_solvers_coarse_obstacles_h
#define fosls_contact_solvers_coarse_obstacles_h

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

namespace FoslsContact
{
  /**
   * The non-linear projections of paper section 5 that turn the defect
   * obstacle of a fine level, d_h = ub_h - v_h (+inf at unbounded and
   * truncated DoFs, eqs. 35-36), into the obstacle of the next coarser
   * level, such that P ub_H <= d_h wherever the fine constraint is
   * enforced (K_H subset of K_h):
   *
   * - displacement, per coarse contact vertex (eq. 29): the minimum over
   *   the coarse contact edges at the vertex of the edge values a) eq.
   *   (26), b) eq. (27), c) eq. (28), or d) +infinity; in 3D the centers
   *   of the coarse contact faces, which no edge covers, enter as in b);
   * - normal stress, per coarse contact face: the minimum over its sons
   *   (eq. 30), divided by the face's entry of @p face_scale (>= 1: a
   *   son that carries the flux of truncated brothers moves by that factor
   *   times the coarse value, FluxRerouting::face_scale()).
   *
   * The work is done face by face (FaceRelation): every coarse contact
   * face, owned by one process, gives the face's value and one value per
   * end of each of its edges; a vertex takes the minimum over its faces,
   * also over those of other processes (compress with min), which is the
   * minimum over its edges of eq. (29).
   */
  class CoarseObstacles
  {
  public:
    /**
     * @p fine_defect with valid ghost values in; @p coarse_obstacle with
     * valid ghost values out. Collective.
     */
    static void project(const Parameters::Solver::Projection projection,
                        const std::vector<FaceRelation> &    faces,
                        const std::vector<double> &          face_scale,
                        const LevelVector &                  fine_defect,
                        LevelVector &                        coarse_obstacle);
  };
} // namespace FoslsContact

#endif
