/* contact_soft.c: the soft contact law's model (parameters, shapes, history layout) and the
 * per-shape driver that runs the kernels of contact_soft_law.c (see contact_soft.h).
 *
 * Step mode tracks a material point per slot (the sole point above each sole sphere; on a
 * capsule the axis point at the parameter s_m where the slot was anchored, offset by -r along
 * the current normal), because an anchor needs the same material point across a step; at the
 * update a capsule's slot moves to the current load centroid keeping its deflection, so the
 * force stays continuous. */
#include "contact_soft.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact_soft_internal.h"
#include "core_math.h"

enum {
  SLOT_INT = 3,   /* doubles per slot, integrated mode: bristle z */
  SLOT_PATCH = 4, /* foot patch, integrated: z and the torsional bristle phi */
  SLOT_STEP = 4   /* doubles per slot, step mode: anchor a and tag */
};

/* surface point xs of a touching slot and its material velocity vs */
static void slotPoint(const cscShape* sh, const cscShapeState* st, const cscSoftGeom* g,
                      double s, double xs[3], double vs[3]);
/* step mode of one point slot: forces (zw == NULL) or the anchor update into zw */
static void slotStep(const cscSoftParams* p, const cscShape* sh, const cscShapeState* st,
                     const cscSoftGeom* g, int touching, const double c[3], const double* zk,
                     double* zw, cscShapeLoad* ld, cscSoftFriction* f, double xs[3]);
/* fill slot info and add to the report for one finished slot */
static void slotReport(int shape, const cscSoftAcc* acc, const cscSoftGeom* g, int touching,
                       const double xs[3], const cscSoftFriction* f, cscSlotInfo* info,
                       cscSoftReport* rep);
/* one shape: normal and friction loads, history rate or (step mode, zw) update; with zw and
 * then_load, the update and then the friction at the updated anchors into ld, info and rep */
static int shapeEvaluate(const cscSoftModel* m, int i, const cscShapeState* st,
                         const double* z, double* zw, int then_load, cscShapeLoad* ld,
                         double* zdot, cscSlotInfo* info, cscSoftReport* rep);


cscSoftParams csc_softDefaultParams(void) {
  cscSoftParams p;
  /* silicone on a dry road, as contact_ode.c (docs/reference.md assumptions) */
  p.mu = 0.8;
  /* 1 N/mm^3: a 15 x 15 mm sole under a stance leg's 0.8 N sinks 3.6 um (stiffness 225 N/mm),
   * a capsule lying along 10 mm of its length under 0.8 N 0.06 mm, the worst case (a capsule
   * crossing an edge, point-like) 0.18 mm: all far below 1 mm, while the contact frequency of
   * a 40 g foot (380 Hz) stays easy for an implicit integrator */
  p.k_area = 1.0;
  /* 0.1 s/mm: Hunt-Crossley with c = 3 (1 - e) / (2 v) gives e ~ 0.3 at 10 mm/s impacts; on a
   * resting 40 g foot under 0.8 N it is a damping ratio of ~0.4 */
  p.c_hc = 0.1;
  /* 1 um: a quarter of the static sink-in, so a resting foot sits on the linear law */
  p.d_onset = 1e-3;
  /* 10 um: the stick range mu delta_t = 8 um of elastic deflection before sliding (rubber on a
   * road shows 1..100 um); stiffness N / delta_t = 80 N/mm at 0.8 N, the normal's order */
  p.delta_t = 0.01;
  /* 1 ms: damping ratio ~0.7 of a 40 g foot on its 80 N/mm tangential stiffness */
  p.tau_t = 1e-3;
  /* 0.8: up to 80 % of mu N the bristle is purely elastic: a foot at 0.6 +- 0.15 mu N, 40 Hz
   * drifts 8e-8 um/s, against 62 um/s with 0 (plastic flow at any load, LuGre-like); the
   * transition from 0.8 to 1 keeps alpha's slope at 10 per unit of u, mild for BDF (0.5, 0.8,
   * 0.95 measured: same creep and Coulomb force, 380-610 steps per 2.1 s run) */
  p.u_elastic = 0.8;
  /* 2 ms: a lifted foot forgets its bristle within ~10 ms, about one macro step */
  p.tau_reset = 2e-3;
  /* 1 um/s: below any sliding speed of interest, far above round-off of the velocities */
  p.v_plastic = 1e-3;
  /* 4 points integrate the line load over the contact stretch to 1.2e-4 (capsule tilted on a
   * face) and 1.6e-3 (across an edge), measured in test_contact_soft; 8 points: 5e-6 tilted */
  p.nquad = 4;
  p.history = CSC_HISTORY_INTEGRATED;
  /* one bristle + one torsional bristle per foot: 4 history doubles instead of 27, which fits
   * a rod's per-element history block; the per-point foot differs only when the sole twists
   * and slides at once (contact_soft_law.c) */
  p.foot = CSC_FOOT_PATCH;
  return p;
}


