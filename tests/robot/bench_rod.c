/* bench_rod.c: cost and accuracy of the Cosserat-rod leg level (not a test: prints numbers).
 *
 *   bench_rod [scenario] [elements_per_segment] [H_ms] [t_end_s] [rtol] [calibration.h5]
 *
 * scenario: road  (eight legs of csr_leg_rod on the flat road with the soft contact, hips held
 *                  at the robot's layout 0.5 mm below touching, the flat-road gait: ACFH and
 *                  BDEG alternate every second; `paper` conditions, 9 s by default; prints the
 *                  real-time factor of the eight legs with contact on one core),
 *           hang  (earth gravity, released straight: settles under its weight),
 *           gait  (gravity on, II1 Ω3&Ω4 and II2 Ω1&Ω2 of the flat-road gait ramped to
 *                  0.1744 MPa over 0.2 s at every whole second, vented the next second),
 *           swing (the hip oscillating ±10 mm at 2 Hz along x, gravity on),
 *           all   (the three, each 2 s, at 2, 4 and 8 elements per segment).
 * Prints per run: CPU time per simulated second (one core), CVODE steps, right-hand sides, Jacobians,
 * restarts and the foot position at t_end; the real-time factor of one leg and of eight.
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
         (r->st.err_fails + r->st.conv_fails) * s, r->foot[0], r->foot[1], r->foot[2], r->ok ? "" : " FAILED");
}


/* eight rod legs on the flat road (scenario road): CPU seconds for t_end, feet's mean |x| travel */
static double runRoad(int nps, double H, double t_end, const csrBendMap* map, int gravity_on) {
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrLegParams lp = csr_defaultLegParams(&act);
  lp.links_per_segment = nps;
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
  /* A..D at -z front to back, E..H at +z (REFERENCE.md); ACFH = k 0, 2, 5, 7 */
  const double xs[4] = {75, 25, -25, -75};
  for (int k = 0; k < 8; k++) {
    csrLegSpec sp;
    memset(&sp, 0, sizeof sp);
    sp.act = &act;
    sp.params = &lp;
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
    for (int k = 0; k < 8; k++) {
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
  for (int k = 0; k < 8; k++) {
    int n = T->contactShapes(legs[k], sh, 256);
    foot += fabs(sh[n - 1].a[0] - base[k].x[0]) / 8;
    T->destroy(legs[k]);
  }
  printf("road  8 legs x %.1f s, %d el/seg, H %.1f ms, gravity %s: %.3f s CPU -> real-time "
         "factor %.1f on one core (%.2f ms per leg-second); mean |foot - hip| along x %.2f mm, "
         "%ld failed advances\n", t_end, nps, H * 1e3, gravity_on ? "on" : "off (paper)", c,
         t_end / c, c / (8 * t_end) * 1e3, foot, failures);
  return c;
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
