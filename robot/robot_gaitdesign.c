/* robot_gaitdesign.c: gait pressures from the calibrated leg model (see robot_gaitdesign.h).
 * Both unknowns are found by bisection: the foot stroke and the segment bend grow
 * monotonically with pressure in every calibration map we have (test_analytic checks it for
 * the analytic model), and bisection needs nothing else. 60 halvings resolve 1 MPa to 1e-18. */
#include "robot_gaitdesign.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "robot_analytic.h"

enum { BISECTIONS = 60 };


csStatus csr_footFromPressures(const csrActuator* act, const csrBendMap* map,
                               const double p[CSR_NSEG * CSR_NCHAMBER], double foot[3],
                               csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  memset(st, 0, sizeof st);
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2], stretch;
    if (map->eval(map->ctx, s, p + 4 * s, bend, &stretch) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    /* bend = -kappa S (robot_analytic.h): back to the stretch-gradient curvature; the prb
     * level ignores the stretch, so the designed motion does too */
    st[s].lambda0 = 1.0;
    st[s].kappa[0] = -bend[0] / act->S[s];
    st[s].kappa[1] = -bend[1] / act->S[s];
  }
  return csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* pressures of the S-shape (stroke) at p, and of the crouch at (p, p2) */
static void shapeS(double p, double P[CSR_NSEG * CSR_NCHAMBER]) {
  memset(P, 0, sizeof(double) * CSR_NSEG * CSR_NCHAMBER);
  P[2] = P[3] = p; /* II1 Ω3&Ω4: bends towards +e1 */
  P[4] = P[5] = p; /* II2 Ω1&Ω2: bends towards -e1 */
}


static void shapeZ(double p, double p2, double P[CSR_NSEG * CSR_NCHAMBER]) {
  shapeS(p, P);
  P[4] = P[5] = p2;
  P[10] = P[11] = p; /* II3 Ω3&Ω4: back towards +e1 */
}


/* total bend angle (rad) of segment s under pressures P */
static double segmentAngle(const csrBendMap* map, int s, const double P[CSR_NCHAMBER]) {
  double bend[2], stretch;
  if (map->eval(map->ctx, s, P, bend, &stretch) != 0) {
    return NAN;
  }
  return hypot(bend[0], bend[1]);
}


csStatus csr_designFlatRoad(const csrActuator* act, const csrBendMap* map, double stroke,
                            double p_max, csrFlatRoadDesign* out, csError* err) {
  if (!(stroke > 0) || !(p_max > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "stroke and p_max must be > 0");
  }
  /* search no higher than the calibration reaches: the map refuses to extrapolate */
  const char* capped = p_max > map->p_max ? " (the calibration's range)" : "";
  p_max = fmin(p_max, map->p_max);
  double P[CSR_NSEG * CSR_NCHAMBER], foot[3], foot0[3];
  memset(P, 0, sizeof P);
  csStatus st = csr_footFromPressures(act, map, P, foot0, err);
  if (st != CS_OK) return st;
  shapeS(p_max, P);
  if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
  if (foot[0] - foot0[0] < stroke) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "a %.1f mm stroke needs more than %.3g MPa%s (reaches %.1f mm)", stroke,
                       p_max, capped, foot[0] - foot0[0]);
  }
  /* stroke: bisection on p */
  double lo = 0, hi = p_max;
  for (int i = 0; i < BISECTIONS; i++) {
    double mid = 0.5 * (lo + hi);
    shapeS(mid, P);
    if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
    if (foot[0] - foot0[0] < stroke) lo = mid; else hi = mid;
  }
  out->p_stroke = 0.5 * (lo + hi);
  shapeS(out->p_stroke, P);
  csr_footFromPressures(act, map, P, foot, err);
  out->stroke = foot[0] - foot0[0];
  out->lift_stroke = foot0[2] - foot[2];
  out->theta_stroke_deg = segmentAngle(map, 0, P) * 180 / 3.14159265358979323846;

  /* crouch: II2 bends twice the S-shape angle */
  double target = 2 * segmentAngle(map, 1, P + 4);
  double Q[CSR_NCHAMBER] = {p_max, p_max, 0, 0};
  if (!(segmentAngle(map, 1, Q) >= target)) {
    return cs_errorSet(err, CS_ERR_RANGE, "the crouch needs more than %.3g MPa%s in II2", p_max,
                       capped);
  }
  lo = out->p_stroke;
  hi = p_max;
  for (int i = 0; i < BISECTIONS; i++) {
    double mid = 0.5 * (lo + hi);
    Q[0] = Q[1] = mid;
    if (segmentAngle(map, 1, Q) < target) lo = mid; else hi = mid;
  }
  out->p_crouch_II2 = 0.5 * (lo + hi);
  shapeZ(out->p_stroke, out->p_crouch_II2, P);
  if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
  out->lift_crouch = foot0[2] - foot[2];
  out->crouch_offset = foot[0] - foot0[0];
  return CS_OK;
}


