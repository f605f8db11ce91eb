/* fem_bend_wall.h: the sweep's view of the actuator's free surfaces (internal to fem/, used by
 * fem_bend.c and fem_bend_limit.c): the crease and contact measures of fem_wall.h on the vented
 * chambers and the skin at every converged state, and the first pressures past the crease
 * onset in the run's summary. Units: mm, MPa, degrees. */
#ifndef CS_FEM_BEND_WALL_H
#define CS_FEM_BEND_WALL_H

#include "fem_bend.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Measure the free surfaces at d->u (vented = the chambers with ratio 0): fills w; with_ref 1
 * also the reference gap w->gap0 of the chamber where the gap is smallest (0: gap0 NAN).
 * Returns CS_OK, or CS_ERR_MEMORY. */
csStatus csf_bendWallMeasure(const csfModel* m, const csfData* d,
                             const double ratio[CSR_NSEG][CSR_NCHAMBER], int with_ref,
                             csfBendWall* w, csError* err);

/* At a converged state (pressure p, total angle deg): measure (csf_bendWallMeasure), copy the
 * step's figures (lam_vented, lam_skin, gap, jmin) into `step` and note the first pressures past
 * the crease onset in `info`. A failed measure leaves the step's figures NAN (the sweep goes
 * on: it is a report, not a condition of the path). */
void csf_bendNoteWall(const csfModel* m, const csfData* d,
                      const double ratio[CSR_NSEG][CSR_NCHAMBER], double p, double angle,
                      csfBendInfo* info, csfBendStep* step);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_BEND_WALL_H */
