/* bench_rom_settle.c: the robot on rom legs settling, step by step (not a test: prints the
 * support's height and speed, the feet's force and the legs' sole depth at every macro step,
 * so a divergence is seen as it grows, and the eight legs' CVODE counters over the step,
 * csrRomStats; docs/notes/rom.md "Settling on rom legs", "The rom leg's contact steps").
 *
 *   bench_rom_settle LEG.h5 STEPS [COUPLING [DT_S [MACRO]]]
 *
 * The scene as test_run_rom: no gait, earth, the legs' segments S from CRAWLSIM_ROM_LEG_S (mm,
 * default 15: the short leg; 50 for the robot's own leg), the provisional calibration from
 * $CS_SOURCE_DIR. Time starts at -settle (the driver's), the steps are
 * cs_step's macro steps from the built robot (0.5 mm above the ground). CS_BENCH_CARRY=0: the
 * Gauss-Seidel scheme without its impulse carry (csOptions.coupling_carry). CRAWLSIM_ROM_TOL:
 * the legs' CVODE tolerances times this (the level's setting rod_tol, `--rod-tol`).
 * CS_BENCH_SCENE=flat-road: that scene with its own gait, calibration, actuator and conditions
 * (`paper`) instead, as `crawlsim run --scene flat-road --legs rom` settles it.
 * CS_BENCH_COND=paper|earth: the conditions. CS_BENCH_LEGS=1: after each step a line per leg
 * (its hip wrench f, m, the foot's force, the sole's friction history z, world), and the
 * support's v and ω vectors in the step's line (docs/notes/rom.md "The rom legs' settling under
 * paper"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <ode/ode.h>

#include "cs_rundef.h"
#include "robot_rom.h"
#include "sim_model.h"

static void quiet(int num, const char* msg, va_list ap) {
  (void)num, (void)msg, (void)ap;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: %s LEG.h5 STEPS [COUPLING [DT_S [MACRO]]]\n", argv[0]);
    return 2;
  }
  const char* src = getenv("CS_SOURCE_DIR");
  char cal[600];
  snprintf(cal, sizeof cal, "%s/robot/calibration_provisional.txt", src ? src : ".");
  const char* es = getenv("CRAWLSIM_ROM_LEG_S");
  const double S = es ? atof(es) : 15.0;
  char s1[32], s2[32], s3[32];
  snprintf(s1, sizeof s1, "S1=%g", S);
  snprintf(s2, sizeof s2, "S2=%g", S);
  snprintf(s3, sizeof s3, "S3=%g", S);
  const char* sets[3] = {s1, s2, s3};
  csRunDef def = cs_defaultRunDef();
  def.legs = "rom";
  def.rom_file = argv[1];
  const char* scene = getenv("CS_BENCH_SCENE");
  if (scene) {
    def.scene = scene;
  } else {
    def.actuator_set = sets;
    def.n_actuator_set = 3;
    def.calibration = cal;
    def.no_gait = 1;
    def.t_end = 1;
    def.conditions = "earth";
  }
  if (getenv("CS_BENCH_COND")) def.conditions = getenv("CS_BENCH_COND");
  const int per_leg = getenv("CS_BENCH_LEGS") ? atoi(getenv("CS_BENCH_LEGS")) : 0;
  if (argc > 3) def.coupling = argv[3];
  if (argc > 4) def.dt = atof(argv[4]);
  if (argc > 5) def.macro_steps = atof(argv[5]);
  if (getenv("CRAWLSIM_ROM_TOL")) def.rod_tol = atof(getenv("CRAWLSIM_ROM_TOL"));
  const long nstep = atol(argv[2]);
  dInitODE2(0);
  dSetMessageHandler(quiet);
  dSetErrorHandler(quiet);
  csModel* m = malloc(sizeof *m);
  cs_modelInit(m);
  csRunPlan plan;
  csError err;
  cs_errorClear(&err);
  clock_t c0 = clock();
  if (cs_runDefBuild(&def, m, &plan, &err) != CS_OK) {
    printf("build: %s\n", err.msg);
    return 1;
  }
  if (getenv("CS_BENCH_CARRY")) {
    m->opt.coupling_carry = atoi(getenv("CS_BENCH_CARRY"));
  }
  csData* d = cs_dataCreate(m, &err);
  if (!d) {
    printf("data: %s\n", err.msg);
    return 1;
  }
  printf("set-up %.1f s CPU; mass %.2f g, h %g s, macro %d, coupling %d\n",
         (double)(clock() - c0) / CLOCKS_PER_SEC, cs_robotMass(d) * 1e6, m->opt.h,
         m->opt.macro_steps, (int)m->opt.coupling);
  printf("step t_s y_mm vy_mm/s |w| sum_fy_N sum_wy_N depth_mm cpu_s | eight legs' CVODE "
         "counters over the step: steps rhs jacs tangents setups newton nfail efail restarts sole\n");
  csrRomStats s0[8];
  for (int k = 0; k < 8; k++) {
    csr_romLegStats(cs_leg(d, k), &s0[k]);
  }
  double p0[3];
  cs_supportDisplacement(d, p0);
  for (long i = 0; i < nstep; i++) {
    clock_t c = clock();
    csStatus st = cs_step(m, d, &err);
    double p[3], v[3], w[3], fy = 0, wy = 0;
    cs_supportDisplacement(d, p);
    cs_supportVelocity(d, v);
    cs_supportAngularVelocity(d, w);
    for (int k = 0; k < 8; k++) {
      double f[3];
      csrWrench wr;
      cs_footForce(m, d, k, f);
      cs_legWrench(d, k, &wr);
      fy += f[1];
      wy += wr.f[1];
    }
    const double cpu = (double)(clock() - c) / CLOCKS_PER_SEC;
    long cnt[10] = {0};
    for (int k = 0; k < 8; k++) {
      csrRomStats s1;
      csr_romLegStats(cs_leg(d, k), &s1);
      cnt[0] += s1.steps - s0[k].steps;
      cnt[1] += s1.rhs - s0[k].rhs;
      cnt[2] += s1.jacs - s0[k].jacs;
      cnt[3] += s1.lin_setups - s0[k].lin_setups;
      cnt[4] += s1.nl_iters - s0[k].nl_iters;
      cnt[5] += s1.nl_fails - s0[k].nl_fails;
      cnt[6] += s1.err_fails - s0[k].err_fails;
      cnt[7] += s1.restarts - s0[k].restarts;
      cnt[8] += s1.sole - s0[k].sole;
      cnt[9] += s1.tangents - s0[k].tangents;
      s0[k] = s1;
    }
    printf("%ld %.5f %.5f %.4g %.3g %.5g %.5g %.5f %.2f | %ld %ld %ld %ld %ld %ld %ld %ld %ld %ld%s%s\n",
           i, cs_time(d), p[1], v[1], sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), fy, wy,
           cs_legContactDepth(m, d), cpu, cnt[0], cnt[1], cnt[2], cnt[9], cnt[3], cnt[4], cnt[5],
           cnt[6], cnt[7], cnt[8], st == CS_OK ? "" : " FAILED: ", st == CS_OK ? "" : err.msg);
    if (per_leg) {
      printf("  v %.4g %.4g %.4g mm/s w %.5g %.5g %.5g rad/s\n", v[0], v[1], v[2], w[0], w[1],
             w[2]);
      const csrLegType* lt = &csr_leg_rom;
      for (int k = 0; k < 8; k++) {
        double f[3];
        csrWrench wr;
        const csrLeg* leg = cs_leg(d, k);
        cs_footForce(m, d, k, f);
        cs_legWrench(d, k, &wr);
        /* the sole's history: the leg state's last 4 doubles (robot_rom.h csr_romGetState;
         * the patch foot's z, phi) */
        const int ns = lt->stateSize(leg);
        double* x = malloc((size_t)ns * sizeof(double));
        lt->getState(leg, x);
        const double* z = x + ns - 4;
        printf("  leg %c f %.4g %.4g %.4g m %.4g %.4g %.4g foot %.4g %.4g %.4g z %.3g %.3g %.3g "
               "%.3g\n", 'A' + k, wr.f[0], wr.f[1], wr.f[2], wr.m[0], wr.m[1], wr.m[2], f[0],
               f[1], f[2], z[0], z[1], z[2], z[3]);
        free(x);
      }
    }
    fflush(stdout);
    if (st != CS_OK) {
      break;
    }
  }
  cs_dataDestroy(d);
  cs_modelDestroy(m);
  free(m);
  dCloseODE();
  return 0;
}
