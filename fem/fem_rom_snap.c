/* fem_rom_snap.c: snapshot rays of the full FE for the reduced-order leg (fem_rom_snap.h).
 *
 * Rationale.
 * Rays. A POD basis spans the states it was shown, so the training must show the leg every way
 * it will be loaded (issue 34): the calibration's chamber modes with the same pattern in every
 * segment (the eight bending directions, elongation, unequal pressures), patterns that differ
 * per segment (the gait's S-shapes and its mirror, one segment alone, random rays), tip forces
 * across and along the leg (a stance leg carries the support's weight along its axis, a foot's
 * friction across it), gravity in three directions, and pressure with loads together. All
 * loads of a ray grow with one parameter t, so each ray's output states are equilibria on one
 * continuous path, and each ray is an FE run of its own (resumable ray by ray).
 * One model for every ray: the actuator is meshed and its sparse pattern analysed once; a ray
 * only rewrites the pressure per face (every chamber's faces are tagged at set-up, so every
 * pressurised set is closed and the tangent stays symmetric: LDL^T), gravity and the tip force,
 * and restarts from the unloaded state.
 * Stepping: the rules of the FE's sweep (fem_bend.c): first step a quarter of an output step,
 * grow by 1.5 after easy steps, shrink after hard ones, halve on failure, a secant predictor
 * on the whole Newton state (u, element dilatations, fibre stresses). No continuation past
 * limit points: a ray that meets one ends there with its converged outputs (the status says
 * so); a stance-like axial load beyond the leg's buckling load is such a ray. */
#include "fem_rom_snap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "core_h5.h"
#include "fem_assembly.h"
#include "fem_element.h"
#include "fem_measure.h"
#include "fem_mesh.h"
#include "robot_bend_io.h"

#define G_EARTH 9810.0  /* mm/s^2 */
#define P_RAY 0.4       /* MPa: the end pressure of the pressure rays (the gait's range) */
#define GROW_ITERS 12   /* step control as fem_bend.c (CSF_BEND_GROW_ITERS, measured there) */
#define SHRINK_ITERS 16
#define FIRST_REL 0.25  /* first step relative to the output spacing (fem_bend.c) */
#define RAND_SEED 20261205u /* the random rays' seed (a fixed draw, not chosen) */
#define RAND_SEED_SPARSE 20261206u /* the sparse random rays' seed (a fixed draw, not chosen) */

csfRomSnapSettings csf_romSnapDefault(void) {
  csfRomSnapSettings s;
  memset(&s, 0, sizeof s);
  s.mesh_size = 4.0;
  s.newton_rtol = 1e-6; /* the FE sweep's default (fem_bend.c CSF_BEND_NEWTON_RTOL) */
  s.fibre_tension_only = 1;
  s.dt_min = 1e-4;
  return s;
}


/* ---- the ray list -------------------------------------------------------------------------- */

/* a uniform draw in [0, 1) from a 32-bit LCG (Numerical Recipes' constants); the state is the
 * caller's */
static double draw(unsigned* state) {
  *state = *state * 1664525u + 1013904223u;
  return (double)(*state >> 8) / 16777216.0;
}

static csfRomRay* addRay(csfRomRay* r, int* n, int cap, const char* name, csfRomRayKind kind,
                         const char* about) {
  if (*n >= cap) {
    return NULL;
  }
  csfRomRay* y = r + (*n)++;
  memset(y, 0, sizeof *y);
  snprintf(y->name, sizeof y->name, "%s", name);
  snprintf(y->about, sizeof y->about, "%s", about);
  y->kind = kind;
  y->nout = 4;
  return y;
}

/* chambers of every segment at ratio c[j] of P_RAY */
static void sameAll(csfRomRay* y, const double c[4]) {
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      y->p[s][j] = P_RAY * c[j];
    }
  }
}

static void segPattern(csfRomRay* y, int s, const double c[4], double pmax) {
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    y->p[s][j] = pmax * c[j];
  }
}

