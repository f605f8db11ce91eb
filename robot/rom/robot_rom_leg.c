/* robot_rom_leg.c: the reduced-order FE leg behind the leg interface (csr_leg_rom, robot_leg.h),
 * over robot_rom.h's dynamics and a leg file (robot_rom_file.h, `crawlsim rom leg-file`).
 *
 * What the eight legs share (sharedCreate): the file's mesh, FE model of the kernels and
 * reduced model, one csrRomModel (the inertia operators and K_r(0): the set-up's cost, paid
 * once), the sole's soft contact (one foot of the actuator's half side a against the terrain,
 * the law's defaults with the run's friction and stiffness scale, as the rod's foot), the
 * centreline's band operators and the gains' factor. Each leg owns its csrRomData.
 * Frames: the file's hip frame (the clamped face at z = 0, the leg along +z, the chambers in
 * x, y) is the leg frame of robot_leg.h (e1, e2, e3), so the hip's R is the leg frame as is.
 * Contact: at the sole only (the rod also has capsules along the leg: a rom leg's shin passes
 * through the terrain unseen). Interface gains: the leg's step of spec->h condensed on the hip,
 * its sole's contact in it (below); the level is coupled `stabilised` by default, the scheme
 * that solves the support's step with them (coupling_stabilised). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "fem_model.h"
#include "robot_leg.h"
#include "robot_rom.h"
#include "robot_rom_file.h"

#define ROM_NBAND 24 /* centreline bands along the leg */
#define ROM_TANGENT_LAG 1e-2 /* mm, csrRomParams.tangent_lag of the level's legs */

typedef struct RomShared_ {
  csrRomLegFile lf;
  csrRomModel* m;
  cscSoftModel* soft;     /* NULL without a terrain */
  double a;               /* the foot's half side, mm */
  double h;               /* the gains' step, s */
  double* Sl;             /* (n x n) Cholesky factor (lower) of M_r + h C + h² K_r(0) */
  double* S0;             /* (n x n) the same matrix, unfactored (the gains in contact add the
                             sole's contact to it) */
  /* the centreline: npt points in order of their reference z, each the mean of a band's nodes
   * (the hip: the clamped face's centroid; the foot: the sole's) */
  int npt;
  double zr[ROM_NBAND + 2];
  double Xp[(ROM_NBAND + 2) * 3];
  double* Up;             /* (npt x 3 x n) */
  double L;               /* mm, the leg's reference length (the sole's z) */
} RomShared;

struct csrLeg_ {
  const RomShared* sh;
  csrRomData* d;
  csrBaseState b_reset;
  double* x;              /* (state size) scratch */
  double* G, *Y;          /* (n x 6) gains' scratch */
  double* G0;             /* (n x 6) G before the contact's part */
  double* Sc;             /* (n x n) gains' scratch: S with the sole's contact, factored */
  double* Fz;             /* (nz) gains' scratch: the history advanced one step */
  double* Fc, *zd;        /* (n), (nz) contact scratch */
  cscSlotInfo* slot;      /* (nslot) */
  double* pts;            /* (npt x 3) centreline scratch */
};

/* Cholesky A = L Lᵀ in place (lower); 0 or the failing row + 1 */
static int cholesky(double* A, int n) {
  for (int j = 0; j < n; j++) {
    double s = A[(size_t)j * n + j];
    for (int k = 0; k < j; k++) {
      s -= A[(size_t)j * n + k] * A[(size_t)j * n + k];
    }
    if (!(s > 0)) {
      return j + 1;
    }
    const double l = sqrt(s);
    A[(size_t)j * n + j] = l;
    for (int i = j + 1; i < n; i++) {
      double t = A[(size_t)i * n + j];
      for (int k = 0; k < j; k++) {
        t -= A[(size_t)i * n + k] * A[(size_t)j * n + k];
      }
      A[(size_t)i * n + j] = t / l;
    }
  }
  return 0;
}

static void cholSolve(const double* L, int n, double* b) {
  for (int i = 0; i < n; i++) {
    double s = b[i];
    for (int k = 0; k < i; k++) {
      s -= L[(size_t)i * n + k] * b[k];
    }
    b[i] = s / L[(size_t)i * n + i];
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = b[i];
    for (int k = i + 1; k < n; k++) {
      s -= L[(size_t)k * n + i] * b[k];
    }
    b[i] = s / L[(size_t)i * n + i];
  }
}

static void sharedDestroyRom(void* p) {
  RomShared* sh = p;
  if (!sh) {
    return;
  }
  csr_romModelDestroy(sh->m);
  csc_softDestroy(sh->soft);
  csr_romLegFileFree(&sh->lf);
  free(sh->Sl), free(sh->S0), free(sh->Up);
  free(sh);
}

