/* cmd_rom_snapshots.c: `crawlsim rom snapshots` (cmd_rom.c holds the subcommand table).
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
#include "cmd_rom_common.h"
#include "cs_signal.h"
#include "fem_measure.h"
#include "fem_rom_act.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

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

static void snapProgress(void* user, const char* ray, double t, int iters, double wall) {
  (void)user;
  fprintf(stderr, "  %s: t = %.4f, %d Newton iterations, %.0f s\n", ray, t, iters, wall);
}


int csx_cmdRomSnapshots(int argc, char** argv) {
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
      bad = !csx_romKnownRay(v) || csx_romPushValue("--ray", v, pick, &npick, CSF_ROM_MAX_RAYS);
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
