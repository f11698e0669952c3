#include <fosls_contact/solvers/mg_patch_smoother.h>

namespace FoslsContact
{
  MGPatchSmoother::MGPatchSmoother(PatchSmoother &                 controls,
                                   const PatchSmoother &           sweeps,
                                   const unsigned int              finest,
                                   const std::vector<LevelVector> &infinite)
    : controls(controls)
    , sweeps(sweeps)
    , finest(finest)
    , infinite(infinite)
    , first_visit(finest + 1, true)
  {}


  void
  MGPatchSmoother::smooth(const unsigned int level, LevelVector &u, const LevelVector &rhs) const
  {
    // the finest level relaxes with the linear roles (on coarser levels
    // the truncation takes care of them)
    controls.use_linear_roles(level, level == finest);
    controls.set_obstacles(level, infinite[level]);
    sweeps.smooth(level, u, rhs);
  }


  void
  MGPatchSmoother::apply(const unsigned int level, LevelVector &u, const LevelVector &rhs) const
  {
    if (first_visit[level])
      u = 0;
    first_visit[level] = false;
    smooth(level, u, rhs);
  }
} // namespace FoslsContact