/* the centreline's points: the clamped face's centroid, the bands' node means, the sole's */
static csStatus buildBands(RomShared* sh, csError* err) {
  const csfMesh* me = sh->lf.mesh;
  const csfRom* rom = sh->lf.rom;
  const int n = rom->n;
  double L = 0;
  for (int a = 0; a < sh->lf.nsole; a++) {
    L = fmax(L, me->x[3 * sh->lf.sole[a] + 2]);
  }
  if (!(L > 0)) {
    return cs_errorSet(err, CS_ERR_IO, "rom leg: the sole is not at z > 0 in the leg file");
  }
  sh->L = L;
  sh->Up = calloc((size_t)(ROM_NBAND + 2) * 3 * n, sizeof(double));
  double cnt[ROM_NBAND + 2] = {0}, zs[ROM_NBAND + 2] = {0}, X[(ROM_NBAND + 2) * 3] = {0};
  if (!sh->Up) {
    return cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
  }
  /* slot 0: the clamped face (z = 0, no displacement); 1..NB: the bands; NB + 1: the sole */
  for (int i = 0; i < me->nnode; i++) {
    const double z = me->x[3 * i + 2];
    int b;
    if (sh->lf.model->fixed[3 * i]) {
      b = 0;
    } else {
      b = 1 + (int)floor(z / L * ROM_NBAND);
      b = b < 1 ? 1 : b > ROM_NBAND ? ROM_NBAND : b;
    }
    cnt[b] += 1, zs[b] += z;
    for (int k = 0; k < 3; k++) {
      X[3 * b + k] += me->x[3 * i + k];
      if (b > 0) {
        const double* Vr = rom->V + (size_t)(3 * i + k) * n;
        double* U = sh->Up + ((size_t)b * 3 + k) * n;
        for (int j = 0; j < n; j++) {
          U[j] += Vr[j];
        }
      }
    }
  }
  sh->npt = 0;
  for (int b = 0; b <= ROM_NBAND; b++) {
    if (cnt[b] == 0) {
      continue;
    }
    const int p = sh->npt++;
    sh->zr[p] = b == 0 ? 0.0 : zs[b] / cnt[b];
    for (int k = 0; k < 3; k++) {
      sh->Xp[3 * p + k] = X[3 * b + k] / cnt[b];
      const double* U = sh->Up + ((size_t)b * 3 + k) * n;
      double* Ud = sh->Up + ((size_t)p * 3 + k) * n;
      for (int j = 0; j < n; j++) {
        Ud[j] = U[j] / cnt[b];
      }
    }
  }
  /* the foot: the sole's centroid (the model's sole operators) */
  const int p = sh->npt++;
  sh->zr[p] = L;
  const csrRomModel* m = sh->m;
  for (int k = 0; k < 3; k++) {
    sh->Xp[3 * p + k] = m->contact ? m->Xs[k] : 0.0;
    double* Ud = sh->Up + ((size_t)p * 3 + k) * n;
    memset(Ud, 0, (size_t)n * sizeof(double));
  }
  if (!m->contact) { /* no sole operators: the sole's nodes' mean here */
    for (int a = 0; a < sh->lf.nsole; a++) {
      const int i = sh->lf.sole[a];
      for (int k = 0; k < 3; k++) {
        sh->Xp[3 * p + k] += me->x[3 * i + k] / sh->lf.nsole;
        const double* Vr = rom->V + (size_t)(3 * i + k) * n;
        double* Ud = sh->Up + ((size_t)p * 3 + k) * n;
        for (int j = 0; j < n; j++) {
          Ud[j] += Vr[j] / sh->lf.nsole;
        }
      }
    }
  } else {
    for (int k = 0; k < 3; k++) {
      memcpy(sh->Up + ((size_t)p * 3 + k) * n, m->Us + (size_t)k * n, (size_t)n * sizeof(double));
    }
  }
  return CS_OK;
}

