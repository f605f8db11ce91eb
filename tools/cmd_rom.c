/* cmd_rom.c: `crawlsim rom`: the reduced-order FE leg's offline stages (issue 34), each
 * subcommand (snapshots, check, ecsw-matrix) parsed from its own option table that also prints
 * its --help (cs_opts.h).
 *
 * snapshots: full-FE static solves on the symmetric mesh along the built-in load rays
 * (fem/fem_rom_snap.h: chamber modes, per-segment patterns, random rays, gravity, tip forces,
 * pressure with loads; training and held-out rays), one HDF5 file per ray in DIR (a finished
 * ray is skipped, so a stopped production resumes ray by ray) and DIR/mesh.h5 (what the offline
 * basis, tools/rom_basis.py, reads). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "cmd_fe_threads.h"
#include "core_math.h"
#include "core_clock.h"
#include "cs_commands.h"
#include "cs_opts.h"
#include "cmd_rom.h"
#include "cs_signal.h"
#include "fem_measure.h"
#include "fem_rom_act.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

/* `crawlsim rom` and `crawlsim rom --help`: the subcommands (each has its own --help) */
static const char kUsage[] =
    "usage: crawlsim rom <subcommand> [options]\n"
    "  snapshots    full-FE statics along the built-in load rays (the basis' training data)\n"
    "  check        the reduced model along the rays of a snapshot directory against the FE\n"
    "  ecsw-matrix  every element's reduced force at the basis' training snapshots (for\n"
    "               tools/rom_ecsw.py)\n"
    "  leg-file     one file with the reduced leg of a basis, for `crawlsim run --legs rom`\n"
    "  modes        the tangents of the FE and of the reduced model at a pressure (for\n"
    "               tools/rom_modes.py: the first eigenfrequencies)\n"
    "  sway         the foot's guided (sway) stiffness of the rod, the reduced model and the FE\n"
    "               under an axial load: the Earth stance's sway-buckling load\n"
    "Run 'crawlsim rom <subcommand> --help' for its options.\n";

