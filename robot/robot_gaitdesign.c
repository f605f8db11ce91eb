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


/* the segments' constant-curvature strains for pressures P[12], with or without the map's
 * axial stretch */
static csStatus strainsOf(const csrActuator* act, const csrBendMap* map, const double P[12],
                          int stretch, csrSegmentStrain st[CSR_NSEG], csError* err) {
  memset(st, 0, CSR_NSEG * sizeof *st);
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2], lam = 1;
    if (map->eval(map->ctx, s, P + 4 * s, bend, &lam) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    st[s].lambda0 = stretch ? lam : 1.0;
    st[s].kappa[0] = -bend[0] / act->S[s]; /* bend = -kappa S (robot_analytic.h) */
    st[s].kappa[1] = -bend[1] / act->S[s];
  }
  return CS_OK;
}


/* foot (leg frame, mm) for pressures P[12] */
static csStatus footAt(const csrActuator* act, const csrBendMap* map, const double P[12],
                       int stretch, double foot[3], csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  csStatus rc = strainsOf(act, map, P, stretch, st, err);
  return rc != CS_OK ? rc : csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* samples per segment of the centreline that times a move (robot_gaitdesign.h) */
enum { SHAPE_SAMPLES = 4, SHAPE_ROWS = CSR_NSEG * (SHAPE_SAMPLES + 1) };


/* the leg's centreline (SHAPE_ROWS x 3, leg frame, mm) for pressures P */
static csStatus shapeAt(const csrActuator* act, const csrBendMap* map, const double P[12],
                        int stretch, double* cl, csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  double tip[3];
  csStatus rc = strainsOf(act, map, P, stretch, st, err);
  return rc != CS_OK ? rc : csr_ccForwardKinematics(act, st, SHAPE_SAMPLES, cl, tip, NULL, err);
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


static int bendOf(const csrBendMap* map, int s, unsigned set, double p, double* b);


/* the pressure in [0, pmax] at which chamber set `set` of segment s bends by `want` (rad): the
 * set's bend grows with its pressure, so bisection; 0 or -1 when the map fails */
static int pressureOfBend(const csrBendMap* map, int s, unsigned set, double pmax, double want,
                          double* p) {
  double lo = 0, hi = pmax;
  for (int it = 0; it < SET_BISECTIONS; it++) {
    double mid = 0.5 * (lo + hi), b;
    if (bendOf(map, s, set, mid, &b)) {
      return -1;
    }
    if (b < want) lo = mid; else hi = mid;
  }
  *p = 0.5 * (lo + hi);
  return 0;
}


/* foot (leg frame, mm) for signed sagittal bends th[3] (rad, > 0 towards +e1) and centreline
 * stretches lam[3] */
static csStatus footOfBends(const csrActuator* act, const double th[3], const double lam[3],
                            double foot[3], csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  memset(st, 0, sizeof st);
  for (int s = 0; s < CSR_NSEG; s++) {
    st[s].lambda0 = lam[s];
    st[s].kappa[0] = -th[s] / act->S[s]; /* bend = -kappa S (robot_analytic.h) */
  }
  return csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* Newton iterations and tolerance of a foot pose: the residual is a smooth function of two
 * bends; 1e-9 mm is far below any effect, 40 damped steps are plenty from the start guesses */
enum { FOOT_NEWTON = 40 };
#define FOOT_TOL_MM 1e-9
/* fixed-point passes between the bends and the stretches they come with (--stretch): the
 * stretch changes by a few % over the whole range; a pass gains one digit or more */
enum { FOOT_STRETCH_PASSES = 60 };
#define FOOT_STRETCH_TOL 1e-9 /* 1.7e-7 mm over the leg */


/* the bends (a, b, -(a + b)) of II1, II2, II3 that put the foot at (X, lift H) with segment
 * stretches lam; *best: the closest residual reached (mm) */
static csStatus footBends(const csrActuator* act, double X, double H, int branch,
                          const double lam[3], const double foot0[3], double th[3], double* best,
                          csError* err) {
  /* start guesses: an S-shape for the stroke plus a crouch for the lift, and its mirror; a
   * named branch (II1 towards +e1: plus, -e1: minus) starts from crouches on it and keeps
   * only shapes on it */
  const double starts[4][2] = {{X / 141.0, -X / 141.0}, {X / 141.0 + 0.3, -X / 141.0 - 0.6},
                               {X / 141.0 + 0.6, -X / 141.0 - 1.2}, {-0.3, 0.6}};
  const double on_branch[5][2] = {{X / 141.0, -X / 141.0}, {0.2, -0.5}, {0.1, -0.3},
                                  {0.4, -1.0}, {0.6, -1.4}};
  *best = INFINITY;
  for (int g = 0; g < (branch ? 5 : 4) && *best > FOOT_TOL_MM; g++) {
    double a = branch ? on_branch[g][0] : starts[g][0], b = branch ? on_branch[g][1] : starts[g][1];
    if (branch && g > 0) {
      a *= branch;
      b *= branch;
    } else if (branch && branch * a <= 0) {
      continue; /* the S-shape guess lies on the other branch */
    }
    for (int it = 0; it < FOOT_NEWTON; it++) {
      double r[2], J[2][2], f[3];
      double t0[3] = {a, b, -(a + b)};
      csStatus st = footOfBends(act, t0, lam, f, err);
      if (st != CS_OK) return st;
      r[0] = f[0] - foot0[0] - X;
      r[1] = (foot0[2] - f[2]) - H;
      double nr = hypot(r[0], r[1]);
      if (nr < *best && (!branch || branch * a > 0)) {
        *best = nr;
        memcpy(th, t0, 3 * sizeof(double));
      }
      if (nr < FOOT_TOL_MM) break;
      for (int c = 0; c < 2; c++) {
        double e = 1e-7, t1[3] = {a + (c == 0) * e, b + (c == 1) * e, 0}, f1[3];
        t1[2] = -(t1[0] + t1[1]);
        if ((st = footOfBends(act, t1, lam, f1, err)) != CS_OK) return st;
        J[0][c] = (f1[0] - f[0]) / e;
        J[1][c] = (f[2] - f1[2]) / e;
      }
      double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      if (!(fabs(det) > 1e-12)) break;
      double da = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
      double db = (-J[1][0] * r[0] + J[0][0] * r[1]) / det;
      /* damped: no step larger than 0.2 rad per bend */
      double sc = fmin(1.0, 0.2 / fmax(1e-30, fmax(fabs(da), fabs(db))));
      a -= sc * da;
      b -= sc * db;
    }
  }
  return CS_OK;
}


/* a foot pose: the bends that put the foot at (X, lift), then each segment's pressure on its
 * sagittal pair from the inverse map; with `stretch` the bends are solved again with the
 * stretches those pressures give until both agree (fixed point), so the pose holds on a leg
 * level that stretches (an FE table's Ω pair lengthens a segment by up to ~10 %) */
static csStatus solveFootPose(const csrActuator* act, const csrBendMap* map,
                              const csgDesignSet* set, double pmax, int stretch,
                              const double foot0[3], double P[12], const char* src,
                              const char* name, csError* err) {
  const double X = set->value, H = set->value2;
  double th[3] = {0, 0, 0}, lam[3] = {1, 1, 1}, best = INFINITY, dlam = INFINITY;
  for (int pass = 0; pass < FOOT_STRETCH_PASSES && dlam > FOOT_STRETCH_TOL; pass++) {
    csStatus st = footBends(act, X, H, set->branch, lam, foot0, th, &best, err);
    if (st != CS_OK) return st;
    if (!(best <= 1e-6)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s: no leg shape with a level sole "
                         "puts the foot at %g mm with lift %g mm (closest %.3g mm off)", src,
                         set->line, name, X, H, best);
    }
    memset(P, 0, 12 * sizeof(double));
    for (int s = 0; s < CSR_NSEG; s++) {
      unsigned pair = th[s] > 0 ? 0xCu : 0x3u; /* Ω3&Ω4 bend towards +e1, Ω1&Ω2 towards -e1 */
      double want = fabs(th[s]), bmax;
      if (want < 1e-12) continue;
      if (bendOf(map, s, pair, pmax, &bmax)) {
        return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
      }
      if (bmax < want) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s: II%d must bend %.1f deg, more "
                           "than %g MPa gives (%.1f deg)", src, set->line, name, s + 1,
                           want * 180 / 3.14159265358979323846, pmax,
                           bmax * 180 / 3.14159265358979323846);
      }
      double ps;
      if (pressureOfBend(map, s, pair, pmax, want, &ps)) {
        return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
      }
      for (int j = 0; j < 4; j++) {
        P[4 * s + j] = (pair & (1u << j)) ? ps : 0;
      }
    }
    dlam = 0;
    for (int s = 0; s < CSR_NSEG && stretch; s++) {
      double bend[2], l = 1;
      if (map->eval(map->ctx, s, P + 4 * s, bend, &l) != 0) {
        return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
      }
      dlam = fmax(dlam, fabs(l - lam[s]));
      lam[s] = l;
    }
  }
  if (dlam > FOOT_STRETCH_TOL) {
    return cs_errorSet(err, CS_ERR_SOLVER, "%s:%d: pose %s: the bends and the stretches they "
                       "come with do not settle in %d passes (last change %.3g)", src,
                       set->line, name, FOOT_STRETCH_PASSES, dlam);
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
    if (po->nset == 1 && po->set[0].kind == CSG_TARGET_FOOT) {
      st = solveFootPose(act, map, &po->set[0], pmax, opt->stretch, foot0, P, d->source,
                         po->name, err);
    }
    for (int i = 0; i < po->nset && st == CS_OK && po->set[0].kind != CSG_TARGET_FOOT; i++) {
      const csgDesignSet* set = &po->set[i];
      double p = 0;
      if (set->kind == CSG_TARGET_PRESSURE) {
        p = set->value;
      } else if (set->kind == CSG_TARGET_PRESSURE_OF) {
        /* the pressure the referenced pose gives these chambers: its set that shares a
         * chamber with this one, else its first set */
        const csgDesignPose* rp = &d->pose[set->ref];
        int k = 0;
        for (int q2 = 0; q2 < rp->nset; q2++) {
          int shared = 0;
          for (int j = 0; j < 12; j++) {
            shared |= rp->set[q2].chambers[j] && set->chambers[j];
          }
          if (shared) {
            k = q2;
            break;
          }
        }
        p = out->set_p[set->ref][k];
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
    if ((sa && bendOf(map, s, sa, pa, &ba)) || (sb && bendOf(map, s, sb, pb, &bb))) {
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
      if (pressureOfBend(map, s, set, pmax, want, &ps)) {
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
  double prev[SHAPE_ROWS * 3], cl[SHAPE_ROWS * 3];
  path->len[0] = 0;
  for (int i = 0; i <= PATH_SAMPLES; i++) {
    csStatus st = shapeAt(act, map, path->p[i], stretch, cl, err);
    if (st != CS_OK) {
      return st;
    }
    if (i > 0) {
      double sum = 0;
      for (int k = 0; k < SHAPE_ROWS * 3; k++) {
        sum += (cl[k] - prev[k]) * (cl[k] - prev[k]);
      }
      path->len[i] = path->len[i - 1] + sqrt(sum / SHAPE_ROWS);
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
    csStatus st = solveFootPose(act, map, &set, pmax, stretch, foot0, path->p[i], d->source,
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
   * and a step move keeps the run's ramp. A row carries the pressures of the next row's
   * time: with the run's ramp >= sample each row's change fills the interval to the next row,
   * so the table follows the designed motion (the run's ramp only shapes each sample). */
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
  if (footAt(act, map, zero, opt->stretch, foot0, err) != CS_OK) {
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


void csr_designPosesFormat(const csgDesign* d, const csrDesignedPoses* poses, char* buf,
                           size_t size) {
  size_t n = 0;
  buf[0] = '\0';
  for (int q = 1; q < d->npose && n < size; q++) {
    int w = snprintf(buf + n, size - n, "%spose %s:", n ? "\n" : "", d->pose[q].name);
    n += w > 0 ? (size_t)w : 0;
    /* per segment: its inflated chambers and their pressure(s) */
    for (int s = 0; s < CSR_NSEG && n < size; s++) {
      const double* P = poses->p[q] + 4 * s;
      for (int j = 0; j < 4 && n < size; j++) {
        if (P[j] <= 0) continue;
        unsigned mask = 0;
        for (int k = j; k < 4; k++) {
          mask |= (P[k] == P[j]) ? 1u << k : 0;
        }
        int first = 1;
        for (int k = 0; k < j; k++) {
          first &= P[k] != P[j];
        }
        if (!first) continue;
        char l[16];
        csu_chamberListFormat(mask, l, sizeof l);
        w = snprintf(buf + n, size - n, " II%d:%s %.4f MPa", s + 1, l, P[j]);
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
