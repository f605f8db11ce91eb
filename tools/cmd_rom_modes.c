/* cmd_rom_modes.c: `crawlsim rom modes`: the static tangents of the full FE and of the reduced
 * model of the same leg at a chamber pressure, for the eigenfrequency check of issue 34 (the
 * first four within 3 % of the FE's at 0 and 0.15 MPa).
 *
 * At each pressure p of --pressure (the chambers of --ray's pattern at p times their share of the
 * ray's largest pressure, no gravity, no tip force): the reduced statics (csf_romActuatorSolve)
 * and its tangent K_r = dr/dq at the converged dilatation and fibre states (sync: the exact
 * derivative, symmetric), then the FE's statics on the same mesh by the snapshots' adaptive ray
 * (csf_romSnapRay, one output state) and its assembled tangent K (CSR, the FE's pattern,
 * Dirichlet rows and columns identity; follower pressure stiffness included). The mass is not
 * needed here: tools/rom_modes.py assembles the FE's consistent mass from the snapshots' mesh
 * file (as tools/rom_basis.py does) and solves K phi = omega^2 M phi for both, the reduced one
 * with V^T M V. Units: K in N/mm, M in t, omega^2 in 1/s^2.
 * With --fd-check K the reduced tangent is checked at each level's equilibrium against central
 * differences of the reduced residual along K random unit directions v of q (|K v - (r(q + h v)
 * - r(q - h v)) / 2h| / |K v|, h = 1e-6 max(|q|, 0.01); |q| ~ 0.004 |u|_mm, V being
 * M-orthonormal with M in t): the tangent of the model as configured (a fibre basis, a pressure
 * basis, weights), at the state the eigenproblem uses; attribute fd_rel_err of /p<k>.
 * Output (format "crawlsim-rom-modes 1"): per level k, group /p<k> with attributes p_MPa,
 * fe_wall_s, rom_wall_s, fe_newton and datasets K_rom [n,n], q [n], u_fe [ndof], K_fe_val [nnz],
 * K_fe_row_ptr [ndof+1], K_fe_col [nnz]; root attributes n, m, ndof, nlevel, ray, basis. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_rom_common.h"
#include "core_clock.h"
#include "core_h5.h"
#include "cs_signal.h"
#include "fem_assembly.h"
#include "fem_rom_snap.h"

enum { MODES_MAX_LEVELS = 8 };

static const csxOpt kModesOpts[] = {
    {"--basis", "BASIS.h5", NULL, "the reduced basis of tools/rom_basis.py (required)"},
    {"--weights", "W.h5", "none: every element",
     "the element weights of tools/rom_ecsw.py (the hyper-reduction)"},
    {"--out", "MODES.h5", NULL, "the tangents' file, for tools/rom_modes.py (required)"},
    {"--ray", "NAME", "O12", "the pressure pattern (one of crawlsim rom snapshots --list)"},
    {"--pressure", "P", "0 and 0.15",
     "a pressure level in MPa, 0 .. 0.6 (repeatable, at most 8): the pattern's largest chamber "
     "pressure"},
    {"--rom-only", NULL, "off",
     "the reduced model's tangents alone (no FE solve: tools/rom_modes.py --fe takes the FE's "
     "from an earlier file of the same mesh and levels)"},
    {"--fd-check", "K", "0: none",
     "check the reduced tangent at each level against central differences of the reduced "
     "residual along K random directions (0 .. 64)"},
    {"--work", "DIR", ".", "where gmsh's files of the basis' mesh are written"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kModesTable = {
    "rom modes", "",
    "The static tangents of the full FE and of the reduced model at each pressure level of the "
    "ray's pattern (the FE solved on the basis' mesh by the snapshots' adaptive ray, the reduced "
    "model by its Newton), for tools/rom_modes.py's eigenfrequencies.",
    kModesOpts, CSX_NOPT(kModesOpts), NULL};

typedef struct ModesSink_ {
  int done;
} ModesSink;

static csStatus modesSink(void* user, const csfActuatorFE* fe, const csfData* d, double t,
                          csError* err) {
  (void)fe, (void)d, (void)t, (void)err;
  ((ModesSink*)user)->done = 1;
  return CS_OK;
}

/* write an int array as doubles (the HDF5 helpers write doubles) */
static csStatus writeIntsAsDoubles(csH5File* f, const char* path, size_t n, const int* v,
                                   csError* err) {
  double* b = malloc((n ? n : 1) * sizeof(double));
  if (!b) {
    return cs_errorSet(err, CS_ERR_MEMORY, "rom modes: out of memory (%zu values)", n);
  }
  for (size_t i = 0; i < n; i++) {
    b[i] = v[i];
  }
  const csStatus st = cs_h5WriteDoubles(f, path, 1, &n, b, err);
  free(b);
  return st;
}

