/* test_fem_bend.c: end-to-end csf_bend on a short coarse actuator variant (S = 15 mm segments,
 * 9 turns, l_soft = 5 mm): angles grow with pressure, the three equal segments bend alike,
 * --until-angle is found by equilibrium solves to within the tolerance, and the VTU and
 * ABAQUS/CalculiX files are written; the sweep tolerance keeps the answer; a volume-controlled
 * stretch lands every output row it passes. Slow (~3 min): label slow. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_bend.h"

/* the short coarse variant: baseline with 15 mm segments, `turns` fibre turns per segment,
 * meshed at l_soft 5; returns the options of a sweep on it */
static csfBendOptions shortActuator(csrActuator* act, int turns, csfBendInfo* info) {
  csError err = {0};
  csr_actuatorPreset(act, "baseline", &err);
  char n[3][16];
  for (int s = 0; s < 3; s++) {
    snprintf(n[s], sizeof n[s], "n%d=%d", s + 1, turns);
  }
  const char* set[] = {"S1=15", "S2=15", "S3=15", n[0], n[1], n[2]};
  for (int i = 0; i < 6; i++) {
    CS_EXPECT(csr_actuatorSetString(act, set[i], &err) == CS_OK);
  }
  csfBendOptions o = csf_bendDefault();
  o.info = info;
  o.spec.mesh_size = 5.0;
  o.spec.fibres = turns > 0;
  return o;
}

static void test_bend_short(void) {
  csError err = {0};
  csrActuator act;
  csfBendInfo info;
  csfBendOptions o = shortActuator(&act, 9, &info);
  o.p_max = 0.1;
  o.p_step = 0.05;
  o.until_angle = 4.0; /* deg, reached near 0.06 MPa */
  o.spec.work_stem = "bend_short";
  o.vtu_path = "bend_short.vtu";
  o.inp_path = "bend_short.inp";
  csrBendCurve bc;
  csr_bendCurveInit(&bc, 8, &err);
  csStatus st = csf_bend(&act, &o, &bc, &err);
  if (st != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
  }
  CS_EXPECT(st == CS_OK);
  printf("  %d Tet10, %d fibre elements, %d steps, %ld Newton iterations, %.1f s (assembly %.1f, "
         "factorisation %.1f)\n", info.ntet, info.nfibre, info.n_steps, info.n_newton,
         info.t_total, info.t_assemble, info.t_factor);
  for (size_t i = 0; i < bc.m; i++) {
    printf("  p %.5f MPa: segments %.3f %.3f %.3f deg, total %.3f deg\n", bc.pressure[i],
           bc.angle_deg[3 * i], bc.angle_deg[3 * i + 1], bc.angle_deg[3 * i + 2],
           bc.angle_total[i]);
  }
  CS_EXPECT(bc.m >= 2);
  /* Newton never repeats an iterate: its watchdog's return to the best iterate must not retake
   * the step that led away from it (fem_newton.c, CSF_LS_GROWTH) */
  printf("  watchdog returns %ld, repeated iterates %ld\n", info.n_restore, info.n_repeat);
  CS_EXPECT(info.n_repeat == 0);
  if (bc.m >= 2) {
    size_t k = bc.m - 1;
    /* equal segments, equal pressure: measured spread 2 %; 10 % catches a wrong chamber tag */
    CS_EXPECT_NEAR(bc.angle_deg[3 * k], bc.angle_deg[3 * k + 1], 0, 0.1);
    CS_EXPECT_NEAR(bc.angle_deg[3 * k + 2], bc.angle_deg[3 * k + 1], 0, 0.1);
    CS_EXPECT(bc.angle_total[k] > bc.angle_total[0]);
  }
  /* the until-angle pressure is an equilibrium whose angle is within angle_tol */
  CS_EXPECT(isfinite(bc.p_until_angle));
  if (isfinite(bc.p_until_angle)) {
    CS_EXPECT_NEAR(bc.angle_total[bc.m - 1], o.until_angle, o.angle_tol, 0);
    printf("  p_until_angle(%.1f deg) = %.5f MPa, %d refinement trials\n", o.until_angle,
           bc.p_until_angle, info.n_until_trials);
    /* the step that crosses the target ends at the crossing the last three states predict
     * (fem_bend.c untilTarget), within angle_tol on this smooth path: no refinement trial
     * (before, the sweep stepped on to 0.075 MPa and refined the bracket by a trial) */
    CS_EXPECT(info.n_until_trials == 0);
  }
  FILE* f = fopen("bend_short.vtu", "r");
  CS_EXPECT(f != NULL);
  if (f) {
    fclose(f);
  }
  f = fopen("bend_short.inp", "r");
  CS_EXPECT(f != NULL);
  if (f) {
    fclose(f);
  }
  csr_bendCurveFree(&bc);
}