csStatus csc_softParamsValidate(const cscSoftParams* p, csError* err) {
  struct {
    const char* name;
    double v;
    double lo;   /* lower bound */
    int open_lo; /* lo itself excluded */
    double hi;   /* upper bound (excluded if open_hi) */
    int open_hi;
  } f[] = {{"mu", p->mu, 0, 0, INFINITY, 1},          {"k_area", p->k_area, 0, 1, INFINITY, 1},
           {"c_hc", p->c_hc, 0, 0, INFINITY, 1},      {"d_onset", p->d_onset, 0, 1, INFINITY, 1},
           {"delta_t", p->delta_t, 0, 1, INFINITY, 1}, {"tau_t", p->tau_t, 0, 0, INFINITY, 1},
           {"u_elastic", p->u_elastic, 0, 0, 1, 1},  {"tau_reset", p->tau_reset, 0, 1, INFINITY, 1},
           {"v_plastic", p->v_plastic, 0, 1, INFINITY, 1}};
  for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
    double v = f[i].v;
    int ok = isfinite(v) && (f[i].open_lo ? v > f[i].lo : v >= f[i].lo) &&
             (f[i].open_hi ? v < f[i].hi : v <= f[i].hi);
    if (!ok) {
      return cs_errorSet(err, CS_ERR_RANGE, "soft contact: %s %g must be finite and %s %g%s",
                         f[i].name, v, f[i].open_lo ? ">" : ">=", f[i].lo,
                         isfinite(f[i].hi) ? (f[i].open_hi ? " and < 1" : " and <= 1") : "");
    }
  }
  if (p->nquad < 1 || p->nquad > CSC_SOFT_MAX_QUAD) {
    return cs_errorSet(err, CS_ERR_RANGE, "soft contact: nquad %d must be in 1..%d", p->nquad,
                       CSC_SOFT_MAX_QUAD);
  }
  if (p->history != CSC_HISTORY_INTEGRATED && p->history != CSC_HISTORY_STEP) {
    return cs_errorSet(err, CS_ERR_RANGE, "soft contact: unknown history mode %d",
                       (int)p->history);
  }
  if (p->foot != CSC_FOOT_PATCH && p->foot != CSC_FOOT_POINTS) {
    return cs_errorSet(err, CS_ERR_RANGE, "soft contact: unknown foot friction %d", (int)p->foot);
  }
  return CS_OK;
}


cscShape csc_softCapsule(double r) {
  cscShape s = {CSC_SHAPE_CAPSULE, r, 0, 0};
  return s;
}


cscShape csc_softFoot(double a) {
  /* 1 mm rim: the sole's edge is moulded round; 3 x 3 points: see the header */
  cscShape s = {CSC_SHAPE_FOOT, 1.0, a, 3};
  return s;
}