static int sharedCreateRom(const csrLegSpec* spec, void** shared, csError* err) {
  *shared = NULL;
  if (!spec || !spec->act || !spec->params) {
    cs_errorSet(err, CS_ERR_ARG, "rom leg: NULL spec, actuator or parameters");
    return -1;
  }
  if (!spec->leg_file) {
    cs_errorSet(err, CS_ERR_ARG, "rom leg: no leg file (--rom-file LEG.h5, made by crawlsim rom "
                "leg-file)");
    return -1;
  }
  RomShared* sh = calloc(1, sizeof *sh);
  if (!sh) {
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    return -1;
  }
  if (csr_romLegFileRead(spec->leg_file, &sh->lf, err) != CS_OK ||
      csr_romLegFileCheckActuator(&sh->lf, spec->leg_file, spec->act, err) != CS_OK) {
    sharedDestroyRom(sh);
    return -1;
  }
  csrRomParams par = csr_romDefaultParams();
  par.rho = spec->act->rho;
  par.damping_time = spec->params->damping_time;
  /* in contact CVODE's Newton fails on the sole's law (touch-down of the sole points, the
   * bristle's stick-slip), not on K_r, and asks for a Jacobian after every failure: keep K_r
   * while the leg moved less than this (mm), its contact part fresh. On the real leg's landing
   * 12 of 77 Jacobians took a tangent, the same steps, a third less CPU (docs/notes/rom.md
   * "The rom leg's contact steps") */
  par.tangent_lag = ROM_TANGENT_LAG;
  double set[CSR_LEG_MAX_SETTINGS];
  csr_legSettingsRead(&csr_leg_rom, spec->settings, set);
  if (set[0] > 0) {
    par.rtol *= set[0];
    par.atol_u *= set[0];
    par.atol_wrench *= set[0];
  }
  if (!spec->weightless) {
    memcpy(par.gravity, spec->gravity, sizeof par.gravity);
  }
  sh->m = csr_romModelCreate(sh->lf.rom, &par, sh->lf.rom->face_ch, err);
  if (!sh->m) {
    sharedDestroyRom(sh);
    return -1;
  }
  sh->a = spec->act->a;
  if (spec->terrain) {
    cscSoftParams sp = csc_softDefaultParams();
    if (spec->contact) {
      sp.mu = spec->contact->mu;
      sp.k_area *= spec->contact->stiffness_scale;
    }
    const cscShape foot = csc_softFoot(sh->a);
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; /* the sole's frame at rest: the hip's */
    sh->soft = csc_softCreate(&sp, spec->terrain, 1, &foot, err);
    if (!sh->soft ||
        csr_romModelSetSole(sh->m, sh->soft, sh->lf.nsole, sh->lf.sole, I, err) != CS_OK) {
      sharedDestroyRom(sh);
      return -1;
    }
  }
  /* the gains' factor: M_r + h C + h² K_r(0), K_r(0) the reduced tangent at rest */
  const int n = sh->m->n;
  sh->h = spec->h > 0 ? spec->h : 1e-3;
  sh->Sl = malloc((size_t)n * n * sizeof(double));
  sh->S0 = malloc((size_t)n * n * sizeof(double));
  csfRomData* fd = csf_romDataCreate(sh->lf.rom, err);
  if (!sh->Sl || !sh->S0 || !fd) {
    if (fd) {
      cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    }
    csf_romDataDestroy(fd);
    sharedDestroyRom(sh);
    return -1;
  }
  csf_romDataReset(sh->lf.rom, fd);
  fd->sync = 1;
  const csfRomLoad ld0 = {NULL, {0, 0, 0}, NULL};
  const int rc = csf_romEvaluate(sh->lf.rom, fd, &ld0, 1);
  for (size_t i = 0; rc == 0 && i < (size_t)n * n; i++) {
    sh->Sl[i] = sh->m->Mr[i] + sh->h * sh->m->C[i] + sh->h * sh->h * fd->K[i];
  }
  csf_romDataDestroy(fd);
  memcpy(sh->S0, sh->Sl, (size_t)n * n * sizeof(double));
  if (rc != 0 || cholesky(sh->Sl, n) != 0) {
    cs_errorSet(err, CS_ERR_ARG, "%s: the reduced tangent at rest is not positive definite",
                spec->leg_file);
    sharedDestroyRom(sh);
    return -1;
  }
  if (buildBands(sh, err) != CS_OK) {
    sharedDestroyRom(sh);
    return -1;
  }
  *shared = sh;
  return 0;
}

static void destroyRom(csrLeg* leg) {
  if (!leg) {
    return;
  }
  csr_romDataDestroy(leg->d);
  free(leg->x), free(leg->G), free(leg->Y), free(leg->Fc), free(leg->zd), free(leg->slot);
  free(leg->G0);
  free(leg->Sc), free(leg->Fz);
  free(leg->pts);
  free(leg);
}

