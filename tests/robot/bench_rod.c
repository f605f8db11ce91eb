/* bench_rod.c: cost and accuracy of the Cosserat-rod leg level (not a test: prints numbers).
 *
 *   bench_rod [scenario] [elements_per_segment] [H_ms] [t_end_s] [rtol] [calibration.h5]
 *
 * scenario: road  (eight legs (BENCH_LEGS=n: the first n) of csr_leg_rod on the flat road with
 *                  the soft contact, hips held
 *                  at the robot's layout 0.5 mm below touching, the flat-road gait: ACFH and
 *                  BDEG alternate every second; `paper` conditions, 9 s by default; prints the
 *                  real-time factor of the eight legs with contact on one core),
 *           hang  (earth gravity, released straight: settles under its weight),
 *           gait  (gravity on, II1 Ω3&Ω4 and II2 Ω1&Ω2 of the flat-road gait ramped to
 *                  0.1744 MPa over 0.2 s at every whole second, vented the next second),
 *           swing (the hip oscillating ±10 mm at 2 Hz along x, gravity on),
 *           all   (the three, each 2 s, at 2, 4 and 8 elements per segment),
 *           pcs   (the discretisation choice: static tip error per unknown of the nodal rod and
 *                  of a piecewise-constant-strain rod (SoRoSim's PCS) on a uniform Timoshenko
 *                  cantilever, and the CPU cost of one right-hand side of each: the nodal rod's
 *                  O(N) kernel against a PCS mass-matrix assembly and dense solve).
 * Prints per run: CPU time per simulated second (one core), CVODE steps, right-hand sides,
 * Jacobians, restarts and the foot position at t_end; the real-time factor of one leg and of
 * eight; single runs also the foot path's error against the same run at rtol 1e-8
 * (BENCH_REF_N=n: against n elements per segment; BENCH_NOREF: none).
 * The calibration defaults to the shipped FE table (robot/calibration_fe_leg.h5 under
 * $CS_SOURCE_DIR or the working directory's ../../..). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "contact_ode.h"
#include "robot_calibration.h"
#include "robot_rod.h"
#include "robot_rod_internal.h"

/* process CPU time (s): the cost on one core, insensitive to other jobs sharing the machine */
static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }


/* gait pressures of one leg at time t: ramps of 0.2 s (smoothstep) at whole seconds, II1
 * Ω3&Ω4 and II2 Ω1&Ω2 at p_on in odd seconds, vented in even ones */
static void gaitPressure(double t, double p_on, double p[12]) {
  memset(p, 0, 12 * sizeof(double));
  double k = floor(t), u = fmin(1.0, (t - k) / 0.2);
  double s = u * u * (3 - 2 * u);
  int on = ((long)k % 2) == 0;
  double level = on ? p_on * s : p_on * (1 - s);
  if (t < 0) {
    level = 0;
  }
  p[2] = p[3] = level;         /* II1 Ω3, Ω4 */
  p[4 + 0] = p[4 + 1] = level; /* II2 Ω1, Ω2 */
}


/* hip of the swing scenario at time t */
static void swingBase(const csrBaseState* rest, double t, int swing, csrBaseState* b) {
  *b = *rest;
  if (swing) {
    const double A = 10, w = 2 * 3.14159265358979 * 2;
    b->x[0] += A * sin(w * t);
    b->v[0] = A * w * cos(w * t);
  }
}


enum { MAX_TRACE = 100000 };

typedef struct {
  double wall_per_s, foot[3];
  csrRodStats st;
  int ok;
  double* trace; /* foot position after every macro step (3 per step), or NULL */
  int ntrace;
} Result;