/* ---- gait design descriptions -> tables ---------------------------------------------------- */

/* samples of a move's pressure path used to time the foot along it (arc-length table): the
 * foot path of a bend is smooth, 64 chords put the arc-length error below 1e-4 relative */
enum { PATH_SAMPLES = 64 };
/* bisection halvings of a set's pressure: 1 MPa / 2^50 ~ 1e-15 MPa */
enum { SET_BISECTIONS = 50 };


csrGaitDesignOptions csr_defaultGaitDesignOptions(void) {
  csrGaitDesignOptions o;
  /* the shipped FE calibration's range (robot/calibration_fe_leg.h5: 0..0.3 MPa) */
  o.p_max = 0.3;
  o.stretch = 0;
  return o;
}


/* foot (leg frame, mm) for pressures P[12], with or without the map's axial stretch */
static csStatus footAt(const csrActuator* act, const csrBendMap* map, const double P[12],
                       int stretch, double foot[3], csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  memset(st, 0, sizeof st);
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2], lam = 1;
    if (map->eval(map->ctx, s, P + 4 * s, bend, &lam) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    st[s].lambda0 = stretch ? lam : 1.0;
    st[s].kappa[0] = -bend[0] / act->S[s];
    st[s].kappa[1] = -bend[1] / act->S[s];
  }
  return csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* the quantity a set's target constrains, for pressures P */
static csStatus measure(const csrActuator* act, const csrBendMap* map, const csgDesignSet* set,
                        const double P[12], const double foot0[3], int stretch, double* v,
                        csError* err) {
  if (set->kind == CSG_TARGET_BEND) {
    int s0 = 0;
    while (s0 < 11 && !set->chambers[s0]) {
      s0++;
    }
    int seg = s0 / 4;
    double bend[2], lam;
    if (map->eval(map->ctx, seg, P + 4 * seg, bend, &lam) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", seg + 1);
    }
    *v = hypot(bend[0], bend[1]) * 180.0 / 3.14159265358979323846;
    return CS_OK;
  }
  double f[3];
  csStatus st = footAt(act, map, P, stretch, f, err);
  if (st != CS_OK) {
    return st;
  }
  switch (set->kind) {
    case CSG_TARGET_STROKE: *v = f[0] - foot0[0]; break;
    case CSG_TARGET_SIDE: *v = f[1] - foot0[1]; break;
    case CSG_TARGET_LIFT: *v = foot0[2] - f[2]; break;
    default: *v = f[2] - foot0[2]; break; /* rise */
  }
  return CS_OK;
}


static void setPressure(const csgDesignSet* set, double p, double P[12]) {
  for (int j = 0; j < 12; j++) {
    if (set->chambers[j]) {
      P[j] = p;
    }
  }
}


static const char* targetName(csgTargetKind k) {
  switch (k) {
    case CSG_TARGET_STROKE: return "stroke";
    case CSG_TARGET_SIDE: return "side";
    case CSG_TARGET_LIFT: return "lift";
    case CSG_TARGET_RISE: return "rise";
    case CSG_TARGET_BEND: return "bend";
    default: return "pressure";
  }
}