static csrLeg* createRom(const csrLegSpec* spec, csError* err) {
  if (!spec || !spec->shared) {
    cs_errorSet(err, CS_ERR_ARG, "rom leg: no shared model (sharedCreate first)");
    return NULL;
  }
  const RomShared* sh = spec->shared;
  csrLeg* leg = calloc(1, sizeof *leg);
  if (!leg) {
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    return NULL;
  }
  leg->sh = sh;
  const int n = sh->m->n, nz = sh->m->nz > 0 ? sh->m->nz : 1;
  const int nslot = sh->soft ? csc_softNSlot(sh->soft) : 1;
  leg->d = csr_romDataCreate(sh->m, err);
  leg->x = malloc((size_t)csr_romStateSize(sh->m) * sizeof(double));
  leg->G = malloc((size_t)n * 6 * sizeof(double));
  leg->Y = malloc((size_t)n * 6 * sizeof(double));
  leg->G0 = malloc((size_t)n * 6 * sizeof(double));
  leg->Sc = malloc((size_t)n * n * sizeof(double));
  leg->Fz = malloc((size_t)nz * sizeof(double));
  leg->Fc = malloc((size_t)n * sizeof(double));
  leg->zd = malloc((size_t)nz * sizeof(double));
  leg->slot = calloc((size_t)nslot, sizeof *leg->slot);
  leg->pts = malloc((size_t)sh->npt * 3 * sizeof(double));
  if (!leg->d || !leg->x || !leg->G || !leg->Y || !leg->Fc || !leg->zd || !leg->slot ||
      !leg->pts || !leg->Sc || !leg->Fz || !leg->G0) {
    if (leg->d) cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    destroyRom(leg);
    return NULL;
  }
  memset(&leg->b_reset, 0, sizeof leg->b_reset);
  memcpy(leg->b_reset.x, spec->hip, sizeof leg->b_reset.x);
  memcpy(leg->b_reset.R, spec->frame, sizeof leg->b_reset.R);
  csr_romReset(sh->m, leg->d, 0.0, &leg->b_reset);
  return leg;
}

static int stateSizeRom(const csrLeg* leg) { return csr_romStateSize(leg->sh->m); }

static void getStateRom(const csrLeg* leg, double* x) { csr_romGetState(leg->sh->m, leg->d, x); }

static int setStateRom(csrLeg* leg, const double* x) {
  return csr_romSetState(leg->sh->m, leg->d, x);
}

static void resetRom(csrLeg* leg) { csr_romReset(leg->sh->m, leg->d, 0.0, &leg->b_reset); }

static int actuateRom(csrLeg* leg, double t0, const double p0[12], double t1,
                      const double p1[12]) {
  csr_romActuate(leg->d, t0, p0, t1, p1);
  return 0;
}

/* The Jacobi schemes (sim_coupling.c) start a step at the support's actual state b0, which differs
 * from where the last step left the hip by ΔV in twist; the leg jumps with it rigidly (its state
 * in the hip frame unchanged), its momenta by M6 ΔV, which its wrench never hands the support
 * (robot_rom.h: balanced against the momenta at b0). The gains charge the support that rigid
 * jump in the step that made it (interfaceGainsRom), so nothing is carried from one advance to
 * the next. */
static int advanceRom(csrLeg* leg, double t, double H, const csrBaseState* b0,
                      const csrBaseState* b1, csrWrench* w, csError* err) {
  return csr_romAdvance(leg->sh->m, leg->d, t, H, b0, b1, w, err);
}

void csr_romLegStats(const csrLeg* leg, csrRomStats* s) { csr_romGetStats(leg->d, s); }

/* the hip state the data holds (the state vector's block after t and y) */
static const double* baseOf(const csrLeg* leg) {
  csr_romGetState(leg->sh->m, leg->d, leg->x);
  return leg->x + 1 + 2 * leg->sh->m->n;
}

/* s(q) = s0 + Tᵀ q (hip frame, t mm) */
static void firstMoment(const csrRomModel* m, const double* q, double s[3]) {
  for (int i = 0; i < 3; i++) {
    double a = m->s0[i];
    for (int k = 0; k < m->n; k++) {
      a += m->T[3 * k + i] * q[k];
    }
    s[i] = a;
  }
}

#define ROM_GAIN_DX 1e-5 /* mm: the contact's step matrix by central differences, the sole
                            moved by h ε = 1e-5 mm (ε = 1e-2 mm/s at h = 1 ms), below the law's
                            smoothing length d_onset 1e-3 mm */
#define ROM_GAIN_NZ 32   /* the longest sole history the gains advance (the foot's: 4) */

/* The sole's contact over one backward-Euler step of h, as seen by the sole's centre: a change
 * Δv of its velocity (world) held over the step changes the force on the leg by -A_c Δv, the
 * position moving by h Δv and the friction history by h Δz' (the law's own rate, so a sticking
 * bristle adds h k_t): A_c = h K_c + D_c (+ the bristle), by central differences
 * of the law at the current state, symmetrised and projected onto semi-definite matrices. Fills p, the sole's centre from the hip (world,
 * mm). Returns 0 when the sole feels nothing (out of contact, no terrain): A_c = 0. */