static const csxOpt kSnapOpts[] = {
    {"--out", "DIR", "rom_snapshots",
     "the snapshot directory: one HDF5 file per ray and DIR/mesh.h5 (created if missing)"},
    {"--ray", "NAME", "every ray of --list, in its order",
     "run this ray (repeatable; the rays run in the order given, so a production can do the most "
     "useful first)"},
    {"--list", NULL, "off", "print the rays (name, train or test, what it loads) and exit"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
    {"--mesh-size", "MM", "4", "the FE mesh's characteristic length l_soft, in mm (0.5 .. 20)"},
    {"--newton-rtol", "R", "1e-6",
     "Newton's relative residual test of every static step (1e-12 .. 1e-3)"},
    {"--threads", "N", "this process's cores, less those other processes hold",
     "the FE's threads, an integer in 1..1024"},
};

static const csxOptTable kSnapTable = {
    "rom snapshots", "",
    "Full-FE statics on the symmetric mesh along the built-in load rays (chamber modes in every "
    "bending direction, patterns that differ per segment, random rays, gravity in three "
    "directions, tip forces across and along the leg, pressure with loads; the held-out rays T_* "
    "are for testing only), four states per ray, one HDF5 file per ray in DIR and DIR/mesh.h5 "
    "(what tools/rom_basis.py reads). Finished rays are skipped, so a stopped production resumes "
    "ray by ray.",
    kSnapOpts, CSX_NOPT(kSnapOpts), NULL};

static const csxOpt kCheckOpts[] = {
    {"--snapshots", "DIR", NULL, "the snapshot directory of crawlsim rom snapshots (required)"},
    {"--basis", "BASIS.h5", NULL,
     "the reduced basis of tools/rom_basis.py (required unless --leg-file)"},
    {"--leg-file", "LEG.h5", "none",
     "the reduced model of a leg file (crawlsim rom leg-file) instead of --basis: no gmsh and "
     "no chamber forms to compute; --weights then replace its sets' weights"},
    {"--weights", "W.h5", "none: every element (or the leg file's)",
     "the element weights of tools/rom_ecsw.py (the hyper-reduction)"},
    {"--ray", "NAME", "the held-out rays (kind test)",
     "check this ray (repeatable; one of crawlsim rom snapshots --list)"},
    {"--all", NULL, "off", "check every ray of DIR, training and held out"},
    {"--states", "DIR", "none",
     "write the reduced model's displacements u = V q of each ray to DIR/RAY.h5 (/u, /t: the "
     "snapshot files' layout, for tools that compare them with the FE's)"},
    {"--checkpoint", "DIR", "none",
     "after every state write the ray's progress to DIR/RAY.K.ckpt (K states; DIR is created): "
     "a check run again with the same DIR and model resumes each ray after its last state, and "
     "prints a finished one from it (not with --states)"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kCheckTable = {
    "rom check", "",
    "The reduced model (basis of tools/rom_basis.py, element weights of tools/rom_ecsw.py) along "
    "the rays of DIR against the full FE's states: each segment's bend (deg and %), the tip (mm), "
    "the chamber volumes (%), a line per state and per ray. Targets (issue 34): bends within 1 "
    "deg or 2 %, tip within 1 % of the leg length, volumes within 1 %. Exit 1 when no ray was "
    "checked.",
    kCheckOpts, CSX_NOPT(kCheckOpts), NULL};

static const csxOpt kEcswOpts[] = {
    {"--basis", "BASIS.h5", NULL,
     "the reduced basis of tools/rom_basis.py, with its training snapshots (required)"},
    {"--leg-file", "LEG.h5", "none: the model built from --basis (gmsh, the chamber forms)",
     "the model from this every-element leg file of the same basis (crawlsim rom leg-file "
     "--basis BASIS.h5): no gmsh, no chamber forms; the training snapshots still from --basis"},
    {"--out", "A.h5", NULL, "the matrices' file (required)"},
    {"--work", "DIR", ".", "where gmsh's files of the basis' mesh are written"},
    {"--stride", "K", "1",
     "every K-th training snapshot only (1 .. 64): the rows grow with the snapshots times the "
     "basis size, the matrices with the elements besides"},
    {"--only", "SET", "both: tet and fibre",
     "write this element set's matrices only (tet or fibre): a set's fit does not need the "
     "other's"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kEcswTable = {
    "rom ecsw-matrix", "",
    "Every element's reduced force at each training snapshot of the basis file (rows snapshot x "
    "coordinate, a column per element; one matrix for the Tet10s, /A_tet, one for the fibres, "
    "/A_fibre; the chambers' pressure loads are exact and not fitted), for tools/rom_ecsw.py's "
    "NNLS. A mixed basis (pressure modes P, m of them) adds to each snapshot's Tet10 rows the "
    "element's constraint share P_e (v_e - V_e), and /A_tet_pressure holds each Tet10's share of "
    "the pressure matrix, so that the weights keep the reduced pressures. A fibre strain basis "
    "(Qf, mf modes) adds to each snapshot's fibre rows the fibre's shares W_f Q_f E_f and W_f "
    "Q_f S(Ebar_f), and /A_fibre_projection holds each fibre's share of the projection matrix "
    "G = sum W_f Q_f Q_f^T (fem/fem_rom_fibre.h).",
    kEcswOpts, CSX_NOPT(kEcswOpts), NULL};


/* one more repeatable value (--set, --ray) into list[*n]; 1 after one error line when full */
int csx_romPushValue(const char* what, const char* v, const char** list, int* n, int max) {
  if (*n == max) {
    fprintf(stderr, "crawlsim rom: more than %d %s options\n", max, what);
    return 1;
  }
  list[(*n)++] = v;
  return 0;
}

/* is `name` one of the built-in rays? 1, or 0 after one error line */
static int knownRay(const char* name) {
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  for (int k = 0; k < nray; k++) {
    if (!strcmp(rays[k].name, name)) {
      return 1;
    }
  }
  fprintf(stderr, "crawlsim rom: --ray '%s': no such ray (see crawlsim rom snapshots --list)\n",
          name);
  return 0;
}

/* an operand where a subcommand takes none: one error line */
int csx_romUnexpected(const csxOptTable* t, const char* a) {
  fprintf(stderr, "crawlsim %s: unexpected argument '%.200s' (see crawlsim %s --help)\n", t->cmd,
          a, t->cmd);
  return 1;
}

int csx_romParseNumber(const char* flag, const char* v, double lo, double hi, double* out) {
  char* end;
  errno = 0;
  double x = strtod(v, &end);
  if (end == v || *end || errno || !isfinite(x) || x < lo || x > hi) {
    fprintf(stderr, "crawlsim rom: %s '%s' must be a number in [%g, %g]\n", flag, v, lo, hi);
    return 1;
  }
  *out = x;
  return 0;
}


/* the actuator (preset, then every --set) into *act; 1 after one error line */
int csx_romActuator(const char* name, const char* const* sets, int nset, int validate,
                    csrActuator* act) {
  csError err;
  cs_errorClear(&err);
  csStatus st = csr_actuatorPreset(act, name, &err);
  for (int k = 0; k < nset && st == CS_OK; k++) {
    st = csr_actuatorSetString(act, sets[k], &err);
  }
  if (st == CS_OK && validate) {
    st = csr_actuatorValidate(act, &err);
  }
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}


/* the reduced actuator on the snapshots' FE model (csf_romSnapSetup's: every chamber tagged,
 * the symmetric mesh of the basis' l_soft; gmsh's files under work/stem); 1 after one error
 * line */
int csx_romOpen(const char* actname, const char* const* sets, int nset, const char* basis,
                   const char* weights, const char* work, const char* stem_name,
                   csrActuator* act, csfRomActuator* ra) {
  if (csx_romActuator(actname, sets, nset, 0, act)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  const double l = csf_romBasisMeshSize(basis, &err);
  if (isnan(l)) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      spec.ratio[s][j] = 1.0;
    }
  }
  spec.mesh_size = l;
  spec.mesh_symmetric = 1;
  char stem[620];
  snprintf(stem, sizeof stem, "%.500s/%.60s", work, stem_name);
  spec.work_stem = stem;
  if (csf_romActuatorCreate(act, &spec, basis, weights, ra, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}


static void snapProgress(void* user, const char* ray, double t, int iters, double wall) {
  (void)user;
  fprintf(stderr, "  %s: t = %.4f, %d Newton iterations, %.0f s\n", ray, t, iters, wall);
}


static int cmdSnapshots(int argc, char** argv) {
  csx_signalInstall();
  const char* dir = "rom_snapshots";
  const char* actname = "leg";
  const char* sets[CSX_ROM_MAX_SETS];
  const char* pick[CSF_ROM_MAX_RAYS];
  int nset = 0, npick = 0, list = 0, threads = 0;
  csfRomSnapSettings ss = csf_romSnapDefault();
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kSnapTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kSnapTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kSnapTable, it.value);
    }
    const char* a = it.opt->name, *v = it.value;
    int bad = 0;
    if (csx_optIs(it.opt, "--list")) {
      list = 1;
    } else if (csx_optIs(it.opt, "--threads")) {
      csError terr;
      bad = csx_feParseThreads(v, &threads, &terr);
      if (bad) {
        fprintf(stderr, "crawlsim rom: %s\n", terr.msg);
      }
    } else if (csx_optIs(it.opt, "--mesh-size")) {
      bad = csx_romParseNumber(a, v, 0.5, 20, &ss.mesh_size);
    } else if (csx_optIs(it.opt, "--newton-rtol")) {
      bad = csx_romParseNumber(a, v, 1e-12, 1e-3, &ss.newton_rtol);
    } else if (csx_optIs(it.opt, "--out")) {
      dir = v;
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--ray")) {
      bad = !knownRay(v) || csx_romPushValue("--ray", v, pick, &npick, CSF_ROM_MAX_RAYS);
    } else if (csx_optIs(it.opt, "--set")) {
      bad = csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS);
    }
    if (bad) {
      return 1;
    }
  }
  if (list) {
    for (int k = 0; k < nray; k++) {
      const csfRomRay* y = rays + k;
      printf("%-10s %-5s  %s\n", y->name, y->kind == CSF_ROM_TRAIN ? "train" : "test", y->about);
    }
    return 0;
  }
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  if (csx_romActuator(actname, sets, nset, 1, &act)) {
    return 1;
  }
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "crawlsim rom: %s: cannot create the snapshot directory: %s\n", dir,
            strerror(errno));
    return 1;
  }
  /* which rays are still to run */
  int todo[CSF_ROM_MAX_RAYS], ntodo = 0;
  char path[CSF_ROM_MAX_RAYS][600];
  for (int k = 0; k < nray; k++) {
    snprintf(path[k], sizeof path[k], "%.500s/%.31s.h5", dir, rays[k].name);
  }
  /* the list's order, or the --ray options' order (a production runs the most useful first) */
  for (int q = 0; q < (npick ? npick : nray); q++) {
    int k = q;
    for (int j = 0; npick && j < nray; j++) {
      k = !strcmp(pick[q], rays[j].name) ? j : k;
    }
    int dup = 0;
    for (int j = 0; j < ntodo; j++) {
      dup |= todo[j] == k;
    }
    if (!dup && !csf_romSnapDone(path[k], rays + k, &ss)) {
      todo[ntodo++] = k;
    }
  }
  char mesh_path[600];
  snprintf(mesh_path, sizeof mesh_path, "%.500s/mesh.h5", dir);
  struct stat sb;
  const int have_mesh = stat(mesh_path, &sb) == 0;
  if (ntodo == 0 && have_mesh) {
    printf("crawlsim rom: every chosen ray is done in %s\n", dir);
    return 0;
  }
  csfThreadPlan plan;
  csx_fePlanThreads(stderr, "rom", threads, &plan);
  ss.threads = plan.threads;
  char stem[620];
  snprintf(stem, sizeof stem, "%.500s/mesh", dir);
  ss.work_stem = stem;
  ss.cancel = csx_signalFlag();
  ss.progress = snapProgress;
  const double t_all = csu_wallSeconds();
  csfActuatorFE fe;
  csfData* d = NULL;
  if (csf_romSnapSetup(&act, &ss, &fe, &d, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  fprintf(stderr, "crawlsim rom: %s, l_soft %g mm, symmetric mesh: %d Tet10, %d dofs, %d fibre "
          "elements (set-up %.1f s)\n", act.name, ss.mesh_size, fe.mesh->ntet, fe.model->ndof,
          fe.model->nfib, csu_wallSeconds() - t_all);
  const size_t ns = csf_stateSize(fe.model);
  double* s0 = malloc(ns * sizeof(double));
  int rc = 0;
  if (!s0) {
    fprintf(stderr, "crawlsim rom: out of memory (%zu values)\n", ns);
    rc = 1;
  } else {
    csf_stateGet(fe.model, d, s0);
  }
  if (rc == 0 && csf_romMeshWrite(&fe, &ss, mesh_path, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    rc = 1;
  }
  int ran = 0;
  for (int q = 0; q < ntodo && rc == 0; q++) {
    const csfRomRay* y = rays + todo[q];
    char part[620];
    snprintf(part, sizeof part, "%.590s.part", path[todo[q]]);
    csfRomSnapInfo info;
    if (csf_romSnapRun(&fe, d, s0, &act, y, &ss, part, &info, &err) != CS_OK) {
      fprintf(stderr, "crawlsim rom: ray %s: %s%s\n", y->name, err.msg,
              err.status == CS_ERR_INTERRUPTED ? " (run again to continue: finished rays are "
              "kept)" : "");
      remove(part);
      rc = err.status != CS_ERR_INTERRUPTED ? 1
           : csx_signalExitCode() ? csx_signalExitCode() : 130;
      break;
    }
    if (rename(part, path[todo[q]]) != 0) {
      fprintf(stderr, "crawlsim rom: %s: cannot rename to %s: %s\n", part, path[todo[q]],
              strerror(errno));
      rc = 1;
      break;
    }
    ran++;
    fprintf(stderr, "crawlsim rom: ray %s (%s): t = %.4g, %d steps, %d cut-backs, %ld Newton "
            "iterations, %.0f s%s%s -> %s\n", y->name, y->kind == CSF_ROM_TRAIN ? "train" : "test",
            info.t_end, info.steps, info.cutbacks, info.newton, info.wall,
            info.complete ? "" : ": ended early: ", info.why, path[todo[q]]);
  }
  printf("crawlsim rom: %d rays run of %d to do (%.0f s)\n", ran, ntodo,
         csu_wallSeconds() - t_all);
  free(s0);
  csf_dataDestroy(d);
  csf_actuatorFEDestroy(&fe);
  return rc;
}


/* one ray of the reduced model against the FE's file; returns the worst errors */
typedef struct CheckErr_ {
  double bend_deg, bend_rel, tip_mm, vol_rel, wall, cpu; /* cpu: the process's (clock()), s */
  long newton; /* reduced Newton iterations of the ray */
  int ok, failed;
} CheckErr;

/* the reduced states of a ray (rom check --states): /u (m x ndof, mm) and /t, as the
 * snapshot files */
static int writeStates(const char* dir, const csfRomSnapFile* sf, int m, size_t ndof,
                       const double* u) {
  char path[620];
  snprintf(path, sizeof path, "%.500s/%.31s.h5", dir, sf->ray.name);
  csError err;
  cs_errorClear(&err);
  csH5File* f = cs_h5Create(path, &err);
  if (!f) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  const size_t du[2] = {(size_t)m, ndof}, dt = (size_t)m;
  csStatus st = cs_h5AttrString(f, "/", "format", "crawlsim-rom-check-states 1", &err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "name", sf->ray.name, &err);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/u", 2, du, u, &err);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/t", 1, &dt, sf->t, &err);
  const csStatus sc = cs_h5CloseChecked(f, &err);
  if (st != CS_OK || sc != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}

/* the checkpoint's measurements from ce (ck->lines stays) and back */
static void ckptFromErr(const CheckErr* ce, int k, csxRomCkpt* ck) {
  ck->k = k, ck->ok = ce->ok;
  ck->bend_deg = ce->bend_deg, ck->bend_rel = ce->bend_rel, ck->tip_mm = ce->tip_mm;
  ck->vol_rel = ce->vol_rel, ck->wall = ce->wall, ck->cpu = ce->cpu, ck->newton = ce->newton;
}

/* one ray along its states; with ckdir (rom check --checkpoint) resumed after the ray's last
 * checkpoint there and a checkpoint written after every state (ck->lines the caller's buffer).
 * 1 after one error line (a checkpoint unreadable or unwritable), else 0 (a failed solve is
 * ce->failed) */
static int checkRay(csfRomActuator* ra, const csrActuator* act, const csfRomSnapFile* sf,
                    double L, double* states, const char* ckdir, const char* basis,
                    csxRomCkpt* ck, CheckErr* ce) {
  memset(ce, 0, sizeof *ce);
  csf_romDataReset(ra->rom, ra->d);
  memset(ra->p, 0, sizeof ra->p);
  memset(ra->gravity, 0, sizeof ra->gravity);
  memset(ra->tip_force, 0, sizeof ra->tip_force);
  memset(ra->q_conv, 0, (size_t)ra->rom->n * sizeof(double));
  ra->nhist = 0;
  ce->ok = 1;
  int k0 = 0;
  size_t used = 0;
  if (ckdir) {
    ck->lines[0] = '\0';
    const int got = csx_romCkptRead(ckdir, sf->ray.name, basis, sf->m, ra, ck);
    if (got < 0) {
      return 1;
    }
    if (got > 0) {
      k0 = ck->k;
      ce->ok = ck->ok;
      ce->bend_deg = ck->bend_deg, ce->bend_rel = ck->bend_rel, ce->tip_mm = ck->tip_mm;
      ce->vol_rel = ck->vol_rel, ce->wall = ck->wall, ce->cpu = ck->cpu;
      ce->newton = ck->newton;
      used = strlen(ck->lines);
      fputs(ck->lines, stdout);
    }
  }
  /* this run's share is added to what a checkpoint brought */
  const double t0 = csu_wallSeconds() - ce->wall;
  const double cpu0 = ce->cpu;
  const clock_t c0 = clock();
  const long it0 = ra->n_newton - ce->newton;
  for (int k = k0; k < sf->m; k++) {
    const double t = sf->t[k];
    double p[CSR_NSEG][CSR_NCHAMBER], g[3], F[3];
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        p[s][j] = t * sf->ray.p[s][j];
      }
    }
    for (int i = 0; i < 3; i++) {
      g[i] = t * sf->ray.gravity[i], F[i] = t * sf->ray.tip_force[i];
    }
    csError err;
    cs_errorClear(&err);
    if (csf_romActuatorSolve(ra, &p[0][0], g, F, &err) != CS_OK) {
      printf("  %-10s t %.3f: %s\n", sf->ray.name, t, err.msg);
      ce->failed = 1;
      ce->ok = 0;
      break;
    }
    const csfData v = csf_romActuatorView(ra);
    csfSegmentState seg[CSR_NSEG];
    double tip[3], Rtip[9], vol[12];
    csf_segmentMeasure(act, ra->fe.gauges, ra->fe.model, &v, seg, tip, Rtip);
    csf_romChamberVolumes(ra->fe.mesh, ra->u, vol);
    if (states) {
      const size_t nd = (size_t)ra->fe.model->ndof;
      memcpy(states + (size_t)k * nd, ra->u, nd * sizeof(double));
    }
    double eb[CSR_NSEG], rb[CSR_NSEG], vmax = 0;
    for (int s = 0; s < CSR_NSEG; s++) {
      const double* b = sf->bend[k][s];
      const double db = hypot(seg[s].bend[0] - b[0], seg[s].bend[1] - b[1]);
      eb[s] = db * 180.0 / CS_PI;
      rb[s] = db / fmax(hypot(b[0], b[1]), 1e-12);
      /* the target: within 1 deg or within 2 % */
      ce->ok &= eb[s] <= 1.0 || rb[s] <= 0.02;
      ce->bend_deg = fmax(ce->bend_deg, eb[s]);
      ce->bend_rel = fmax(ce->bend_rel, fmin(rb[s], 1e9));
    }
    int qw = 0; /* the worst chamber (segment qw / 4, chamber qw % 4) */
    for (int q = 0; q < 12; q++) {
      const double e = fabs(vol[q] / sf->vol[k][q] - 1.0);
      qw = e > vmax ? q : qw;
      vmax = fmax(vmax, e);
    }
    const double et = hypot(hypot(tip[0] - sf->tip[k][0], tip[1] - sf->tip[k][1]),
                            tip[2] - sf->tip[k][2]);
    ce->ok &= et <= 0.01 * L && vmax <= 0.01;
    ce->tip_mm = fmax(ce->tip_mm, et);
    ce->vol_rel = fmax(ce->vol_rel, vmax);
    /* the worst chamber's signed error, and its volume change's: a chamber that inflates
     * sixfold misses its volume by a sixth of the error of its volume change */
    const double v0 = ra->rom->nch > qw ? ra->rom->ch_V0[qw] : NAN;
    char line[400];
    snprintf(line, sizeof line, "  %-10s t %.3f: bend error %6.3f %6.3f %6.3f deg (%5.2f %5.2f "
             "%5.2f %%), tip %7.3f mm, volumes %5.2f %% (worst II%d Omega%d: %+.2f %%, V/V0 "
             "%.2f, its change %+.1f %%)\n", sf->ray.name, t, eb[0], eb[1], eb[2], 100 * rb[0],
             100 * rb[1], 100 * rb[2], et, 100 * vmax, qw / 4 + 1, qw % 4 + 1,
             100 * (vol[qw] / sf->vol[k][qw] - 1.0), sf->vol[k][qw] / v0,
             100 * (vol[qw] - sf->vol[k][qw]) / (sf->vol[k][qw] - v0));
    fputs(line, stdout);
    if (ckdir) {
      /* the next state starts from what the file holds: no kept tangent, no BFGS pairs */
      ra->d->lu_valid = 0;
      ra->d->bf_k = 0;
      const size_t len = strlen(line);
      if (used + len + 1 > ck->lines_cap) {
        fprintf(stderr, "crawlsim rom: check: ray %s has more state lines than %zu bytes\n",
                sf->ray.name, ck->lines_cap);
        return 1;
      }
      memcpy(ck->lines + used, line, len + 1);
      used += len;
      ce->wall = csu_wallSeconds() - t0;
      ce->cpu = cpu0 + (double)(clock() - c0) / CLOCKS_PER_SEC;
      ce->newton = ra->n_newton - it0;
      ckptFromErr(ce, k + 1, ck);
      fflush(stdout);
      if (csx_romCkptWrite(ckdir, sf->ray.name, basis, ra, ck)) {
        return 1;
      }
    }
  }
  ce->wall = csu_wallSeconds() - t0;
  ce->cpu = cpu0 + (double)(clock() - c0) / CLOCKS_PER_SEC;
  ce->newton = ra->n_newton - it0;
  return 0;
}

/* the reduced actuator from a leg file (as bend --model rom --rom-file), its weights replaced
 * by those of `weights` (may be NULL); 1 after one error line */
int csx_romOpenLegFile(const char* actname, const char* const* sets, int nset, const char* path,
                       const char* weights, csrActuator* act, csfRomActuator* ra,
                       double* l_soft) {
  if (csx_romActuator(actname, sets, nset, 0, act)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csrRomLegFile lf;
  csStatus st = csr_romLegFileRead(path, &lf, &err);
  if (st == CS_OK) {
    st = csr_romLegFileCheckActuator(&lf, path, act, &err);
  }
  if (st == CS_OK) {
    csfActuatorSpec spec = csf_actuatorSpecDefault();
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        spec.ratio[s][j] = 1.0;
      }
    }
    spec.mesh_size = lf.l_soft;
    spec.mesh_symmetric = 1;
    if (l_soft) {
      *l_soft = lf.l_soft;
    }
    csfMesh* me = lf.mesh;
    csfModel* m = lf.model;
    csfRom* rom = lf.rom;
    lf.mesh = NULL, lf.model = NULL, lf.rom = NULL; /* ra owns them from here */
    st = csf_romActuatorFromModel(act, &spec, me, m, rom, path, ra, &err);
    if (st == CS_OK && weights && (st = csf_romActuatorSetWeights(ra, weights, &err)) != CS_OK) {
      csf_romActuatorDestroy(ra);
    }
  }
  csr_romLegFileFree(&lf);
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}

