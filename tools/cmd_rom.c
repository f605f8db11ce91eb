/* cmd_rom.c: `crawlsim rom`: the reduced-order FE leg's offline stages (issue 34).
 *
 *   crawlsim rom snapshots [--out DIR] [--ray NAME]... [--list] [--actuator leg|...]
 *                          [--set NAME=VALUE]... [--mesh-size MM] [--newton-rtol R]
 *                          [--threads N]
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

#include "cmd_fe_threads.h"
#include "core_clock.h"
#include "cs_commands.h"
#include "cs_signal.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"

static const char kUsage[] =
    "usage: crawlsim rom snapshots [--out DIR] [--ray NAME]... [--list]\n"
    "                              [--actuator leg|baseline|fig1] [--set NAME=VALUE]...\n"
    "                              [--mesh-size MM] [--newton-rtol R] [--threads N]\n"
    "  snapshots: full-FE statics on the symmetric mesh along the built-in load rays (chamber\n"
    "  modes in every bending direction, patterns that differ per segment, random rays,\n"
    "  gravity in three directions, tip forces across and along the leg, pressure with loads;\n"
    "  the held-out rays T_* are for testing only), four states per ray, one file per ray in\n"
    "  DIR (default rom_snapshots/) and DIR/mesh.h5; finished rays are skipped (resumable);\n"
    "  with --ray the rays run in the order given.\n"
    "  --list prints the rays. Defaults: actuator leg, l_soft 4 mm, Newton's test 1e-6.\n";

enum { MAX_SETS = 32 };

static int parseNumber(const char* flag, const char* v, double lo, double hi, double* out) {
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


static int cmdSnapshots(int argc, char** argv) {
  csx_signalInstall();
  const char* dir = "rom_snapshots";
  const char* actname = "leg";
  const char* sets[MAX_SETS];
  const char* pick[CSF_ROM_MAX_RAYS];
  int nset = 0, npick = 0, list = 0, threads = 0;
  csfRomSnapSettings ss = csf_romSnapDefault();
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  for (int i = 1; i < argc; i++) {
    const char* a = argv[i];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      fputs(kUsage, stdout);
      return 0;
    }
    if (!strcmp(a, "--list")) {
      list = 1;
      continue;
    }
    if (i + 1 >= argc || a[0] != '-') {
      fprintf(stderr, a[0] == '-' ? "crawlsim rom: %s needs a value\n"
                                  : "crawlsim rom: unexpected argument '%s'\n", a);
      return 1;
    }
    const char* v = argv[++i];
    int bad = 0;
    if (!strcmp(a, "--threads")) {
      bad = csx_feParseThreads("rom", v, &threads);
    } else if (!strcmp(a, "--mesh-size")) {
      bad = parseNumber(a, v, 0.5, 20, &ss.mesh_size);
    } else if (!strcmp(a, "--newton-rtol")) {
      bad = parseNumber(a, v, 1e-12, 1e-3, &ss.newton_rtol);
    } else if (!strcmp(a, "--out")) {
      dir = v;
    } else if (!strcmp(a, "--actuator")) {
      actname = v;
    } else if (!strcmp(a, "--ray")) {
      int found = 0;
      for (int k = 0; k < nray; k++) {
        found |= !strcmp(rays[k].name, v);
      }
      if (!found) {
        fprintf(stderr, "crawlsim rom: --ray '%s': no such ray (see --list)\n", v);
        return 1;
      }
      if (npick == CSF_ROM_MAX_RAYS) {
        fprintf(stderr, "crawlsim rom: more than %d --ray options\n", CSF_ROM_MAX_RAYS);
        return 1;
      }
      pick[npick++] = v;
    } else if (!strcmp(a, "--set")) {
      if (nset == MAX_SETS) {
        fprintf(stderr, "crawlsim rom: more than %d --set options\n", MAX_SETS);
        return 1;
      }
      sets[nset++] = v;
    } else {
      fprintf(stderr, "crawlsim rom: unknown option '%s'\n", a);
      return 1;
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
  if (csr_actuatorPreset(&act, actname, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&act, sets[k], &err) != CS_OK) {
      fprintf(stderr, "crawlsim rom: %s\n", err.msg);
      return 1;
    }
  }
  if (csr_actuatorValidate(&act, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
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
  csx_fePlanThreads("rom", threads, &plan);
  ss.threads = plan.threads;
  char stem[620];
  snprintf(stem, sizeof stem, "%.500s/mesh", dir);
  ss.work_stem = stem;
  ss.cancel = csx_signalFlag();
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


int csx_cmdRom(int argc, char** argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  if (!strcmp(argv[1], "snapshots")) {
    return cmdSnapshots(argc - 1, argv + 1);
  }
  fprintf(stderr, "crawlsim rom: unknown stage '%s' (expected snapshots)\n", argv[1]);
  return 1;
}