static int soleStepMatrix(const csrLeg* leg, const double* b, double Ac[9], double p[3]) {
  const RomShared* sh = leg->sh;
  const csrRomModel* m = sh->m;
  memset(Ac, 0, 9 * sizeof(double));
  if (!m->contact || m->nz > ROM_GAIN_NZ) {
    return 0;
  }
  const double* q = csr_romQ(leg->d);
  const double* qd = csr_romQdot(leg->d);
  const double* z = csr_romZ(leg->d);
  cscShapeLoad ld;
  double x0[3], zd0[ROM_GAIN_NZ];
  if (csr_romSoleLoad(m, b + 3, b, b + 12, b + 15, q, qd, z, leg->Fc, zd0, &ld, x0,
                      leg->slot) != 0) {
    return 0;
  }
  csu_sub3(p, x0, b);
  const double h = sh->h, e = ROM_GAIN_DX / h;
  int any = 0;
  for (int j = 0; j < 3; j++) {
    double fs[2][3];
    for (int side = 0; side < 2; side++) {
      const double sg = side ? -1.0 : 1.0;
      double xh[3], vh[3];
      csu_copy3(xh, b);
      csu_copy3(vh, b + 12);
      xh[j] += sg * h * e;
      vh[j] += sg * e;
      double zd[ROM_GAIN_NZ];
      if (csr_romSoleLoad(m, b + 3, xh, vh, b + 15, q, qd, z, leg->Fc, zd, &ld, x0,
                          leg->slot) != 0) {
        return 0;
      }
      for (int i = 0; i < m->nz; i++) {
        leg->Fz[i] = z[i] + h * (zd[i] - zd0[i]);
      }
      if (csr_romSoleLoad(m, b + 3, xh, vh, b + 15, q, qd, leg->Fz, leg->Fc, zd, &ld, x0,
                          leg->slot) != 0) {
        return 0;
      }
      csu_copy3(fs[side], ld.f0);
    }
    for (int i = 0; i < 3; i++) {
      Ac[3 * i + j] = -(fs[0][i] - fs[1][i]) / (2 * e);
      any |= Ac[3 * i + j] != 0;
    }
  }
  /* its symmetric part, projected onto positive semi-definite matrices (a bristle between
   * stick and slip, or advanced over a long h, can give a negative direction: passive gains,
   * as the stabilised scheme asks) */
  double w[3], V[9];
  csu_symEigen3(Ac, w, V);
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      double a = 0;
      for (int k = 0; k < 3; k++) {
        a += V[3 * i + k] * fmax(w[k], 0.0) * V[3 * j + k];
      }
      Ac[3 * i + j] = a;
    }
  }
  return any;
}

/* Interface gains: the leg's inertia, and in contact its sole's, condensed on the hip over one
 * backward-Euler step of h. A change ΔV = [Δv; Δω] (world) of the hip's twist over the step
 * drives the reduced coordinates through G = [T Rᵀ, E(q) Rᵀ] (E_k = e_k + Q_k q: robot_rom.h's
 * base-acceleration terms, impulse form) and moves the sole's centre p (from the hip) by
 * J_s ΔV + R Ū Δq', J_s = [1, -[p]×]; the sole's contact answers with -A_c times that
 * (soleStepMatrix). The leg's step, S Δq' = -G ΔV + h Ūᵀ Rᵀ Δf with S = M_r + h C + h² K_r(0):
 *   S' Δq' = -G' ΔV,  S' = S + h Ūᵀ Rᵀ A_c R Ū,  G' = G + h Ūᵀ Rᵀ A_c J_s,
 * and the support's impulse, the leg's momenta change M6 ΔV + Gᵀ Δq' (M6 the rigid spatial
 * inertia of the deformed leg about the hip; the same G carries q' into the momenta) less the
 * contact's impulse h J_sᵀ Δf, is -Z ΔV with
 *   Z = M6 + h J_sᵀ A_c J_s - G'ᵀ S'⁻¹ G'   (symmetric, positive semi-definite):
 * C = (Z + G0ᵀ S'⁻¹ G') / h (the flexible share added back: below), K = 0. Out of contact
 * (A_c = 0) Z is the inertia alone, M6 - Gᵀ S⁻¹ G (a free leg has no stiffness at its hip), and
 * C = M6 / h. Without the contact in them, a leg standing on its sole
 * hands the support an explicit stiffness that the light support's step cannot carry
 * (docs/notes/rom.md "Settling on rom legs"). Not in them: the sole's rotation (the
 * contact's couple on its tilt). */
