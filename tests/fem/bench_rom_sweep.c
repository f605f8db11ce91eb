/* bench_rom_sweep.c: the reduced model's 0-0.4 MPa bend sweep with each Newton setting in one
 * run (issue 34, the 300x target; docs/notes/rom.md, session romfast). Built, not registered.
 *
 *   bench_rom_sweep BASIS.h5 WEIGHTS.h5|none [S] [K_LAG[bP][rRTOL][k][s] ...]  (bP: P BFGS
 *                   pairs, default 8, on the kept factor; session romacc; session romsweep:
 *                   rRTOL the residual test, default CSF_ROM_ACT_RTOL; k the pairs kept from
 *                   one load step to the next; s the tangent at the converged states theta =
 *                   v/V, S(E), csfRomData.sync)
 *   bench_rom_sweep LEG.h5 leg [S] [K_LAG[bP][rRTOL] ...]  (a leg file of `crawlsim rom
 *                   leg-file`: no gmsh, the set-up's CPU is the file's read)
 *
 * The short leg (segments of S mm, default 15) meshed once as `crawlsim bend --model rom` does,
 * Omega1 and Omega2 of every segment from 0 to 0.4 MPa in rows of 0.05 MPa, the sweep repeated
 * for each K_LAG (csfRomNewtonOptions.k_lag; default 0, 0.25, 0.5, 0.75, 0.9) with the
 * predictor on, and once more at the first K_LAG without it. Prints per setting the sweep's CPU
 * time (CLOCK_PROCESS_CPUTIME_ID), iterations, evaluations, tangents, and the largest
 * difference of the segment bends and of the reduced coordinates from the first setting's
 * (the residual test decides every setting: the differences are of the Newton tolerance). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fem_measure.h"
#include "fem_rom_act.h"
#include "robot_rom_file.h"

static double cpuSeconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { NROW = 9, MAXSET = 12 };

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: bench_rom_sweep BASIS.h5 WEIGHTS.h5|none [S_mm] [K_LAG ...]\n");
    return 2;
  }
  const char* basis = argv[1];
  const int leg = !strcmp(argv[2], "leg");
  const char* weights = strcmp(argv[2], "none") && !leg ? argv[2] : NULL;
  const double S = argc > 3 ? atof(argv[3]) : 15.0;
  double lags[MAXSET] = {0.0, 0.25, 0.5, 0.75, 0.9};
  int bfgs[MAXSET] = {0};
  double rtol[MAXSET];
  int keep[MAXSET] = {0}, sync[MAXSET] = {0};
  for (int k = 0; k < MAXSET; k++) {
    rtol[k] = CSF_ROM_ACT_RTOL;
  }
  int nlag = 5;
  if (argc > 4) {
    nlag = 0;
    for (int i = 4; i < argc && nlag < MAXSET - 1; i++) {
      /* K_LAG, or K_LAGbP: with P BFGS pairs on the kept factor (csfRomNewtonOptions.bfgs) */
      char* end;
      lags[nlag] = strtod(argv[i], &end);
      bfgs[nlag] = 0;
      if (*end == 'b') {
        bfgs[nlag] = (int)strtol(end + 1, &end, 10);
        bfgs[nlag] = bfgs[nlag] ? bfgs[nlag] : 8;
      }
      keep[nlag] = sync[nlag] = 0;
      for (int more = 1; more;) {
        if (*end == 'r') {
          rtol[nlag] = strtod(end + 1, &end);
        } else if (*end == 'k') {
          keep[nlag] = 1, end++;
        } else if (*end == 's') {
          sync[nlag] = 1, end++;
        } else {
          more = 0;
        }
      }
      nlag++;
    }
  }
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  char set[64];
  if (csr_actuatorPreset(&act, "leg", &err) != CS_OK) {
    fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
    return 1;
  }
  for (int s = 1; s <= 3; s++) {
    snprintf(set, sizeof set, "S%d=%g", s, S);
    if (csr_actuatorSetString(&act, set, &err) != CS_OK) {
      fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
      return 1;
    }
  }
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  for (int s = 0; s < CSR_NSEG; s++) {
    spec.ratio[s][0] = spec.ratio[s][1] = 1.0;
    spec.ratio[s][2] = spec.ratio[s][3] = 0.0;
  }
  spec.mesh_symmetric = 1;
  spec.work_stem = "bench_rom_sweep";
  csfRomActuator ra;
  memset(&ra, 0, sizeof ra);
  const double c0 = cpuSeconds();
  if (leg) {
    csrRomLegFile lf;
    if (csr_romLegFileRead(basis, &lf, &err) != CS_OK ||
        csr_romLegFileCheckActuator(&lf, basis, &act, &err) != CS_OK) {
      fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
      return 1;
    }
    csfMesh* me = lf.mesh;
    csfModel* mo = lf.model;
    csfRom* rom = lf.rom;
    lf.mesh = NULL, lf.model = NULL, lf.rom = NULL;
    csr_romLegFileFree(&lf);
    if (csf_romActuatorFromModel(&act, &spec, me, mo, rom, basis, &ra, &err) != CS_OK) {
      fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
      return 1;
    }
  } else {
    const double l = csf_romBasisMeshSize(basis, &err);
    if (isnan(l)) {
      fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
      return 1;
    }
    spec.mesh_size = l;
    if (csf_romActuatorCreate(&act, &spec, basis, weights, &ra, &err) != CS_OK) {
      fprintf(stderr, "bench_rom_sweep: %s\n", err.msg);
      return 1;
    }
  }
  const int n = ra.rom->n;
  printf("bench_rom_sweep: n = %d, m = %d, %d Tet10, %d fibres kept; set-up %.2f s CPU\n", n,
         ra.rom->m, ra.rom->nel[CSF_ROM_SET_TET], ra.rom->nel[CSF_ROM_SET_FIBRE],
         cpuSeconds() - c0);
  double ang0[NROW][3], q0[NROW * 256];
  int have0 = 0;
  printf("   k_lag  bfgs     rtol  keep  sync  predictor   CPU (s)   iterations  evaluations  tangents   max |d bend| (deg)  "
         "max |dq| / max |q|\n");
  for (int k = 0; k <= nlag; k++) {
    const double lag = k < nlag ? lags[k] : lags[0];
    const int pred = k < nlag;
    csf_romDataReset(ra.rom, ra.d);
    memset(ra.p, 0, sizeof ra.p);
    memset(ra.q_conv, 0, (size_t)n * sizeof(double));
    ra.nhist = 0;
    ra.k_lag = lag;
    ra.bfgs = k < nlag ? bfgs[k] : bfgs[0];
    ra.rtol = k < nlag ? rtol[k] : rtol[0];
    ra.bfgs_keep = k < nlag ? keep[k] : keep[0];
    ra.d->sync = k < nlag ? sync[k] : sync[0];
    const long it0 = ra.n_newton, ev0 = ra.d->n_eval, tg0 = ra.d->n_tangent;
    double prev[4] = {0, 0, 0, 0}, dang = 0, dq = 0, qmax = 0;
    const double t0 = cpuSeconds();
    for (int i = 0; i < NROW; i++) {
      double P[CSR_NSEG * CSR_NCHAMBER] = {0};
      for (int s = 0; s < CSR_NSEG; s++) {
        P[4 * s] = P[4 * s + 1] = 0.05 * i;
      }
      if (!pred) {
        ra.nhist = 0; /* no history: every step starts from the last solution */
      }
      const double g[3] = {0, 0, 0}, F[3] = {0, 0, 0};
      if (csf_romActuatorSolve(&ra, P, g, F, &err) != CS_OK) {
        printf("  k_lag %g: %s\n", lag, err.msg);
        break;
      }
      const csfData v = csf_romActuatorView(&ra);
      double ang[3], tot, tip[3];
      csf_bendMeasure(&act, ra.fe.gauges, ra.fe.model, &v, ra.fe.axis, prev, ang, &tot, tip);
      prev[0] = ang[0], prev[1] = ang[1], prev[2] = ang[2], prev[3] = tot;
      for (int s = 0; s < 3; s++) {
        if (have0) {
          dang = fmax(dang, fabs(ang[s] - ang0[i][s]));
        } else {
          ang0[i][s] = ang[s];
        }
      }
      for (int j = 0; j < n && n <= 256; j++) {
        if (have0) {
          dq = fmax(dq, fabs(ra.d->q[j] - q0[i * 256 + j]));
        } else {
          q0[i * 256 + j] = ra.d->q[j];
        }
        qmax = fmax(qmax, fabs(ra.d->q[j]));
      }
    }
    const double t = cpuSeconds() - t0;
    have0 = 1;
    printf("  %6.2f  %4d  %7.0e  %4d  %4d  %9s  %8.3f  %11ld  %11ld  %8ld   %18.2e  %18.2e\n",
           lag, ra.bfgs, ra.rtol, ra.bfgs_keep, ra.d->sync, pred ? "secant" : "none",
           t, ra.n_newton - it0, ra.d->n_eval - ev0, ra.d->n_tangent - tg0, dang, dq / qmax);
  }
  printf("bench_rom_sweep: rows at 0.4 MPa of the first setting: %.3f %.3f %.3f deg\n",
         ang0[NROW - 1][0], ang0[NROW - 1][1], ang0[NROW - 1][2]);
  csf_romActuatorDestroy(&ra);
  return 0;
}