static int cmdCheck(int argc, char** argv) {
  const char* dir = NULL, *basis = NULL, *weights = NULL, *actname = "leg", *sdir = NULL;
  const char* legf = NULL, *ckdir = NULL;
  const char* sets[CSX_ROM_MAX_SETS];
  const char* pick[CSF_ROM_MAX_RAYS];
  int nset = 0, npick = 0, all = 0;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kCheckTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kCheckTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kCheckTable, it.value);
    }
    const char* v = it.value;
    int bad = 0;
    if (csx_optIs(it.opt, "--all")) {
      all = 1;
    } else if (csx_optIs(it.opt, "--snapshots")) {
      dir = v;
    } else if (csx_optIs(it.opt, "--basis")) {
      basis = v;
    } else if (csx_optIs(it.opt, "--leg-file")) {
      legf = v;
    } else if (csx_optIs(it.opt, "--weights")) {
      weights = v;
    } else if (csx_optIs(it.opt, "--states")) {
      sdir = v;
    } else if (csx_optIs(it.opt, "--checkpoint")) {
      ckdir = v;
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--ray")) {
      bad = !knownRay(v) || csx_romPushValue("--ray", v, pick, &npick, CSF_ROM_MAX_RAYS);
    } else if (csx_optIs(it.opt, "--set")) {
      bad = csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS);
    }
    if (bad) {
      return 1;
    }
  }
  if (!dir || !basis == !legf) {
    fprintf(stderr, "crawlsim rom: check needs --snapshots DIR and --basis FILE (or --leg-file "
            "FILE instead of --basis)\n");
    return 1;
  }
  /* a resumed ray has not kept its earlier states' displacements */
  if (ckdir && sdir) {
    fprintf(stderr, "crawlsim rom: check: --checkpoint and --states together: a resumed ray has "
            "no displacements of its earlier states\n");
    return 1;
  }
  if (ckdir && mkdir(ckdir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "crawlsim rom: %s: cannot create the checkpoint directory: %s\n", ckdir,
            strerror(errno));
    return 1;
  }
  csrActuator act;
  csfRomActuator ra;
  const double t0 = csu_wallSeconds();
  if (legf ? csx_romOpenLegFile(actname, sets, nset, legf, weights, &act, &ra, NULL)
           : csx_romOpen(actname, sets, nset, basis, weights, dir, "check_mesh", &act, &ra)) {
    return 1;
  }
  basis = legf ? legf : basis;
  /* what a checkpoint must have been written for: the same file and weights */
  char model_id[1100];
  snprintf(model_id, sizeof model_id, "%.540s (weights %.540s)", basis, weights ? weights : "none");
  const double L = act.S[0] + act.S[1] + act.S[2] + act.LS[0] + act.LS[1];
  printf("crawlsim rom: check: basis %s (n = %d, m = %d pressure modes, mf = %d fibre strain "
         "modes), weights %s: %d of %d Tet10, %d of %d fibre elements, %d of %d faces (set-up "
         "%.1f s)\n", basis, ra.rom->n, ra.rom->m, ra.rom->mf, weights ? weights : "none",
         ra.rom->nel[CSF_ROM_SET_TET], ra.fe.mesh->ntet, ra.rom->nel[CSF_ROM_SET_FIBRE],
         ra.fe.model->nfib, ra.rom->nel[CSF_ROM_SET_FACE], ra.fe.mesh->nface,
         csu_wallSeconds() - t0);
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  int nrun = 0, nok = 0;
  double fe_wall = 0, rom_wall = 0;
  for (int k = 0; k < nray; k++) {
    int chosen = npick ? 0 : (all || rays[k].kind == CSF_ROM_TEST);
    for (int q = 0; q < npick; q++) {
      chosen |= !strcmp(pick[q], rays[k].name);
    }
    char path[620];
    snprintf(path, sizeof path, "%.500s/%.31s.h5", dir, rays[k].name);
    csfRomSnapFile sf;
    csError err;
    cs_errorClear(&err);
    if (!chosen || csf_romSnapRead(path, &sf, &err) != CS_OK) {
      continue; /* not chosen, or not produced (yet) */
    }
    CheckErr ce;
    const size_t nd = (size_t)ra.fe.model->ndof;
    double* states = sdir ? malloc((size_t)sf.m * nd * sizeof(double) + 1) : NULL;
    if (sdir && !states) {
      fprintf(stderr, "crawlsim rom: out of memory (the states of ray %s)\n", sf.ray.name);
      csf_romActuatorDestroy(&ra);
      return 1;
    }
    /* the state lines a checkpoint carries: at most 400 bytes each (checkRay's line) */
    csxRomCkpt ck = {0};
    ck.lines_cap = 400 * (size_t)sf.m + 1;
    ck.lines = ckdir ? malloc(ck.lines_cap) : NULL;
    if (ckdir && !ck.lines) {
      fprintf(stderr, "crawlsim rom: out of memory (the state lines of ray %s)\n", sf.ray.name);
      free(states);
      csf_romActuatorDestroy(&ra);
      return 1;
    }
    if (checkRay(&ra, &act, &sf, L, states, ckdir, model_id, &ck, &ce)) {
      free(ck.lines);
      free(states);
      csf_romActuatorDestroy(&ra);
      return 1;
    }
    free(ck.lines);
    if (states && !ce.failed && writeStates(sdir, &sf, sf.m, nd, states)) {
      free(states);
      csf_romActuatorDestroy(&ra);
      return 1;
    }
    free(states);
    nrun++;
    nok += ce.ok;
    fe_wall += sf.wall;
    rom_wall += ce.wall;
    printf("crawlsim rom: ray %-10s (%s): worst bend %.3g deg (%.3g %%), tip %.3g mm (%.3g %% of "
           "L), volumes %.3g %%: %s; reduced %.2f s (%ld Newton iterations, %.3g ms each; CPU "
           "%.2f s, %.3g ms each), FE %.0f s\n", sf.ray.name,
           sf.ray.kind == CSF_ROM_TEST ? "held out" : "trained", ce.bend_deg, 100 * ce.bend_rel,
           ce.tip_mm, 100 * ce.tip_mm / L, 100 * ce.vol_rel,
           ce.failed ? "FAILED to solve" : ce.ok ? "within the targets" : "outside the targets",
           ce.wall, ce.newton, ce.newton > 0 ? 1e3 * ce.wall / (double)ce.newton : NAN, ce.cpu,
           ce.newton > 0 ? 1e3 * ce.cpu / (double)ce.newton : NAN, sf.wall);
  }
  printf("crawlsim rom: %d rays checked, %d within the targets; reduced %.1f s against the FE's "
         "%.0f s (x%.0f; the FE's under its own run's load)\n", nrun, nok, rom_wall, fe_wall,
         rom_wall > 0 ? fe_wall / rom_wall : NAN);
  csf_romActuatorDestroy(&ra);
  return nrun > 0 ? 0 : 1;
}


