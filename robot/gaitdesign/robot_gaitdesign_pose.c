/* robot_gaitdesign_pose.c: a design's poses on the calibrated leg model (robot_gaitdesign.h):
 * the leg's constant-curvature forward kinematics on the calibration map (foot, centreline,
 * bends), the inverse problems of one chamber set (bisection on its pressure) and of a foot
 * pose (Newton on two bends with a level sole, then the pressures from the inverse map, with the
 * map's stretch to a fixed point), and the poses' report. The moves between poses and the table
 * are in robot_gaitdesign.c. */
#include "robot_gaitdesign.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core_text.h"
#include "robot_analytic.h"
#include "robot_gaitdesign_internal.h"

/* bisection halvings of a set's pressure: 1 MPa / 2^50 ~ 1e-15 MPa */
enum { SET_BISECTIONS = 50 };

/* a length for the gait file's "%.2f mm" comment: anything that prints as zero is printed as 0,
 * so the sign of a round-off residue (a foot's side of -1e-15 mm) never changes the file */
static double printedMm(double v) { return fabs(v) < 0.005 ? 0.0 : v; }

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
csStatus csr_gdFootAt_(const csrActuator* act, const csrBendMap* map, const double P[12],
                       int stretch, double foot[3], csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  csStatus rc = strainsOf(act, map, P, stretch, st, err);
  return rc != CS_OK ? rc : csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* the leg's centreline (CSR_GD_SHAPE_ROWS x 3, leg frame, mm) for pressures P */
csStatus csr_gdShapeAt_(const csrActuator* act, const csrBendMap* map, const double P[12],
                        int stretch, double* cl, csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  double tip[3];
  csStatus rc = strainsOf(act, map, P, stretch, st, err);
  return rc != CS_OK ? rc
                    : csr_ccForwardKinematics(act, st, CSR_GD_SHAPE_SAMPLES, cl, tip, NULL, err);
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
  csStatus st = csr_gdFootAt_(act, map, P, stretch, f, err);
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


/* the pressure in [0, pmax] at which chamber set `set` of segment s bends by `want` (rad): the
 * set's bend grows with its pressure, so bisection; 0 or -1 when the map fails */
int csr_gdPressureOfBend_(const csrBendMap* map, int s, unsigned set, double pmax, double want,
                          double* p) {
  double lo = 0, hi = pmax;
  for (int it = 0; it < SET_BISECTIONS; it++) {
    double mid = 0.5 * (lo + hi), b;
    if (csr_gdBendOf_(map, s, set, mid, &b)) {
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
csStatus csr_gdSolveFootPose_(const csrActuator* act, const csrBendMap* map,
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
      if (csr_gdBendOf_(map, s, pair, pmax, &bmax)) {
        return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
      }
      if (bmax < want) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s: II%d must bend %.1f deg, more "
                           "than %g MPa gives (%.1f deg)", src, set->line, name, s + 1,
                           want * 180 / 3.14159265358979323846, pmax,
                           bmax * 180 / 3.14159265358979323846);
      }
      double ps;
      if (csr_gdPressureOfBend_(map, s, pair, pmax, want, &ps)) {
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
  csStatus st = csr_gdFootAt_(act, map, zero, opt->stretch, foot0, err);
  for (int q = 1; q < d->npose && st == CS_OK; q++) {
    const csgDesignPose* po = &d->pose[q];
    double* P = out->p[q];
    if (po->nset == 1 && po->set[0].kind == CSG_TARGET_FOOT) {
      st = csr_gdSolveFootPose_(act, map, &po->set[0], pmax, opt->stretch, foot0, P, d->source,
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
                           "stretches (without it the legs bend only)", d->source, set->line, po->name);
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
    if (st == CS_OK) st = csr_gdFootAt_(act, map, P, opt->stretch, f, err);
    if (st == CS_OK) {
      for (int k = 0; k < 3; k++) {
        out->foot[q][k] = f[k] - foot0[k];
      }
    }
  }
  return st;
}


/* bend magnitude (rad) of segment s with pressure p on the chambers of `set` */
int csr_gdBendOf_(const csrBendMap* map, int s, unsigned set, double p, double* b) {
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
                   printedMm(poses->foot[q][0]), printedMm(poses->foot[q][1]),
                   printedMm(-poses->foot[q][2]));
      n += w > 0 ? (size_t)w : 0;
    }
  }
}
