/* cmd_rom_check.c: `crawlsim rom check` (cmd_rom.c holds the subcommand table): the reduced
 * model along the rays of a snapshot directory against the full FE's states, with its
 * checkpoints (cmd_rom_ckpt.c) and the reduced states (--states). */
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
#include "cmd_rom_common.h"
#include "cs_signal.h"
#include "fem_measure.h"
#include "fem_rom_act.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

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


int csx_cmdRomCheck(int argc, char** argv) {
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
      bad = !csx_romKnownRay(v) || csx_romPushValue("--ray", v, pick, &npick, CSF_ROM_MAX_RAYS);
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