csStatus csr_designPoses(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                         const csrGaitDesignOptions* opt, csrDesignedPoses* out, csError* err) {
  memset(out, 0, sizeof *out);
  out->npose = d->npose;
  double pmax = fmin(opt->p_max, map->p_max);
  double zero[12] = {0}, foot0[3];
  csStatus st = footAt(act, map, zero, opt->stretch, foot0, err);
  for (int q = 1; q < d->npose && st == CS_OK; q++) {
    const csgDesignPose* po = &d->pose[q];
    double* P = out->p[q];
    for (int i = 0; i < po->nset && st == CS_OK; i++) {
      const csgDesignSet* set = &po->set[i];
      double p = 0;
      if (set->kind == CSG_TARGET_PRESSURE) {
        p = set->value;
      } else if (set->kind == CSG_TARGET_PRESSURE_OF) {
        p = out->set_p[set->ref][0];
      } else if (set->kind == CSG_TARGET_RISE && !opt->stretch) {
        return cs_errorSet(err, CS_ERR_ARG, "%s:%d: pose %s: 'rise' needs a leg level that "
                           "stretches (the prb chain bends only)", d->source, set->line, po->name);
      } else {
        /* bisection on the set's pressure: the target must lie between its ends */
        double v0, v1;
        setPressure(set, 0, P);
        st = measure(act, map, set, P, foot0, opt->stretch, &v0, err);
        setPressure(set, pmax, P);
        if (st == CS_OK) st = measure(act, map, set, P, foot0, opt->stretch, &v1, err);
        if (st != CS_OK) break;
        double want = set->value;
        if (!((want - v0) * (want - v1) <= 0)) {
          return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s: %s %g is not reachable with "
                             "this chamber set in 0..%g MPa (it gives %.2f .. %.2f)", d->source,
                             set->line, po->name, targetName(set->kind), want, pmax, v0, v1);
        }
        double lo = 0, hi = pmax, sgn = v1 >= v0 ? 1 : -1;
        for (int it = 0; it < SET_BISECTIONS && st == CS_OK; it++) {
          double mid = 0.5 * (lo + hi), v;
          setPressure(set, mid, P);
          st = measure(act, map, set, P, foot0, opt->stretch, &v, err);
          if (sgn * (v - want) < 0) lo = mid; else hi = mid;
        }
        p = 0.5 * (lo + hi);
      }
      if (p > pmax + 1e-12) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s: %.4g MPa is above the calibrated "
                           "range (%g MPa)", d->source, set->line, po->name, p, pmax);
      }
      setPressure(set, p, P);
      out->set_p[q][i] = p;
    }
    double f[3];
    if (st == CS_OK) st = footAt(act, map, P, opt->stretch, f, err);
    if (st == CS_OK) {
      for (int k = 0; k < 3; k++) {
        out->foot[q][k] = f[k] - foot0[k];
      }
    }
  }
  return st;
}


/* A move's path: pressures at PATH_SAMPLES + 1 values of λ in [0, 1] and the foot's arc length
 * there. Each segment's bend vector goes linearly from the old pose's to the new pose's, and
 * its pressures follow from the inverse map of the chamber set that makes that bend: linear in
 * bend, not in pressure, so a foot that is vertical at both ends stays vertical on the way (the
 * S-shape's θ, -θ, 0 or the crouch's θ, -2θ, θ), which a straight pressure path does not do
 * (the map is far from linear: the FE ratio grows from 1.4 to 3.2 over 0..0.3 MPa). A segment
 * whose chambers change from one set to another, or whose set holds unequal pressures, goes
 * linearly in pressure instead. */
typedef struct {
  double p[PATH_SAMPLES + 1][12];
  double len[PATH_SAMPLES + 1];
} MovePath;


/* the common pressure of segment s's inflated chambers in P (mask in *set), or -1 if they
 * differ; 0 with *set = 0 when the segment is vented */
static double segmentSet(const double P[12], int s, unsigned* set) {
  double p = 0;
  *set = 0;
  for (int j = 0; j < 4; j++) {
    double v = P[4 * s + j];
    if (v > 0) {
      if (*set && v != p) {
        return -1;
      }
      p = v;
      *set |= 1u << j;
    }
  }
  return p;
}


/* bend magnitude (rad) of segment s with pressure p on the chambers of `set` */
static int bendOf(const csrBendMap* map, int s, unsigned set, double p, double* b) {
  double q[4], bend[2], lam;
  for (int j = 0; j < 4; j++) {
    q[j] = (set & (1u << j)) ? p : 0;
  }
  if (map->eval(map->ctx, s, q, bend, &lam) != 0) {
    return -1;
  }
  *b = hypot(bend[0], bend[1]);
  return 0;
}


