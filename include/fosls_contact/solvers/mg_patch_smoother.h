#ifndef fosls_contact_solvers_mg_patch_smoother_h
#define fosls_contact_solvers_mg_patch_smoother_h

#include <deal.II/multigrid/mg_base.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/patch_smoother.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The patch smoother as the MGSmootherBase of the linear truncated cycle
   * run by deal.II's Multigrid (LinearMultigrid): smooth() does the sweeps
   * of @p sweeps (the pre-smoother's forward or the post-smoother's
   * backward ones, with their numbers of steps) with the obstacles +inf,
   * on the finest level with the linear roles of the Newton step, as the
   * own linear cycle (MonotoneCycle) does.
   *
   * apply() differs from deal.II's default (zero the iterate, then
   * smooth) on a level's second visit in a W- or F-cycle: deal.II 9.4's
   * Multigrid::level_step() starts every visit with apply() on the same
   * defect, so that the second visit would recompute the first one's
   * correction and throw it away. Here a visit after the first one since
   * the last restriction to the level (new_defect()) smooths on from the
   * first visit's correction instead; the sweeps are affine, so this is
   * the own cycle's second visit (a correction for the defect left by the
   * first, added to it) up to round-off.
   */
  class MGPatchSmoother : public MGSmootherBase<LevelVector>
  {
  public:
    /**
     * Sweeps of @p sweeps on levels up to @p finest, with the obstacles
     * @p infinite (one vector of +inf per level) and the linear roles set
     * through @p controls (the smoother that owns the patches).
     */
    MGPatchSmoother(PatchSmoother &                 controls,
                    const PatchSmoother &           sweeps,
                    const unsigned int              finest,
                    const std::vector<LevelVector> &infinite);

    void smooth(const unsigned int level, LevelVector &u, const LevelVector &rhs) const override;
    /** u = 0 on a level's first visit since new_defect(), then smooth(). */
    void apply(const unsigned int level, LevelVector &u, const LevelVector &rhs) const override;
    void clear() override {}

    /** A new defect was restricted to level @p level (or a new cycle starts). */
    void new_defect(const unsigned int level) const { first_visit[level] = true; }

  private:
    PatchSmoother &                 controls;
    const PatchSmoother &           sweeps;
    const unsigned int              finest;
    const std::vector<LevelVector> &infinite;
    mutable std::vector<bool>       first_visit;
  };
} // namespace FoslsContact

#endif