/* Gravity is ramped before the pressure sweep: the short actuator, axis horizontal (gravity
 * along -e1), at G_FACTOR x Earth gravity sags by ~40 % of its length, too far for one Newton
 * solve (the first attempt fails after 40 iterations); the ramp must reach full gravity in
 * several steps. The sag is compared with the linear Euler-Bernoulli value w = q L^4 / (8 E I)
 * (E = 6 C10, the chambers' holes subtracted from A and I over the whole length): measured
 * 23.08 vs 23.02 mm - shear (L/h = 3.8) adds, the large rotation and
 * the solid caps and joints take away. The band [0.25, 1.3] x w_lin only guards against a ramp
 * that stops early (sag ~ 0) or a wrong gravity scaling (x2). Before the line search's watchdog
 * (fem_newton.c) a single solve under the full weight failed and the ramp took 4 steps, 82
 * iterations; with it the first full-load solve converges (1 step, 12 iterations): the ramp's
 * cut-back path is no longer exercised here. */
#define G_FACTOR 20.0

static void test_gravity_ramp(void) {
  csError err = {0};
  csrActuator act;
  csfBendInfo info;
  csfBendOptions o = shortActuator(&act, 0, &info);
  o.p_max = 0.002; /* a token pressure step after gravity */
  o.p_step = 0.002;
  o.spec.gravity[0] = -G_FACTOR * 9810.0; /* mm/s^2 */
  o.spec.work_stem = "bend_gravity";
  csrBendCurve bc;
  csr_bendCurveInit(&bc, 4, &err);
  csStatus st = csf_bend(&act, &o, &bc, &err);
  if (st != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
  }
  CS_EXPECT(st == CS_OK);
  if (st == CS_OK && bc.m >= 1) {
    /* linear beam sag of the tip: section 2a x 2a minus 4 chambers of radius r1 at (+-b, +-b) */
    const double L = csr_actuatorLength(&act), a2 = 2.0 * act.a;
    const double Ah = CS_PI * act.r1 * act.r1;
    const double A = a2 * a2 - 4.0 * Ah;
    const double I = a2 * a2 * a2 * a2 / 12.0 -
                     4.0 * (Ah * act.r1 * act.r1 / 4.0 + Ah * act.b * act.b);
    const double q = act.rho * A * G_FACTOR * 9810.0; /* N/mm */
    const double w_lin = q * L * L * L * L / (8.0 * 6.0 * act.C10 * I);
    const double sag = -(bc.tip[0] - 0.0); /* tip centroid x at p = 0 (row 0) */
    printf("  %d gravity steps, %ld Newton iterations; tip sag %.2f mm, linear beam %.2f mm "
           "(L = %.0f mm)\n", info.n_gravity_steps, info.n_newton, sag, w_lin, L);
    CS_EXPECT(info.n_gravity_steps >= 1);
    CS_EXPECT(sag > 0.25 * w_lin && sag < 1.3 * w_lin);
  }
  csr_bendCurveFree(&bc);
}

/* A dead tip force is ramped with gravity before the sweep, so the p = 0 row is the
 * equilibrium under it (before 2026-12-02 the row was the unloaded reference state and the
 * force entered with the first pressure step). Checks: the row's tip moves along the force,
 * by the linear cantilever deflection F L^3 / (3 E I) of the chambered section (E = 6 C10)
 * within the same band as the gravity test (the short, coarse, fibre-free variant: shear,
 * the solid joints and l_soft 5 make it stiffer or softer by tens of %), and twice the force
 * gives twice the deflection (small load: linear within 3 %). */