static csStatus movePath(const csrActuator* act, const csrBendMap* map, const double P[12],
                         const double Q[12], int stretch, MovePath* path, csError* err) {
  for (int i = 0; i <= PATH_SAMPLES; i++) {
    double lam = (double)i / PATH_SAMPLES;
    for (int j = 0; j < 12; j++) {
      path->p[i][j] = P[j] + lam * (Q[j] - P[j]);
    }
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    unsigned sa, sb;
    double pa = segmentSet(P, s, &sa), pb = segmentSet(Q, s, &sb);
    if (pa < 0 || pb < 0 || (sa && sb && sa != sb) || (!sa && !sb) || pa == pb) {
      continue; /* linear in pressure (or nothing changes) */
    }
    unsigned set = sa ? sa : sb;
    double ba = 0, bb = 0, pmax = fmax(pa, pb);
    if ((sa && bendOf(map, s, set, pa, &ba)) || (sb && bendOf(map, s, set, pb, &bb))) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    for (int i = 1; i < PATH_SAMPLES; i++) {
      double lam = (double)i / PATH_SAMPLES;
      double want = ba + lam * (bb - ba);
      /* the set's bend grows with its pressure: bisection on [0, max of both ends] */
      double lo = 0, hi = pmax;
      for (int it = 0; it < SET_BISECTIONS; it++) {
        double mid = 0.5 * (lo + hi), b;
        if (bendOf(map, s, set, mid, &b)) {
          return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
        }
        if (b < want) lo = mid; else hi = mid;
      }
      for (int j = 0; j < 4; j++) {
        path->p[i][4 * s + j] = (set & (1u << j)) ? 0.5 * (lo + hi) : 0;
      }
    }
  }
  double prev[3];
  path->len[0] = 0;
  for (int i = 0; i <= PATH_SAMPLES; i++) {
    double f[3];
    csStatus st = footAt(act, map, path->p[i], stretch, f, err);
    if (st != CS_OK) {
      return st;
    }
    if (i > 0) {
      path->len[i] = path->len[i - 1] + sqrt((f[0] - prev[0]) * (f[0] - prev[0]) +
                                             (f[1] - prev[1]) * (f[1] - prev[1]) +
                                             (f[2] - prev[2]) * (f[2] - prev[2]));
    }
    memcpy(prev, f, sizeof prev);
  }
  return CS_OK;
}


/* pressures at the fraction s of the foot's path: λ from the arc length (linear between
 * samples; a path on which the foot does not move, < 1 um, is timed by λ = s), pressures
 * linear between the path's samples */
static void pathAt(const MovePath* path, double s, double P[12]) {
  const double* len = path->len;
  double total = len[PATH_SAMPLES], x;
  if (!(total > 1e-3)) {
    x = s * PATH_SAMPLES;
  } else {
    double want = s * total;
    int i = 0;
    while (i < PATH_SAMPLES - 1 && len[i + 1] < want) {
      i++;
    }
    double a = len[i], b = len[i + 1];
    double f = b > a ? (want - a) / (b - a) : 0;
    x = i + fmin(1.0, fmax(0.0, f));
  }
  int i = (int)floor(x);
  if (i >= PATH_SAMPLES) {
    i = PATH_SAMPLES - 1;
  }
  double f = x - i;
  for (int j = 0; j < 12; j++) {
    P[j] = path->p[i][j] + f * (path->p[i + 1][j] - path->p[i][j]);
  }
}


/* rows of a move: n >= 1 */
static int moveRows(const csgDesign* d, const csgDesignMove* m) {
  if (!(m->duration > 0)) {
    return 1;
  }
  int n = (int)ceil(m->duration / d->sample - 1e-9);
  return n < 1 ? 1 : n;
}


static int cmpDouble(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}