/* a constant matrix's element shares, e.g. the pressure matrix sum_e (V_e / kappa) P_e P_e^T:
 * column e (of cols) holds the lower triangle of c_e B_e B_e^T, B_e row e of B (cols x m),
 * c_e = scale x[e] (y ? y[e] : 1), into dataset `name`; 0, or 1 after one error line */
static int writeOuterRows(csH5File* f, const char* name, int cols_i, int m, const double* B,
                          const double* x, const double* y, double scale) {
  const size_t rows = (size_t)m * (size_t)(m + 1) / 2, cols = (size_t)cols_i;
  double* A = malloc(rows * cols * sizeof(double) + 1);
  if (!A) {
    fprintf(stderr, "crawlsim rom: out of memory (%zu x %zu)\n", rows, cols);
    return 1;
  }
  for (size_t e = 0; e < cols; e++) {
    const double* Be = B + e * (size_t)m;
    const double c = scale * x[e] * (y ? y[e] : 1.0);
    size_t row = 0;
    for (int i = 0; i < m; i++) {
      for (int j = 0; j <= i; j++) {
        A[row++ * cols + e] = c * Be[i] * Be[j];
      }
    }
  }
  const size_t dims[2] = {rows, cols};
  csError err;
  cs_errorClear(&err);
  const int rc = cs_h5WriteDoubles(f, name, 2, dims, A, &err) != CS_OK;
  if (rc) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
  }
  free(A);
  return rc;
}

