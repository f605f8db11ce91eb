/* fem_bend.c: pressure sweep of the FE actuator with adaptive load stepping (see fem_bend.h).
 *
 * Rationale.
 * Load stepping: pressure control with a secant predictor (u_pred = u_n + dp/dp_prev (u_n -
 * u_n-1)), which follows the large rotations of a 360 deg bend with few Newton iterations; the
 * step halves on divergence and grows by 1.5 after easy steps (<= 5 iterations), capped at
 * p_step so that every output pressure is hit exactly. A step that collapses below
 * CSF_BEND_DP_MIN is taken as a limit point of the pressure-controlled path: the path is then
 * followed by chamber-volume control (csf_passLimit, fem_path.h) through the pressure maximum,
 * which is reported as p_limit; where the pressure rises above it again the sweep resumes under
 * pressure control (a pressure-controlled actuator snaps across), else it ends there.
 * States: predictors and restarts copy the whole Newton state (csf_stateGet: u, element
 * dilatations, fibre stresses), not u alone.
 * --until-angle: once a step crosses the target angle, the crossing is bracketed by two
 * converged states and refined by safeguarded regula falsi, each trial an equilibrium solve, to
 * |angle - target| <= angle_tol: the reported pressure is an equilibrium, not an extrapolation.
 * Angles: each end face of a segment is a plane of mesh nodes (the geometry is split there);
 * a rigid frame is fitted to each face (least squares on the in-plane directions, polar
 * orthonormalisation), and a segment's angle is the rotation between its two face frames,
 * taken about the bending axis (swing-twist: smooth through full turns) and unwrapped, so
 * angles past 180 and 360 deg are followed. The total
 * angle is measured the same way between the base and the tip faces (it includes the small
 * rotation of the solid joints; the sum of segment angles is the paper's Theta = sum theta_i).
 * Fibres: two counter-wound helices per segment (n turns each over S) on the rounded-square
 * perimeter, inset CSF_FIBRE_INSET below the outer surface so the tie points lie inside the
 * host elements. */
#include "fem_bend.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem_output.h"
#include "fem_path.h"

#define CSF_BEND_DP_MIN_REL 1e-3 /* smallest step, relative to p_step, before "limit point" */
/* a step that would end within this fraction of itself below an output pressure is stretched to
 * it (measured: a 0.0002 MPa sliver step after a 0.0166 step cost 3 Newton iterations, 22 s) */
#define CSF_BEND_SNAP 0.25
#define CSF_FIBRE_INSET 0.2      /* mm below the outer surface (fibre radius 0.089 mm) */
#define CSF_PLANE_TOL 1e-6       /* mm: nodes on a face plane */

csfBendOptions csf_bendDefault(void) {
  csfBendOptions o;
  memset(&o, 0, sizeof o);
  for (int s = 0; s < CSR_NSEG; s++) {
    o.chambers[s] = 0x3; /* Omega1 & Omega2 */
  }
  o.p_max = 0.4;
  o.p_step = 0.05;
  o.until_angle = NAN;
  o.angle_tol = 0.1;
  o.mesh_size = 4.0;
  o.fibre_size = 0.0;
  o.fibres = 1;
  /* fibres carry compression (the paper's B32 beams do) with the consistent tangent: the
   * smoothed tension-only law makes Newton cycle because the fibre strains of the first
   * increments (|E| < 5e-4 for all 6642 fibre elements of the baseline at 0.05 MPa) lie inside its
   * smoothing zone; dropping the compressive geometric stiffness (fibre_geo_tension) converges
   * only linearly (20-27 iterations per step) (fem/README.md, "Fibre law") */
  o.fibre_compression = 1;
  o.fibre_geo_tension = 0;
  o.continuation = 1;
  o.krylov = 0;
  o.fibre_split = 1;
  o.work_stem = "crawlsim_fe";
  return o;
}


csStatus csf_bendSetChambers(csfBendOptions* opts, const char* list, csError* err) {
  unsigned mask = 0;
  for (const char* c = list; *c; c++) {
    if (*c >= '1' && *c <= '4') {
      mask |= 1u << (*c - '1');
    } else if (*c != ',' && *c != ' ') {
      return cs_errorSet(err, CS_ERR_PARSE, "--chambers '%s': expected a list of 1..4", list);
    }
  }
  if (!mask) {
    return cs_errorSet(err, CS_ERR_PARSE, "--chambers '%s': no chamber given", list);
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    opts->chambers[s] = mask;
  }
  return CS_OK;
}