int csf_romRays(csfRomRay* rays, int cap) {
  int n = 0;
  csfRomRay* y;
  /* the calibration's chamber modes, the same pattern in every segment (all four bending
   * directions of the single and paired chambers: the basis is not told the symmetry) */
  static const struct {
    const char* name;
    double c[4];
    const char* about;
  } kModes[] = {
      {"O1", {1, 0, 0, 0}, "Omega1 alone, every segment, to 0.4 MPa"},
      {"O2", {0, 1, 0, 0}, "Omega2 alone, every segment, to 0.4 MPa"},
      {"O3", {0, 0, 1, 0}, "Omega3 alone, every segment, to 0.4 MPa"},
      {"O4", {0, 0, 0, 1}, "Omega4 alone, every segment, to 0.4 MPa"},
      {"O12", {1, 1, 0, 0}, "Omega1&Omega2 (the gait's mode), every segment, to 0.4 MPa"},
      {"O23", {0, 1, 1, 0}, "Omega2&Omega3, every segment, to 0.4 MPa"},
      {"O34", {0, 0, 1, 1}, "Omega3&Omega4, every segment, to 0.4 MPa"},
      {"O41", {1, 0, 0, 1}, "Omega4&Omega1, every segment, to 0.4 MPa"},
      {"O13", {1, 0, 1, 0}, "Omega1&Omega3 (elongation), every segment, to 0.4 MPa"},
      {"O1234", {1, 1, 1, 1}, "all four (elongation), every segment, to 0.4 MPa"},
      {"O124", {1, 1, 0, 1}, "Omega1&Omega2&Omega4, every segment, to 0.4 MPa"},
      {"O12O3r05", {1, 1, 0.5, 0}, "Omega1&Omega2 at p, Omega3 at p/2, every segment"},
      {"O1O234r05", {1, 0.5, 0.5, 0.5}, "Omega1 at p, the other three at p/2, every segment"},
  };
  for (size_t k = 0; k < sizeof kModes / sizeof kModes[0]; k++) {
    if (!(y = addRay(rays, &n, cap, kModes[k].name, CSF_ROM_TRAIN, kModes[k].about))) {
      return n;
    }
    sameAll(y, kModes[k].c);
  }
  /* patterns that differ per segment: the gait's S-shape (II1 Omega3&Omega4, II2 Omega1&Omega2;
   * gaits/flat_road_paper.gait) and its mirror, each segment alone */
  static const double c12[4] = {1, 1, 0, 0}, c34[4] = {0, 0, 1, 1}, c23[4] = {0, 1, 1, 0},
                      c41[4] = {1, 0, 0, 1};
  if ((y = addRay(rays, &n, cap, "S", CSF_ROM_TRAIN, "S-shape: II1 Omega3&Omega4, II2 "
                  "Omega1&Omega2 to 0.4 MPa, II3 vented"))) {
    segPattern(y, 0, c34, P_RAY), segPattern(y, 1, c12, P_RAY);
  }
  if ((y = addRay(rays, &n, cap, "Smirror", CSF_ROM_TRAIN, "mirrored S: II1 Omega1&Omega2, II2 "
                  "Omega3&Omega4 to 0.4 MPa, II3 vented"))) {
    segPattern(y, 0, c12, P_RAY), segPattern(y, 1, c34, P_RAY);
  }
  if ((y = addRay(rays, &n, cap, "Z", CSF_ROM_TRAIN, "three directions: II1 Omega2&Omega3, II2 "
                  "Omega4&Omega1, II3 Omega1&Omega2 to 0.4 MPa"))) {
    segPattern(y, 0, c23, P_RAY), segPattern(y, 1, c41, P_RAY), segPattern(y, 2, c12, P_RAY);
  }
  static const char* const kSegName[3] = {"II1only", "II2only", "II3only"};
  static const char* const kSegAbout[3] = {"II1 alone: Omega1&Omega2 to 0.4 MPa",
                                           "II2 alone: Omega2&Omega3 to 0.4 MPa",
                                           "II3 alone: Omega3&Omega4 to 0.4 MPa"};
  static const double* const kSegPat[3] = {c12, c23, c34};
  for (int s = 0; s < CSR_NSEG; s++) {
    if ((y = addRay(rays, &n, cap, kSegName[s], CSF_ROM_TRAIN, kSegAbout[s]))) {
      segPattern(y, s, kSegPat[s], P_RAY);
    }
  }
  /* random rays: every chamber of every segment uniform in [0, 0.4] MPa */
  unsigned seed = RAND_SEED;
  for (int k = 0; k < 6; k++) {
    char name[16];
    snprintf(name, sizeof name, "R%d", k + 1);
    if (!(y = addRay(rays, &n, cap, name, CSF_ROM_TRAIN, "random: every chamber uniform in "
                     "[0, 0.4] MPa (fixed seed)"))) {
      return n;
    }
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        y->p[s][j] = P_RAY * draw(&seed);
      }
    }
  }
  /* gravity in three directions (vented leg): across (e1, e2) and along the leg (hanging) */
  static const struct {
    const char* name;
    double g[3];
    const char* about;
  } kGrav[] = {
      {"Gx", {-G_EARTH, 0, 0}, "gravity 9.81 m/s^2 along -e1 (the horizontal leg sags), vented"},
      {"Gy", {0, -G_EARTH, 0}, "gravity 9.81 m/s^2 along -e2, vented"},
      {"Gz", {0, 0, G_EARTH}, "gravity 9.81 m/s^2 along +e3 (the leg hangs from its hip), vented"},
  };
  for (size_t k = 0; k < sizeof kGrav / sizeof kGrav[0]; k++) {
    if ((y = addRay(rays, &n, cap, kGrav[k].name, CSF_ROM_TRAIN, kGrav[k].about))) {
      memcpy(y->gravity, kGrav[k].g, sizeof y->gravity);
    }
  }
  /* tip forces: across the leg (a foot's friction; 0.05 N deflects the vented leg 25 mm,
   * fem_bend.c) and along it (a stance leg carries about a quarter of the robot's 3.3 N weight
   * on Earth: compression; and tension) */
  static const struct {
    const char* name;
    double F[3];
    const char* about;
  } kTip[] = {
      {"Fx", {0.1, 0, 0}, "tip force 0.1 N along e1, vented"},
      {"Fy", {0, 0.1, 0}, "tip force 0.1 N along e2, vented"},
      {"Fzc", {0, 0, -0.8}, "tip force 0.8 N along -e3 (compression, a stance leg on Earth)"},
      {"Fzt", {0, 0, 1.0}, "tip force 1 N along +e3 (tension)"},
  };
  for (size_t k = 0; k < sizeof kTip / sizeof kTip[0]; k++) {
    if ((y = addRay(rays, &n, cap, kTip[k].name, CSF_ROM_TRAIN, kTip[k].about))) {
      memcpy(y->tip_force, kTip[k].F, sizeof y->tip_force);
    }
  }
  /* pressure and loads together */
  if ((y = addRay(rays, &n, cap, "O12Fc", CSF_ROM_TRAIN, "Omega1&Omega2 to 0.3 MPa with a tip "
                  "force (0.05, 0, -0.4) N (a bent stance leg)"))) {
    for (int s = 0; s < CSR_NSEG; s++) {
      segPattern(y, s, c12, 0.3);
    }
    y->tip_force[0] = 0.05, y->tip_force[2] = -0.4;
  }
  if ((y = addRay(rays, &n, cap, "SGy", CSF_ROM_TRAIN, "S-shape to 0.3 MPa under gravity "
                  "9.81 m/s^2 along -e2"))) {
    segPattern(y, 0, c34, 0.3), segPattern(y, 1, c12, 0.3);
    y->gravity[1] = -G_EARTH;
  }
  /* held out: never in the basis or the weights (issue 34: other per-segment patterns, the
   * calibration's held-out chamber combinations, tip loads with pressure and gravity) */
  static const double h4[4] = {1, 0.75, 0.375, 0.75}, h7[4] = {1, 0.3, 0.7, 0.2};
  if ((y = addRay(rays, &n, cap, "T_H4", CSF_ROM_TEST, "held out: the calibration's H4 (Omega1 "
                  "0.4 + Omega2, Omega4 0.3 + Omega3 0.15 MPa), every segment"))) {
    sameAll(y, h4);
  }
  if ((y = addRay(rays, &n, cap, "T_H7", CSF_ROM_TEST, "held out: the calibration's H7 (Omega1 "
                  "0.4 + Omega2 0.12 + Omega3 0.28 + Omega4 0.08 MPa), every segment"))) {
    sameAll(y, h7);
  }
  if ((y = addRay(rays, &n, cap, "T_S2", CSF_ROM_TEST, "held out: an unequal S (II1 0, 0.12, "
                  "0.4, 0.28; II2 0.4, 0.24, 0, 0.08; II3 0.1 Omega4 MPa)"))) {
    static const double a[4] = {0, 0.3, 1, 0.7}, b[4] = {1, 0.6, 0, 0.2}, c[4] = {0, 0, 0, 1};
    segPattern(y, 0, a, P_RAY), segPattern(y, 1, b, P_RAY), segPattern(y, 2, c, 0.1);
  }
  if ((y = addRay(rays, &n, cap, "T_R", CSF_ROM_TEST, "held out: random, every chamber uniform "
                  "in [0, 0.4] MPa (another draw of the same seed's stream)"))) {
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        y->p[s][j] = P_RAY * draw(&seed);
      }
    }
  }
  if ((y = addRay(rays, &n, cap, "T_O12GF", CSF_ROM_TEST, "held out: Omega1&Omega2 to 0.25 MPa, "
                  "gravity 9.81 m/s^2 along -e1, tip force (0.03, 0.02, -0.3) N"))) {
    for (int s = 0; s < CSR_NSEG; s++) {
      segPattern(y, s, c12, 0.25);
    }
    y->gravity[0] = -G_EARTH;
    y->tip_force[0] = 0.03, y->tip_force[1] = 0.02, y->tip_force[2] = -0.3;
  }
  /* sparse random rays, appended after the held-out ones so that every ray above keeps its
   * draw (session romacc): per segment a level uniform in [0.1, 0.4] MPa, each chamber vented
   * with probability 0.4, else uniform in [0, 1] of the level. They train what R1-R6 (every
   * chamber loaded) leave out: vented chambers squeezed between loaded ones, and segments
   * loaded lightly while their neighbours are loaded hard, independently per segment. */
  unsigned seed_sparse = RAND_SEED_SPARSE;
  for (int k = 0; k < 6; k++) {
    char name[16];
    snprintf(name, sizeof name, "RS%d", k + 1);
    if (!(y = addRay(rays, &n, cap, name, CSF_ROM_TRAIN, "sparse random: per segment a level "
                     "in [0.1, 0.4] MPa, each chamber vented (p 0.4) or uniform below it"))) {
      return n;
    }
    for (int s = 0; s < CSR_NSEG; s++) {
      const double level = 0.1 + (P_RAY - 0.1) * draw(&seed_sparse);
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        const double vent = draw(&seed_sparse), frac = draw(&seed_sparse);
        y->p[s][j] = vent < 0.4 ? 0.0 : level * frac;
      }
    }
  }
  /* squeezed-chamber rays SQ1-SQ6 (session rom10), appended after RS1-RS6 so that no earlier
   * ray changes: a deterministic family of what the random draws reached too seldom on the real
   * leg (docs/notes/rom.md, "The real leg's sparse random rays"): per segment a dominant chamber
   * k at the segment's level, the diagonally opposite chamber k+2 vented and squeezed as the
   * segment bends away from it, and the two flanks k+1, k+3 (each the neighbour of both) lightly
   * or unequally loaded; or a vented chamber between two loaded flanks. Patterns are ratios of
   * the level on a quarter grid, indexed from k around Ω1 -> Ω2 -> Ω3 -> Ω4 (cyclic; Ω1 and Ω3
   * diagonal, robot_actuator.h):
   *   A  (1, 3/4, 0, 1/4)  unequal flanks: the light flank between the vented and the full one
   *   A' (1, 1/4, 0, 3/4)  its mirror (the fibres' helix makes mirrors differ)
   *   B  (1, 1/4, 0, 1/4)  equal light flanks: the vented chamber squeezed between them
   *   C  (1, 1/4, 1, 0)    a vented chamber between two full ones, the fourth light
   * Adjacent segments' k differ (S- and Z-shapes; the basis' quarter turns add the leg's global
   * rotations, not these relative ones); SQ1-SQ3 a Latin square of A, A', B at 0.4 MPa, SQ4-SQ6
   * one of A, B, C with one segment at half the level. */
  enum { PAT_A, PAT_A2, PAT_B, PAT_C };
  static const double kSqPat[4][4] = {
      {1, 0.75, 0, 0.25}, {1, 0.25, 0, 0.75}, {1, 0.25, 0, 0.25}, {1, 0.25, 1, 0}};
  static const struct {
    const char* name;
    int pat[CSR_NSEG], k[CSR_NSEG]; /* k: the dominant chamber, 0-based (0 = Ω1) */
    double level[CSR_NSEG];        /* MPa */
  } kSq[] = {
      {"SQ1", {PAT_A, PAT_A2, PAT_B}, {0, 2, 1}, {P_RAY, P_RAY, P_RAY}},
      {"SQ2", {PAT_A2, PAT_B, PAT_A}, {1, 3, 0}, {P_RAY, P_RAY, P_RAY}},
      {"SQ3", {PAT_B, PAT_A, PAT_A2}, {2, 3, 1}, {P_RAY, P_RAY, P_RAY}},
      {"SQ4", {PAT_C, PAT_A, PAT_B}, {0, 1, 3}, {P_RAY, 0.5 * P_RAY, P_RAY}},
      {"SQ5", {PAT_A, PAT_B, PAT_C}, {3, 1, 2}, {P_RAY, P_RAY, 0.5 * P_RAY}},
      {"SQ6", {PAT_B, PAT_C, PAT_A}, {1, 2, 0}, {0.5 * P_RAY, P_RAY, P_RAY}},
  };
  for (size_t r = 0; r < sizeof kSq / sizeof kSq[0]; r++) {
    if (!(y = addRay(rays, &n, cap, kSq[r].name, CSF_ROM_TRAIN, "squeezed chambers: per segment "
                     "a dominant chamber, the opposite vented, the flanks light or unequal"))) {
      return n;
    }
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int i = 0; i < CSR_NCHAMBER; i++) {
        y->p[s][(kSq[r].k[s] + i) % CSR_NCHAMBER] = kSq[r].level[s] * kSqPat[kSq[r].pat[s]][i];
      }
    }
  }
  return n;
}