/* The largest relative error over nfd random unit directions v of K v against central
 * differences of r (the reduced model at its current q with its load ld; d->K is K and stays).
 * -1 out of memory or when an evaluation fails. */
static double fdCheck(csfRomActuator* ra, const csfRomLoad* ld, int nfd) {
  csfRomData* d = ra->d;
  const int n = ra->rom->n;
  double* buf = malloc((size_t)n * 5 * sizeof(double));
  if (!buf) {
    return -1;
  }
  double* q0 = buf, *v = buf + n, *rp = buf + 2 * (size_t)n, *kv = buf + 3 * (size_t)n;
  double* r0 = buf + 4 * (size_t)n;
  memcpy(q0, d->q, (size_t)n * sizeof(double));
  memcpy(r0, d->r, (size_t)n * sizeof(double));
  double qn = 0;
  for (int i = 0; i < n; i++) {
    qn += q0[i] * q0[i];
  }
  const double h = 1e-6 * fmax(sqrt(qn), 0.01);
  unsigned long long s = 0x9E3779B97F4A7C15ull; /* a fixed LCG: the same directions every run */
  double worst = 0;
  const int sync = d->sync;
  d->sync = 1;
  for (int k = 0; k < nfd && worst >= 0; k++) {
    double vn = 0;
    for (int i = 0; i < n; i++) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      v[i] = (double)(s >> 11) / 9007199254740992.0 - 0.5;
      vn += v[i] * v[i];
    }
    double kn = 0;
    for (int i = 0; i < n; i++) {
      v[i] /= sqrt(vn);
    }
    for (int i = 0; i < n; i++) {
      double a = 0;
      for (int j = 0; j < n; j++) {
        a += d->K[(size_t)i * n + j] * v[j];
      }
      kv[i] = a;
      kn += a * a;
    }
    for (int i = 0; i < n; i++) {
      d->q[i] = q0[i] + h * v[i];
    }
    int ev = csf_romEvaluate(ra->rom, d, ld, 0);
    memcpy(rp, d->r, (size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) {
      d->q[i] = q0[i] - h * v[i];
    }
    ev = ev ? ev : csf_romEvaluate(ra->rom, d, ld, 0);
    double e = 0;
    for (int i = 0; i < n; i++) {
      const double fd = (rp[i] - d->r[i]) / (2 * h);
      e += (kv[i] - fd) * (kv[i] - fd);
    }
    worst = ev ? -1 : fmax(worst, sqrt(e / fmax(kn, 1e-300)));
  }
  memcpy(d->q, q0, (size_t)n * sizeof(double));
  memcpy(d->r, r0, (size_t)n * sizeof(double));
  d->sync = sync;
  free(buf);
  return worst;
}

