/* robot_rod_act.c: the Cosserat-rod leg's actuation: each segment's four chamber pressures ->
 * its intrinsic curvature and stretch (csrRodSegmentActuation) from the calibration, over a
 * macro step (csr_rodActuate: the values at both ends, interpolated in time by the right-hand
 * side), and the calibration's lazily filled tables that make that cheap (csrRodActCache: one
 * per leg, or one shared by the legs of a robot; a memo of recent pressure sets in front).
 * Split from robot_rod_dyn.c (the dynamics layer reads d->act only). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_rod_internal.h"

/* pressures equal within this (MPa) reuse the cached actuation (1e-7 MPa moves
 * a bend by < 1e-6 relative at gait pressures) */
#define CSR_ROD_P_TOL 1e-7


csrRodActCache* csr_rodActCacheCreate(csError* err) {
  csrRodActCache* c = calloc(1, sizeof *c);
  if (!c) {
    cs_errorSet(err, CS_ERR_MEMORY, "rod: out of memory (calibration tables)");
  }
  return c;
}


void csr_rodActCacheDestroy(csrRodActCache* c) { free(c); }


int csr_rodDataUseCache(csrRodData* d, csrRodActCache* c) {
  if (c) {
    /* its own tables would only take memory (~1 MB a leg) */
    free(d->own_cache);
    d->own_cache = NULL;
    d->cache = c;
    return 0;
  }
  if (!d->own_cache) {
    d->own_cache = calloc(1, sizeof *d->own_cache);
  }
  d->cache = d->own_cache;
  return d->own_cache ? 0 : -1;
}


/* pressures of one segment equal within CSR_ROD_P_TOL */
static int samePressures(const double* a, const double* b) {
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (fabs(a[j] - b[j]) > CSR_ROD_P_TOL) {
      return 0;
    }
  }
  return 1;
}


/* the pattern of p: the chambers above CSR_ROD_P_TOL as a bit mask, when they all share one
 * level (returned in *level), else 0 */
static int patternOf(const double p[4], double* level) {
  int mask = 0;
  double top = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (p[j] > CSR_ROD_P_TOL) {
      mask |= 1 << j;
      top = fmax(top, p[j]);
    }
  }
  for (int j = 0; j < CSR_NCHAMBER && mask; j++) {
    if ((mask >> j & 1) && fabs(p[j] - top) > CSR_ROD_P_TOL) {
      return 0;
    }
  }
  *level = top;
  return mask;
}


/* the table's actuation at level k of pattern slot q (evaluated once); 0 or the map's code */
static int tableNode(const csrRodModel* m, csrRodData* d, int s, int q, int k,
                     const csrRodSegmentActuation** a) {
  csrRodActTable* tb = &d->cache->table[s];
  if (!tb->known[q][k]) {
    double pk[4];
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      pk[j] = (tb->mask[q] >> j & 1) ? k * CSR_ROD_TAB_DP : 0;
    }
    int rc = csr_rodActuationEval_(m, s, pk, &tb->a[q][k], d->cb_msg, sizeof d->cb_msg);
    if (rc != 0) {
      return rc;
    }
    tb->known[q][k] = 1;
  }
  *a = &tb->a[q][k];
  return 0;
}


/* interpolate between two actuations: (1 - u) a + u b */
void csr_rodActuationLerp_(const csrRodSegmentActuation* a, const csrRodSegmentActuation* b,
                           double u, csrRodSegmentActuation* out) {
  memset(out, 0, sizeof *out);
  for (int k = 0; k < 3; k++) {
    out->u0[k] = a->u0[k] + u * (b->u0[k] - a->u0[k]);
    out->sigma0[k] = a->sigma0[k] + u * (b->sigma0[k] - a->sigma0[k]);
  }
  out->has_section = a->has_section && b->has_section;
  if (out->has_section) {
    const csrRodSection *sa = &a->section, *sb = &b->section;
    csrRodSection* so = &out->section;
    so->EA = sa->EA + u * (sb->EA - sa->EA);
    so->GJ = sa->GJ + u * (sb->GJ - sa->GJ);
    for (int k = 0; k < 2; k++) {
      so->GA[k] = sa->GA[k] + u * (sb->GA[k] - sa->GA[k]);
      so->EI[k] = sa->EI[k] + u * (sb->EI[k] - sa->EI[k]);
    }
  }
}