/* ---- set-up and one ray ------------------------------------------------------------------ */

csStatus csf_romSnapSetup(const csrActuator* act, const csfRomSnapSettings* s, csfActuatorFE* fe,
                          csfData** d, csError* err) {
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  for (int g = 0; g < CSR_NSEG; g++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      spec.ratio[g][j] = 1.0; /* every chamber's faces carry a pressure slot */
    }
  }
  spec.mesh_size = s->mesh_size;
  spec.mesh_symmetric = 1;
  spec.fibre_compression = !s->fibre_tension_only;
  spec.work_stem = s->work_stem;
  memset(fe, 0, sizeof *fe);
  csStatus st = csf_actuatorFECreate(act, &spec, fe, err);
  if (st != CS_OK) {
    return st;
  }
  fe->model->solver.max_threads = s->threads;
  *d = csf_dataCreate(fe->model, err);
  if (!*d) {
    csf_actuatorFEDestroy(fe);
    return err && err->status ? err->status : CS_ERR_MEMORY;
  }
  return CS_OK;
}


/* the loads of ray parameter t */
static void setLoads(csfActuatorFE* fe, const csfRomRay* ray, double t) {
  csfModel* m = fe->model;
  const csfMesh* me = fe->mesh;
  for (int f = 0; f < me->nface; f++) {
    const int tag = me->face_tag[f];
    m->face_p[f] = 0.0;
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        if (tag == CSF_TAG_CHAMBER(s, j + 1)) {
          m->face_p[f] = ray->p[s][j]; /* MPa per unit load factor t */
        }
      }
    }
  }
  const double F[3] = {t * ray->tip_force[0], t * ray->tip_force[1], t * ray->tip_force[2]};
  for (int i = 0; i < 3; i++) {
    m->gravity[i] = t * ray->gravity[i];
  }
  csf_actuatorSetTipForce(fe, F);
}