cscSoftModel* csc_softCreate(const cscSoftParams* p, const cstTerrain* terrain, int nshape,
                             const cscShape* shapes, csError* err) {
  if (!p || !terrain || nshape < 0 || (nshape > 0 && !shapes)) {
    cs_errorSet(err, CS_ERR_ARG, "soft contact: missing parameters, terrain or shapes");
    return NULL;
  }
  if (csc_softParamsValidate(p, err) != CS_OK) {
    return NULL;
  }
  if (terrain->nbox < 0 || terrain->nbox > CST_MAX_BOXES) {
    cs_errorSet(err, CS_ERR_RANGE, "soft contact: terrain has %d boxes (0..%d)", terrain->nbox,
                CST_MAX_BOXES);
    return NULL;
  }
  for (int i = 0; i < nshape; i++) {
    const cscShape* s = &shapes[i];
    if (s->kind == CSC_SHAPE_CAPSULE) {
      if (!(isfinite(s->radius) && s->radius > 0)) {
        cs_errorSet(err, CS_ERR_RANGE, "soft contact: shape %d: capsule radius %g must be > 0",
                    i, s->radius);
        return NULL;
      }
    } else if (s->kind == CSC_SHAPE_FOOT) {
      if (!(isfinite(s->half_side) && s->half_side > 0 && isfinite(s->radius) &&
            s->radius > 0 && s->radius < s->half_side)) {
        cs_errorSet(err, CS_ERR_RANGE,
                    "soft contact: shape %d: foot half side %g and rim %g must satisfy "
                    "0 < rim < half side", i, s->half_side, s->radius);
        return NULL;
      }
      if (s->nside < CSC_SOFT_MIN_SIDE || s->nside > CSC_SOFT_MAX_SIDE) {
        cs_errorSet(err, CS_ERR_RANGE, "soft contact: shape %d: %d sole points per side (%d..%d)",
                    i, s->nside, CSC_SOFT_MIN_SIDE, CSC_SOFT_MAX_SIDE);
        return NULL;
      }
    } else {
      cs_errorSet(err, CS_ERR_RANGE, "soft contact: shape %d: unknown kind %d", i, (int)s->kind);
      return NULL;
    }
  }
  cscSoftModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "soft contact: out of memory");
    return NULL;
  }
  m->p = *p;
  m->terrain = *terrain;
  m->nshape = nshape;
  size_t ns = nshape > 0 ? (size_t)nshape : 1;
  m->shape = calloc(ns, sizeof *m->shape);
  m->patch = calloc(ns, sizeof *m->patch);
  m->first = calloc(ns + 1, sizeof *m->first);
  m->zoff = calloc(ns + 1, sizeof *m->zoff);
  if (!m->shape || !m->patch || !m->first || !m->zoff) {
    csc_softDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "soft contact: out of memory");
    return NULL;
  }
  if (nshape > 0) {
    memcpy(m->shape, shapes, (size_t)nshape * sizeof *shapes);
  }
  /* slots and history per shape (contact_soft_internal.h); the patch foot exists only with
   * integrated history (step mode anchors material points, one per sole point) */
  int step = p->history == CSC_HISTORY_STEP;
  for (int i = 0; i < nshape; i++) {
    int foot = shapes[i].kind == CSC_SHAPE_FOOT;
    m->patch[i] = foot && !step && p->foot == CSC_FOOT_PATCH;
    int nsl = foot && !m->patch[i] ? shapes[i].nside * shapes[i].nside : 1;
    int nz = step ? SLOT_STEP * nsl : (m->patch[i] ? SLOT_PATCH : SLOT_INT * nsl);
    m->first[i + 1] = m->first[i] + nsl;
    m->zoff[i + 1] = m->zoff[i] + nz;
  }
  m->nslot = m->first[nshape];
  m->nstate = m->zoff[nshape];
  csc_softGaussLegendre(p->nquad, m->gl_x, m->gl_w);
  return m;
}


void csc_softDestroy(cscSoftModel* m) {
  if (!m) {
    return;
  }
  free(m->shape);
  free(m->patch);
  free(m->first);
  free(m->zoff);
  free(m);
}


int csc_softNShape(const cscSoftModel* m) { return m->nshape; }
int csc_softNSlot(const cscSoftModel* m) { return m->nslot; }
int csc_softNState(const cscSoftModel* m) { return m->nstate; }
const cscSoftParams* csc_softParams(const cscSoftModel* m) { return &m->p; }