/* the two-level pattern of p: the chambers above CSR_ROD_P_TOL in exactly two groups of equal
 * pressure (within CSR_ROD_P_TOL); group A holds the lowest such chamber. Returns 1 with the
 * masks and levels, else 0 */
static int twoLevelsOf(const double p[4], int* mask_a, double* xa, int* mask_b, double* xb) {
  int ma = 0, mb = 0;
  double la = 0, lb = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (!(p[j] > CSR_ROD_P_TOL)) {
      continue;
    }
    if (!ma || fabs(p[j] - la) <= CSR_ROD_P_TOL) {
      la = ma ? fmax(la, p[j]) : p[j];
      ma |= 1 << j;
    } else if (!mb || fabs(p[j] - lb) <= CSR_ROD_P_TOL) {
      lb = mb ? fmax(lb, p[j]) : p[j];
      mb |= 1 << j;
    } else {
      return 0; /* a third level */
    }
  }
  if (!ma || !mb) {
    return 0;
  }
  /* each group within the tolerance of its level (a chain of near values does not merge) */
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (((ma >> j & 1) && fabs(p[j] - la) > CSR_ROD_P_TOL) ||
        ((mb >> j & 1) && fabs(p[j] - lb) > CSR_ROD_P_TOL)) {
      return 0;
    }
  }
  *mask_a = ma;
  *xa = la;
  *mask_b = mb;
  *xb = lb;
  return 1;
}


/* the two-level table's node (i, j) of masks (ma, mb) in segment s (evaluated once); 0 or the
 * map's code */
static int table2Node(const csrRodModel* m, csrRodData* d, int s, int ma, int mb, int i, int j,
                      csrRodSegmentActuation* a) {
  csrRodActTable2* tb = &d->cache->table2[s];
  const unsigned long long key =
      ((((unsigned long long)ma << 4 | (unsigned long long)mb) << 16 | (unsigned)i) << 16 |
       (unsigned)j) + 1;
  unsigned h = (unsigned)((key * 0x9E3779B97F4A7C15ull) >> 40) & (CSR_ROD_TAB2_CAP - 1);
  while (tb->key[h] != 0) {
    if (tb->key[h] == key) {
      *a = tb->a[h];
      return 0;
    }
    h = (h + 1) & (CSR_ROD_TAB2_CAP - 1);
  }
  if (tb->n >= CSR_ROD_TAB2_CAP / 2) {
    /* half full: start over (the nodes are exact evaluations; dropping them changes no value) */
    memset(tb->key, 0, sizeof tb->key);
    tb->n = 0;
    h = (unsigned)((key * 0x9E3779B97F4A7C15ull) >> 40) & (CSR_ROD_TAB2_CAP - 1);
  }
  double pk[4];
  for (int c = 0; c < CSR_NCHAMBER; c++) {
    pk[c] = (ma >> c & 1) ? i * CSR_ROD_TAB_DP : ((mb >> c & 1) ? j * CSR_ROD_TAB_DP : 0);
  }
  int rc = csr_rodActuationEval_(m, s, pk, &tb->a[h], d->cb_msg, sizeof d->cb_msg);
  if (rc != 0) {
    return rc;
  }
  tb->key[h] = key;
  tb->n++;
  *a = tb->a[h];
  return 0;
}


