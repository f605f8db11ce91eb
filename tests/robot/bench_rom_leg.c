/* bench_rom_leg.c: cost of the reduced FE leg's dynamics (robot/rom/robot_rom.h) on a real
 * basis (not a test: prints numbers; built, not registered).
 *
 *   bench_rom_leg BASIS.h5 [WEIGHTS.h5|-] [scenario] [t_end_s] [H_ms] [S_mm]
 *
 * The reduced actuator is built as `crawlsim bend --model rom` builds it (fem/fem_rom_act.h:
 * the `leg` preset with S1 = S2 = S3 = S_mm (default 15: the short leg of docs/notes/rom.md),
 * meshed again with gmsh on the basis' l_soft and checked against its mesh signature, the
 * chambers' pressure loads in closed form, ECSW weights when given); the leg hangs from a hip
 * whose e3 points down (world -y), earth gravity. Scenarios:
 *   gait  (default) the hip held still; II1 Ω1&Ω2 ramped to 0.1 MPa over 0.2 s (smoothstep)
 *         at t = 0, held;
 *   swing the hip oscillating ±5 mm at 2 Hz along x, vented;
 *   stance the sole (the tip face's nodes) in contact with a flat ground (csr_romModelSetSole,
 *         contact_soft.h's foot with its defaults, half side from the face): the ground
 *         0.05 mm below the hanging sole, the hip lowered 0.3 mm over 0.1 s and held, then
 *         gait's pressures from t = 0.1 s: the leg bends against its foot's friction.
 * Prints: basis size, the set-up's wall time, CPU time per simulated second (one core),
 * CVODE steps, right-hand sides, Jacobians, the foot's displacement (the tip face's mean,
 * hip frame) and the step-averaged base wrench at t_end; for gait, the foot of the reduced
 * statics of the end's load (fem_rom_act.h), where the damped leg settles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core_clock.h"
#include "contact_soft.h"
#include "core_math.h"
#include "fem_mesh.h"
#include "fem_rom_act.h"
#include "robot_rom.h"

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static void pressures(double t, int gait, double p[12]) {
  memset(p, 0, 12 * sizeof(double));
  if (!gait) {
    return;
  }
  const double u = fmin(1.0, fmax(0.0, t / 0.2)), s = u * u * (3 - 2 * u);
  p[0] = p[1] = 0.1 * s;
}

/* stance: the hip lowered 0.3 mm over 0.1 s (smoothstep) */
static void hipStance(double t, csrBaseState* b) {
  const double u = fmin(1.0, fmax(0.0, t / 0.1));
  b->x[1] = -0.3 * u * u * (3 - 2 * u);
  b->v[1] = -0.3 * 6 * u * (1 - u) / 0.1;
}