static Result run(const char* scen, int nps, double H, double t_end, double rtol,
                  const csrBendMap* map, double atol_scale, double* trace) {
  Result res;
  memset(&res, 0, sizeof res);
  res.trace = trace;
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrRodParams par = csr_rodDefaultParams(&act);
  par.elements_per_segment = nps;
  par.rtol = rtol;
  par.atol_pos *= atol_scale;
  par.atol_rot *= atol_scale;
  par.atol_vel *= atol_scale;
  par.atol_omega *= atol_scale;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &act;
  sp.params = &par;
  sp.map = map;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0}; /* hanging: e3 = -y */
  memcpy(sp.frame, F, sizeof F);
  sp.gravity[1] = -9810;
  csrRodModel* m = csr_rodModelCreate(&sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  if (!d) {
    fprintf(stderr, "bench_rod: %s\n", err.msg);
    csr_rodModelDestroy(m);
    return res;
  }
  const int gait = !strcmp(scen, "gait"), swing = !strcmp(scen, "swing");
  csrBaseState rest = csr_rodRestBase(m), b0, b1;
  double p0[12], p1[12];
  double t = 0, t0 = cpu();
  res.ok = 1;
  while (t < t_end - 1e-12) {
    double h = fmin(H, t_end - t);
    gaitPressure(gait ? t : -1, 0.1744, p0);
    gaitPressure(gait ? t + h : -1, 0.1744, p1);
    int rc = csr_rodActuate(m, d, t, p0, t + h, p1);
    swingBase(&rest, t, swing, &b0);
    swingBase(&rest, t + h, swing, &b1);
    csrWrench w;
    if (rc == 0) {
      rc = csr_rodAdvance(m, d, t, h, &b0, &b1, &w, &err);
    }
    if (rc != 0) {
      fprintf(stderr, "bench_rod: %s at t = %g: %s\n", scen, t, err.msg);
      res.ok = 0;
      break;
    }
    t += h;
    if (res.trace && res.ntrace < MAX_TRACE) {
      double x[3 * 256];
      csr_rodNodes(m, d, x);
      memcpy(res.trace + 3 * res.ntrace, x + 3 * csr_rodElements(m), 3 * sizeof(double));
      res.ntrace++;
    }
    if (getenv("BENCH_TRACE") && fabs(t * 10 - floor(t * 10 + 0.5)) < 1e-9) {
      csrRodStats st;
      csr_rodGetStats(d, &st);
      fprintf(stderr, "  t %.1f steps %ld jac %ld fails %ld\n", t, st.steps, st.jac_evals,
              st.err_fails + st.conv_fails);
    }
  }
  res.wall_per_s = (cpu() - t0) / t_end;
  double x[3 * 256];
  csr_rodNodes(m, d, x);
  memcpy(res.foot, x + 3 * csr_rodElements(m), sizeof res.foot);
  csr_rodGetStats(d, &res.st);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
  return res;
}


static void print(const char* scen, int nps, double H, double t_end, double rtol,
                  const Result* r) {
  double s = 1.0 / t_end;
  printf("%-5s %2d el/seg H %5.1f ms rtol %.0e: %7.2f ms/s (leg RTF %6.1f, 8 legs %5.1f) | "
         "per s: %6.0f steps %6.0f newton %7.0f rhs %5.0f jac %5.0f LU %4.0f restarts %4.0f fails "
         "| foot (%.3f, %.3f, %.3f)%s\n",
         scen, nps, H * 1e3, rtol, r->wall_per_s * 1e3, 1.0 / r->wall_per_s,
         1.0 / (8 * r->wall_per_s), r->st.steps * s, r->st.newton_iters * s, r->st.rhs_evals * s,
         r->st.jac_evals * s, r->st.lin_setups * s, r->st.reinits * s,
         (r->st.err_fails + r->st.conv_fails) * s, r->foot[0], r->foot[1], r->foot[2],
         r->ok ? "" : " FAILED");
}


/* eight rod legs on the flat road (scenario road; BENCH_LEGS=n: the first n of them, for the
 * cost against the number of legs): CPU seconds for t_end, feet's mean |x| travel */