csStatus csf_romSnapRay(csfActuatorFE* fe, csfData* d, const double* s0, const csfRomRay* ray,
                        const csfRomSnapSettings* s, csfRomSnapSink sink, void* user,
                        csfRomSnapInfo* info, csError* err) {
  memset(info, 0, sizeof *info);
  const csfModel* m = fe->model;
  const size_t ns = csf_stateSize(m);
  double* buf = malloc(3 * ns * sizeof(double));
  if (!buf) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_snap: out of memory (3 x %zu values)", ns);
  }
  double *sc = buf, *sp = buf + ns, *st = buf + 2 * ns; /* converged, previous, trial */
  memcpy(sc, s0, ns * sizeof(double));
  memcpy(sp, s0, ns * sizeof(double));
  csf_stateSet(m, d, s0);
  csfNewtonOptions no = csf_newtonDefault();
  no.threads = s->threads;
  no.rtol = s->newton_rtol;
  no.max_iter = 40; /* slender body (fem_bend.c) */
  const double t0 = csf_wallTime();
  const double dout = 1.0 / ray->nout;
  double t = 0.0, dt = FIRST_REL * dout, dt_prev = 0.0;
  int kout = 1;
  csStatus rc = CS_OK;
  while (kout <= ray->nout) {
    if (s->cancel && *s->cancel) {
      rc = cs_errorSet(err, CS_ERR_INTERRUPTED, "fem_rom_snap: ray %s interrupted at t = %.4g",
                       ray->name, t);
      break;
    }
    const double target = kout * dout;
    double step = fmin(dt, target - t);
    if (target - (t + step) < 0.25 * step) {
      step = target - t; /* no sliver steps before an output (fem_bend.c CSF_BEND_SNAP) */
    }
    const double tn = t + step;
    setLoads(fe, ray, tn);
    /* secant predictor on the whole state, then Newton; a failed predicted start is retried
     * from the converged state before the step is cut */
    int it = 0, ok = 0;
    csError lerr;
    cs_errorClear(&lerr);
    for (int tryk = dt_prev > 0 ? 0 : 1; tryk < 2 && !ok; tryk++) {
      if (tryk == 0) {
        const double a = step / dt_prev;
        for (size_t i = 0; i < ns; i++) {
          st[i] = sc[i] + a * (sc[i] - sp[i]);
        }
        csf_stateSet(m, d, st);
      } else {
        csf_stateSet(m, d, sc);
      }
      int itk = 0;
      ok = csf_newtonSolve(m, d, tn, &no, &itk, &lerr) == CS_OK;
      it += itk;
    }
    info->newton += it;
    if (!ok) {
      info->cutbacks++;
      csf_stateSet(m, d, sc);
      dt = 0.5 * step;
      if (dt < s->dt_min) {
        snprintf(info->why, sizeof info->why, "no equilibrium beyond t = %.5g (step %.2g): %.200s",
                 t,
                 step, lerr.msg);
        setLoads(fe, ray, t);
        break;
      }
      continue;
    }
    memcpy(sp, sc, ns * sizeof(double));
    csf_stateGet(m, d, sc);
    info->steps++;
    if (s->progress) {
      s->progress(s->progress_user, ray->name, tn, it, csf_wallTime() - t0);
    }
    dt_prev = step;
    t = tn;
    info->t_end = t;
    dt = it <= GROW_ITERS ? 1.5 * step : it > SHRINK_ITERS ? 0.7 * step : step;
    dt = fmin(dt, dout);
    if (fabs(t - target) < 1e-12) {
      t = target;
      rc = sink(user, fe, d, t, err);
      if (rc != CS_OK) {
        break;
      }
      kout++;
    }
  }
  info->complete = rc == CS_OK && kout > ray->nout;
  info->wall = csf_wallTime() - t0;
  free(buf);
  return rc;
}