static void interfaceGainsRom(const csrLeg* leg, double K[36], double C[36]) {
  const RomShared* sh = leg->sh;
  const csrRomModel* m = sh->m;
  const int n = m->n;
  const double h = sh->h;
  const double* b = baseOf(leg);
  const double* R = b + 3;
  const double* q = csr_romQ(leg->d);
  double* G = leg->G;
  double* Y = leg->Y;
  for (int k = 0; k < n; k++) {
    double E[3];
    for (int i = 0; i < 3; i++) {
      const double* Qi = m->Q + ((size_t)i * n + k) * n;
      double a = m->e[(size_t)i * n + k];
      for (int l = 0; l < n; l++) {
        a += Qi[l] * q[l];
      }
      E[i] = a;
    }
    for (int j = 0; j < 3; j++) {
      double gt = 0, ge = 0;
      for (int i = 0; i < 3; i++) {
        gt += m->T[3 * k + i] * R[3 * j + i];
        ge += E[i] * R[3 * j + i];
      }
      G[6 * k + j] = gt;
      G[6 * k + 3 + j] = ge;
    }
  }
  memcpy(leg->G0, G, (size_t)n * 6 * sizeof(double));
  /* the sole's contact, if it touches: S', G' and the rigid part h J_sᵀ A_c J_s */
  double Ac[9], p[3], Js[18], AJ[18], P[18], Zc[36];
  memset(Zc, 0, sizeof Zc);
  const double* Sf = sh->Sl;
  if (soleStepMatrix(leg, b, Ac, p)) {
    /* J_s = [1, -[p]x] (3 x 6) */
    const double px[9] = {0, -p[2], p[1], p[2], 0, -p[0], -p[1], p[0], 0};
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        Js[6 * i + j] = i == j;
        Js[6 * i + 3 + j] = -px[3 * i + j];
      }
    }
    /* AJ = A_c J_s (3 x 6); P = Rᵀ AJ; B = Rᵀ A_c R (hip frame) */
    double B[9], RtA[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 6; j++) {
        double a = 0;
        for (int l = 0; l < 3; l++) {
          a += Ac[3 * i + l] * Js[6 * l + j];
        }
        AJ[6 * i + j] = a;
      }
    }
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 6; j++) {
        double a = 0;
        for (int l = 0; l < 3; l++) {
          a += R[3 * l + i] * AJ[6 * l + j];
        }
        P[6 * i + j] = a;
      }
      for (int j = 0; j < 3; j++) {
        double a = 0;
        for (int l = 0; l < 3; l++) {
          a += R[3 * l + i] * Ac[3 * l + j];
        }
        RtA[3 * i + j] = a;
      }
    }
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        double a = 0;
        for (int l = 0; l < 3; l++) {
          a += RtA[3 * i + l] * R[3 * l + j];
        }
        B[3 * i + j] = a;
      }
    }
    for (int i = 0; i < 6; i++) {
      for (int j = 0; j < 6; j++) {
        double a = 0;
        for (int l = 0; l < 3; l++) {
          a += Js[6 * l + i] * AJ[6 * l + j];
        }
        Zc[6 * i + j] = h * a;
      }
    }
    /* S' = S + h Ūᵀ B Ū, G' = G + h Ūᵀ P (Ū: 3 x n, row i = m->Us + i n) */
    const double* U = m->Us;
    for (int k = 0; k < n; k++) {
      for (int l = 0; l < n; l++) {
        double a = 0;
        for (int i = 0; i < 3; i++) {
          double t = 0;
          for (int j = 0; j < 3; j++) {
            t += B[3 * i + j] * U[(size_t)j * n + l];
          }
          a += U[(size_t)i * n + k] * t;
        }
        leg->Sc[(size_t)k * n + l] = sh->S0[(size_t)k * n + l] + h * a;
      }
      for (int j = 0; j < 6; j++) {
        double a = 0;
        for (int i = 0; i < 3; i++) {
          a += U[(size_t)i * n + k] * P[6 * i + j];
        }
        G[6 * k + j] += h * a;
      }
    }
    if (cholesky(leg->Sc, n) == 0) {
      Sf = leg->Sc;
    } else { /* not passive: the contact left out, the inertia alone (as out of contact) */
      memset(Zc, 0, sizeof Zc);
      for (int k = 0; k < n; k++) {
        for (int j = 0; j < 6; j++) {
          double a = 0;
          for (int i = 0; i < 3; i++) {
            a += U[(size_t)i * n + k] * P[6 * i + j];
          }
          G[6 * k + j] -= h * a;
        }
      }
    }
  }
  double col[4096];
  double* c = n <= 4096 ? col : NULL;
  for (int j = 0; c && j < 6; j++) {
    for (int k = 0; k < n; k++) {
      c[k] = G[6 * k + j];
    }
    cholSolve(Sf, n, c);
    for (int k = 0; k < n; k++) {
      Y[6 * k + j] = c[k];
    }
  }
  /* M6: [[m 1, -[s]x], [[s]x, J]] about the hip, world */
  double s[3], sw[3];
  firstMoment(m, q, s);
  csu_mulMatVec3(sw, R, s);
  /* ∫ρ r_i r_j = J0_ij + 2 d_ijᵀ q + qᵀ S_ij q (hip frame; order 00 11 22 01 02 12) */
  static const int ii[6] = {0, 1, 2, 0, 0, 1}, jj[6] = {0, 1, 2, 1, 2, 2};
  double Jm[9];
  for (int p = 0; p < 6; p++) {
    double a = m->J0[p];
    const double* dp = m->d + (size_t)p * n;
    const double* Sp = m->S + (size_t)p * n * n;
    for (int k = 0; k < n; k++) {
      double t = 0;
      for (int l = 0; l < n; l++) {
        t += Sp[(size_t)k * n + l] * q[l];
      }
      a += 2 * dp[k] * q[k] + q[k] * t;
    }
    Jm[3 * ii[p] + jj[p]] = Jm[3 * jj[p] + ii[p]] = a;
  }
  const double tr = Jm[0] + Jm[4] + Jm[8];
  double Ih[9], RI[9], Iw[9], Rt[9];
  for (int i = 0; i < 9; i++) {
    Ih[i] = (i % 4 == 0 ? tr : 0.0) - Jm[i];
  }
  csu_mulMat3(RI, R, Ih);
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      Rt[3 * i + j] = R[3 * j + i];
    }
  }
  csu_mulMat3(Iw, RI, Rt);
  double Z[36];
  memset(Z, 0, sizeof Z);
  const double sx[9] = {0, -sw[2], sw[1], sw[2], 0, -sw[0], -sw[1], sw[0], 0};
  for (int i = 0; i < 3; i++) {
    Z[6 * i + i] = m->mass;
    for (int j = 0; j < 3; j++) {
      Z[6 * i + 3 + j] = -sx[3 * i + j];
      Z[6 * (3 + i) + j] = sx[3 * i + j];
      Z[6 * (3 + i) + 3 + j] = Iw[3 * i + j];
    }
  }
  /* What the leg does with ΔV is not what Z assumes: the Jacobi schemes never hand it the
   * response Δq' = -S'⁻¹ G' ΔV, it jumps rigidly with its hip at the next step's start (its
   * momenta by M6 ΔV; advanceRom). So the support is charged that jump: Z's flexible share
   * G0ᵀ S'⁻¹ G' (G0 without the contact's part, which is an impulse from the ground) is added
   * back, C h = Z + G0ᵀ S'⁻¹ G' = M6 + h J_sᵀ A_c J_s - (G' - G0)ᵀ S'⁻¹ G', unsymmetrised in
   * contact (the impulse, row for row), M6 out of contact (G' = G0): exact. Left out (Z alone),
   * that share is momentum created at every step (the robot fell at 1.075 g at H = 1 ms);
   * handed back explicitly a step late (the carry of branch romrun) it is an added-mass
   * feedback of ratio -share / (support + Z) per step, which the light support's yaw
   * (0.27 t mm², against 2.0 t mm² of the eight 34.8 g legs at their hips) amplified 1.3 times
   * a step, alternating, until the flat road's settling failed (docs/notes/rom.md "The rom
   * legs' settling under paper") */
  for (int i = 0; c && i < 36; i++) {
    Z[i] += Zc[i];
  }
  for (int i = 0; i < 36; i++) {
    K[i] = 0.0;
    C[i] = 0.5 * (Z[i] + Z[6 * (i % 6) + i / 6]) / h;
  }
  for (int i = 0; c && Sf != sh->Sl && i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double a = 0;
      for (int k = 0; k < n; k++) {
        a += (G[6 * k + i] - leg->G0[6 * k + i]) * Y[6 * k + j];
      }
      C[6 * i + j] -= a / h;
    }
  }
}