/* a + u (b - a) + v (c - b): linear interpolation on a triangle of table nodes */
static void actuationTri(const csrRodSegmentActuation* a, const csrRodSegmentActuation* b,
                         const csrRodSegmentActuation* c, double u, double v,
                         csrRodSegmentActuation* out) {
  memset(out, 0, sizeof *out);
  for (int k = 0; k < 3; k++) {
    out->u0[k] = a->u0[k] + u * (b->u0[k] - a->u0[k]) + v * (c->u0[k] - b->u0[k]);
    out->sigma0[k] =
        a->sigma0[k] + u * (b->sigma0[k] - a->sigma0[k]) + v * (c->sigma0[k] - b->sigma0[k]);
  }
  out->has_section = a->has_section && b->has_section && c->has_section;
  if (out->has_section) {
    const csrRodSection *sa = &a->section, *sb = &b->section, *sc = &c->section;
    csrRodSection* so = &out->section;
    so->EA = sa->EA + u * (sb->EA - sa->EA) + v * (sc->EA - sb->EA);
    so->GJ = sa->GJ + u * (sb->GJ - sa->GJ) + v * (sc->GJ - sb->GJ);
    for (int k = 0; k < 2; k++) {
      so->GA[k] = sa->GA[k] + u * (sb->GA[k] - sa->GA[k]) + v * (sc->GA[k] - sb->GA[k]);
      so->EI[k] = sa->EI[k] + u * (sb->EI[k] - sa->EI[k]) + v * (sc->EI[k] - sb->EI[k]);
    }
  }
}


/* segment s's actuation at a two-level pattern of p (twoLevelsOf) from the two-level table: the
 * cell (i, j) of (x, y) = (level A, level B) / dP is split along its diagonal u = v, the line
 * x = y where the calibration's maximum pressure (its FE row interpolation) has a kink; on each
 * triangle the interpolation is linear, so its error is second order everywhere, as the
 * one-level table's. 0, 1 when p has no two-level pattern or the grid does not reach it, or
 * the map's code (a node it refuses) */
static int actuationAt2(const csrRodModel* m, csrRodData* d, int s, const double p[4],
                        csrRodSegmentActuation* out) {
  int ma, mb;
  double xa, xb;
  if (!twoLevelsOf(p, &ma, &xa, &mb, &xb)) {
    return 1;
  }
  const double x = xa / CSR_ROD_TAB_DP, y = xb / CSR_ROD_TAB_DP;
  const int i = (int)floor(x), j = (int)floor(y);
  if (i + 1 >= CSR_ROD_TAB_N || j + 1 >= CSR_ROD_TAB_N) {
    return 1;
  }
  const double u = x - i, v = y - j;
  /* copies: a later node may clear the hash and take an earlier node's slot */
  csrRodSegmentActuation na, nb, nc;
  const csrRodSegmentActuation *a = &na, *b = &nb, *c = &nc;
  int rc = table2Node(m, d, s, ma, mb, i, j, &na);
  if (rc == 0) {
    rc = u >= v ? table2Node(m, d, s, ma, mb, i + 1, j, &nb)
                : table2Node(m, d, s, ma, mb, i, j + 1, &nb);
  }
  if (rc == 0) {
    rc = table2Node(m, d, s, ma, mb, i + 1, j + 1, &nc);
  }
  if (rc != 0) {
    return rc;
  }
  /* (0,0) -> (1,0) -> (1,1) below the diagonal, (0,0) -> (0,1) -> (1,1) above it */
  if (u >= v) {
    actuationTri(a, b, c, u, v, out);
  } else {
    actuationTri(a, b, c, v, u, out);
  }
  return 0;
}


/* segment s's actuation at pressures p. Chambers inflated together at one level: the pattern's
 * table, interpolated linearly between its 5 kPa levels (measured on the leg's S-shape over
 * 0..0.3 MPa against the map itself: at most 0.005 deg of bend and 4e-7 of stretch, where the
 * FE table's own rows are 25 kPa apart and interpolated linearly). Two groups at two levels
 * (the lag between the gait's rows): the two-level table on the same grid (actuationAt2;
 * test_rod_acttable: at most 0.0051 deg and 8.4e-7, the one-level table's 0.0053 deg and
 * 3.9e-7 on the same sampling). Any other pressures: a remembered evaluation within
 * CSR_ROD_P_TOL, else the calibration's (then remembered). */