int csf_fitPlaneFrame(int n, const double* X, const double* x, double R[9], double centroid[3]) {
  if (n < 3) {
    return -1;
  }
  double Xc[3] = {0, 0, 0}, xc[3] = {0, 0, 0};
  for (int i = 0; i < n; i++) {
    for (int d = 0; d < 3; d++) {
      Xc[d] += X[3 * i + d] / n;
      xc[d] += x[3 * i + d] / n;
    }
  }
  /* C2 = sum dX dX^T (in-plane 2x2), H2 = sum dx dX^T (3x2) */
  double C[4] = {0}, H[6] = {0};
  for (int i = 0; i < n; i++) {
    double dX[2] = {X[3 * i] - Xc[0], X[3 * i + 1] - Xc[1]};
    for (int a = 0; a < 2; a++) {
      for (int b = 0; b < 2; b++) {
        C[2 * a + b] += dX[a] * dX[b];
      }
      for (int d = 0; d < 3; d++) {
        H[2 * d + a] += (x[3 * i + d] - xc[d]) * dX[a];
      }
    }
  }
  double det = C[0] * C[3] - C[1] * C[2];
  if (!(det > 0)) {
    return -1;
  }
  const double Ci[4] = {C[3] / det, -C[1] / det, -C[2] / det, C[0] / det};
  double B[6]; /* B = H2 C2^-1 */
  for (int d = 0; d < 3; d++) {
    B[2 * d] = H[2 * d] * Ci[0] + H[2 * d + 1] * Ci[2];
    B[2 * d + 1] = H[2 * d] * Ci[1] + H[2 * d + 1] * Ci[3];
  }
  /* polar: Q = B (B^T B)^-1/2, with sqrt(S) = (S + sqrt(det S) I) / sqrt(tr S + 2 sqrt(det S)) */
  double S[4] = {0};
  for (int d = 0; d < 3; d++) {
    S[0] += B[2 * d] * B[2 * d];
    S[1] += B[2 * d] * B[2 * d + 1];
    S[3] += B[2 * d + 1] * B[2 * d + 1];
  }
  S[2] = S[1];
  double ds = S[0] * S[3] - S[1] * S[2];
  if (!(ds > 0)) {
    return -1;
  }
  double sq = sqrt(ds), t = sqrt(S[0] + S[3] + 2 * sq);
  double Rt[4] = {(S[0] + sq) / t, S[1] / t, S[2] / t, (S[3] + sq) / t};
  double dr = Rt[0] * Rt[3] - Rt[1] * Rt[2];
  double Ri[4] = {Rt[3] / dr, -Rt[1] / dr, -Rt[2] / dr, Rt[0] / dr};
  double q1[3], q2[3], q3[3];
  for (int d = 0; d < 3; d++) {
    q1[d] = B[2 * d] * Ri[0] + B[2 * d + 1] * Ri[2];
    q2[d] = B[2 * d] * Ri[1] + B[2 * d + 1] * Ri[3];
  }
  csu_cross3(q3, q1, q2);
  for (int d = 0; d < 3; d++) {
    R[3 * d] = q1[d];
    R[3 * d + 1] = q2[d];
    R[3 * d + 2] = q3[d];
  }
  if (centroid) {
    csu_copy3(centroid, xc);
  }
  return 0;
}


/* frame of the node plane z = zp at the current state */
static int planeFrame(const csfModel* m, const csfData* d, double zp, double R[9], double c[3]) {
  const csfMesh* me = m->mesh;
  int n = 0;
  for (int i = 0; i < me->nnode; i++) {
    n += fabs(me->x[3 * i + 2] - zp) < CSF_PLANE_TOL;
  }
  double* X = malloc((size_t)(n > 0 ? n : 1) * 6 * sizeof(double));
  if (!X) {
    return -1;
  }
  double* x = X + 3 * n;
  int k = 0;
  for (int i = 0; i < me->nnode; i++) {
    if (fabs(me->x[3 * i + 2] - zp) < CSF_PLANE_TOL) {
      for (int q = 0; q < 3; q++) {
        X[3 * k + q] = me->x[3 * i + q];
        x[3 * k + q] = me->x[3 * i + q] + d->u[3 * i + q];
      }
      k++;
    }
  }
  int st = csf_fitPlaneFrame(n, X, x, R, c);
  free(X);
  return st;
}