/* the sole's load at the current state (0 out of contact or without a terrain) */
static int soleNow(const csrLeg* leg, cscShapeLoad* ld, double x0[3]) {
  const RomShared* sh = leg->sh;
  if (!sh->m->contact) {
    return -1;
  }
  const double* b = baseOf(leg);
  return csr_romSoleLoad(sh->m, b + 3, b, b + 12, b + 15, csr_romQ(leg->d), csr_romQdot(leg->d),
                         csr_romZ(leg->d), leg->Fc, leg->zd, ld, x0, leg->slot);
}

static int contactShapesRom(const csrLeg* leg, csrContactShape* shapes, int max) {
  const RomShared* sh = leg->sh;
  const csrRomModel* m = sh->m;
  if (max < 1 || !m->contact) {
    return m->contact ? 1 : 0;
  }
  const int n = m->n;
  const double* b = baseOf(leg);
  const double* q = csr_romQ(leg->d);
  double xb[3], th[3], Rth[9], Rf[9], xw[3];
  for (int i = 0; i < 3; i++) {
    double a = m->Xs[i], c = 0;
    for (int k = 0; k < n; k++) {
      a += m->Us[(size_t)i * n + k] * q[k];
      c += m->Ws[(size_t)i * n + k] * q[k];
    }
    xb[i] = a, th[i] = c;
  }
  csu_rotVecToMat3(Rth, th);
  csu_mulMat3(Rf, b + 3, Rth);
  csu_mulMatVec3(xw, b + 3, xb);
  csrContactShape* c = &shapes[0];
  memset(c, 0, sizeof *c);
  c->kind = CSR_SHAPE_BOX;
  /* a thin box on the sole, 0.5 mm into the leg along its e3 */
  for (int k = 0; k < 3; k++) {
    c->a[k] = b[k] + xw[k] - 0.5 * Rf[3 * k + 2];
  }
  memcpy(c->R, Rf, sizeof c->R);
  c->half[0] = c->half[1] = sh->a;
  c->half[2] = 0.5;
  c->s = sh->L;
  return 1;
}