static int actuationAt(const csrRodModel* m, csrRodData* d, int s, const double p[4],
                       csrRodSegmentActuation* out) {
  double level = 0;
  int mask = patternOf(p, &level);
  int k = (int)floor(level / CSR_ROD_TAB_DP);
  if (mask && k + 1 < CSR_ROD_TAB_N) {
    csrRodActTable* tb = &d->cache->table[s];
    int q = -1;
    for (int i = 0; i < CSR_ROD_TAB_SLOTS; i++) {
      q = tb->mask[i] == mask ? i : q;
    }
    if (q < 0) {
      q = tb->next;
      tb->next = (tb->next + 1) % CSR_ROD_TAB_SLOTS;
      tb->mask[q] = mask;
      memset(tb->known[q], 0, sizeof tb->known[q]);
    }
    const csrRodSegmentActuation *a = NULL, *b = NULL;
    if (tableNode(m, d, s, q, k, &a) == 0 && tableNode(m, d, s, q, k + 1, &b) == 0) {
      csr_rodActuationLerp_(a, b, level / CSR_ROD_TAB_DP - k, out);
      return 0;
    }
    /* a level the map refuses (above its range): the direct evaluation says why */
  } else if (!mask && actuationAt2(m, d, s, p, out) == 0) {
    return 0;
  }
  csrRodActMemo* mm = &d->memo[s];
  for (int k = 0; k < mm->n; k++) {
    if (samePressures(p, mm->p[k])) {
      *out = mm->a[k];
      return 0;
    }
  }
  int rc = csr_rodActuationEval_(m, s, p, out, d->cb_msg, sizeof d->cb_msg);
  if (rc == 0) {
    memcpy(mm->p[mm->next], p, sizeof mm->p[0]);
    mm->a[mm->next] = *out;
    mm->next = (mm->next + 1) % CSR_ROD_MEMO;
    mm->n = mm->n < CSR_ROD_MEMO ? mm->n + 1 : mm->n;
  }
  return rc;
}


int csr_rodActuate(const csrRodModel* m, csrRodData* d, double t0, const double p0[12],
                   double t1, const double p1[12]) {
  csrRodActState n;
  memset(&n, 0, sizeof n);
  n.ta = t0;
  n.tb = t1;
  memcpy(n.pa, p0, sizeof n.pa);
  memcpy(n.pb, p1, sizeof n.pb);
  for (int s = 0; s < CSR_NSEG; s++) {
    const int o = CSR_NCHAMBER * s;
    int rc = 0;
    /* the start of this step is usually the end of the last: reuse its evaluation */
    if (d->act.set && samePressures(p0 + o, d->act.pb + o)) {
      n.a[s] = d->act.b[s];
    } else if (d->act.set && samePressures(p0 + o, d->act.pa + o)) {
      n.a[s] = d->act.a[s];
    } else {
      rc = actuationAt(m, d, s, p0 + o, &n.a[s]);
    }
    if (rc == 0) {
      if (samePressures(p1 + o, p0 + o)) {
        n.b[s] = n.a[s];
      } else {
        rc = actuationAt(m, d, s, p1 + o, &n.b[s]);
      }
    }
    if (rc != 0) {
      return rc; /* the previous actuation stays */
    }
    /* a pressure jump against where the last step ended is a discontinuity */
    if (d->act.set && !samePressures(p0 + o, d->act.pb + o)) {
      d->need_reinit = 1;
    }
  }
  if (!d->act.set) {
    d->need_reinit = 1;
  }
  n.set = 1;
  d->act = n;
  return 0;
}
