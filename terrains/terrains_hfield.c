/* terrains_hfield.c: heightfield geometry and its ODE geom (see terrains_hfield.h). */
#include "terrains_hfield.h"

#include <math.h>
#include <stdint.h>


static double sampleH(const cstHeightfield* hf, int i, int j) { return hf->h[j * hf->nx + i]; }


static void vertex(const cstHeightfield* hf, int i, int j, double v[3]) {
  v[0] = hf->x0 + i * hf->dx;
  v[1] = sampleH(hf, i, j);
  v[2] = hf->z0 + j * hf->dz;
}


double cst_hfHeightAt(const cstHeightfield* hf, double x, double z) {
  double u = (x - hf->x0) / hf->dx, w = (z - hf->z0) / hf->dz;
  if (!(u >= 0 && u <= hf->nx - 1 && w >= 0 && w <= hf->nz - 1)) {
    return -INFINITY;
  }
  int i = (int)u, j = (int)w;
  if (i > hf->nx - 2) i = hf->nx - 2; /* the far edge belongs to the last cell */
  if (j > hf->nz - 2) j = hf->nz - 2;
  double a = u - i, b = w - j;
  /* triangle ABC (a + b < 1) or DBC: linear on each (the same split as ODE's GetHeight) */
  if (a + b < 1) {
    double hA = sampleH(hf, i, j);
    return hA + (sampleH(hf, i + 1, j) - hA) * a + (sampleH(hf, i, j + 1) - hA) * b;
  }
  double hD = sampleH(hf, i + 1, j + 1);
  return hD + (sampleH(hf, i + 1, j) - hD) * (1 - b) + (sampleH(hf, i, j + 1) - hD) * (1 - a);
}


/* closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5) */
static void closestOnTriangle(const double p[3], const double a[3], const double b[3],
                              const double c[3], double q[3]) {
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  for (int k = 0; k < 3; k++) {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = p[k] - a[k];
    bp[k] = p[k] - b[k];
    cp[k] = p[k] - c[k];
  }
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
  double d1 = DOT(ab, ap), d2 = DOT(ac, ap);
  if (d1 <= 0 && d2 <= 0) {
    for (int k = 0; k < 3; k++) q[k] = a[k];
    return;
  }
  double d3 = DOT(ab, bp), d4 = DOT(ac, bp);
  if (d3 >= 0 && d4 <= d3) {
    for (int k = 0; k < 3; k++) q[k] = b[k];
    return;
  }
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    double v = d1 / (d1 - d3);
    for (int k = 0; k < 3; k++) q[k] = a[k] + v * ab[k];
    return;
  }
  double d5 = DOT(ab, cp), d6 = DOT(ac, cp);
  if (d6 >= 0 && d5 <= d6) {
    for (int k = 0; k < 3; k++) q[k] = c[k];
    return;
  }
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    double w = d2 / (d2 - d6);
    for (int k = 0; k < 3; k++) q[k] = a[k] + w * ac[k];
    return;
  }
  double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    for (int k = 0; k < 3; k++) q[k] = b[k] + w * (c[k] - b[k]);
    return;
  }
  double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
  for (int k = 0; k < 3; k++) q[k] = a[k] + ab[k] * v + ac[k] * w;
#undef DOT
}


/* the cell index of coordinate x along an axis of n samples from x0, dx apart, clamped to
 * -1..n in floating point first (a far point must not overflow the int) */
static int cellIndex(double x, double x0, double dx, int n) {
  double c = floor((x - x0) / dx);
  return c < -1 ? -1 : (c > n ? n : (int)c);
}


double cst_hfSignedDistance(const cstHeightfield* hf, const double p[3], double reach,
                            double cp[3], double n[3]) {
  double hs = cst_hfHeightAt(hf, p[0], p[2]);
  int below = isfinite(hs) && p[1] < hs;
  if (below && p[1] < hf->hmin - hf->thickness) {
    return INFINITY; /* under the solid */
  }
  if (!below && p[1] - reach > hf->hmax) {
    return INFINITY;
  }
  /* the cells whose x-z extent comes within reach of p */
  int i0 = cellIndex(p[0] - reach, hf->x0, hf->dx, hf->nx);
  int i1 = cellIndex(p[0] + reach, hf->x0, hf->dx, hf->nx);
  int j0 = cellIndex(p[2] - reach, hf->z0, hf->dz, hf->nz);
  int j1 = cellIndex(p[2] + reach, hf->z0, hf->dz, hf->nz);
  if (i0 < 0) i0 = 0;
  if (j0 < 0) j0 = 0;
  if (i1 > hf->nx - 2) i1 = hf->nx - 2;
  if (j1 > hf->nz - 2) j1 = hf->nz - 2;
  double best = INFINITY, bq[3] = {0, 0, 0};
  for (int j = j0; j <= j1; j++) {
    for (int i = i0; i <= i1; i++) {
      double A[3], B[3], C[3], D[3], q[3];
      vertex(hf, i, j, A);
      vertex(hf, i + 1, j, B);
      vertex(hf, i, j + 1, C);
      vertex(hf, i + 1, j + 1, D);
      for (int t = 0; t < 2; t++) {
        closestOnTriangle(p, t ? D : A, B, C, q);
        double e0 = p[0] - q[0], e1 = p[1] - q[1], e2 = p[2] - q[2];
        double d2 = e0 * e0 + e1 * e1 + e2 * e2;
        if (d2 < best) {
          best = d2;
          bq[0] = q[0];
          bq[1] = q[1];
          bq[2] = q[2];
        }
      }
    }
  }
  if (!isfinite(best)) {
    return INFINITY;
  }
  double d = sqrt(best);
  if (cp) {
    for (int k = 0; k < 3; k++) cp[k] = bq[k];
  }
  if (n) {
    if (d > 0) {
      for (int k = 0; k < 3; k++) n[k] = (below ? bq[k] - p[k] : p[k] - bq[k]) / d;
    } else {
      n[0] = 0; /* on the surface: up (the law sees depth = radius there: deep) */
      n[1] = 1;
      n[2] = 0;
    }
  }
  return below ? -d : d;
}


dGeomID cst_hfBuildOde(const cstHeightfield* hf, dSpaceID space) {
  dHeightfieldDataID data = dGeomHeightfieldDataCreate();
  double W = hf->dx * (hf->nx - 1), D = hf->dz * (hf->nz - 1);
  /* referenced, not copied: sample (i, j) at h[i + j nx], as ODE reads it (x + z * width) */
  dGeomHeightfieldDataBuildDouble(data, hf->h, 0, W, D, hf->nx, hf->nz, 1.0, 0.0,
                                  hf->thickness, 0);
  dGeomHeightfieldDataSetBounds(data, hf->hmin, hf->hmax);
  dGeomID g = dCreateHeightfield(space, data, 1);
  /* ODE's heightfield is centred on its position (x from -W/2 to W/2) */
  dGeomSetPosition(g, hf->x0 + 0.5 * W, 0, hf->z0 + 0.5 * D);
  dGeomSetData(g, hf->own_mu ? (void*)(uintptr_t)&hf->mu : NULL);
  return g;
}


void cst_hfReleaseOde(dSpaceID space) {
  int n = dSpaceGetNumGeoms(space);
  for (int i = 0; i < n; i++) {
    dGeomID g = dSpaceGetGeom(space, i);
    if (dGeomGetClass(g) == dHeightfieldClass) {
      dGeomHeightfieldDataDestroy(dGeomHeightfieldGetHeightfieldData(g));
    }
  }
}
