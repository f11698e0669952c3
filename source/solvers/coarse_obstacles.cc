#include <fosls_contact/solvers/coarse_obstacles.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  void
  CoarseObstacles::project(const Parameters::Solver::Projection projection,
                           const std::vector<FaceRelation> &    faces,
                           const std::vector<double> &          face_scale,
                           const LevelVector &                  d_vector,
                           LevelVector &                        ub_vector)
  {
    using P               = Parameters::Solver::Projection;
    const double infinity = std::numeric_limits<double>::infinity();
    double *     ub       = ub_vector.begin(); // local elements, owned and ghost
    const double *d       = d_vector.begin();
    std::fill(ub,
              ub + ub_vector.locally_owned_size() +
                ub_vector.get_partitioner()->n_ghost_indices(),
              infinity);
    auto lower = [&](const types::global_dof_index dof, const double value) {
      ub[dof] = std::min(ub[dof], value);
    };

    for (unsigned int k = 0; k < faces.size(); ++k)
      {
        const auto &face  = faces[k];
        double      value = infinity;
        for (const auto son : face.sons)
          value = std::min(value, d[son]);
        lower(face.coarse_dof, value / face_scale[k]);

        if (projection == P::d)
          continue;
        for (const auto &edge : face.edges)
          for (unsigned int end = 0; end < 2; ++end)
            {
              if (edge.coarse[end] == numbers::invalid_dof_index)
                continue;
              const double self = d[edge.fine[end]], other = d[edge.fine[1 - end]],
                           mid = d[edge.fine_midpoint];
              double edge_value;
              switch (projection)
                {
                  case P::a:
                    // eq. (26); an unconstrained midpoint leaves the vertex
                    // value, an unconstrained other end makes 2 mid - other
                    // = -inf
                    if (std::isinf(mid))
                      edge_value = self;
                    else
                      edge_value =
                        std::min(self,
                                 std::max(mid,
                                          std::isinf(other) ? -infinity :
                                                              2. * mid - other));
                    break;
                  case P::b: // eq. (27)
                    edge_value = std::min(self, mid);
                    break;
                  default: // c, eq. (28)
                    edge_value = std::min(self, std::min(mid, other));
                    break;
                }
              lower(edge.coarse[end], edge_value);
            }
        if (face.fine_center != numbers::invalid_dof_index)
          for (const auto vertex : face.coarse_vertices)
            lower(vertex, d[face.fine_center]);
      }
    // each vertex: the minimum over the faces at it, on every process
    send_ghost_parts(ub_vector, VectorOperation::min);
    update_ghosts(ub_vector);
  }
} // namespace FoslsContact