/* ---- files --------------------------------------------------------------------------------- */

static csStatus writeSettings(csH5File* f, const csfActuatorFE* fe, const csfRomSnapSettings* s,
                              csError* err) {
  csStatus st = cs_h5AttrDouble(f, "/", "fe_mesh_size_mm", s->mesh_size, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_mesh_symmetric", 1, err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "fe_fibre_law", csr_fibreLawName(s->fibre_tension_only), err);
  }
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_newton_rtol", s->newton_rtol, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "ndof", fe->model->ndof, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_n_tet10", fe->mesh->ntet, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_n_fibre_elements", fe->model->nfib, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "version", CSR_OUTPUT_VERSION, err);
  return st;
}


static csStatus writeInts(csH5File* f, const char* path, size_t n0, size_t n1, const int* v,
                          csError* err) {
  double* b = malloc(n0 * n1 * sizeof(double));
  if (!b) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_snap: out of memory (%s)", path);
  }
  for (size_t i = 0; i < n0 * n1; i++) {
    b[i] = v[i];
  }
  const size_t dims[2] = {n0, n1};
  csStatus st = cs_h5WriteDoubles(f, path, n1 > 1 ? 2 : 1, dims, b, err);
  free(b);
  return st;
}


csStatus csf_romMeshWrite(const csfActuatorFE* fe, const csfRomSnapSettings* s, const char* path,
                          csError* err) {
  const csfMesh* me = fe->mesh;
  const csfModel* m = fe->model;
  csH5File* f = cs_h5Create(path, err);
  if (!f) {
    return err->status;
  }
  csStatus st = cs_h5AttrString(f, "/", "format", CSF_ROM_MESH_FORMAT, err);
  if (st == CS_OK) st = writeSettings(f, fe, s, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "rho", m->mat.rho, err);
  const size_t dx[2] = {(size_t)me->nnode, 3};
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/x", 2, dx, me->x, err);
  if (st == CS_OK) st = writeInts(f, "/tet", (size_t)me->ntet, 10, me->tet, err);
  if (st == CS_OK) st = writeInts(f, "/face", (size_t)me->nface, 6, me->face, err);
  if (st == CS_OK) st = writeInts(f, "/face_tag", (size_t)me->nface, 1, me->face_tag, err);
  if (st == CS_OK) {
    double* fx = malloc((size_t)m->ndof * sizeof(double));
    if (!fx) {
      st = cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_snap: out of memory (fixed)");
    } else {
      for (int i = 0; i < m->ndof; i++) {
        fx[i] = m->fixed[i];
      }
      const size_t dn = (size_t)m->ndof;
      st = cs_h5WriteDoubles(f, "/fixed", 1, &dn, fx, err);
      if (st == CS_OK) st = cs_h5WriteDoubles(f, "/tip_unit", 1, &dn, fe->tip_unit, err);
      free(fx);
    }
  }
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "status", "complete", err);
  }
  csStatus cst = cs_h5CloseChecked(f, st == CS_OK ? err : NULL);
  return st != CS_OK ? st : cst;
}