/* Rotation angle (rad) of Ra^T Rb about `axis`, unwrapped near `prev` (rad): the twist part of
 * the swing-twist decomposition of the relative rotation, 2 atan2(q_v . axis, q_w) of its unit
 * quaternion (Shepperd's extraction). For a rotation about `axis` alone it is the rotation angle;
 * unlike (rotation angle) x sign(rotation axis . axis), it stays smooth where the bend passes a
 * full turn: there the relative rotation is a small out-of-plane tilt whose axis is arbitrary,
 * and the signed full angle jumped from 360 - eps to 360 + eps (eps = the tilt, ~0.2 deg on the
 * baseline), so a 360 deg target within 0.1 deg could not be bracketed (fem/README.md).
 * axis NULL: the full rotation angle (>= 0). */
double csf_bendAxisAngle(const double Ra[9], const double Rb[9], const double axis[3],
                         double prev) {
  double R[9];
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = Ra[i] * Rb[j] + Ra[3 + i] * Rb[3 + j] + Ra[6 + i] * Rb[6 + j];
    }
  }
  double q[4]; /* w, x, y, z */
  const double tr = R[0] + R[4] + R[8];
  if (tr > 0) {
    const double S = 2.0 * sqrt(tr + 1.0);
    q[0] = 0.25 * S, q[1] = (R[7] - R[5]) / S, q[2] = (R[2] - R[6]) / S, q[3] = (R[3] - R[1]) / S;
  } else if (R[0] > R[4] && R[0] > R[8]) {
    const double S = 2.0 * sqrt(1.0 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / S, q[1] = 0.25 * S, q[2] = (R[1] + R[3]) / S, q[3] = (R[2] + R[6]) / S;
  } else if (R[4] > R[8]) {
    const double S = 2.0 * sqrt(1.0 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / S, q[1] = (R[1] + R[3]) / S, q[2] = 0.25 * S, q[3] = (R[5] + R[7]) / S;
  } else {
    const double S = 2.0 * sqrt(1.0 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / S, q[1] = (R[2] + R[6]) / S, q[2] = (R[5] + R[7]) / S, q[3] = 0.25 * S;
  }
  double a;
  if (axis) {
    a = 2.0 * atan2(q[1] * axis[0] + q[2] * axis[1] + q[3] * axis[2], q[0]);
  } else {
    a = 2.0 * atan2(sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), fabs(q[0]));
  }
  /* q and -q are the same rotation: the twist is defined modulo 2 pi, hence the unwrap */
  while (a - prev > CS_PI) {
    a -= 2 * CS_PI;
  }
  while (a - prev < -CS_PI) {
    a += 2 * CS_PI;
  }
  return a;
}


void csf_bendMeasure(const csrActuator* act, const csfModel* m, const csfData* d,
                     const double axis[3], const double prev[4], double angle_deg[3],
                     double* total_deg, double tip[3]) {
  double Ra[9], Rb[9], c[3];
  for (int s = 0; s < CSR_NSEG; s++) {
    double z0 = csr_actuatorSegmentStart(act, s);
    angle_deg[s] = NAN;
    if (planeFrame(m, d, z0, Ra, c) == 0 && planeFrame(m, d, z0 + act->S[s], Rb, c) == 0) {
      angle_deg[s] = csf_bendAxisAngle(Ra, Rb, axis, prev ? prev[s] * CS_DEG : 0.0) / CS_DEG;
    }
  }
  *total_deg = NAN;
  tip[0] = tip[1] = tip[2] = NAN;
  if (planeFrame(m, d, 0.0, Ra, c) == 0 && planeFrame(m, d, csr_actuatorLength(act), Rb, tip) == 0) {
    *total_deg = csf_bendAxisAngle(Ra, Rb, axis, prev ? prev[3] * CS_DEG : 0.0) / CS_DEG;
  }
}


/* point at arc length s on the rounded square of half side h, corner radius r (CCW from (h,0)) */
static void roundedSquarePoint(double h, double r, double s, double p[2]) {
  const double ls = 2.0 * (h - r), la = 0.5 * CS_PI * r, P = 4 * ls + 4 * la;
  s = fmod(s, P);
  if (s < 0) {
    s += P;
  }
  /* start in the middle of the +x side: shift so that piece 0 starts at the corner (h, -(h-r)) */
  s += 0.5 * ls;
  if (s >= P) {
    s -= P;
  }
  for (int side = 0; side < 4; side++) {
    /* side k: straight piece then corner; rotate the +x side by k * 90 deg */
    double q[2];
    if (s <= ls) {
      q[0] = h, q[1] = -(h - r) + s;
    } else if (s <= ls + la) {
      double t = (s - ls) / (r > 0 ? r : 1.0);
      q[0] = (h - r) + r * cos(t), q[1] = (h - r) + r * sin(t);
    } else {
      s -= ls + la;
      continue;
    }
    double c = cos(side * 0.5 * CS_PI), sn = sin(side * 0.5 * CS_PI);
    p[0] = c * q[0] - sn * q[1];
    p[1] = sn * q[0] + c * q[1];
    return;
  }
  p[0] = h, p[1] = -(h - r);
}


/* embed the two counter-wound helices of every segment with n > 0 */
static csStatus addFibres(const csrActuator* act, csfModel* m, double lf, double inset,
                          csError* err) {
  const double h = act->a - inset, r = fmax(act->r2 - inset, 0.0);
  const double P = 8.0 * (h - r) + 2.0 * CS_PI * r;
  for (int s = 0; s < CSR_NSEG; s++) {
    if (!(act->n[s] > 0)) {
      continue;
    }
    const double z0 = csr_actuatorSegmentStart(act, s), S = act->S[s];
    const double len = sqrt(pow(act->n[s] * P, 2) + S * S);
    const int np = (int)ceil(len / lf) + 1;
    double* pts = malloc((size_t)np * 3 * sizeof(double));
    if (!pts) {
      return cs_errorSet(err, CS_ERR_MEMORY, "fem_bend: out of memory (fibre)");
    }
    for (int hand = -1; hand <= 1; hand += 2) {
      for (int k = 0; k < np; k++) {
        double t = (double)k / (np - 1), p2[2];
        roundedSquarePoint(h, r, hand * act->n[s] * P * t, p2);
        pts[3 * k] = p2[0];
        pts[3 * k + 1] = p2[1];
        pts[3 * k + 2] = z0 + t * S;
      }
      csStatus st = csf_modelAddFibre(m, np, pts, act->Ef, act->rf, err);
      if (st != CS_OK) {
        free(pts);
        return st;
      }
    }
    free(pts);
  }
  return CS_OK;
}


/* everything a sweep owns, freed in one place */
typedef struct {
  csfMesh* mesh;
  csfModel* model;
  csfData* data;
  double* s_conv; /* (csf_stateSize) last converged state */
  double* s_prev; /* (csf_stateSize) the converged state before it */
  double* s_tmp;  /* (csf_stateSize) scratch */
} Sweep;


static void sweepFree(Sweep* w) {
  csf_dataDestroy(w->data);
  csf_modelDestroy(w->model);
  csf_meshDestroy(w->mesh);
  free(w->s_conv);
  free(w->s_prev);
  free(w->s_tmp);
}


/* Per-state watcher of the volume-controlled path past a limit point (csf_passLimit callback):
 * tracks the angles (for unwrapping), the angles at the pressure maximum, reports progress, and
 * stops the path when the --until-angle target is reached. */
typedef struct {
  const csrActuator* act;
  const csfBendOptions* o;
  const double* axis;
  double* ang_conv;                   /* [4] last angles: 3 segments, total (deg) */
  double a_limit, ang_limit[3], tip_limit[3]; /* at the pressure maximum */
  int until_hit; /* 1: target reached before the limit (stable state), 2: after it (in the snap) */
  double p_hit, a_hit, ang_hit[3], tip_hit[3];
} LimitWatch;

static int limitWatch(void* user, const csfModel* m, const csfData* d, const csfPathPoint* pt) {
  LimitWatch* lw = user;
  double ang[3], tot, tip[3];
  csf_bendMeasure(lw->act, m, d, lw->axis, lw->ang_conv, ang, &tot, tip);
  lw->ang_conv[0] = ang[0], lw->ang_conv[1] = ang[1], lw->ang_conv[2] = ang[2];
  lw->ang_conv[3] = tot;
  if (pt->is_max) {
    lw->a_limit = tot;
    memcpy(lw->ang_limit, ang, sizeof ang);
    memcpy(lw->tip_limit, tip, sizeof tip);
  }
  if (lw->o->progress) {
    csfBendStep rep = {pt->p, pt->dp, pt->newton_iters, 0, pt->wall, tot, {ang[0], ang[1], ang[2]},
                       1, pt->volume};
    lw->o->progress(lw->o->progress_user, &rep);
  }
  if (isfinite(lw->o->until_angle) && tot >= lw->o->until_angle) {
    lw->until_hit = pt->past_limit ? 2 : 1;
    lw->p_hit = pt->p, lw->a_hit = tot;
    memcpy(lw->ang_hit, ang, sizeof ang);
    memcpy(lw->tip_hit, tip, sizeof tip);
    return 1;
  }
  return 0;
}


csStatus csf_bend(const csrActuator* act, const csfBendOptions* o, csrBendCurve* out,
                  csError* err) {
  const double t_start = csf_wallTime();
  csStatus st = csr_actuatorValidate(act, err);
  if (st != CS_OK) {
    return st;
  }
  if (!(o->p_step > 0) || !(o->p_max > 0) || !(o->mesh_size > 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_bend: need p_step, p_max, mesh_size > 0");
  }
  csfBendInfo info;
  memset(&info, 0, sizeof info);
  info.p_limit = info.p_resume = info.angle_limit = info.angle_resume = NAN;
  out->p_until_angle = NAN;
  Sweep w;
  memset(&w, 0, sizeof w);
  /* mesh */
  w.mesh = csf_meshActuator(act, o->mesh_size, o->work_stem ? o->work_stem : "crawlsim_fe", err);
  if (!w.mesh) {
    return err ? err->status : CS_ERR_EXTERNAL;
  }
  info.t_mesh = csf_wallTime() - t_start;
  /* model: clamped base, chambers, fibres */
  csfMaterial mat = csf_materialDefault(act->C10, act->C20, act->rho);
  mat.form = o->form;
  w.model = csf_modelCreate(w.mesh, &mat, err);
  if (!w.model) {
    sweepFree(&w);
    return err ? err->status : CS_ERR_ARG;
  }
  csfModel* m = w.model;
  for (int i = 0; i < w.mesh->nnode; i++) {
    if (fabs(w.mesh->x[3 * i + 2]) < CSF_PLANE_TOL) {
      m->fixed[3 * i] = m->fixed[3 * i + 1] = m->fixed[3 * i + 2] = 1;
    }
  }
  double cc[2] = {0, 0}; /* centroid of the pressurised chambers, for the bending axis */
  int ncc = 0;
  static const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, -1, 1};
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < 4; j++) {
      if (o->chambers[s] & (1u << j)) {
        if (csf_modelAddPressure(m, CSF_TAG_CHAMBER(s, j + 1), 1.0) <= 0) {
          sweepFree(&w);
          return cs_errorSet(err, CS_ERR_EXTERNAL, "fem_bend: chamber %d of segment %d has no "
                             "tagged faces in the mesh", j + 1, s + 1);
        }
        cc[0] += sx[j], cc[1] += sy[j], ncc++;
      }
    }
  }
  for (int i = 0; i < 3; i++) {
    m->gravity[i] = o->gravity[i];
  }
  if (o->fibres) {
    double lf = o->fibre_size > 0 ? o->fibre_size : fmax(0.4 * o->mesh_size - 0.1, 0.2);
    m->fib_split = o->fibre_split;
    st = addFibres(act, m, lf, CSF_FIBRE_INSET, err);
    if (st != CS_OK) {
      sweepFree(&w);
      return st;
    }
    m->fib_tension_only = !o->fibre_compression;
    m->fib_geo_tension = o->fibre_geo_tension;
  }
  st = csf_modelFinalize(m, err);
  if (st != CS_OK) {
    sweepFree(&w);
    return st;
  }
  w.data = csf_dataCreate(m, err);
  const size_t ns = csf_stateSize(m);
  w.s_conv = calloc(ns, sizeof(double));
  w.s_prev = calloc(ns, sizeof(double));
  w.s_tmp = calloc(ns, sizeof(double));
  if (!w.data || !w.s_conv || !w.s_prev || !w.s_tmp) {
    sweepFree(&w);
    return err && err->status ? err->status : CS_ERR_MEMORY;
  }
  csfData* d = w.data;
  info.ntet = w.mesh->ntet, info.nnode = w.mesh->nnode, info.nfibre = m->nfib;
  info.ndof = m->ndof;
  info.t_setup = csf_wallTime() - t_start - info.t_mesh;
  /* bending axis: e3 x (direction away from the pressurised chambers) */
  double axis[3] = {0, 1, 0};
  if (ncc && (cc[0] != 0 || cc[1] != 0)) {
    double dir[3] = {-cc[0], -cc[1], 0}, e3[3] = {0, 0, 1};
    csu_normalize3(dir);
    csu_cross3(axis, e3, dir);
  }
  csfNewtonOptions nopt = csf_newtonDefault();
  nopt.threads = o->threads;
  nopt.krylov = o->krylov;
  nopt.line_search = o->line_search;
  nopt.monitor = o->newton_monitor;
  nopt.monitor_user = o->progress_user;
  nopt.max_iter = 40; /* slender body: Newton crosses flat energy valleys (measured up to 12) */
  csError lerr = {0};
  /* gravity alone at p = 0, ramped in factor gamma (m->gravity = gamma g) with the load
   * stepping's rules: a soft leg under its full weight in one step does not converge (the leg
   * at 9.81 m/s^2, fem/README.md) */
  if (o->gravity[0] != 0 || o->gravity[1] != 0 || o->gravity[2] != 0) {
    double gam = 0.0, dgam = 1.0;
    while (gam < 1.0) {
      const double next = fmin(gam + dgam, 1.0);
      for (int i = 0; i < 3; i++) {
        m->gravity[i] = next * o->gravity[i];
      }
      int it = 0;
      const csStatus gst = csf_newtonSolve(m, d, 0.0, &nopt, &it, &lerr);
      info.n_newton += it;
      if (gst == CS_OK) {
        gam = next;
        info.n_gravity_steps++;
        if (it <= 5) {
          dgam *= 1.5;
        }
      } else if ((dgam *= 0.5) < 1e-3) {
        sweepFree(&w);
        return cs_errorSet(err, CS_ERR_DIVERGED, "fem_bend: no equilibrium under gravity beyond "
                           "%.4g of its value: %s", gam, lerr.msg);
      }
    }
  }
  csf_stateGet(m, d, w.s_conv);
  memcpy(w.s_prev, w.s_conv, ns * sizeof(double));
  double ang_conv[4] = {0, 0, 0, 0}, ang_prev[4] = {0, 0, 0, 0};
  double p = 0.0, p_prev = 0.0, dp = o->p_step;
  csf_assemble(m, d, 0.0, 0); /* the initial chamber volume */
  double V_conv = d->vol_w, V_prev = d->vol_w; /* weighted chamber volumes of those states */
  const double dp_min = CSF_BEND_DP_MIN_REL * o->p_step;
  const double eps = 1e-9 * o->p_step;
  int k_out = 1;
  int have_prev = 0, done = 0;
  const int want_until = isfinite(o->until_angle);
  /* row at p = 0 */
  {
    double ang[3], tot, tip[3];
    csf_bendMeasure(act, m, d, axis, ang_conv, ang, &tot, tip);
    st = csr_bendCurvePush(out, 0.0, ang, tip, err);
    if (st != CS_OK) {
      sweepFree(&w);
      return st;
    }
    out->angle_total[out->m - 1] = tot;
  }
  while (!done && p < o->p_max - eps) {
    const double t_step = csf_wallTime();
    int cut = 0, iters = 0;
    double target;
    /* one converged step, cutting back on failure */
    for (;;) {
      double next_out = fmin(k_out * o->p_step, o->p_max);
      target = fmin(p + dp, next_out);
      if (next_out - target < CSF_BEND_SNAP * dp) {
        target = next_out; /* no sliver step just before an output pressure */
      }
      /* secant predictor on the whole state (u, element dilatations, fibre stresses) */
      if (have_prev && p > p_prev) {
        double f = (target - p) / (p - p_prev);
        for (size_t i = 0; i < ns; i++) {
          w.s_tmp[i] = w.s_conv[i] + f * (w.s_conv[i] - w.s_prev[i]);
        }
        csf_stateSet(m, d, w.s_tmp);
      } else {
        csf_stateSet(m, d, w.s_conv);
      }
      if (csf_newtonSolve(m, d, target, &nopt, &iters, &lerr) == CS_OK) {
        break;
      }
      info.n_newton += iters;
      cut++;
      info.n_cutbacks++;
      dp = 0.5 * (target - p);
      if (dp < dp_min) {
        break;
      }
    }
    if (dp < dp_min && !o->continuation) {
      info.p_limit = p;
      csf_stateSet(m, d, w.s_conv);
      break;
    }
    if (dp < dp_min) {
      /* the pressure-controlled step collapsed: a limit point; follow the path by volume */
      LimitWatch lw;
      memset(&lw, 0, sizeof lw);
      lw.act = act, lw.o = o, lw.axis = axis, lw.ang_conv = ang_conv;
      csf_stateSet(m, d, w.s_conv);
      csf_bendMeasure(act, m, d, axis, ang_conv, lw.ang_limit, &lw.a_limit, lw.tip_limit);
      csfLimitOptions lopt = csf_limitDefault();
      lopt.callback = limitWatch;
      lopt.user = &lw;
      csfLimitResult lr;
      csStatus lst = csf_passLimit(m, d, w.s_prev, w.s_conv, w.s_tmp, V_prev, V_conv, p, &nopt,
                                   &lopt, &lr, &lerr);
      info.n_newton += lr.n_newton;
      info.n_volume_steps += lr.n_steps;
      if (!lr.no_limit) {
        info.p_limit = lr.p_limit;
        info.angle_limit = lw.a_limit;
      }
      p = d->load;
      if (lst == CS_OK && lr.stopped) {
        /* the target angle: before the limit the state at p_hit is an equilibrium, not refined;
         * after it a pressure-controlled load reaches the angle by snapping at p_limit */
        const int snap = lw.until_hit == 2;
        if (snap || fabs(lw.a_hit - o->until_angle) <= o->angle_tol) {
          out->p_until_angle = snap ? lr.p_limit : lw.p_hit;
        }
        snprintf(info.until_note, sizeof info.until_note,
                 snap ? "reached in the snap-through at the limit pressure %.6g MPa (%.2f deg "
                        "at the limit, %.2f deg on the volume-controlled path)"
                      : "passed under volume control below the limit (%.6g MPa so far; %.2f "
                        "deg there, %.2f deg): not refined",
                 lr.p_limit, lw.a_limit, lw.a_hit);
        st = csr_bendCurvePush(out, snap ? lr.p_limit : lw.p_hit, snap ? lw.ang_limit : lw.ang_hit,
                               snap ? lw.tip_limit : lw.tip_hit, err);
        if (st == CS_OK) {
          out->angle_total[out->m - 1] = snap ? lw.a_limit : lw.a_hit;
        }
        break;
      }
      if (lst != CS_OK) {
        snprintf(info.limit_note, sizeof info.limit_note, "%.190s", lerr.msg);
        break; /* no stable branch found: the sweep ends at the last volume-controlled state */
      }
      /* stable again above the limit: resume pressure control from the volume path's last two
       * states; output pressures passed in the snap are skipped (no stable state there) */
      info.p_resume = lr.p_resume;
      info.angle_resume = ang_conv[3];
      V_prev = V_conv = d->vol_w; /* d is the last converged volume-controlled state */
      p_prev = lr.p_before;
      have_prev = p > p_prev;
      memcpy(ang_prev, ang_conv, sizeof ang_prev);
      while (k_out * o->p_step <= p + eps) {
        k_out++;
      }
      dp = 0.25 * o->p_step;
      continue;
    }
    V_prev = V_conv;
    V_conv = d->vol_w; /* the converged state's weighted chamber volume (last assembly) */
    info.n_newton += iters;
    info.n_steps++;
    double ang[3], tot, tip[3];
    csf_bendMeasure(act, m, d, axis, ang_conv, ang, &tot, tip);
    csfBendStep rep = {target, target - p, iters, cut, csf_wallTime() - t_step, tot,
                       {ang[0], ang[1], ang[2]}, 0, d->vol_w};
    /* accept */
    memcpy(w.s_prev, w.s_conv, ns * sizeof(double));
    csf_stateGet(m, d, w.s_conv);
    memcpy(ang_prev, ang_conv, sizeof ang_prev);
    ang_conv[0] = ang[0], ang_conv[1] = ang[1], ang_conv[2] = ang[2], ang_conv[3] = tot;
    p_prev = p;
    p = target;
    have_prev = 1;
    if (o->progress) {
      o->progress(o->progress_user, &rep);
    }
    if (want_until && tot >= o->until_angle) {
      /* bracket [p_prev, p] by converged states; regula falsi with 10 % safeguard */
      double lo = p_prev, hi = p, alo = ang_prev[3], ahi = tot;
      double* slo = w.s_prev;
      double* shi = w.s_conv;
      double a_found = tot, p_found = p;
      double ang_found[3] = {ang[0], ang[1], ang[2]}, tip_found[3] = {tip[0], tip[1], tip[2]};
      int fails = 0;
      for (int it = 0; it < 40 && fabs(a_found - o->until_angle) > o->angle_tol; it++) {
        double f = (o->until_angle - alo) / (ahi - alo);
        f = fails ? 0.5 : fmin(fmax(f, 0.1), 0.9); /* bisect after a failure */
        double pm = lo + f * (hi - lo);
        /* each trial starts from the nearer bracketing state, restored whole (u, element
         * dilatations, fibre stresses: csf_stateSet), and reaches pm by load stepping with
         * cut-backs; an interpolated start shortens the rotated fibres (chord of an arc) */
        const int from_lo = f <= 0.5;
        csf_stateSet(m, d, from_lo ? slo : shi);
        int itb = 0;
        info.n_until_trials++;
        /* load stepping from the restored state's pressure (d->load) to pm */
        if (csf_loadRamp(m, d, pm, 1, &nopt, &itb, &lerr) != CS_OK) {
          info.n_newton += itb;
          info.n_until_failed++;
          snprintf(info.until_note, sizeof info.until_note, "trial %.6g MPa from %.6g MPa: %.150s",
                   pm, from_lo ? lo : hi, lerr.msg);
          if (++fails > 4) {
            break;
          }
          continue;
        }
        fails = 0;
        info.n_newton += itb;
        double am[3], tm, tpm[3], pr[4] = {ang_prev[0], ang_prev[1], ang_prev[2], alo};
        csf_bendMeasure(act, m, d, axis, pr, am, &tm, tpm);
        a_found = tm, p_found = pm;
        memcpy(ang_found, am, sizeof am);
        memcpy(tip_found, tpm, sizeof tpm);
        if (tm < o->until_angle) {
          lo = pm, alo = tm;
          csf_stateGet(m, d, slo);
        } else {
          hi = pm, ahi = tm;
          csf_stateGet(m, d, shi);
        }
      }
      if (fabs(a_found - o->until_angle) <= o->angle_tol) {
        out->p_until_angle = p_found;
      }
      st = csr_bendCurvePush(out, p_found, ang_found, tip_found, err);
      if (st == CS_OK) {
        out->angle_total[out->m - 1] = a_found; /* base-to-tip rotation, joints included */
      }
      done = 1;
      break;
    }
    if (fabs(p - fmin(k_out * o->p_step, o->p_max)) <= eps) {
      st = csr_bendCurvePush(out, p, ang, tip, err);
      if (st != CS_OK) {
        break;
      }
      out->angle_total[out->m - 1] = tot; /* base-to-tip rotation, joints included */
      k_out++;
    }
    /* step control */
    if (iters <= 5) {
      dp = fmin(1.5 * dp, o->p_step);
    } else if (iters > 10) {
      dp *= 0.7;
    }
  }
  if (st == CS_OK) {
    /* volume preservation at the final state */
    csf_assemble(m, d, p, 0);
    for (int e = 0; e < w.mesh->ntet; e++) {
      info.max_j_dev = fmax(info.max_j_dev, fabs(d->vratio[e] - 1.0));
    }
    if (o->vtu_path) {
      st = csf_writeVtu(m, d, o->vtu_path, err);
    }
    if (st == CS_OK && o->inp_path) {
      st = csf_writeInp(m, act, d->load, o->inp_path, err);
    }
  }
  info.t_assemble = d->stats.t_assemble;
  info.t_factor = d->stats.t_factor;
  info.t_solve = d->stats.t_solve;
  info.factor_nnz = csf_linSolverFactorNnz(d->ls);
  info.n_factor = d->stats.n_factor;
  info.n_krylov = d->stats.n_krylov;
  info.n_krylov_iter = d->stats.n_krylov_iter;
  snprintf(info.solver, sizeof info.solver, "%s", csf_linSolverName(d->ls));
  info.t_total = csf_wallTime() - t_start;
  if (o->info) {
    *o->info = info;
  }
  sweepFree(&w);
  return st;
}