void csc_softShapeSlots(const cscSoftModel* m, int i, int* first, int* count) {
  *first = m->first[i];
  *count = m->first[i + 1] - m->first[i];
}


void csc_softShapeState(const cscSoftModel* m, int i, int* offset, int* count) {
  *offset = m->zoff[i];
  *count = m->zoff[i + 1] - m->zoff[i];
}


void csc_softShapeStateInit(const cscSoftModel* m, int i, double* z) {
  int n = m->zoff[i + 1] - m->zoff[i];
  for (int k = 0; k < n; k++) z[k] = 0;
  if (m->p.history == CSC_HISTORY_STEP) {
    for (int k = SLOT_STEP - 1; k < n; k += SLOT_STEP) z[k] = CSC_SOFT_FREE;
  }
}


void csc_softStateInit(const cscSoftModel* m, double* z) {
  for (int i = 0; i < m->nshape; i++) csc_softShapeStateInit(m, i, z + m->zoff[i]);
}


static void slotPoint(const cscShape* sh, const cscShapeState* st, const cscSoftGeom* g,
                      double s, double xs[3], double vs[3]) {
  if (sh->kind == CSC_SHAPE_CAPSULE) {
    double xa[3], va[3], wr[3], off[3];
    csc_softAxisPoint(st, s, xa, va);
    csu_scale3(off, g->n, -sh->radius);
    csu_add3(xs, xa, off);
    csu_cross3(wr, st->w, off);
    csu_add3(vs, va, wr);
  } else {
    csu_addScl3(xs, g->xc, g->n, -sh->radius);
    csc_softFootVelocity(st, xs, vs);
  }
}


static void slotStep(const cscSoftParams* p, const cscShape* sh, const cscShapeState* st,
                     const cscSoftGeom* g, int touching, const double c[3], const double* zk,
                     double* zw, cscShapeLoad* ld, cscSoftFriction* f, double xs[3]) {
  double tag = zk[3], xm[3] = {0, 0, 0}, vm[3] = {0, 0, 0};
  double sm = tag >= 0 ? tag : g->sc;
  if (touching) {
    if (sh->kind == CSC_SHAPE_CAPSULE) {
      slotPoint(sh, st, g, sm, xm, vm);
    } else {
      /* the sole point above the sphere: c + rho e3 (e3 points out of the sole) */
      for (int j = 0; j < 3; j++) xm[j] = c[j] + sh->radius * st->R[3 * j + 2];
      csc_softFootVelocity(st, xm, vm);
    }
  }
  if (!zw) {
    if (touching && tag >= 0 && p->mu > 0) {
      csc_softFrictionStep(p, g, xm, vm, zk, f);
      csc_softAddForce(sh, st, sm, xm, f->ft, ld);
      csu_copy3(xs, xm);
    }
    return;
  }
  /* csc_softUpdate: free a lifted slot, anchor a new one where it is, pull an anchor to at most
   * u = 2 - u_elastic behind (where the saturation is already 1: the force is unchanged while
   * the slip runs along the deflection, whose damped part tau_t w then only adds to it) */
  if (!touching) {
    csu_set3(zw, 0, 0, 0);
    zw[3] = CSC_SOFT_FREE;
    return;
  }
  double zr[3] = {0, 0, 0};
  if (tag >= 0 && p->mu > 0) {
    csu_sub3(zr, xm, zk);
    csu_addScl3(zr, zr, g->n, -csu_dot3(zr, g->n));
    double u = csu_norm3(zr) / (p->mu * p->delta_t), u_clip = 2 - p->u_elastic;
    if (u > u_clip) {
      csu_scale3(zr, zr, u_clip / u);
    }
  }
  double xn[3], vn[3];
  if (sh->kind == CSC_SHAPE_CAPSULE) {
    slotPoint(sh, st, g, g->sc, xn, vn); /* the slot moves to today's load centroid */
    zw[3] = g->sc;
  } else {
    csu_copy3(xn, xm);
    zw[3] = 0;
  }
  csu_sub3(zw, xn, zr);
}