/* the rows of one ray, gathered by the sink */
typedef struct Rows_ {
  const csrActuator* act;
  const csfRomRay* ray;
  int m, cap;
  size_t ndof;
  double* t;      /* (cap) */
  double* u;      /* (cap x ndof) */
  double* bend;   /* (cap x 3 x 2) */
  double* stretch, *tip; /* (cap x 3) */
  double* vol;    /* (cap x 3 x 4) */
} Rows;

void csf_romChamberVolumes(const csfMesh* me, const double* u, double vol[12]) {
  memset(vol, 0, 12 * sizeof(double));
  for (int f = 0; f < me->nface; f++) {
    const int tag = me->face_tag[f], s = tag / 10 - 11, j = tag % 10 - 1;
    if (tag < CSF_TAG_CHAMBER(0, 1) || s < 0 || s >= CSR_NSEG || j < 0 || j >= CSR_NCHAMBER) {
      continue;
    }
    double xf[18], fe1[18], vf;
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        const int q = 3 * me->face[6 * f + a] + i;
        xf[3 * a + i] = me->x[q] + u[q];
      }
    }
    csf_faceKernel(xf, 1.0, fe1, NULL, &vf);
    vol[4 * s + j] += vf;
  }
}

static csStatus sinkRows(void* user, const csfActuatorFE* fe, const csfData* d, double t,
                         csError* err) {
  Rows* r = user;
  if (r->m >= r->cap) {
    return cs_errorSet(err, CS_ERR_RANGE, "fem_rom_snap: more outputs than the ray's %d", r->cap);
  }
  const int k = r->m++;
  r->t[k] = t;
  memcpy(r->u + (size_t)k * r->ndof, d->u, r->ndof * sizeof(double));
  csfSegmentState seg[CSR_NSEG];
  double tip[3], Rtip[9];
  if (csf_segmentMeasure(r->act, fe->gauges, fe->model, d, seg, tip, Rtip) != 0) {
    return cs_errorSet(err, CS_ERR_RANGE, "fem_rom_snap: ray %s: degenerate face frame at t = %g",
                       r->ray->name, t);
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    r->bend[6 * k + 2 * s] = seg[s].bend[0];
    r->bend[6 * k + 2 * s + 1] = seg[s].bend[1];
    r->stretch[3 * k + s] = seg[s].stretch;
  }
  memcpy(r->tip + 3 * k, tip, 3 * sizeof(double));
  csf_romChamberVolumes(fe->mesh, d->u, r->vol + 12 * k);
  return CS_OK;
}

