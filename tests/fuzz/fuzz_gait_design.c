/* fuzz_gait_design.c: fuzz harness of the gait design description reader (gaits_design.h,
 * csg_designRead) and, compiled with CSZ_DESIGN_BUILD, of all of `crawlsim gait design`: the
 * description's poses solved on the shipped calibration (robot/calibration_fe_leg.h5) and its
 * gait table built (robot_gaitdesign.h).
 *
 * Per input: the error contract (fuzz_common.h); a description the reader accepts must hold
 * what the header promises (poses and their sets within their arrays, `straight` first, moves
 * sorted by start, each naming legs A..H and an existing pose, the end after the last move).
 * With CSZ_DESIGN_BUILD: pose solving and table building follow the same error contract (their
 * messages name the description), and a table they build passes the gait reader's own rules
 * (csg_gaitValidate): a designed gait that `crawlsim run` would refuse is a wrong result.
 *
 * Two programs from one file because the build is ~1000 times slower than the reader (the
 * shipped map runs the analytic model's Newton solve per evaluation, and a pose takes a
 * bisection of them): the reader gets its 10^7 executions, the build what time allows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "gaits_csv.h"
#include "gaits_design.h"

#ifdef CSZ_DESIGN_BUILD
#include "robot_calibration.h"
#include "robot_gaitdesign.h"
#endif

/* the reader's limits (gaits_design.c) the accepted values must respect */
#define MAX_TIME_S 86400.0
#define MIN_SAMPLE_S 1e-3
#define MAX_SAMPLE_S 1.0

/* parsed once, read-only afterwards (test code) */
static csgDesign* g_design; /* ~60 KB: one buffer for every input */
#ifdef CSZ_DESIGN_BUILD
static csrActuator g_leg;
static csrCalibration* g_cal;
static csrDesignedPoses* g_poses;
#endif


int csz_harnessInit(void) {
  g_design = malloc(sizeof *g_design);
  if (!g_design || !csz_tempPath(0, ".gait")) {
    return 1;
  }
#ifdef CSZ_DESIGN_BUILD
  csError err;
  g_poses = malloc(sizeof *g_poses);
  if (!g_poses || csr_actuatorPreset(&g_leg, "leg", &err) != CS_OK) {
    return 1;
  }
  g_cal = csr_calibrationOpen(CS_SOURCE_DIR "/robot/calibration_fe_leg.h5", &g_leg, &err);
  if (!g_cal) {
    fprintf(stderr, "fuzz_gait_design_build: %s\n", err.msg);
    return 1;
  }
#endif
  return 0;
}


static int terminated(const char* s, size_t size) { return memchr(s, '\0', size) != NULL; }


static void checkDesign(const csgDesign* d) {
  if (d->npose < 1 || d->npose > CSG_DESIGN_MAX_POSES || strcmp(d->pose[0].name, "straight") ||
      d->pose[0].nset != 0) {
    csz_fail("accepted design: %d poses, first '%.32s'", d->npose, d->pose[0].name);
  }
  if (!terminated(d->name, sizeof d->name) || !d->name[0]) {
    csz_fail("accepted design: name empty or not terminated");
  }
  if (!(d->sample >= MIN_SAMPLE_S && d->sample <= MAX_SAMPLE_S) || d->mirror > 0xFFu) {
    csz_fail("accepted design: sample %g s, mirror %#x", d->sample, d->mirror);
  }
  for (int q = 0; q < d->npose; q++) {
    const csgDesignPose* po = &d->pose[q];
    if (!terminated(po->name, sizeof po->name) || po->nset < 0 || po->nset > CSG_DESIGN_MAX_SETS) {
      csz_fail("accepted design: pose %d has %d sets or an unterminated name", q, po->nset);
    }
    for (int s = 0; s < po->nset; s++) {
      const csgDesignSet* set = &po->set[s];
      if (set->kind < CSG_TARGET_PRESSURE || set->kind > CSG_TARGET_FOOT ||
          !isfinite(set->value) || !isfinite(set->value2)) {
        csz_fail("accepted design: pose %s set %d: kind %d, value %g", po->name, s,
                 (int)set->kind, set->value);
      }
      if (set->kind == CSG_TARGET_PRESSURE_OF && (set->ref <= 0 || set->ref >= q)) {
        csz_fail("accepted design: pose %s (%d) takes pressure-of pose %d", po->name, q,
                 set->ref);
      }
    }
  }
  if (d->nmove < 1 || d->nmove > CSG_DESIGN_MAX_MOVES) {
    csz_fail("accepted design: %d moves", d->nmove);
  }
  double t_last = 0;
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* m = &d->move[i];
    if (m->legs == 0 || m->legs > 0xFFu || m->pose < 0 || m->pose >= d->npose ||
        !(m->t0 >= 0) || !(m->duration >= 0) || !(m->t0 + m->duration <= MAX_TIME_S) ||
        (i > 0 && m->t0 < d->move[i - 1].t0)) {
      csz_fail("accepted design: move %d (line %d): legs %#x pose %d at %g for %g s", i, m->line,
               m->legs, m->pose, m->t0, m->duration);
    }
    t_last = fmax(t_last, m->t0 + m->duration);
  }
  if (d->end != 0 && !(d->end >= t_last - 1e-9 && d->end <= MAX_TIME_S)) {
    csz_fail("accepted design: end %g s, last move ends at %g s", d->end, t_last);
  }
}


#ifdef CSZ_DESIGN_BUILD
/* solve the poses and build the table; the status of the first step that fails */
static csStatus build(const csgDesign* d, const char* path, const uint8_t* data, size_t size,
                      csError* err) {
  csrBendMap map = csr_calibrationMap(g_cal);
  csrGaitDesignOptions opt = csr_defaultGaitDesignOptions();
  opt.stretch = d->nmove % 2; /* both kinematics, by the input's own parity */
  cs_errorClear(err);
  csStatus st = csr_designPoses(&g_leg, &map, d, &opt, g_poses, err);
  csz_checkError(st, st == CS_OK, err, path, data, size, CSZ_TEXT);
  if (st != CS_OK) {
    return st;
  }
  cs_errorClear(err);
  csgGait* g = csr_designGait(&g_leg, &map, d, &opt, g_poses, err);
  st = g ? CS_OK : err->status;
  csz_checkError(st, g != NULL, err, path, data, size, CSZ_TEXT);
  if (g) {
    csError e2;
    if (csg_gaitValidate(g, NULL, &e2) != CS_OK) {
      csz_fail("crawlsim gait design built a table the gait reader refuses: %s", e2.msg);
    }
    char text[4096];
    csr_designPosesFormat(d, g_poses, text, sizeof text);
    if (!memchr(text, '\0', sizeof text)) {
      csz_fail("pose summary not terminated");
    }
    csg_gaitDestroy(g);
  }
  return st;
}
#endif


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".gait");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csStatus st = csg_designRead(g_design, path, err);
  csz_checkError(st, st == CS_OK, err, path, data, size, CSZ_TEXT);
  if (st == CS_OK) {
    checkDesign(g_design);
#ifdef CSZ_DESIGN_BUILD
    st = build(g_design, path, data, size, err);
#endif
  }
  return st;
}
