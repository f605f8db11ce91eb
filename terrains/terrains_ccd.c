/* terrains_ccd.c: support functions, exact distance and broad phase of the terrain's boxes
 * (see terrains_ccd.h). Only libccd's types and inline vector accessors are used here, no
 * library call, so cs_terrains needs libccd's headers but not its library. */
#include "terrains_ccd.h"

#include <math.h>


void cst_boxToLocal(const cstBox* b, const double x[3], double y[3]) {
  double d[3] = {x[0] - b->c[0], x[1] - b->c[1], x[2] - b->c[2]};
  for (int k = 0; k < 3; k++) {
    y[k] = b->R[k] * d[0] + b->R[3 + k] * d[1] + b->R[6 + k] * d[2]; /* R^T d */
  }
}


void cst_boxDirToWorld(const cstBox* b, const double y[3], double x[3]) {
  for (int k = 0; k < 3; k++) {
    x[k] = b->R[3 * k] * y[0] + b->R[3 * k + 1] * y[1] + b->R[3 * k + 2] * y[2];
  }
}


void cst_boxPointToWorld(const cstBox* b, const double y[3], double x[3]) {
  cst_boxDirToWorld(b, y, x);
  for (int k = 0; k < 3; k++) x[k] += b->c[k];
}


void cst_ccdBoxSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const cstBox* b = obj;
  if (!b->oriented) {
    for (int k = 0; k < 3; k++) {
      out->v[k] = dir->v[k] >= 0 ? b->hi[k] : b->lo[k];
    }
    return;
  }
  /* the corner furthest along R^T dir in the box frame, turned back: R s(R^T dir) + c */
  double dl[3], y[3], x[3];
  for (int k = 0; k < 3; k++) {
    dl[k] = b->R[k] * dir->v[0] + b->R[3 + k] * dir->v[1] + b->R[6 + k] * dir->v[2];
    y[k] = dl[k] >= 0 ? b->hi[k] : b->lo[k];
  }
  cst_boxPointToWorld(b, y, x);
  for (int k = 0; k < 3; k++) out->v[k] = x[k];
}


void cst_ccdBoxCenter(const void* obj, ccd_vec3_t* out) {
  const cstBox* b = obj;
  for (int k = 0; k < 3; k++) {
    out->v[k] = b->oriented ? b->c[k] : 0.5 * (b->lo[k] + b->hi[k]);
  }
}


static double signedDistanceAligned(const cstBox* b, const double x[3], double cp[3],
                                    double n[3]);


double cst_boxSignedDistance(const cstBox* b, const double x[3], double cp[3], double n[3]) {
  if (!b->oriented) {
    return signedDistanceAligned(b, x, cp, n);
  }
  /* distance is invariant under the rigid motion: compute in the box frame, turn back */
  double y[3], cl[3], nl[3];
  cst_boxToLocal(b, x, y);
  double d = signedDistanceAligned(b, y, cl, nl);
  if (cp) cst_boxPointToWorld(b, cl, cp);
  if (n) cst_boxDirToWorld(b, nl, n);
  return d;
}


static double signedDistanceAligned(const cstBox* b, const double x[3], double cp[3],
                                    double n[3]) {
  /* outside (or on the surface): the closest point is x clamped to the box, per axis */
  double c[3], e[3], e2 = 0;
  int inside = 1;
  for (int k = 0; k < 3; k++) {
    c[k] = fmin(fmax(x[k], b->lo[k]), b->hi[k]);
    e[k] = x[k] - c[k];
    e2 += e[k] * e[k];
    if (x[k] <= b->lo[k] || x[k] >= b->hi[k]) {
      inside = 0;
    }
  }
  if (!inside) {
    double dist = sqrt(e2);
    if (cp) {
      for (int k = 0; k < 3; k++) cp[k] = c[k];
    }
    if (n) {
      if (dist > 0) {
        for (int k = 0; k < 3; k++) n[k] = e[k] / dist;
      } else {
        /* on the surface: the normal of the face x lies on (first found in face order) */
        for (int k = 0; k < 3; k++) n[k] = 0;
        for (int k = 0; k < 3; k++) {
          if (x[k] <= b->lo[k]) {
            n[k] = -1;
            break;
          }
          if (x[k] >= b->hi[k]) {
            n[k] = 1;
            break;
          }
        }
      }
    }
    return dist;
  }
  /* strictly inside: the nearest of the six faces (ties: lowest face index) */
  int face = 0;
  double best = INFINITY;
  for (int f = 0; f < 6; f++) {
    int k = f / 2;
    double gap = (f % 2) ? b->hi[k] - x[k] : x[k] - b->lo[k];
    if (gap < best) {
      best = gap;
      face = f;
    }
  }
  int k = face / 2;
  double sgn = (face % 2) ? 1.0 : -1.0;
  if (cp) {
    for (int j = 0; j < 3; j++) cp[j] = x[j];
    cp[k] = (face % 2) ? b->hi[k] : b->lo[k];
  }
  if (n) {
    for (int j = 0; j < 3; j++) n[j] = 0;
    n[k] = sgn;
  }
  return -best;
}


int cst_terrainBoxesNear(const cstTerrain* t, const double lo[3], const double hi[3],
                         double margin, int* idx, int max_idx) {
  int count = 0;
  for (int i = 0; i < t->nbox; i++) {
    const cstBox* b = &t->box[i];
    /* an oriented box by its world bounds: the narrow phase is exact, this only has to
     * contain every box within reach */
    const double* blo = b->oriented ? b->wlo : b->lo;
    const double* bhi = b->oriented ? b->whi : b->hi;
    int overlap = 1;
    for (int k = 0; k < 3 && overlap; k++) {
      overlap = blo[k] - margin <= hi[k] && lo[k] <= bhi[k] + margin;
    }
    if (overlap) {
      if (count < max_idx) {
        idx[count] = i;
      }
      count++;
    }
  }
  return count;
}