static csStatus writeRay(csH5File* f, const csfActuatorFE* fe, const csfRomRay* ray,
                         const csfRomSnapSettings* s, const Rows* r, const csfRomSnapInfo* info,
                         csError* err) {
  csStatus st = cs_h5AttrString(f, "/", "format", CSF_ROM_SNAP_FORMAT, err);
  if (st == CS_OK) st = writeSettings(f, fe, s, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "name", ray->name, err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "kind", ray->kind == CSF_ROM_TRAIN ? "train" : "test", err);
  }
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "about", ray->about, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "t_end", info->t_end, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "wall_time_s", info->wall, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "newton_iterations", (double)info->newton, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "steps", info->steps, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "cutbacks", info->cutbacks, err);
  const size_t d34[2] = {3, 4}, d3 = 3;
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/pressure_end", 2, d34, &ray->p[0][0], err);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/gravity_end", 1, &d3, ray->gravity, err);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/tip_force_end", 1, &d3, ray->tip_force, err);
  const size_t M = (size_t)r->m;
  if (M > 0) {
    double* lp = malloc(M * 18 * sizeof(double));
    if (!lp) {
      return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_snap: out of memory (loads)");
    }
    double *pr = lp, *gr = lp + 12 * M, *fr = lp + 15 * M;
    for (size_t k = 0; k < M; k++) {
      for (int q = 0; q < 12; q++) {
        pr[12 * k + q] = r->t[k] * (&ray->p[0][0])[q];
      }
      for (int i = 0; i < 3; i++) {
        gr[3 * k + i] = r->t[k] * ray->gravity[i];
        fr[3 * k + i] = r->t[k] * ray->tip_force[i];
      }
    }
    const size_t dt[1] = {M}, du[2] = {M, r->ndof}, dp[3] = {M, 3, 4}, d32[3] = {M, 3, 2},
                 dm3[2] = {M, 3};
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/t", 1, dt, r->t, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/u", 2, du, r->u, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/pressure", 3, dp, pr, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/gravity", 2, dm3, gr, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/tip_force", 2, dm3, fr, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/bend", 3, d32, r->bend, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/stretch", 2, dm3, r->stretch, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/tip", 2, dm3, r->tip, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/chamber_volume", 3, dp, r->vol, err);
    free(lp);
  }
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "status", info->complete ? "complete" : info->why, err);
  }
  return st;
}