static void test_tip_force_row_zero_is_loaded(void) {
  csError err = {0};
  csrActuator act;
  /* 0 N: the reference state's tip (the measure has a mesh offset of a few um); 0.02 and
   * 0.04 N along e1: ~0.5 and ~1 mm, far above that offset, still linear */
  const double F[3] = {0.0, 0.02, 0.04};
  double x[3] = {NAN, NAN, NAN};
  int nsteps = 0;
  for (int k = 0; k < 3; k++) {
    csfBendInfo info;
    csfBendOptions o = shortActuator(&act, 0, &info);
    o.p_max = 0.002; /* a token pressure step after the ramp */
    o.p_step = 0.002;
    o.spec.tip_force[0] = F[k];
    o.spec.work_stem = "bend_tip";
    csrBendCurve bc;
    csr_bendCurveInit(&bc, 4, &err);
    const csStatus st = csf_bend(&act, &o, &bc, &err);
    if (st != CS_OK) {
      fprintf(stderr, "%s\n", err.msg);
    }
    CS_EXPECT(st == CS_OK && bc.m >= 1);
    if (st == CS_OK && bc.m >= 1) {
      x[k] = bc.tip[0]; /* tip x at p = 0 (row 0) */
      nsteps = k > 0 ? info.n_gravity_steps : nsteps;
    }
    csr_bendCurveFree(&bc);
  }
  const double L = csr_actuatorLength(&act), a2 = 2.0 * act.a;
  const double Ah = CS_PI * act.r1 * act.r1;
  const double I = a2 * a2 * a2 * a2 / 12.0 - 4.0 * (Ah * act.r1 * act.r1 / 4.0 + Ah * act.b * act.b);
  const double w_lin = F[1] * L * L * L / (3.0 * 6.0 * act.C10 * I);
  const double d1 = x[1] - x[0], d2 = x[2] - x[0];
  printf("  p = 0 row tip x: %.4f mm unloaded, %+.4f mm at %.2f N (linear cantilever %.4f mm), "
         "%+.4f mm at %.2f N (ratio %.4f); %d ramp steps\n", x[0], d1, F[1], w_lin, d2, F[2],
         d2 / d1, nsteps);
  CS_EXPECT(nsteps >= 1);
  CS_EXPECT(d1 > 0.25 * w_lin && d1 < 1.3 * w_lin);
  CS_EXPECT_NEAR(d2 / d1, 2.0, 0, 0.03);
}

/* The sweep's Newton tolerance (CSF_BEND_NEWTON_RTOL, 1e-6 of the force scale) against the
 * element tests' 1e-8: the same sweep to 0.05 MPa on the short variant must give the same bend
 * and tip, in fewer Newton iterations (the iteration counts are deterministic). Bound: at |R| =
 * 1e-6 (|f_int| + |f_ext|), a few 1e-6 N here, the displacement left is of order |K^-1 R|, far
 * below the 1e-4 mm and 1e-4 of the 2.9 deg angle asked (measured: equal to every printed
 * digit, 1e-3 deg and 1e-3 mm; so was a tolerance of 1e-3, in 26 iterations against 36, so
 * this bound guards the answer of the shipped default, not every looser choice). */
static void test_sweep_tolerance_keeps_the_answer(void) {
  csError err = {0};
  csrActuator act;
  csfBendInfo info[2];
  csrBendCurve bc[2];
  const double rtol[2] = {0.0, 1e-8}; /* 0: the sweep's default */
  for (int k = 0; k < 2; k++) {
    csfBendOptions o = shortActuator(&act, 9, &info[k]);
    o.p_max = 0.05;
    o.p_step = 0.05;
    if (rtol[k] > 0) {
      o.newton_rtol = rtol[k];
    }
    o.spec.work_stem = "bend_tol";
    csr_bendCurveInit(&bc[k], 4, &err);
    const csStatus st = csf_bend(&act, &o, &bc[k], &err);
    if (st != CS_OK) {
      fprintf(stderr, "%s\n", err.msg);
    }
    CS_EXPECT(st == CS_OK && bc[k].m == 2);
  }
  if (bc[0].m == 2 && bc[1].m == 2) {
    printf("  0.05 MPa: total %.6f deg in %ld iterations (default) vs %.6f deg in %ld (1e-8)\n",
           bc[0].angle_total[1], info[0].n_newton, bc[1].angle_total[1], info[1].n_newton);
    CS_EXPECT_NEAR(bc[0].angle_total[1], bc[1].angle_total[1], 0, 1e-4);
    for (int i = 0; i < 3; i++) {
      CS_EXPECT_NEAR(bc[0].tip[3 + i], bc[1].tip[3 + i], 1e-4, 0);
    }
    CS_EXPECT(info[0].n_newton < info[1].n_newton);
    CS_EXPECT(info[0].n_repeat == 0 && info[1].n_repeat == 0);
  }
  csr_bendCurveFree(&bc[0]);
  csr_bendCurveFree(&bc[1]);
}