static void slotReport(int shape, const cscSoftAcc* acc, const cscSoftGeom* g, int touching,
                       const double xs[3], const cscSoftFriction* f, cscSlotInfo* info,
                       cscSoftReport* rep) {
  if (info) {
    info->shape = shape;
    info->depth = acc->dmax;
    info->N = g->N;
    csu_copy3(info->normal, g->n);
    csu_copy3(info->point, xs);
    csu_copy3(info->ft, f->ft);
    info->torsion = f->T;
    info->ratio = f->ratio;
    info->sliding = f->sliding;
  }
  if (rep) {
    rep->ndeep += acc->deep;
    if (touching) {
      rep->ncontact++;
      rep->nsliding += f->sliding;
      rep->max_depth = fmax(rep->max_depth, acc->dmax);
      rep->max_ratio = fmax(rep->max_ratio, f->ratio);
    }
  }
}


/* broad phase of a foot: 0 when no terrain box comes within d_onset of the box bounding all
 * its sole spheres (centres x0 + ξ e1 + η e2 - ρ e3, |ξ|, |η| <= a, radius ρ; 1 µm of slack
 * for the rounding of the centres), so that no sphere's own query (csc_softSolePointNormal)
 * would find one: skipping them then gives the same bits. A foot in the air (swing) saves
 * nine sphere queries per right-hand side: measured -0.76 % of the instructions of the flat
 * road's first 0.8 s on rod legs (callgrind, gs coupling at 1 ms, 7.716e9 -> 7.657e9), the
 * support's x at 3 s the same to every digit. (The capsules need none: their own box query
 * is the broad phase.) */
static int footNearTerrain(const cscSoftModel* m, const cscShape* sh, const cscShapeState* st) {
  const double a = sh->half_side, rho = sh->radius;
  double lo[3], hi[3];
  for (int k = 0; k < 3; k++) {
    const double* R = st->R + 3 * k;
    double c = st->x0[k] - rho * R[2], ext = a * (fabs(R[0]) + fabs(R[1])) + rho + 1e-3;
    lo[k] = c - ext;
    hi[k] = c + ext;
  }
  int idx[CST_MAX_BOXES];
  if (m->terrain.has_hf) {
    /* the heightfield's bounds: its footprint, up to its highest sample */
    const cstHeightfield* hf = &m->terrain.hf;
    double e = m->p.d_onset;
    double xe = hf->x0 + hf->dx * (hf->nx - 1), ze = hf->z0 + hf->dz * (hf->nz - 1);
    if (lo[1] <= hf->hmax + e && hi[0] >= hf->x0 - e && hi[2] >= hf->z0 - e &&
        lo[0] <= xe + e && lo[2] <= ze + e) {
      return 1;
    }
  }
  return cst_terrainBoxesNear(&m->terrain, lo, hi, m->p.d_onset, idx, CST_MAX_BOXES) > 0;
}