/* a leg file stands in for --basis's model only when it is that basis' model with every
 * element at weight 1 (each column is one element's force at the unreduced state): the sizes
 * and the bases V, P, Qf bit for bit, every Tet10 and fibre kept; 1 after one error line */
static int ecswLegFileMatches(const char* legf, const char* basis, const csfRomActuator* ra) {
  const csfRom* r = ra->rom;
  const int nt = ra->fe.mesh->ntet, nf = ra->fe.model->nfib;
  if (r->nel[CSF_ROM_SET_TET] != nt || r->nel[CSF_ROM_SET_FIBRE] != nf) {
    fprintf(stderr, "crawlsim rom: ecsw-matrix: %s keeps %d of %d Tet10 and %d of %d fibre "
            "elements: the matrices need its every-element model (rom leg-file without "
            "--weights)\n", legf, r->nel[CSF_ROM_SET_TET], nt, r->nel[CSF_ROM_SET_FIBRE], nf);
    return 1;
  }
  for (int e = 0; e < nt; e++) {
    if (r->w[CSF_ROM_SET_TET][e] != 1.0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: Tet10 %d has weight %.17g, not 1\n", legf,
              e, r->w[CSF_ROM_SET_TET][e]);
      return 1;
    }
  }
  for (int e = 0; e < nf; e++) {
    if (r->w[CSF_ROM_SET_FIBRE][e] != 1.0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: fibre element %d has weight %.17g, not 1\n",
              legf, e, r->w[CSF_ROM_SET_FIBRE][e]);
      return 1;
    }
  }
  const size_t nd = (size_t)ra->fe.model->ndof;
  const struct {
    const char* name;
    const double* x;
    size_t cnt;
  } mat[3] = {{"V", r->V, nd * (size_t)r->n},
              {"P", r->P, (size_t)nt * (size_t)r->m},
              {"Qf", r->Qf, (size_t)nf * (size_t)r->mf}};
  int rc = 0;
  H5E_BEGIN_TRY {
    const hid_t f = H5Fopen(basis, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: cannot open the basis file\n", basis);
      rc = 1;
    }
    for (int k = 0; k < 3 && rc == 0; k++) {
      if (mat[k].cnt == 0) {
        continue;
      }
      hsize_t dims[2] = {0, 0};
      H5T_class_t cls;
      size_t sz;
      double* x = NULL;
      if (H5LTfind_dataset(f, mat[k].name) <= 0 ||
          H5LTget_dataset_info(f, mat[k].name, dims, &cls, &sz) < 0 ||
          (size_t)dims[0] * (size_t)dims[1] != mat[k].cnt) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s is not the model of %s: no /%s of its "
                "size there\n", legf, basis, mat[k].name);
        rc = 1;
      } else if (!(x = malloc(mat[k].cnt * sizeof(double)))) {
        fprintf(stderr, "crawlsim rom: out of memory (/%s of %s)\n", mat[k].name, basis);
        rc = 1;
      } else if (H5LTread_dataset_double(f, mat[k].name, x) < 0) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: /%s unreadable\n", basis, mat[k].name);
        rc = 1;
      } else if (memcmp(x, mat[k].x, mat[k].cnt * sizeof(double)) != 0) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s is not the model of %s: its /%s differs\n",
                legf, basis, mat[k].name);
        rc = 1;
      }
      free(x);
    }
    if (f >= 0) {
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  return rc;
}