/* one pressure level: the reduced and the FE tangents into group /p<k> of f */
static csStatus modesLevel(csfRomActuator* ra, const csfRomRay* pattern, double pmax, int k,
                           int rom_only, int nfd, csH5File* f, csError* err) {
  const int n = ra->rom->n;
  const csfModel* m = ra->fe.model;
  double scale = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      scale = fmax(scale, pattern->p[s][j]);
    }
  }
  csfRomRay ray = *pattern;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      ray.p[s][j] = scale > 0 ? pmax * pattern->p[s][j] / scale : 0.0;
    }
  }
  memset(ray.gravity, 0, sizeof ray.gravity);
  memset(ray.tip_force, 0, sizeof ray.tip_force);
  ray.nout = 1;
  /* the reduced statics from the unloaded state, then its exact tangent */
  csf_romDataReset(ra->rom, ra->d);
  memset(ra->p, 0, sizeof ra->p);
  memset(ra->gravity, 0, sizeof ra->gravity);
  memset(ra->tip_force, 0, sizeof ra->tip_force);
  memset(ra->q_conv, 0, (size_t)n * sizeof(double));
  const double g0[3] = {0, 0, 0};
  double t0 = csu_wallSeconds();
  csStatus st = csf_romActuatorSolve(ra, &ray.p[0][0], g0, g0, err);
  if (st != CS_OK) {
    return st;
  }
  csfRomLoad ld;
  csf_romActuatorLoad(ra, &ray.p[0][0], g0, g0, &ld);
  ra->d->sync = 1;
  const int ev = csf_romEvaluate(ra->rom, ra->d, &ld, 1);
  ra->d->sync = 0;
  if (ev != 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "rom modes: the reduced state at %g MPa is not "
                       "physical", pmax);
  }
  const double rom_wall = csu_wallSeconds() - t0;
  /* the check evaluates r only: K (written below) is the equilibrium's */
  const double fd_err = nfd > 0 ? fdCheck(ra, &ld, nfd) : 0.0;
  if (fd_err < 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "rom modes: --fd-check at %g MPa: an evaluation "
                       "failed (out of memory or an element inverted)", pmax);
  }
  if (nfd > 0) {
    printf("crawlsim rom: modes: %g MPa: |K v - central differences of r| / |K v| = %.2e "
           "(worst of %d directions)\n", pmax, fd_err, nfd);
  }
  const size_t dnn[2] = {(size_t)n, (size_t)n}, dn = (size_t)n;
  char g[32], path[64];
  snprintf(g, sizeof g, "/p%d", k);
  if (rom_only) {
    snprintf(path, sizeof path, "%s/K_rom", g);
    st = cs_h5WriteDoubles(f, path, 2, dnn, ra->d->K, err);
    snprintf(path, sizeof path, "%s/q", g);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, path, 1, &dn, ra->d->q, err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, g, "p_MPa", pmax, err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, g, "rom_wall_s", rom_wall, err);
    if (st == CS_OK && nfd > 0) st = cs_h5AttrDouble(f, g, "fd_rel_err", fd_err, err);
    if (st == CS_OK) {
      printf("crawlsim rom: modes: %g MPa: reduced statics and tangent %.2f s\n", pmax, rom_wall);
    }
    return st;
  }
  /* the FE's statics on the same model and its tangent */
  csfData* d = csf_dataCreate(m, err);
  if (!d) {
    return err->status ? err->status : CS_ERR_MEMORY;
  }
  const size_t ns = csf_stateSize(m);
  double* s0 = malloc(ns * sizeof(double));
  if (!s0) {
    csf_dataDestroy(d);
    return cs_errorSet(err, CS_ERR_MEMORY, "rom modes: out of memory (%zu values)", ns);
  }
  csf_stateGet(m, d, s0);
  csfRomSnapSettings ss = csf_romSnapDefault();
  ss.threads = 1;
  ss.cancel = csx_signalFlag();
  csfRomSnapInfo info = {0};
  t0 = csu_wallSeconds();
  if (pmax == 0) {
    /* unloaded: the chambers' pressure slots hold their unit pressure (csf_modelAddPressure),
     * which the assembly at load 1 would apply */
    for (int f = 0; f < ra->fe.mesh->nface; f++) {
      ra->fe.model->face_p[f] = 0.0;
    }
    for (int i = 0; i < 3; i++) {
      ra->fe.model->gravity[i] = 0.0;
    }
    csf_actuatorSetTipForce(&ra->fe, g0);
  } else {
    ModesSink sink = {0};
    st = csf_romSnapRay(&ra->fe, d, s0, &ray, &ss, modesSink, &sink, &info, err);
    if (st == CS_OK && !sink.done) {
      st = cs_errorSet(err, CS_ERR_DIVERGED, "rom modes: the FE did not reach %g MPa: %s", pmax,
                       info.why);
    }
  }
  if (st == CS_OK) {
    csf_dataSyncVolume(m, d); /* theta = v/V: K is the exact derivative of R */
    if (csf_assemble(m, d, 1.0, 1) != 0) {
      st = cs_errorSet(err, CS_ERR_DIVERGED, "rom modes: the FE state at %g MPa is not physical",
                       pmax);
    }
  }
  const double fe_wall = csu_wallSeconds() - t0;
  const size_t dd = (size_t)m->ndof, dz = (size_t)m->nnz;
  snprintf(path, sizeof path, "%s/K_rom", g);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, path, 2, dnn, ra->d->K, err);
  snprintf(path, sizeof path, "%s/q", g);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, path, 1, &dn, ra->d->q, err);
  snprintf(path, sizeof path, "%s/u_fe", g);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, path, 1, &dd, d->u, err);
  snprintf(path, sizeof path, "%s/K_fe_val", g);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, path, 1, &dz, d->kval, err);
  snprintf(path, sizeof path, "%s/K_fe_row_ptr", g);
  if (st == CS_OK) st = writeIntsAsDoubles(f, path, dd + 1, m->row_ptr, err);
  snprintf(path, sizeof path, "%s/K_fe_col", g);
  if (st == CS_OK) st = writeIntsAsDoubles(f, path, dz, m->col, err);
  /* the group exists once its datasets do (intermediate groups are created) */
  if (st == CS_OK) st = cs_h5AttrDouble(f, g, "p_MPa", pmax, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, g, "rom_wall_s", rom_wall, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, g, "fe_wall_s", fe_wall, err);
  if (st == CS_OK && nfd > 0) st = cs_h5AttrDouble(f, g, "fd_rel_err", fd_err, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, g, "fe_newton", (double)info.newton, err);
  if (st == CS_OK) {
    printf("crawlsim rom: modes: %g MPa: reduced statics and tangent %.2f s; FE %.0f s (%ld "
           "Newton iterations)\n", pmax, rom_wall, fe_wall, info.newton);
  }
  free(s0);
  csf_dataDestroy(d);
  return st;
}