csgGait* csr_designGait(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                        const csrGaitDesignOptions* opt, const csrDesignedPoses* poses,
                        csError* err) {
  /* row times: every move's rows, the end row; sorted, equal times merged */
  int ntime = 1;
  for (int i = 0; i < d->nmove; i++) {
    ntime += moveRows(d, &d->move[i]);
  }
  double* times = malloc((size_t)ntime * sizeof(double));
  /* per move: the from-pose of each leg is its previous move's pose (0 = straight at first);
   * the path tables are per move (legs of one move share from and to poses when they moved
   * together before; otherwise the move is split per leg below) */
  int* from = malloc((size_t)d->nmove * 8 * sizeof(int));
  /* one path per (from, to) pair of poses */
  int npair = d->npose * d->npose;
  MovePath* paths = calloc((size_t)npair, sizeof *paths);
  unsigned char* have = calloc((size_t)npair, 1);
  csgGait* g = NULL;
  if (!times || !from || !paths || !have) {
    cs_errorSet(err, CS_ERR_MEMORY, "gait design: out of memory");
    goto fail;
  }
  int nt = 0;
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* m = &d->move[i];
    int n = moveRows(d, m);
    for (int k = 0; k < n; k++) {
      times[nt++] = m->t0 + (n > 1 ? m->duration * k / n : 0);
    }
  }
  if (d->end > 0) {
    times[nt++] = d->end;
  }
  qsort(times, (size_t)nt, sizeof(double), cmpDouble);
  int nu = 0;
  for (int i = 0; i < nt; i++) {
    if (nu == 0 || times[i] > times[nu - 1] + 1e-9) {
      times[nu++] = times[i];
    }
  }
  /* from-poses and foot path tables per (move, leg) */
  int pose_of[8] = {0};
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* m = &d->move[i];
    for (int k = 0; k < 8; k++) {
      from[8 * i + k] = pose_of[k];
      if (!(m->legs & (1u << k))) {
        continue;
      }
      int pair = pose_of[k] * d->npose + m->pose;
      if (!have[pair]) {
        if (movePath(act, map, poses->p[pose_of[k]], poses->p[m->pose], opt->stretch,
                     &paths[pair], err) != CS_OK) {
          goto fail;
        }
        have[pair] = 1;
      }
      pose_of[k] = m->pose;
    }
  }
  g = csg_gaitCreate(nu, err);
  if (!g) {
    goto fail;
  }
  for (int r = 0; r < nu; r++) {
    double t = times[r];
    csg_gaitSetTime(g, r, t, NULL);
    for (int k = 0; k < 8; k++) {
      /* the leg's latest move that has started by t */
      int im = -1;
      for (int i = 0; i < d->nmove; i++) {
        if ((d->move[i].legs & (1u << k)) && d->move[i].t0 <= t + 1e-9) {
          im = i;
        }
      }
      double P[12] = {0};
      if (im >= 0) {
        const csgDesignMove* m = &d->move[im];
        const MovePath* path = &paths[from[8 * im + k] * d->npose + m->pose];
        int n = moveRows(d, m);
        double u = 1;
        if (n > 1) {
          int kk = (int)floor((t - m->t0) * n / m->duration + 1e-9);
          u = fmin(1.0, (double)(kk + 1) / n);
        }
        pathAt(path, u * u * (3 - 2 * u), P);
      }
      for (int j = 0; j < 12; j++) {
        /* label = 12 k + 4 (s - 1) + j + 1: leg k's twelve chambers are contiguous */
        csg_gaitSetPressure(g, r, 12 * k + j + 1, P[j], NULL);
      }
    }
  }
  free(times);
  free(from);
  free(paths);
  free(have);
  return g;
fail:
  free(times);
  free(from);
  free(paths);
  free(have);
  csg_gaitDestroy(g);
  return NULL;
}


void csr_designPosesFormat(const csgDesign* d, const csrDesignedPoses* poses, char* buf,
                           size_t size) {
  size_t n = 0;
  buf[0] = '\0';
  for (int q = 1; q < d->npose && n < size; q++) {
    const csgDesignPose* po = &d->pose[q];
    int w = snprintf(buf + n, size - n, "%spose %s:", n ? "\n" : "", po->name);
    n += w > 0 ? (size_t)w : 0;
    for (int i = 0; i < po->nset && n < size; i++) {
      for (int s = 0; s < CSR_NSEG && n < size; s++) {
        unsigned mask = 0;
        for (int j = 0; j < 4; j++) {
          mask |= po->set[i].chambers[4 * s + j] ? 1u << j : 0;
        }
        if (mask) {
          char l[16];
          csu_chamberListFormat(mask, l, sizeof l);
          w = snprintf(buf + n, size - n, " II%d:%s", s + 1, l);
          n += w > 0 ? (size_t)w : 0;
        }
      }
      if (n < size) {
        w = snprintf(buf + n, size - n, " %.4f MPa%s", poses->set_p[q][i],
                     i + 1 < po->nset ? ";" : "");
        n += w > 0 ? (size_t)w : 0;
      }
    }
    if (n < size) {
      w = snprintf(buf + n, size - n, " -> foot stroke %.2f, side %.2f, lift %.2f mm",
                   poses->foot[q][0], poses->foot[q][1], -poses->foot[q][2]);
      n += w > 0 ? (size_t)w : 0;
    }
  }
}