static double runRoad(int nps, double H, double t_end, const csrBendMap* map, int gravity_on) {
  const char* nl = getenv("BENCH_LEGS");
  const int nleg = nl && atoi(nl) >= 1 && atoi(nl) <= 8 ? atoi(nl) : 8;
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrLegParams lp = csr_defaultLegParams(&act);
  csrLegSettings set;
  csr_legSettingsDefault(&csr_leg_rod, &set);
  if (csr_legSettingSet(&csr_leg_rod, &set, "links", nps, &err) != CS_OK) {
    fprintf(stderr, "bench_rod: %s\n", err.msg);
    return NAN;
  }
  cstTerrain tr;
  memset(&tr, 0, sizeof tr);
  tr.nbox = 1;
  const double lo[3] = {-400, -50, -200}, hi[3] = {400, 0, 200};
  memcpy(tr.box[0].lo, lo, sizeof lo);
  memcpy(tr.box[0].hi, hi, sizeof hi);
  cscContactParams cp = csc_defaultContactParams();
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  const double L = csr_actuatorLength(&act);
  const csrLegType* T = &csr_leg_rod;
  csrLeg* legs[8];
  csrBaseState base[8];
  /* A..D at -z front to back, E..H at +z (docs/reference.md); ACFH = k 0, 2, 5, 7 */
  const double xs[4] = {75, 25, -25, -75};
  for (int k = 0; k < nleg; k++) {
    csrLegSpec sp;
    memset(&sp, 0, sizeof sp);
    sp.act = &act;
    sp.params = &lp;
    sp.settings = &set;
    sp.map = map;
    memcpy(sp.frame, F, sizeof F);
    sp.hip[0] = xs[k % 4];
    sp.hip[1] = L - 0.5;
    sp.hip[2] = k < 4 ? -65 : 65;
    sp.gravity[1] = -9810;
    sp.weightless = !gravity_on;
    sp.h = 1e-3;
    sp.terrain = &tr;
    sp.contact = &cp;
    legs[k] = T->create(&sp, &err);
    if (!legs[k]) {
      fprintf(stderr, "bench_rod: %s\n", err.msg);
      return NAN;
    }
    memset(&base[k], 0, sizeof base[k]);
    memcpy(base[k].x, sp.hip, sizeof base[k].x);
    memcpy(base[k].R, F, sizeof F);
  }
  double t = 0, c0 = cpu();
  long failures = 0;
  while (t < t_end - 1e-12) {
    double h = fmin(H, t_end - t);
    for (int k = 0; k < nleg; k++) {
      int group = (k == 0 || k == 2 || k == 5 || k == 7) ? 0 : 1;
      double p0[12], p1[12];
      gaitPressure(t - group, 0.1744, p0);
      gaitPressure(t + h - group, 0.1744, p1);
      if (t - group < 0) {
        memset(p0, 0, sizeof p0);
      }
      if (t + h - group < 0) {
        memset(p1, 0, sizeof p1);
      }
      csrWrench w;
      if (T->actuate(legs[k], t, p0, t + h, p1) != 0 ||
          T->advance(legs[k], t, h, &base[k], &base[k], &w, &err) != 0) {
        failures++;
        if (failures < 4) {
          fprintf(stderr, "bench_rod: road leg %d at t = %g: %s\n", k, t, err.msg);
        }
      }
    }
    t += h;
  }
  double c = cpu() - c0;
  csrContactShape sh[256];
  double foot = 0;
  for (int k = 0; k < nleg; k++) {
    int n = T->contactShapes(legs[k], sh, 256);
    foot += fabs(sh[n - 1].a[0] - base[k].x[0]) / nleg;
    T->destroy(legs[k]);
  }
  printf("road  %d legs x %.1f s, %d el/seg, H %.1f ms, gravity %s: %.3f s CPU -> real-time "
         "factor %.1f on one core (%.2f ms per leg-second); mean |foot - hip| along x %.2f mm, "
         "%ld failed advances\n", nleg, t_end, nps, H * 1e3, gravity_on ? "on" : "off (paper)",
         c, t_end / c, c / (nleg * t_end) * 1e3, foot, failures);
  return c;
}


/* ---- pcs: the discretisation choice ------------------------------------------------------ */

/* relative tip error of a piecewise-constant-strain (PCS) cantilever of n equal pieces under a
 * tip force: strain j = the piece's mean of M/EI (Galerkin with a constant basis), shear exact,
 * δ = Σ κ_j l (L - s_mid,j) + P L / kGA, against δ = P L³/(3EI) + P L/kGA (small deflection) */
static double pcsTipError(int n, double L, double EI, double kGA) {
  const double P = 1.0, l = L / n;
  double d = P * L / kGA;
  for (int j = 0; j < n; j++) {
    double smid = (j + 0.5) * l;
    d += P * (L - smid) / EI * l * (L - smid);
  }
  double exact = P * L * L * L / (3 * EI) + P * L / kGA;
  return (d - exact) / exact;
}


/* CPU seconds per call of a PCS right-hand side's core for n pieces of 6 strains, 2 Gauss
 * points each: forward kinematics (SE(3) products), the 6 x 6n geometric Jacobian at each
 * point, M = Σ Jᵀ Λ J (6n x 6n) and its Cholesky solve (the Coriolis and force terms would add
 * about as much again: this is a lower bound) */