static void hip(double t, int swing, csrBaseState* b) {
  memset(b, 0, sizeof *b);
  /* e1 = x, e2 = z, e3 = -y (columns) */
  const double R[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(b->R, R, sizeof R);
  if (swing) {
    const double w = 2 * M_PI * 2.0;
    b->x[0] = 5.0 * sin(w * t);
    b->v[0] = 5.0 * w * cos(w * t);
  }
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: bench_rom_leg BASIS.h5 [WEIGHTS.h5|-] [gait|swing] [t_end_s] "
            "[H_ms] [S_mm]\n");
    return 2;
  }
  const char* basis = argv[1];
  const char* weights = argc > 2 && strcmp(argv[2], "-") != 0 ? argv[2] : NULL;
  const int swing = argc > 3 && strcmp(argv[3], "swing") == 0;
  const int stance = argc > 3 && strcmp(argv[3], "stance") == 0;
  const double t_end = argc > 4 ? atof(argv[4]) : 0.5;
  const double H = (argc > 5 ? atof(argv[5]) : 1.0) * 1e-3;
  const double S = argc > 6 ? atof(argv[6]) : 15.0;
  csError err = {0};
  csrActuator act;
  if (csr_actuatorPreset(&act, "leg", &err) != CS_OK ||
      csr_actuatorSet(&act, "S1", S, &err) != CS_OK ||
      csr_actuatorSet(&act, "S2", S, &err) != CS_OK ||
      csr_actuatorSet(&act, "S3", S, &err) != CS_OK) {
    fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
    return 1;
  }
  const double l = csf_romBasisMeshSize(basis, &err);
  if (isnan(l)) {
    fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
    return 1;
  }
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.mesh_size = l;
  spec.mesh_symmetric = 1;
  spec.work_stem = "bench_rom_leg_mesh";
  const double w0 = csu_wallSeconds();
  csfRomActuator ra;
  if (csf_romActuatorCreate(&act, &spec, basis, weights, &ra, &err) != CS_OK) {
    fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
    return 1;
  }
  const double w_act = csu_wallSeconds() - w0;
  const csfMesh* me = ra.fe.mesh;
  int* face_ch = malloc((size_t)me->nface * sizeof(int));
  for (int f = 0; f < me->nface; f++) {
    face_ch[f] = -1;
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 1; j <= CSR_NCHAMBER; j++) {
        if (me->face_tag[f] == CSF_TAG_CHAMBER(s, j)) {
          face_ch[f] = CSR_NCHAMBER * s + j - 1;
        }
      }
    }
  }
  csrRomParams par = csr_romDefaultParams();
  par.rho = act.rho;
  par.damping_time = csr_defaultLegParams(&act).damping_time;
  par.gravity[1] = -9810.0;
  const double w1 = csu_wallSeconds();
  csrRomModel* m = csr_romModelCreate(ra.rom, &par, face_ch, &err);
  cscSoftModel* cm = NULL;
  int* sole = malloc((size_t)me->nnode * sizeof(int));
  int nsole = 0;
  if (m && stance) {
    /* the sole: the tip face's nodes (tip_unit's support); the leg hangs along the hip's e3,
     * so the sole's frame at rest is the hip's; the ground 0.05 mm below its lowest node */
    double zmax = -INFINITY, half = 0, xc[2] = {0, 0};
    for (int i = 0; i < me->nnode; i++) {
      if (ra.fe.tip_unit[3 * i] != 0 || ra.fe.tip_unit[3 * i + 2] != 0) {
        sole[nsole++] = i;
        zmax = fmax(zmax, me->x[3 * i + 2]);
        xc[0] += me->x[3 * i], xc[1] += me->x[3 * i + 1];
      }
    }
    for (int a = 0; a < nsole; a++) {
      half = fmax(half, fabs(me->x[3 * sole[a]] - xc[0] / nsole));
    }
    cstTerrain tr;
    memset(&tr, 0, sizeof tr);
    tr.nbox = 1;
    tr.box[0] = (cstBox){.lo = {-300, -zmax - 50, -150}, .hi = {300, -zmax - 0.05, 150}};
    cscSoftParams cp = csc_softDefaultParams();
    cscShape foot = csc_softFoot(half);
    cm = csc_softCreate(&cp, &tr, 1, &foot, &err);
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (!cm || csr_romModelSetSole(m, cm, nsole, sole, I, &err) != CS_OK) {
      fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
      return 1;
    }
    printf("stance: %d sole nodes, foot half side %.3g mm, ground at y = %.4g mm\n", nsole,
           half, -zmax - 0.05);
  }
  csrRomData* d = m ? csr_romDataCreate(m, &err) : NULL;
  if (!d) {
    fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
    return 1;
  }
  const double w_model = csu_wallSeconds() - w1;
  printf("basis %s: n = %d, m = %d, %d Tet10 (%d kept), %d fibres (%d kept), mass %.4g g, "
         "damping time %.3g s\n", basis, m->n, ra.rom->m, me->ntet, ra.rom->nel[0],
         ra.fe.model->nfib, ra.rom->nel[1], m->mass * 1e6, par.damping_time);
  printf("set-up: reduced actuator %.1f s wall (gmsh, chamber tensors), inertia operators and "
         "K_r(0) %.2f s wall\n", w_act, w_model);
  csrBaseState b0, b1;
  hip(0, swing, &b0);
  csr_romReset(m, d, 0.0, &b0);
  double p0[12], p1[12], t = 0;
  csrWrench w = {{0, 0, 0}, {0, 0, 0}};
  const double c0 = cpu();
  long nstep = 0;
  while (t < t_end - 1e-12) {
    pressures(t, !swing, p0);
    pressures(t + H, !swing, p1);
    hip(t + H, swing, &b1);
    if (stance) {
      hipStance(t + H, &b1);
      pressures(t - 0.1, 1, p0);
      pressures(t + H - 0.1, 1, p1);
    }
    csr_romActuate(d, t, p0, t + H, p1);
    const int rc = csr_romAdvance(m, d, t, H, &b0, &b1, &w, &err);
    if (rc != 0) {
      fprintf(stderr, "bench_rom_leg: %s\n", err.msg);
      return 1;
    }
    b0 = b1;
    t += H;
    nstep++;
  }
  const double c = cpu() - c0;
  long st, nr, nj, nre;
  csr_romStats(d, &st, &nr, &nj, &nre);
  /* the foot: the tip face's mean displacement (tip_unit: nodal weights of a unit traction) */
  double* u = malloc((size_t)ra.fe.model->ndof * sizeof(double));
  csf_romExpand(ra.rom, csr_romQ(d), u);
  double foot[3] = {0, 0, 0};
  for (int i = 0; i < me->nnode; i++) {
    for (int k = 0; k < 3; k++) {
      foot[k] += ra.fe.tip_unit[3 * i + k] * u[3 * i + k];
    }
  }
  printf("%s, H = %g ms, %g s simulated: CPU %.3g s per simulated second (one leg, one core), "
         "%ld macro steps, %ld CVODE steps, %ld rhs, %ld jacobians, %ld restarts\n",
         swing ? "swing" : (stance ? "stance" : "gait"), H * 1e3, t, c / t, nstep, st, nr, nj, nre);
  printf("foot displacement (hip frame) %.4f %.4f %.4f mm; wrench f %.5g %.5g %.5g N, m %.5g "
         "%.5g %.5g N mm (weight %.5g N)\n", foot[0], foot[1], foot[2], w.f[0], w.f[1], w.f[2],
         w.m[0], w.m[1], w.m[2], m->mass * 9810.0);
  if (stance) {
    const double* z = csr_romZ(d);
    printf("stance: the sole's friction history (bristle mm, torsion rad) %.4g %.4g %.4g %.4g; "
           "the support carries f_y %.5g N (weight %.5g N)\n", z[0], z[1], z[2], z[3], w.f[1],
           -m->mass * 9810.0);
  }
  /* the reduced statics of the end's load (gravity in the hip frame, the end's pressures),
   * ramped from rest by fem_rom_act.h: where the damped dynamics settle once the load holds */
  double pe[12], ge[3];
  pressures(t, !swing, pe);
  csu_mulMatTVec3(ge, b0.R, par.gravity);
  const double F0[3] = {0, 0, 0};
  /* how far the dynamics' end is from the statics' equations: their residual at its q, and the
   * consistent mass' gravity T against the FE's body-force rule G */
  {
    csfRomLoad ld;
    csf_romActuatorLoad(&ra, pe, ge, F0, &ld);
    memcpy(ra.d->q, csr_romQ(d), (size_t)m->n * sizeof(double));
    if (csf_romEvaluate(ra.rom, ra.d, &ld, 0) == 0) {
      double rn = 0, tg = 0, gg = 0;
      for (int k = 0; k < m->n; k++) {
        rn += ra.d->r[k] * ra.d->r[k];
        for (int i = 0; i < 3; i++) {
          tg = fmax(tg, fabs(m->T[3 * k + i] - ra.rom->G[3 * k + i]));
          gg = fmax(gg, fabs(ra.rom->G[3 * k + i]));
        }
      }
      printf("the statics' residual at the dynamics' end: |r| %.3g N (force scale %.3g N); "
             "|T - G| %.3g of %.3g t\n", sqrt(rn), ra.d->fnorm, tg, gg);
    }
  }
  if (!swing && !stance && csf_romActuatorSolve(&ra, pe, ge, F0, &err) == CS_OK) {
    double fs[3] = {0, 0, 0};
    for (int i = 0; i < me->nnode; i++) {
      for (int k = 0; k < 3; k++) {
        fs[k] += ra.fe.tip_unit[3 * i + k] * ra.u[3 * i + k];
      }
    }
    printf("reduced statics of the end's load: foot %.4f %.4f %.4f mm\n", fs[0], fs[1], fs[2]);
  } else if (!swing && !stance) {
    printf("reduced statics of the end's load: %s\n", err.msg);
  }
  free(u), free(face_ch), free(sole);
  csc_softDestroy(cm);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  csf_romActuatorDestroy(&ra);
  return 0;
}
