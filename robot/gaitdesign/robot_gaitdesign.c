/* robot_gaitdesign.c: gait pressures from the calibrated leg model (see robot_gaitdesign.h):
 * the flat-road S/Z shapes (csr_designFlatRoad) and a design description's table (the moves'
 * pressure paths, timed along the leg's shape, sampled into rows). The poses a description
 * names are solved in robot_gaitdesign_pose.c.
 * The S/Z shapes' unknowns are found by bisection: the foot stroke and the segment bend grow
 * monotonically with pressure in every calibration map we have (test_analytic checks it for
 * the analytic model), and bisection needs nothing else. 60 halvings resolve 1 MPa to 1e-18. */
#include "robot_gaitdesign.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_analytic.h"
#include "robot_gaitdesign_internal.h"

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
    /* bend = -kappa S (robot_analytic.h): back to the stretch-gradient curvature; without
     * --stretch the designed motion ignores the stretch (the older gaits' legs bent only) */
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


/* A move's path: pressures at PATH_SAMPLES + 1 values of λ in [0, 1] and the foot's arc length
 * there. Each segment's bend vector goes linearly from the old pose's to the new pose's, and
 * its pressures follow from the inverse map of the chamber set that makes that bend: linear in
 * bend, not in pressure, so a foot that is vertical at both ends stays vertical on the way (the
 * S-shape's θ, -θ, 0 or the crouch's θ, -2θ, θ), which a straight pressure path does not do
 * (the map is far from linear: the FE ratio grows from 1.4 to 3.2 over 0..0.3 MPa). A segment
 * that changes to the opposite set (bending the other way) passes through straight; one whose
 * chambers change to an unrelated set, or whose set holds unequal pressures, goes linearly in
 * pressure instead. */
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


static csStatus shapeLength(const csrActuator* act, const csrBendMap* map, int stretch,
                            MovePath* path, csError* err);


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
    /* opposite sets (Ω3&Ω4 vs Ω1&Ω2, Ω1&Ω4 vs Ω2&Ω3, one chamber vs its diagonal one): the
     * bend changes sign; the signed magnitude goes linearly through zero, set A before it,
     * set B after it */
    unsigned rot = ((sa << 2) | (sa >> 2)) & 15u; /* the point reflection of set A */
    int opposite = sa && sb && sb == rot;
    if (pa < 0 || pb < 0 || (sa && sb && sa != sb && !opposite) || (!sa && !sb) ||
        (pa == pb && sa == sb)) {
      continue; /* linear in pressure (or nothing changes) */
    }
    double ba = 0, bb = 0;
    if ((sa && csr_gdBendOf_(map, s, sa, pa, &ba)) || (sb && csr_gdBendOf_(map, s, sb, pb, &bb))) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    if (opposite) {
      ba = -ba; /* signed along B's direction */
    }
    for (int i = 1; i < PATH_SAMPLES; i++) {
      double lam = (double)i / PATH_SAMPLES;
      double want = ba + lam * (bb - ba);
      unsigned set = want < 0 ? sa : (sb ? sb : sa);
      double pmax = want < 0 ? pa : (sb ? pb : pa);
      want = fabs(want);
      double ps; /* on [0, the set's end pressure] */
      if (csr_gdPressureOfBend_(map, s, set, pmax, want, &ps)) {
        return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
      }
      for (int j = 0; j < 4; j++) {
        path->p[i][4 * s + j] = (set & (1u << j)) ? ps : 0;
      }
    }
  }
  return shapeLength(act, map, stretch, path, err);
}


/* the path's length in shape space: the RMS displacement of the centreline's points, so that
 * the leg's mass moves at the profile's pace (a foot-only measure let an S-shape's middle swing
 * out while its foot had hardly moved: measured 6 mm of stance slip) */
static csStatus shapeLength(const csrActuator* act, const csrBendMap* map, int stretch,
                            MovePath* path, csError* err) {
  double prev[CSR_GD_SHAPE_ROWS * 3], cl[CSR_GD_SHAPE_ROWS * 3];
  path->len[0] = 0;
  for (int i = 0; i <= PATH_SAMPLES; i++) {
    csStatus st = csr_gdShapeAt_(act, map, path->p[i], stretch, cl, err);
    if (st != CS_OK) {
      return st;
    }
    if (i > 0) {
      double sum = 0;
      for (int k = 0; k < CSR_GD_SHAPE_ROWS * 3; k++) {
        sum += (cl[k] - prev[k]) * (cl[k] - prev[k]);
      }
      path->len[i] = path->len[i - 1] + sqrt(sum / CSR_GD_SHAPE_ROWS);
    }
    memcpy(prev, cl, sizeof prev);
  }
  return CS_OK;
}