/* A volume-controlled stretch lands a row at every output pressure it passes: the fibre-free
 * short actuator's sweep asked to follow the path by chamber volume from 0.02 MPa
 * (csfBendOptions.volume_from; it ran to 0.072 MPa, passing the eight output pressures up to
 * p_max) has the rows
 * of the pressure-controlled sweep and the same equilibria to Newton's tolerance (both are
 * solved under pressure control at the output pressures; measured 4e-9 mm, 6e-9 deg; bound
 * 1e-4, the tolerance test's), none skipped. Before, only the last output
 * pressure of a stretch got its row (the symmetric-mesh O13 lost its 0.35 MPa row that way). */
typedef struct {
  double p_vmax; /* highest pressure of a volume-controlled state */
  int nvol;
} VolumeWatch;


static void watchVolume(void* user, const csfBendStep* step) {
  VolumeWatch* w = user;
  if (step->volume_control) {
    w->nvol++;
    w->p_vmax = fmax(w->p_vmax, step->p);
  }
}


static void test_volume_stretch_lands_every_row(void) {
  csError err = {0};
  csrActuator act;
  csfBendInfo info[2];
  csrBendCurve bc[2];
  VolumeWatch vw = {0, 0};
  const double p_max = 0.06, p_step = 0.005, p_from = 0.02;
  for (int k = 0; k < 2; k++) {
    csfBendOptions o = shortActuator(&act, 0, &info[k]);
    o.p_max = p_max;
    o.p_step = p_step;
    if (k == 1) {
      o.volume_from = p_from;
      o.progress = watchVolume;
      o.progress_user = &vw;
    }
    o.spec.work_stem = "bend_volume";
    csr_bendCurveInit(&bc[k], 16, &err);
    const csStatus st = csf_bend(&act, &o, &bc[k], &err);
    if (st != CS_OK) {
      fprintf(stderr, "%s\n", err.msg);
    }
    CS_EXPECT(st == CS_OK);
  }
  /* output pressures in the stretch (p_from, min(p_vmax, p_max)]: the old sweep kept only the
   * last */
  const int inside = (int)floor(fmin(vw.p_vmax, p_max) / p_step + 1e-9) -
                     (int)floor(p_from / p_step + 1e-9);
  printf("  volume-controlled states %d up to %.5f MPa (%d output pressures inside), rows %zu "
         "and %zu, skipped %d\n", vw.nvol, vw.p_vmax, inside, bc[0].m, bc[1].m,
         info[1].n_rows_skipped);
  CS_EXPECT(vw.nvol > 0 && inside >= 2);
  CS_EXPECT(info[1].n_rows_skipped == 0);
  CS_EXPECT(bc[0].m == (size_t)lround(p_max / p_step) + 1 && bc[1].m == bc[0].m);
  double dtip = 0, dang = 0;
  for (size_t i = 0; i < bc[0].m && i < bc[1].m; i++) {
    CS_EXPECT_NEAR(bc[1].pressure[i], bc[0].pressure[i], 0, 1e-12);
    for (int c = 0; c < 3; c++) {
      dtip = fmax(dtip, fabs(bc[1].tip[3 * i + c] - bc[0].tip[3 * i + c]));
    }
    dang = fmax(dang, fabs(bc[1].angle_total[i] - bc[0].angle_total[i]));
  }
  printf("  %d + %d steps, %ld + %ld Newton iterations, %.1f + %.1f s\n", info[0].n_steps,
         info[1].n_steps, info[0].n_newton, info[1].n_newton, info[0].t_total, info[1].t_total);
  printf("  largest difference to the pressure-controlled sweep: tip %.2e mm, angle %.2e deg\n",
         dtip, dang);
  CS_EXPECT(dtip < 1e-4 && dang < 1e-4);
  csr_bendCurveFree(&bc[0]);
  csr_bendCurveFree(&bc[1]);
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_bend_short);
  CS_RUN(test_gravity_ramp);
  CS_RUN(test_sweep_tolerance_keeps_the_answer);
  CS_RUN(test_tip_force_row_zero_is_loaded);
  CS_RUN(test_volume_stretch_lands_every_row);
  return cs_testSummary();
}