static double pcsRhsCost(int n, int reps) {
  const int nq = 6 * n;
  double* J = calloc((size_t)6 * nq, sizeof(double));
  double* M = calloc((size_t)nq * nq, sizeof(double));
  double* b = calloc((size_t)nq, sizeof(double));
  double sink = 0, t0 = cpu();
  for (int rep = 0; rep < reps; rep++) {
    memset(M, 0, (size_t)nq * nq * sizeof(double));
    memset(J, 0, (size_t)6 * nq * sizeof(double));
    double g[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int j = 0; j < n; j++) {
      for (int q = 0; q < 2; q++) {
        /* pose: g <- g exp(ξ l/2) (a rotation and translation per half piece) */
        double c = cos(1e-3 * (j + q + rep % 7)), sn = sin(1e-3 * (j + q)), e[16] = {
            c, -sn, 0, 0, sn, c, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1};
        double h[16];
        for (int r = 0; r < 4; r++) {
          for (int k = 0; k < 4; k++) {
            h[4 * r + k] = g[4 * r] * e[k] + g[4 * r + 1] * e[4 + k] + g[4 * r + 2] * e[8 + k] +
                           g[4 * r + 3] * e[12 + k];
          }
        }
        memcpy(g, h, sizeof g);
        /* the Jacobian's columns of pieces 0..j: Ad(g_i⁻¹ g) of each basis twist (a 6 x 6
         * adjoint product per earlier piece) */
        for (int i = 0; i <= j; i++) {
          for (int r = 0; r < 6; r++) {
            for (int k = 0; k < 6; k++) {
              double a = 0;
              for (int z = 0; z < 3; z++) {
                a += g[4 * (r % 3) + z] * g[4 * z + (k % 3)];
              }
              J[(size_t)nq * r + 6 * i + k] = a * (1 + 1e-3 * i);
            }
          }
        }
        /* M += Jᵀ Λ J over the columns reached (Λ diagonal mass/inertia) */
        const int nc = 6 * (j + 1);
        for (int r = 0; r < nc; r++) {
          for (int k = 0; k <= r; k++) {
            double a = 0;
            for (int z = 0; z < 6; z++) {
              a += J[(size_t)nq * z + r] * J[(size_t)nq * z + k] * (z < 3 ? 1e-6 : 1e-5);
            }
            M[(size_t)nq * r + k] += a;
          }
        }
      }
    }
    /* Cholesky of M (lower) and one solve */
    for (int k = 0; k < nq; k++) {
      M[(size_t)nq * k + k] += 1e-3;
      b[k] = 1;
    }
    for (int k = 0; k < nq; k++) {
      double dkk = M[(size_t)nq * k + k];
      for (int z = 0; z < k; z++) {
        dkk -= M[(size_t)nq * k + z] * M[(size_t)nq * k + z];
      }
      dkk = sqrt(fabs(dkk) + 1e-30);
      M[(size_t)nq * k + k] = dkk;
      for (int r = k + 1; r < nq; r++) {
        double a = M[(size_t)nq * r + k];
        for (int z = 0; z < k; z++) {
          a -= M[(size_t)nq * r + z] * M[(size_t)nq * k + z];
        }
        M[(size_t)nq * r + k] = a / dkk;
      }
    }
    for (int k = 0; k < nq; k++) {
      double a = b[k];
      for (int z = 0; z < k; z++) {
        a -= M[(size_t)nq * k + z] * b[z];
      }
      b[k] = a / M[(size_t)nq * k + k];
    }
    sink += b[nq - 1];
  }
  double c = (cpu() - t0) / reps;
  free(J);
  free(M);
  free(b);
  return sink == 12345.678 ? 0 : c; /* keep the work observable */
}