/* the (stroke, lift) of pose q if it is a foot pose or `straight` (0, 0); 0 otherwise */
static int footTarget(const csgDesign* d, int q, double* X, double* H) {
  if (q == CSG_POSE_STRAIGHT) {
    *X = *H = 0;
    return 1;
  }
  const csgDesignPose* po = &d->pose[q];
  if (po->nset == 1 && po->set[0].kind == CSG_TARGET_FOOT) {
    *X = po->set[0].value;
    *H = po->set[0].value2;
    return 1;
  }
  return 0;
}


/* the branch a foot path between poses qa and qb keeps: the one both name (or the named one
 * when the other end is `straight`, which lies on both); 0 (the solver's choice per sample)
 * otherwise */
static int footPathBranch(const csgDesign* d, int qa, int qb) {
  int ba = qa == CSG_POSE_STRAIGHT ? 0 : d->pose[qa].set[0].branch;
  int bb = qb == CSG_POSE_STRAIGHT ? 0 : d->pose[qb].set[0].branch;
  if (qa == CSG_POSE_STRAIGHT) return bb;
  if (qb == CSG_POSE_STRAIGHT) return ba;
  return ba == bb ? ba : 0;
}


/* A move between two foot poses: the foot goes along the straight line from (Xa, Ha) to
 * (Xb, Hb) in (stroke, lift) with a level sole, every sample a foot pose of its own. Why: a
 * segment-wise bend path between poses whose segments all change sides (a swing from behind
 * the hip to in front of it) passes through a nearly straight leg half way, lift ~0: measured,
 * the swinging feet of the flat-road gait brushed the road mid-swing (height 0.1 mm) and held
 * the support back. On the line the lift never drops below the smaller end's. */
static csStatus footPath(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                         int qa, int qb, double Xa, double Ha, double Xb, double Hb, double pmax,
                         int stretch, const double foot0[3], MovePath* path, csError* err) {
  csgDesignSet set;
  memset(&set, 0, sizeof set);
  set.kind = CSG_TARGET_FOOT;
  set.branch = footPathBranch(d, qa, qb);
  set.line = d->pose[qb].line ? d->pose[qb].line : d->pose[qa].line;
  for (int i = 0; i <= PATH_SAMPLES; i++) {
    double lam = (double)i / PATH_SAMPLES;
    set.value = Xa + lam * (Xb - Xa);
    set.value2 = Ha + lam * (Hb - Ha);
    if (set.value2 < 1e-9 && fabs(set.value) < 1e-9) {
      memset(path->p[i], 0, sizeof path->p[i]); /* straight: vented */
      continue;
    }
    csStatus st = csr_gdSolveFootPose_(act, map, &set, pmax, stretch, foot0, path->p[i], d->source,
                                d->pose[qb].name, err);
    if (st != CS_OK) {
      return st;
    }
  }
  return shapeLength(act, map, stretch, path, err);
}


/* pressures at the fraction s of the path: λ from its shape-space length (linear between
 * samples; a path on which the leg does not move, < 1 um, is timed by λ = s), pressures
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


/* the pressures (12) of leg k for the row at t_row whose values are reached at t_next: its
 * latest move started by then (a timed move by t_next, a step move by t_row, which so lands
 * on its own row and keeps the run's ramp), at the fraction of that move's path its profile
 * has reached (before any move: vented) */
static void legAt(const csgDesign* d, const MovePath* paths, const int* from, int k, double t_row,
                  double t_next, double P[12]) {
  int im = -1;
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* m = &d->move[i];
    double t = m->duration > 0 ? t_next : t_row;
    if ((m->legs & (1u << k)) && m->t0 <= t + 1e-9) {
      im = i;
    }
  }
  memset(P, 0, 12 * sizeof(double));
  if (im < 0) {
    return;
  }
  const csgDesignMove* m = &d->move[im];
  double u = m->duration > 0 ? (t_next - m->t0) / m->duration : 1.0;
  u = fmin(1.0, fmax(0.0, u));
  double sp = m->linear == CSG_PROFILE_LINEAR    ? u
              : m->linear == CSG_PROFILE_EASE_IN   ? u * u
              : m->linear == CSG_PROFILE_EASE_OUT  ? u * (2 - u)
                                                   : u * u * (3 - 2 * u);
  pathAt(&paths[from[8 * im + k] * d->npose + m->pose], sp, P);
}


static int cmpDouble(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}