csStatus csf_romSnapRun(csfActuatorFE* fe, csfData* d, const double* s0, const csrActuator* act,
                        const csfRomRay* ray, const csfRomSnapSettings* s, const char* path,
                        csfRomSnapInfo* info, csError* err) {
  Rows r;
  memset(&r, 0, sizeof r);
  r.act = act, r.ray = ray, r.cap = ray->nout, r.ndof = (size_t)fe->model->ndof;
  const size_t cap = (size_t)r.cap;
  double* mem = calloc(cap * (r.ndof + 1 + 6 + 3 + 3 + 12), sizeof(double));
  if (!mem) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_snap: out of memory (%d states of %zu dofs)",
                       r.cap, r.ndof);
  }
  r.u = mem, r.t = mem + cap * r.ndof, r.bend = r.t + cap, r.stretch = r.bend + 6 * cap;
  r.tip = r.stretch + 3 * cap, r.vol = r.tip + 3 * cap;
  csStatus st = csf_romSnapRay(fe, d, s0, ray, s, sinkRows, &r, info, err);
  if (st == CS_OK) {
    csH5File* f = cs_h5Create(path, err);
    if (!f) {
      st = err->status;
    } else {
      st = writeRay(f, fe, ray, s, &r, info, err);
      const csStatus cst = cs_h5CloseChecked(f, st == CS_OK ? err : NULL);
      st = st != CS_OK ? st : cst;
    }
  }
  free(mem);
  return st;
}


static int attrDouble(hid_t f, const char* name, double* v) {
  return H5Aexists(f, name) > 0 && H5LTget_attribute_double(f, "/", name, v) >= 0;
}

int csf_romSnapDone(const char* path, const csfRomRay* ray, const csfRomSnapSettings* s) {
  FILE* probe = fopen(path, "rb");
  if (!probe) {
    return 0;
  }
  fclose(probe);
  int ok = 0;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    double l = 0, rt = 0, te = 0;
    char fmt[64] = "", name[CSF_ROM_NAME_SIZE] = "";
    if (f >= 0) {
      hsize_t dims;
      H5T_class_t cls;
      size_t sz = 0;
      ok = H5LTget_attribute_info(f, "/", "format", &dims, &cls, &sz) >= 0 && sz < sizeof fmt &&
           H5LTget_attribute_string(f, "/", "format", fmt) >= 0 &&
           H5LTget_attribute_info(f, "/", "name", &dims, &cls, &sz) >= 0 && sz < sizeof name &&
           H5LTget_attribute_string(f, "/", "name", name) >= 0 &&
           attrDouble(f, "fe_mesh_size_mm", &l) && attrDouble(f, "fe_newton_rtol", &rt) &&
           attrDouble(f, "t_end", &te);
      ok = ok && !strcmp(fmt, CSF_ROM_SNAP_FORMAT) && !strcmp(name, ray->name) &&
           l == s->mesh_size && rt == s->newton_rtol;
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  return ok;
}


csStatus csf_romSnapRead(const char* path, csfRomSnapFile* s, csError* err) {
  memset(s, 0, sizeof *s);
  csStatus st = CS_OK;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hsize_t dims[3] = {0, 0, 0};
    H5T_class_t cls;
    size_t sz = 0;
    char kind[16] = "";
    if (f < 0) {
      st = cs_errorSet(err, CS_ERR_IO, "%s: cannot open the ray file", path);
    } else if (H5LTget_attribute_info(f, "/", "name", dims, &cls, &sz) < 0 ||
               sz >= sizeof s->ray.name ||
               H5LTget_attribute_string(f, "/", "name", s->ray.name) < 0 ||
               H5LTget_attribute_info(f, "/", "kind", dims, &cls, &sz) < 0 || sz >= sizeof kind ||
               H5LTget_attribute_string(f, "/", "kind", kind) < 0 ||
               H5LTget_dataset_info(f, "/t", dims, &cls, &sz) < 0 || dims[0] < 1 ||
               dims[0] > CSF_ROM_MAX_OUT) {
      st = cs_errorSet(err, CS_ERR_IO, "%s: not a finished ray file (name, kind, t of 1..%d rows)",
                       path, CSF_ROM_MAX_OUT);
    } else {
      s->m = (int)dims[0];
      s->ray.nout = s->m;
      s->ray.kind = strcmp(kind, "test") ? CSF_ROM_TRAIN : CSF_ROM_TEST;
      if (H5LTread_dataset_double(f, "/t", s->t) < 0 ||
          H5LTread_dataset_double(f, "/pressure_end", &s->ray.p[0][0]) < 0 ||
          H5LTread_dataset_double(f, "/gravity_end", s->ray.gravity) < 0 ||
          H5LTread_dataset_double(f, "/tip_force_end", s->ray.tip_force) < 0 ||
          H5LTread_dataset_double(f, "/bend", &s->bend[0][0][0]) < 0 ||
          H5LTread_dataset_double(f, "/tip", &s->tip[0][0]) < 0 ||
          H5LTread_dataset_double(f, "/chamber_volume", &s->vol[0][0]) < 0 ||
          !attrDouble(f, "wall_time_s", &s->wall) ||
          !attrDouble(f, "newton_iterations", &s->newton)) {
        st = cs_errorSet(err, CS_ERR_IO, "%s: a ray file without its loads or measurements", path);
      }
    }
    if (f >= 0) {
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  return st;
}