static int shapeEvaluate(const cscSoftModel* m, int i, const cscShapeState* st,
                         const double* z, double* zw, int then_load, cscShapeLoad* ld,
                         double* zdot, cscSlotInfo* info, cscSoftReport* rep) {
  const cscSoftParams* p = &m->p;
  const cscShape* sh = &m->shape[i];
  int step = p->history == CSC_HISTORY_STEP, nz = m->zoff[i + 1] - m->zoff[i];
  memset(ld, 0, sizeof *ld);
  if (zdot) {
    memset(zdot, 0, (size_t)nz * sizeof *zdot);
  }
  /* a non-finite pose or history: recoverable, the integrator retries with a smaller step */
  const double* v = (const double*)st;
  for (size_t k = 0; k < sizeof *st / sizeof(double); k++) {
    if (!isfinite(v[k])) {
      return 1;
    }
  }
  for (int k = 0; k < nz; k++) {
    if (!isfinite(z[k])) {
      return 1;
    }
  }
  int ndeep = 0;
  if (m->patch[i]) {
    /* the foot as one patch: all sole points into one slot, translation and torsion */
    cscSoftAcc acc = {.dmax = -INFINITY};
    cscSoleLoads sl; /* not zeroed: npt, then only what the points wrote is read */
    sl.npt = 0;
    if (footNearTerrain(m, sh, st)) {
      sl.npt = sh->nside * sh->nside;
      for (int k = 0; k < sl.npt; k++) {
        double A;
        csc_softSolePoint(sh, st, k / sh->nside, k % sh->nside, sl.c[k], &A);
        sl.nel[k] = csc_softSolePointNormal(m, sh->radius, A, sl.c[k], st, &acc, ld, sl.el[k]);
      }
    }
    cscSoftGeom g;
    int touching = csc_softSlotFinish(&acc, &g);
    double xs[3] = {0, 0, 0}, vs[3] = {0, 0, 0}, zd[4], Jel = 0, R1el = 0;
    if (touching) {
      slotPoint(sh, st, &g, 0, xs, vs);
      csc_softFootTorsionMoments(&sl, sh->radius, g.xc, g.n, &Jel, &R1el);
    }
    cscSoftFriction f;
    cscSoftParams pbuf;
    const cscSoftParams* pf = csc_softSlotParams(m, &acc, &pbuf);
    csc_softFrictionIntegrated(pf, &acc, &g, touching, vs, z, zd, &f);
    csc_softFrictionTorsion(pf, &acc, &g, touching, csu_dot3(st->w, g.n), Jel, R1el, z[3],
                            &zd[3], &f);
    if (zdot) {
      memcpy(zdot, zd, sizeof zd);
    }
    if (touching) {
      csc_softAddForce(sh, st, 0, xs, f.ft, ld);
      csu_addScl3(ld->m, ld->m, g.n, f.T);
    }
    slotReport(i, &acc, &g, touching, xs, &f, info, rep);
    return acc.deep > 0 ? 1 : 0;
  }
  int nsl = m->first[i + 1] - m->first[i], ss = step ? SLOT_STEP : SLOT_INT;
  int nside = sh->kind == CSC_SHAPE_FOOT ? sh->nside : 1;
  for (int k = 0; k < nsl; k++) {
    cscSoftAcc acc = {.dmax = -INFINITY};
    double c[3] = {0, 0, 0}, A = 0;
    if (sh->kind == CSC_SHAPE_CAPSULE) {
      csc_softCapsuleNormal(m, sh, st, &acc, ld);
    } else {
      csc_softSolePoint(sh, st, k / nside, k % nside, c, &A);
      csc_softSolePointNormal(m, sh->radius, A, c, st, &acc, ld, NULL);
    }
    ndeep += acc.deep;
    cscSoftGeom g;
    int touching = csc_softSlotFinish(&acc, &g);
    double xs[3] = {0, 0, 0}, vs[3] = {0, 0, 0};
    if (touching) {
      slotPoint(sh, st, &g, g.sc, xs, vs);
    }
    cscSoftFriction f = {{0, 0, 0}, 0, 0, 0};
    const double* zk = z + (size_t)k * ss;
    cscSoftParams pbuf;
    const cscSoftParams* pf = csc_softSlotParams(m, &acc, &pbuf);
    if (!step) {
      double zd[3];
      csc_softFrictionIntegrated(pf, &acc, &g, touching, vs, zk, zd, &f);
      if (zdot) {
        csu_copy3(zdot + (size_t)k * ss, zd);
      }
      if (touching) {
        csc_softAddForce(sh, st, g.sc, xs, f.ft, ld);
      }
    } else {
      slotStep(pf, sh, st, &g, touching, c, zk, zw ? zw + (size_t)k * ss : NULL, ld, &f, xs);
      if (zw && then_load) {
        /* the load at the updated anchor from the same geometry: what a new evaluation with
         * the updated history would add, in the same order */
        slotStep(pf, sh, st, &g, touching, c, zw + (size_t)k * ss, NULL, ld, &f, xs);
      }
    }
    slotReport(i, &acc, &g, touching, xs, &f, info ? &info[k] : NULL, rep);
  }
  return ndeep > 0 ? 1 : 0;
}