csgGait* csr_designGait(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                        const csrGaitDesignOptions* opt, const csrDesignedPoses* poses,
                        csError* err) {
  /* row times on one grid for every leg: the points k * sample (rounded to 1 ns, so they
   * print as the decimals they are) from one sample before each timed move to its end, each
   * step move's own time, and the end row. Between moves there are no rows: the table holds,
   * and a step move changes over one sample (the table's ramp; the run's ramp in a table of
   * step moves only). A row carries the pressures
   * of the next row's time: with the table's ramp (= sample, `# @ramp`) each row's change
   * fills the interval to the next row, so the table follows the designed motion. */
  long ncand = 2;
  for (int i = 0; i < d->nmove; i++) {
    ncand += 3 + (long)ceil(d->move[i].duration / d->sample);
  }
  if (ncand > 200000) {
    cs_errorSet(err, CS_ERR_RANGE, "%s: more than 100000 rows at %g s a row", d->source,
                d->sample);
    return NULL;
  }
  double* times = malloc((size_t)ncand * sizeof(double));
  if (!times) {
    cs_errorSet(err, CS_ERR_MEMORY, "gait design: out of memory");
    return NULL;
  }
  long nt = 0;
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* m = &d->move[i];
    if (!(m->duration > 0)) {
      times[nt++] = m->t0;
      continue;
    }
    long k0 = (long)floor(m->t0 / d->sample + 1e-9) - 1, k1 = (long)ceil((m->t0 + m->duration) /
                                                                            d->sample - 1e-9);
    for (long k = k0 < 0 ? 0 : k0; k <= k1; k++) {
      times[nt++] = round((double)k * d->sample * 1e9) / 1e9;
    }
  }
  if (d->end > 0) {
    times[nt++] = d->end;
  }
  qsort(times, (size_t)nt, sizeof(double), cmpDouble);
  long nrow = 0;
  for (long i = 0; i < nt; i++) {
    if (nrow == 0 || times[i] > times[nrow - 1] + 1e-9) {
      times[nrow++] = times[i];
    }
  }
  if (nrow > 100000) {
    free(times);
    cs_errorSet(err, CS_ERR_RANGE, "%s: %ld rows is more than a gait table holds (100000)",
                d->source, nrow);
    return NULL;
  }
  /* the foot poses' solver works from the straight leg's foot and the calibrated range */
  double pmax = fmin(opt->p_max, map->p_max), zero[12] = {0}, foot0[3];
  if (csr_gdFootAt_(act, map, zero, opt->stretch, foot0, err) != CS_OK) {
    free(times);
    return NULL;
  }
  int* from = malloc((size_t)d->nmove * 8 * sizeof(int));
  /* one path per (from, to) pair of poses */
  int npair = d->npose * d->npose;
  MovePath* paths = calloc((size_t)npair, sizeof *paths);
  unsigned char* have = calloc((size_t)npair, 1);
  csgGait* g = NULL;
  if (!from || !paths || !have) {
    cs_errorSet(err, CS_ERR_MEMORY, "gait design: out of memory");
    goto fail;
  }
  /* from-poses (each leg's previous move's pose, straight at first) and the paths */
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
        double Xa, Ha, Xb, Hb;
        csStatus st;
        if (footTarget(d, pose_of[k], &Xa, &Ha) && footTarget(d, m->pose, &Xb, &Hb) &&
            pose_of[k] != m->pose) {
          st = footPath(act, map, d, pose_of[k], m->pose, Xa, Ha, Xb, Hb, pmax, opt->stretch,
                        foot0, &paths[pair], err);
        } else {
          st = movePath(act, map, poses->p[pose_of[k]], poses->p[m->pose], opt->stretch,
                        &paths[pair], err);
        }
        if (st != CS_OK) {
          goto fail;
        }
        have[pair] = 1;
      }
      pose_of[k] = m->pose;
    }
  }
  g = csg_gaitCreate((int)nrow, err);
  if (!g) {
    goto fail;
  }
  /* a table with timed moves states the sample as its ramp, so each row's change fills the
   * interval to the next row and the run plays the designed motion (gaits_schedule.h), or
   * the actuation time the description states (`ramp`); --ramp overrides. One of step moves
   * only (the paper's table) leaves the run's ramp unless the description states one. */
  for (int i = 0; i < d->nmove; i++) {
    if (d->move[i].duration > 0.0) {
      g->ramp = d->sample;
    }
  }
  if (d->ramp > 0.0) {
    g->ramp = d->ramp;
  }
  for (long r = 0; r < nrow; r++) {
    double t = times[r];
    double t_next = r + 1 < nrow ? times[r + 1] : t;
    csg_gaitSetTime(g, (int)r, t, NULL);
    for (int k = 0; k < 8; k++) {
      double P[12];
      legAt(d, paths, from, k, t, t_next, P);
      for (int j = 0; j < 12; j++) {
        /* a mirrored leg's pose reflected across its sagittal plane: Ω1 <-> Ω2, Ω3 <-> Ω4 */
        int jj = (d->mirror & (1u << k)) ? (j ^ 1) : j;
        /* label = 12 k + 4 (s - 1) + j + 1: leg k's twelve chambers are contiguous */
        /* round-off of a vented chamber (1e-16 MPa) is written as the 0 it is */
        csg_gaitSetPressure(g, (int)r, 12 * k + jj + 1, P[j] > 1e-9 ? P[j] : 0.0, NULL);
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
