/* fem_bend_wall.c: crease and contact measures of the sweep (see fem_bend_wall.h).
 *
 * Rationale. The b = 3 sweeps stalled on positive definite tangents with the elements of a
 * vented chamber's wall on the compressed side folding (J_min ~ 0.4); the question was whether
 * that is the mesh's limit or the physical one of a model without self-contact (a crease of the
 * compressed free surface, or the chamber's opposite walls meeting). Both are cheap to measure
 * on the converged state (well under a second for six chambers, an estimate from the operation
 * count, against 10 s and more per load step), so
 * every step reports them, and the summary keeps the first pressure past the crease onset. */
#include "fem_bend_wall.h"

#include <math.h>
#include <stdlib.h>

#include "fem_assembly.h"
#include "fem_mesh.h"


csStatus csf_bendWallMeasure(const csfModel* m, const csfData* d,
                             const double ratio[CSR_NSEG][CSR_NCHAMBER], int with_ref,
                             csfBendWall* w, csError* err) {
  const csfMesh* me = m->mesh;
  int vented[CSR_NSEG * CSR_NCHAMBER], nv = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      if (ratio[s][j] == 0.0) {
        vented[nv++] = CSF_TAG_CHAMBER(s, j + 1);
      }
    }
  }
  const int skin = 0; /* the outer lateral surface is the only untagged boundary */
  csf_wallStretch(me, d->u, nv, vented, &w->vented);
  csf_wallStretch(me, d->u, 1, &skin, &w->skin);
  w->gap.gap = INFINITY, w->gap.gap_ref = NAN, w->gap.node = -1;
  w->gap_tag = -1;
  w->gap0 = NAN;
  for (int k = 0; k < nv; k++) {
    csfWallGap g;
    csStatus st = csf_wallGap(me, d->u, 1, &vented[k], CSF_WALL_COS_OPPOSITE, &g, err);
    if (st != CS_OK) {
      return st;
    }
    if (g.gap < w->gap.gap) {
      w->gap = g;
      w->gap_tag = vented[k];
    }
  }
  if (with_ref && w->gap_tag >= 0) {
    /* the same chamber undeformed, for scale (a zero displacement; a report, not the path) */
    double* zero = calloc((size_t)3 * me->nnode, sizeof *zero);
    if (!zero) {
      return cs_errorSet(err, CS_ERR_MEMORY, "csf_bendWallMeasure: %d nodes", me->nnode);
    }
    csfWallGap g0;
    csStatus st = csf_wallGap(me, zero, 1, &w->gap_tag, CSF_WALL_COS_OPPOSITE, &g0, err);
    free(zero);
    if (st != CS_OK) {
      return st;
    }
    w->gap0 = g0.gap;
  }
  return CS_OK;
}


void csf_bendNoteWall(const csfModel* m, const csfData* d,
                      const double ratio[CSR_NSEG][CSR_NCHAMBER], double p, double angle,
                      csfBendInfo* info, csfBendStep* step) {
  double X[3];
  step->jmin = csf_worstElement(m, d, X);
  step->lam_vented = step->lam_skin = step->gap = NAN;
  csfBendWall w;
  csError err;
  cs_errorClear(&err);
  if (csf_bendWallMeasure(m, d, ratio, 0, &w, &err) != CS_OK) {
    return;
  }
  step->lam_vented = w.vented.lam_eq;
  step->lam_skin = w.skin.lam_eq;
  step->gap = w.gap.gap;
  if (isnan(info->p_crease) && w.vented.lam_eq < CSF_CREASE_STRETCH) {
    info->p_crease = p, info->angle_crease = angle;
  }
  if (isnan(info->p_crease_skin) && w.skin.lam_eq < CSF_CREASE_STRETCH) {
    info->p_crease_skin = p;
  }
}