int csx_cmdRomModes(int argc, char** argv) {
  csx_signalInstall();
  const char* basis = NULL, *weights = NULL, *out = NULL, *work = ".", *actname = "leg";
  const char* rayname = "O12";
  const char* sets[CSX_ROM_MAX_SETS];
  int nset = 0, np = 0, rom_only = 0;
  double nfd = 0;
  double plev[MODES_MAX_LEVELS];
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kModesTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kModesTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kModesTable, it.value);
    }
    const char* v = it.value;
    int bad = 0;
    if (csx_optIs(it.opt, "--basis")) {
      basis = v;
    } else if (csx_optIs(it.opt, "--weights")) {
      weights = v;
    } else if (csx_optIs(it.opt, "--out")) {
      out = v;
    } else if (csx_optIs(it.opt, "--work")) {
      work = v;
    } else if (csx_optIs(it.opt, "--rom-only")) {
      rom_only = 1;
    } else if (csx_optIs(it.opt, "--fd-check")) {
      bad = csx_romParseNumber("--fd-check", v, 0, 64, &nfd);
      if (!bad && nfd != floor(nfd)) {
        fprintf(stderr, "crawlsim rom: --fd-check '%s' must be a whole number\n", v);
        bad = 1;
      }
    } else if (csx_optIs(it.opt, "--ray")) {
      rayname = v;
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--pressure")) {
      if (np == MODES_MAX_LEVELS) {
        fprintf(stderr, "crawlsim rom: more than %d --pressure options\n", MODES_MAX_LEVELS);
        return 1;
      }
      bad = csx_romParseNumber("--pressure", v, 0.0, 0.6, &plev[np++]);
    } else if (csx_optIs(it.opt, "--set")) {
      bad = csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS);
    }
    if (bad) {
      return 1;
    }
  }
  if (!basis || !out) {
    fprintf(stderr, "crawlsim rom: modes needs --basis FILE and --out FILE\n");
    return 1;
  }
  if (np == 0) {
    plev[np++] = 0.0;
    plev[np++] = 0.15;
  }
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  const csfRomRay* pattern = NULL;
  for (int k = 0; k < nray; k++) {
    pattern = !strcmp(rays[k].name, rayname) ? rays + k : pattern;
  }
  if (!pattern) {
    fprintf(stderr, "crawlsim rom: --ray '%s': no such ray (see crawlsim rom snapshots --list)\n",
            rayname);
    return 1;
  }
  csrActuator act;
  csfRomActuator ra;
  if (csx_romOpen(actname, sets, nset, basis, weights, work, "modes_mesh", &act, &ra)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csH5File* f = cs_h5Create(out, &err);
  csStatus st = f ? CS_OK : err.status;
  for (int k = 0; k < np && st == CS_OK; k++) {
    st = modesLevel(&ra, pattern, plev[k], k, rom_only, (int)nfd, f, &err);
  }
  if (f) {
    if (st == CS_OK) st = cs_h5AttrString(f, "/", "format", "crawlsim-rom-modes 1", &err);
    if (st == CS_OK) st = cs_h5AttrString(f, "/", "ray", rayname, &err);
    if (st == CS_OK) st = cs_h5AttrString(f, "/", "basis", basis, &err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "n", ra.rom->n, &err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "m", ra.rom->m, &err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "ndof", ra.fe.model->ndof, &err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "nlevel", np, &err);
    const csStatus sc = cs_h5CloseChecked(f, &err);
    st = st == CS_OK ? sc : st;
  }
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: modes: %s\n", err.msg);
  } else {
    printf("crawlsim rom: modes: %d levels -> %s (tools/rom_modes.py reads it)\n", np, out);
  }
  csf_romActuatorDestroy(&ra);
  return st == CS_OK ? 0 : 1;
}