static void centerlineRom(const csrLeg* leg, int k, double* out) {
  const RomShared* sh = leg->sh;
  const int n = sh->m->n, np = sh->npt;
  const double* b = baseOf(leg);
  const double* q = csr_romQ(leg->d);
  for (int p = 0; p < np; p++) {
    double xl[3], xw[3];
    for (int i = 0; i < 3; i++) {
      const double* U = sh->Up + ((size_t)p * 3 + i) * n;
      double a = sh->Xp[3 * p + i];
      for (int j = 0; j < n; j++) {
        a += U[j] * q[j];
      }
      xl[i] = a;
    }
    csu_mulMatVec3(xw, b + 3, xl);
    for (int i = 0; i < 3; i++) {
      leg->pts[3 * p + i] = b[i] + xw[i];
    }
  }
  /* k points equally spaced in the reference arc length (the leg's z), linear between the
   * band points */
  int p = 0;
  for (int i = 0; i < k; i++) {
    const double z = k > 1 ? sh->L * i / (k - 1) : 0.0;
    while (p < np - 2 && sh->zr[p + 1] < z) {
      p++;
    }
    const double dz = sh->zr[p + 1] - sh->zr[p];
    const double u = dz > 0 ? fmin(1.0, fmax(0.0, (z - sh->zr[p]) / dz)) : 0.0;
    for (int j = 0; j < 3; j++) {
      out[3 * i + j] = (1 - u) * leg->pts[3 * p + j] + u * leg->pts[3 * (p + 1) + j];
    }
  }
}

static double massRom(const csrLeg* leg) { return leg->sh->m->mass; }

static void massMomentRom(const csrLeg* leg, double mx[3]) {
  const csrRomModel* m = leg->sh->m;
  const double* b = baseOf(leg);
  double s[3], sw[3];
  firstMoment(m, csr_romQ(leg->d), s);
  csu_mulMatVec3(sw, b + 3, s);
  for (int i = 0; i < 3; i++) {
    mx[i] = m->mass * b[i] + sw[i];
  }
}

static double contactDepthRom(const csrLeg* leg) {
  cscShapeLoad ld;
  double x0[3];
  if (soleNow(leg, &ld, x0) < 0) {
    return 0.0;
  }
  int first = 0, cnt = 0;
  csc_softShapeSlots(leg->sh->soft, 0, &first, &cnt);
  double depth = 0.0;
  for (int i = first; i < first + cnt; i++) {
    depth = fmax(depth, leg->slot[i].depth);
  }
  return depth;
}

static void contactForceRom(const csrLeg* leg, double f[3]) {
  cscShapeLoad ld;
  double x0[3];
  f[0] = f[1] = f[2] = 0.0;
  if (soleNow(leg, &ld, x0) < 0) {
    return;
  }
  csu_add3(f, ld.f0, ld.f1);
}

/* the level's own settings (robot_leg.h csrLegSetting) */
static const csrLegSetting kRomSettings[] = {
    /* every CVODE tolerance of the legs (rtol, atol_u, atol_wrench: csr_romDefaultParams) times
     * this; 0 or 1: those. The rod's knob of the same name and meaning (`--rod-tol`): the rom's
     * contact steps' cost falls with it (docs/notes/rom.md "C1 hip motion") */
    {"rod_tol", "times the shipped CVODE tolerances", 1, 0, 1000, 0},
};

const csrLegType csr_leg_rom = {
    .name = "rom",
    .in_world = 0,
    .settings = kRomSettings,
    .nsettings = (int)(sizeof kRomSettings / sizeof kRomSettings[0]),
    .needs_file = 1,
    .coupling_stabilised = 1,
    .create = createRom,
    .destroy = destroyRom,
    .sharedCreate = sharedCreateRom,
    .sharedDestroy = sharedDestroyRom,
    .stateSize = stateSizeRom,
    .getState = getStateRom,
    .setState = setStateRom,
    .reset = resetRom,
    .actuate = actuateRom,
    .advance = advanceRom,
    .interfaceGains = interfaceGainsRom,
    .contactShapes = contactShapesRom,
    .centerline = centerlineRom,
    .mass = massRom,
    .massMoment = massMomentRom,
    .contactDepth = contactDepthRom,
    .contactForce = contactForceRom,
};