int csc_softComputeShape(const cscSoftModel* m, int i, const cscShapeState* s, const double* z,
                         cscShapeLoad* load, double* zdot, cscSlotInfo* slot,
                         cscSoftReport* rep) {
  if (!m || i < 0 || i >= m->nshape || !s || !load || (!z && m->zoff[i + 1] > m->zoff[i])) {
    return -1;
  }
  return shapeEvaluate(m, i, s, z, NULL, 0, load, zdot, slot, rep);
}


int csc_softUpdateShape(const cscSoftModel* m, int i, const cscShapeState* s, double* z) {
  if (!m || i < 0 || i >= m->nshape || !s || (!z && m->zoff[i + 1] > m->zoff[i])) {
    return -1;
  }
  if (m->p.history != CSC_HISTORY_STEP) {
    return 0;
  }
  cscShapeLoad scratch;
  return shapeEvaluate(m, i, s, z, z, 0, &scratch, NULL, NULL, NULL);
}


int csc_softUpdateShapeLoad(const cscSoftModel* m, int i, const cscShapeState* s, double* z,
                            cscShapeLoad* load, cscSlotInfo* slot, cscSoftReport* rep) {
  if (!m || i < 0 || i >= m->nshape || !s || !load || (!z && m->zoff[i + 1] > m->zoff[i])) {
    return -1;
  }
  if (m->p.history != CSC_HISTORY_STEP) {
    /* integrated history: the update changes nothing */
    return shapeEvaluate(m, i, s, z, NULL, 0, load, NULL, slot, rep);
  }
  return shapeEvaluate(m, i, s, z, z, 1, load, NULL, slot, rep);
}


int csc_softCompute(const cscSoftModel* m, const cscShapeState* s, const double* z,
                    cscShapeLoad* load, double* zdot, cscSlotInfo* slot, cscSoftReport* rep) {
  if (!m || (!s && m->nshape > 0) || (!z && m->nstate > 0)) {
    return -1;
  }
  if (rep) {
    memset(rep, 0, sizeof *rep);
  }
  int worst = 0;
  for (int i = 0; i < m->nshape; i++) {
    cscShapeLoad scratch;
    int rc = shapeEvaluate(m, i, &s[i], z + m->zoff[i], NULL, 0, load ? &load[i] : &scratch,
                           zdot ? zdot + m->zoff[i] : NULL, slot ? slot + m->first[i] : NULL,
                           rep);
    worst = rc > worst ? rc : worst;
  }
  return worst;
}


int csc_softUpdate(const cscSoftModel* m, const cscShapeState* s, double* z) {
  if (!m || (!s && m->nshape > 0) || (!z && m->nstate > 0)) {
    return -1;
  }
  int worst = 0;
  for (int i = 0; i < m->nshape; i++) {
    int rc = csc_softUpdateShape(m, i, &s[i], z + m->zoff[i]);
    worst = rc > worst ? rc : worst;
  }
  return worst;
}


void csc_softLoadAsPointForce(const cscSoftModel* m, int i, const cscShapeState* s,
                              const cscShapeLoad* load, double f[3], double P[3], double M[3]) {
  csu_add3(f, load->f0, load->f1);
  csu_copy3(M, load->m);
  if (m->shape[i].kind != CSC_SHAPE_CAPSULE) {
    csu_copy3(P, s->x0);
    return;
  }
  double ff = csu_dot3(f, f), xi = ff > 0 ? csu_dot3(load->f1, f) / ff : 0.5, v[3], r[3], t[3];
  xi = fmin(fmax(xi, 0.0), 1.0);
  csc_softAxisPoint(s, xi, P, v);
  /* M = m + (x0 - P) x f0 + (x1 - P) x f1: the moment the single force at P leaves out */
  csu_sub3(r, s->x0, P);
  csu_cross3(t, r, load->f0);
  csu_add3(M, M, t);
  csu_sub3(r, s->x1, P);
  csu_cross3(t, r, load->f1);
  csu_add3(M, M, t);
}