/* the nodal rod: static tip error of the same cantilever, and one right-hand side's cost */
static void runPcs(void) {
  const double L = 100, E = 1.0, A = 100, I = 1e4 / 12, G = E / 3, k = 10.0 * 1.5 / 17.5;
  const double EI = E * I, kGA = k * G * A;
  printf("pcs: uniform Timoshenko cantilever under a tip force, relative tip error per unknown\n");
  printf("  %8s %14s %14s\n", "unknowns", "nodal rod", "PCS");
  for (int n = 2; n <= 32; n *= 2) {
    csrRodParams par = csr_rodDefaultParams(NULL);
    csrRodPiece p;
    memset(&p, 0, sizeof p);
    p.length = L;
    p.nelem = n;
    p.segment = -1;
    p.section.EA = E * A;
    p.section.GA[0] = p.section.GA[1] = kGA;
    p.section.EI[0] = p.section.EI[1] = EI;
    p.section.GJ = G * 0.1406 * 1e4;
    p.rhoA = 1e-7;
    p.rhoI[0] = p.rhoI[1] = 1e-9 * I;
    p.rhoI[2] = 2e-9 * I;
    csrRodSpec sp;
    memset(&sp, 0, sizeof sp);
    sp.params = &par;
    csu_eye3(sp.frame);
    csError err;
    csrRodModel* m = csr_rodModelCreatePieces(&p, 1, &sp, &err);
    csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
    double en = NAN;
    if (d) {
      csrRodStaticLoad ld;
      memset(&ld, 0, sizeof ld);
      ld.tip_force[0] = 1e-4;
      if (csr_rodStatic(m, d, &ld, NULL, &err) == CS_OK) {
        double x[3 * 40];
        csr_rodNodes(m, d, x);
        double exact = 1e-4 * (L * L * L / (3 * EI) + L / kGA);
        en = (x[3 * n] - exact) / exact;
      }
    }
    csr_rodDataDestroy(d);
    csr_rodModelDestroy(m);
    printf("  %8d %+14.3e %+14.3e\n", 6 * n, en, pcsTipError(n, L, EI, kGA));
  }
  /* cost of one right-hand side: the leg (14 elements, 84 unknowns) against PCS */
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &act;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  sp.gravity[1] = -9810;
  csrRodModel* m = csr_rodModelCreate(&sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  if (d) {
    N_Vector f = N_VClone(d->yv);
    const int reps = 20000;
    double t0 = cpu();
    for (int r = 0; r < reps; r++) {
      csr_rodRhs_(0.0, d->yv, f, d);
    }
    double cn = (cpu() - t0) / reps;
    N_VDestroy(f);
    printf("  one right-hand side: nodal leg (14 elements, 84 unknowns, 182 states) %.2f us; "
           "PCS core (mass matrix + Cholesky, a lower bound) 5 pieces (30 unknowns) %.2f us, "
           "10 pieces %.2f us, 14 pieces %.2f us\n", cn * 1e6, pcsRhsCost(5, 4000) * 1e6,
           pcsRhsCost(10, 1000) * 1e6, pcsRhsCost(14, 500) * 1e6);
  }
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


/* largest distance between two foot traces (mm) */
static double traceError(const Result* a, const Result* b) {
  double e = 0;
  int n = a->ntrace < b->ntrace ? a->ntrace : b->ntrace;
  for (int k = 0; k < n; k++) {
    double d[3];
    for (int c = 0; c < 3; c++) {
      d[c] = a->trace[3 * k + c] - b->trace[3 * k + c];
    }
    e = fmax(e, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  return e;
}


int main(int argc, char** argv) {
  const char* scen = argc > 1 ? argv[1] : "all";
  int nps = argc > 2 ? atoi(argv[2]) : 4;
  double H = argc > 3 ? atof(argv[3]) * 1e-3 : 5e-3;
  double t_end = argc > 4 ? atof(argv[4]) : 2.0;
  double rtol = argc > 5 ? atof(argv[5]) : 1e-4;
  double atol_scale = argc > 6 ? atof(argv[6]) : 1.0;
  if (!strcmp(scen, "pcs")) {
    runPcs();
    return 0;
  }
  char path[1024];
  if (argc > 7) {
    snprintf(path, sizeof path, "%s", argv[7]);
  } else {
    const char* src = getenv("CS_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/robot/calibration_fe_leg.h5", src ? src : "../../..");
  }
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrCalibration* cal = csr_calibrationOpen(path, &act, &err);
  if (!cal) {
    fprintf(stderr, "bench_rod: %s\n", err.msg);
    return 1;
  }
  csrBendMap map = csr_calibrationMap(cal);
  if (!strcmp(scen, "road")) {
    runRoad(nps, H, argc > 4 ? t_end : 9.0, &map, getenv("BENCH_GRAVITY") != NULL);
  } else if (!strcmp(scen, "all")) {
    const char* sc[3] = {"hang", "gait", "swing"};
    const int ns[3] = {2, 4, 8};
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        Result r = run(sc[i], ns[j], H, t_end, rtol, &map, atol_scale, NULL);
        print(sc[i], ns[j], H, t_end, rtol, &r);
      }
    }
  } else {
    /* the run, and the same run at tight tolerances (rtol 1e-8, absolute tolerances / 1000)
     * as the reference of its foot path */
    int nstep = (int)ceil(t_end / H - 1e-9);
    double* tr = calloc(3 * (size_t)nstep + 3, sizeof(double));
    double* tref = calloc(3 * (size_t)nstep + 3, sizeof(double));
    Result r = run(scen, nps, H, t_end, rtol, &map, atol_scale, tr);
    print(scen, nps, H, t_end, rtol, &r);
    if (!getenv("BENCH_NOREF")) {
      /* BENCH_REF_N: the reference's elements per segment (discretisation error) */
      int nref = getenv("BENCH_REF_N") ? atoi(getenv("BENCH_REF_N")) : nps;
      Result ref = run(scen, nref, H, t_end, 1e-8, &map, 1e-3, tref);
      printf("      foot path error against %d el/seg, rtol 1e-8 (atol / 1000): %.3g mm "
             "(reference %.1f ms/s)\n", nref, traceError(&r, &ref), ref.wall_per_s * 1e3);
    }
    free(tr);
    free(tref);
  }
  csr_calibrationClose(cal);
  return 0;
}
