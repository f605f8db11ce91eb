/* fuzz_levels.c: fuzz harness of the leg-level table of `--legs auto` (robot_levels.h,
 * csr_levelTableRead and the pick).
 *
 * Per input: read it and check the error contract (fuzz_common.h); a table the reader accepts
 * must hold what the header promises (1..CSR_LEVELS_MAX_ROWS rows; each a non-empty scene word
 * and a registered level, NUL-terminated; links 1..64, macro steps 1..100000, 0 < dt <= 0.01,
 * 0 < rod_tol <= 1000, step_order 0..2, 0 <= step_tol_mm <= 100 and > 0 only on a tree-stepped
 * level, finite error >= 0, whole_run -1, 0 or 1, finite costs > 0, a line number within the
 * input; no configuration twice), and the pick must keep its promise for the first row's
 * scene at three tolerances (below, at and above the row's error) and each step kind (any,
 * fixed, adaptive): a picked row is of that scene and kind, within the tolerance, its whole
 * run not failing (whole_run 0), and no such row of the scene and kind within it is cheaper; a
 * refusal names the file. */
#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "robot_leg.h"
#include "robot_levels.h"

static csrLevelTable g_t; /* large: not on the stack */


int csz_harnessInit(void) {
  return csz_tempPath(0, ".csv") ? 0 : 1;
}


static void checkRow(const csrLevelRow* r, size_t size) {
  if (!memchr(r->scene, '\0', sizeof r->scene) || !r->scene[0] ||
      !memchr(r->level, '\0', sizeof r->level) || !csr_legTypeFind(r->level, NULL)) {
    csz_fail("accepted row: scene or level not a terminated name of a registered level");
  }
  if (r->links < 1 || r->links > 64 || r->macro_steps < 1 || r->macro_steps > 100000 ||
      !(r->dt_s > 0 && r->dt_s <= 0.01) || !(r->rod_tol > 0 && r->rod_tol <= 1000) ||
      r->step_order < 0 || r->step_order > 2 || !(r->step_tol_mm >= 0 && r->step_tol_mm <= 100) ||
      (r->step_tol_mm > 0 && !csr_legTypeFind(r->level, NULL)->prepare) ||
      !(r->error_mm >= 0) || !isfinite(r->error_mm) || r->whole_run < -1 || r->whole_run > 1 ||
      !(r->cpu_s_per_s > 0) || !isfinite(r->cpu_s_per_s) || !(r->wall_s_per_s > 0) ||
      !isfinite(r->wall_s_per_s)) {
    csz_fail("accepted row of line %d: a value out of range", r->line);
  }
  if (r->line < 1 || (size_t)r->line > size + 1) {
    csz_fail("accepted row: line %d outside the input", r->line);
  }
}


/* is row r of kind k (robot_levels.h csrStepKind)? */
static int ofKind(const csrLevelRow* r, csrStepKind k) {
  return k == CSR_STEP_ANY || (k == CSR_STEP_ADAPTIVE) == (r->step_tol_mm > 0);
}


static void checkPick(const char* path, double tol, csrStepKind kind) {
  const char* scene = g_t.row[0].scene;
  csError err;
  cs_errorClear(&err);
  int k = csr_levelTablePickStep(&g_t, scene, tol, kind, &err);
  if (k < 0) {
    if (!err.msg[0] || strstr(err.msg, path) != err.msg) {
      csz_fail("pick refused without naming the file: '%s'", err.msg);
    }
    for (int i = 0; i < g_t.nrow; i++) {
      if (!strcmp(g_t.row[i].scene, scene) && ofKind(&g_t.row[i], kind) &&
          g_t.row[i].error_mm <= tol && g_t.row[i].whole_run != 0) {
        csz_fail("pick refused --tol %g though line %d meets it", tol, g_t.row[i].line);
      }
    }
    return;
  }
  const csrLevelRow* p = &g_t.row[k];
  if (strcmp(p->scene, scene) || !ofKind(p, kind) || !(p->error_mm <= tol) ||
      p->whole_run == 0) {
    csz_fail("picked line %d is of another scene or step kind, beyond --tol %g or failing its "
             "whole run", p->line, tol);
  }
  for (int i = 0; i < g_t.nrow; i++) {
    const csrLevelRow* r = &g_t.row[i];
    if (!strcmp(r->scene, scene) && ofKind(r, kind) && r->error_mm <= tol &&
        r->whole_run != 0 && r->cpu_s_per_s < p->cpu_s_per_s) {
      csz_fail("picked line %d but line %d is cheaper within --tol %g", p->line, r->line, tol);
    }
  }
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".csv");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csStatus st = csr_levelTableRead(path, &g_t, err);
  csz_checkError(st, st == CS_OK && g_t.nrow > 0, err, path, data, size, CSZ_TEXT);
  if (st != CS_OK) {
    return st;
  }
  if (g_t.nrow < 1 || g_t.nrow > CSR_LEVELS_MAX_ROWS) {
    csz_fail("accepted table has %d rows", g_t.nrow);
  }
  for (int i = 0; i < g_t.nrow; i++) {
    checkRow(&g_t.row[i], size);
    for (int j = 0; j < i; j++) {
      const csrLevelRow* a = &g_t.row[i];
      const csrLevelRow* b = &g_t.row[j];
      if (!strcmp(a->scene, b->scene) && !strcmp(a->level, b->level) && a->links == b->links &&
          a->macro_steps == b->macro_steps && a->dt_s == b->dt_s && a->rod_tol == b->rod_tol &&
          a->step_order == b->step_order && a->step_tol_mm == b->step_tol_mm) {
        csz_fail("accepted table repeats a configuration (lines %d, %d)", b->line, a->line);
      }
    }
  }
  double e = g_t.row[0].error_mm;
  for (int kind = CSR_STEP_ANY; kind <= CSR_STEP_ADAPTIVE; kind++) {
    checkPick(path, 0.5 * e, (csrStepKind)kind);
    checkPick(path, e, (csrStepKind)kind);
    checkPick(path, 2 * e + 1, (csrStepKind)kind);
  }
  return st;
}
