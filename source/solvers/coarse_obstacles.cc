#include <fosls_contact/solvers/coarse_obstacles.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  void
  CoarseObstacles::project(const Parameters::Solver::Projection projection,
                           const std::vector<VertexRelation> &  vertices,
                           const std::vector<FaceRelation> &    faces,
                           const std::vector<double> &          face_scale,
                           const Vector<double> &               d,
                           Vector<double> &                     ub)
  {
    using P                = Parameters::Solver::Projection;
    const double infinity  = std::numeric_limits<double>::infinity();
    ub                     = infinity;

    for (const auto &r : vertices)
      {
        if (projection == P::d)
          continue;
        const double self  = d[r.fine_self];
        double       value = self;
        for (const auto &[other_dof, mid_dof] : r.edges)
          {
            const double other = d[other_dof], mid = d[mid_dof];
            double       edge_value;
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
            value = std::min(value, edge_value);
          }
        for (const auto center : r.centers)
          value = std::min(value, d[center]);
        ub[r.coarse_dof] = value;
      }

    for (unsigned int k = 0; k < faces.size(); ++k)
      {
        double value = infinity;
        for (const auto son : faces[k].sons)
          value = std::min(value, d[son]);
        ub[faces[k].coarse_dof] = value / face_scale[k];
      }
  }
} // namespace FoslsContact