/* the element force matrices of the ECSW fit (tools/rom_ecsw.py) */
static int cmdEcswMatrix(int argc, char** argv) {
  const char* basis = NULL, *out = NULL, *work = ".", *actname = "leg", *legf = NULL;
  const char* sets[CSX_ROM_MAX_SETS];
  int nset = 0, stride = 1, only = -1;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kEcswTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kEcswTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kEcswTable, it.value);
    }
    const char* v = it.value;
    if (csx_optIs(it.opt, "--basis")) {
      basis = v;
    } else if (csx_optIs(it.opt, "--leg-file")) {
      legf = v;
    } else if (csx_optIs(it.opt, "--out")) {
      out = v;
    } else if (csx_optIs(it.opt, "--work")) {
      work = v;
    } else if (csx_optIs(it.opt, "--stride")) {
      double d;
      if (csx_romParseNumber("--stride", v, 1, 64, &d)) {
        return 1;
      }
      if (d != floor(d)) {
        fprintf(stderr, "crawlsim rom: --stride %s: not a whole number\n", v);
        return 1;
      }
      stride = (int)d;
    } else if (csx_optIs(it.opt, "--only")) {
      only = !strcmp(v, "tet") ? CSF_ROM_SET_TET : !strcmp(v, "fibre") ? CSF_ROM_SET_FIBRE : -2;
      if (only == -2) {
        fprintf(stderr, "crawlsim rom: --only '%s': expected tet or fibre\n", v);
        return 1;
      }
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--set") &&
               csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS)) {
      return 1;
    }
  }
  if (!basis || !out) {
    fprintf(stderr, "crawlsim rom: ecsw-matrix needs --basis FILE and --out FILE\n");
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  csfRomActuator ra;
  if (legf ? csx_romOpenLegFile(actname, sets, nset, legf, NULL, &act, &ra, NULL)
           : csx_romOpen(actname, sets, nset, basis, NULL, work, "ecsw_mesh", &act, &ra)) {
    return 1;
  }
  if (legf && ecswLegFileMatches(legf, basis, &ra)) {
    csf_romActuatorDestroy(&ra);
    return 1;
  }
  const int n = ra.rom->n;
  int ns = 0;
  double *q, *p, *g, *F;
  if (csf_romBasisReadTraining(basis, n, &ns, &q, &p, &g, &F, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    csf_romActuatorDestroy(&ra);
    return 1;
  }
  /* --stride: keep snapshots 0, K, 2K, ... (compacted in place) */
  const int ns_all = ns;
  ns = 0;
  for (int k = 0; k < ns_all; k += stride, ns++) {
    memmove(q + (size_t)ns * n, q + (size_t)k * n, (size_t)n * sizeof(double));
    memmove(p + 12 * (size_t)ns, p + 12 * (size_t)k, 12 * sizeof(double));
    memmove(g + 3 * (size_t)ns, g + 3 * (size_t)k, 3 * sizeof(double));
    memmove(F + 3 * (size_t)ns, F + 3 * (size_t)k, 3 * sizeof(double));
  }
  const int cnt[CSF_ROM_NSET] = {ra.fe.mesh->ntet, ra.fe.model->nfib, ra.fe.mesh->nface};
  static const char* const kName[CSF_ROM_NSET] = {"/A_tet", "/A_fibre", "/A_face"};
  csH5File* f = cs_h5Create(out, &err);
  int rc = f ? 0 : 1;
  /* the bodies and the fibres; the chambers' faces are in closed form (csf_romChamberTensors:
   * exact), so the face set is not fitted */
  for (int s = 0; s < CSF_ROM_SET_FACE && rc == 0; s++) {
    if (only >= 0 && s != only) {
      continue;
    }
    const int wd = csf_romElementForcesWidth(ra.rom, (csfRomSet)s);
    const size_t rows = (size_t)ns * (size_t)wd, cols = (size_t)cnt[s];
    double* A = malloc(rows * cols * sizeof(double));
    double* G = malloc(cols * (size_t)wd * sizeof(double));
    if (!A || !G) {
      fprintf(stderr, "crawlsim rom: out of memory (%zu x %zu)\n", rows, cols);
      rc = 1;
    }
    for (int k = 0; k < ns && rc == 0; k++) {
      memcpy(ra.d->q, q + (size_t)k * n, (size_t)n * sizeof(double));
      csfRomLoad ld;
      csf_romActuatorLoad(&ra, p + 12 * (size_t)k, g + 3 * (size_t)k, F + 3 * (size_t)k, &ld);
      if (csf_romElementForces(ra.rom, ra.d, &ld, (csfRomSet)s, G) != 0) {
        fprintf(stderr, "crawlsim rom: snapshot %d: an element inverts at its projection\n", k);
        rc = 1;
        break;
      }
      for (size_t e = 0; e < cols; e++) {
        for (int j = 0; j < wd; j++) {
          A[((size_t)k * wd + j) * cols + e] = G[e * (size_t)wd + j];
        }
      }
    }
    const size_t dims[2] = {rows, cols};
    if (rc == 0 && cs_h5WriteDoubles(f, kName[s], 2, dims, A, &err) != CS_OK) {
      fprintf(stderr, "crawlsim rom: %s\n", err.msg);
      rc = 1;
    }
    free(A), free(G);
  }
  /* the mixed model's pressure matrix A = sum_e w_e (V_e / kappa) P_e P_e^T, per element (its
   * lower triangle, mm^3/MPa; constant in q): weights fitted to it as well keep p^ = A^-1 b */
  const int mp = ra.rom->m;
  if (mp > 0 && rc == 0 && only != CSF_ROM_SET_FIBRE) {
    rc = writeOuterRows(f, "/A_tet_pressure", cnt[0], mp, ra.rom->P, ra.fe.model->vol, NULL,
                        1.0 / ra.fe.model->mat.kappa);
  }
  /* the fibre projection matrix G = sum_f W_f Q_f Q_f^T, per fibre (its lower triangle, N;
   * constant in q): weights fitted to it keep E^ and S* (fem/fem_rom_fibre.h) */
  const int mf = ra.rom->mf;
  if (mf > 0 && rc == 0 && only != CSF_ROM_SET_TET) {
    rc = writeOuterRows(f, "/A_fibre_projection", cnt[1], mf, ra.rom->Qf, ra.fe.model->fib_EA,
                        ra.fe.model->fib_L0, 1.0);
  }
  if (f) {
    cs_h5AttrDouble(f, "/", "m", mp, &err);
    cs_h5AttrDouble(f, "/", "mf", mf, &err);
    cs_h5AttrString(f, "/", "format", "crawlsim-rom-ecsw-matrix 1", &err);
    cs_h5AttrString(f, "/", "basis", basis, &err);
    cs_h5AttrDouble(f, "/", "n", n, &err);
    cs_h5AttrDouble(f, "/", "nsnap", ns, &err);
    cs_h5AttrDouble(f, "/", "stride", stride, &err);
    if (cs_h5CloseChecked(f, &err) != CS_OK && rc == 0) {
      fprintf(stderr, "crawlsim rom: %s\n", err.msg);
      rc = 1;
    }
  }
  if (rc == 0) {
    printf("crawlsim rom: ecsw-matrix: %d snapshots (of %d, stride %d) x %d coordinates (%d "
           "pressure modes, %d fibre strain modes) over %d Tet10 and %d fibre elements (%s) "
           "-> %s\n", ns, ns_all, stride, n, mp, mf, cnt[0], cnt[1],
           only < 0 ? "both sets" : only == 0 ? "the Tet10s only" : "the fibres only", out);
  }
  free(q), free(p), free(g), free(F);
  csf_romActuatorDestroy(&ra);
  return rc;
}


int csx_cmdRom(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "crawlsim rom: missing subcommand (snapshots, check, ecsw-matrix or modes; see "
            "crawlsim rom --help)\n");
    return 1;
  }
  if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(kUsage, stdout);
    return 0;
  }
  if (!strcmp(argv[1], "snapshots")) {
    return cmdSnapshots(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "check")) {
    return cmdCheck(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "ecsw-matrix")) {
    return cmdEcswMatrix(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "modes")) {
    return csx_cmdRomModes(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "leg-file")) {
    return csx_cmdRomLegFile(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "sway")) {
    return csx_cmdRomSway(argc - 1, argv + 1);
  }
  fprintf(stderr, "crawlsim rom: unknown stage '%.64s' (expected snapshots, check, ecsw-matrix, "
          "modes, leg-file or sway; "
          "see crawlsim rom --help)\n", argv[1]);
  return 1;
}
