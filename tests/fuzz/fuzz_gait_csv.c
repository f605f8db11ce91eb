/* fuzz_gait_csv.c: fuzz harness of the gait CSV reader (gaits_csv.h, csg_gaitRead).
 *
 * Per input: read it with the default limits and check the error contract (fuzz_common.h); a
 * table the reader accepts must pass csg_gaitValidate, give a summary, and survive the writer:
 * csg_gaitWrite then csg_gaitRead gives the same times and stated ramp exactly and the same
 * pressures to the writer's 6 digits. The input is read a second time with tight limits (4 rows, 64-byte lines,
 * 0.5 MPa), which must refuse whatever the defaults refuse (limits only ever take away). */
#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "gaits_csv.h"

/* tables up to this many rows are written back and re-read (the write costs 96 columns a row) */
#define ROUNDTRIP_ROWS 64
/* the writer prints pressures with %.6g: read back within half a unit of the 6th significant
 * digit, 5e-6 relative at worst (a value just above a power of ten: 1.000005 -> 1.00001) */
#define WRITE_RTOL 5e-6


int csz_harnessInit(void) { return csz_tempPath(0, ".csv") && csz_tempPath(1, ".csv") ? 0 : 1; }


static void roundTrip(const csgGait* g) {
  const char* path = csz_tempPath(1, ".csv");
  csError err;
  if (csg_gaitWrite(g, path, "fuzz round trip\nsecond line", &err) != CS_OK) {
    csz_fail("csg_gaitWrite refused a table csg_gaitRead accepted: %s", err.msg);
  }
  csgGait* back = csg_gaitRead(path, NULL, &err);
  if (!back) {
    csz_fail("csg_gaitRead refused what csg_gaitWrite wrote: %s", err.msg);
  }
  if (back->nrow != g->nrow) {
    csz_fail("round trip: %d rows became %d", g->nrow, back->nrow);
  }
  /* the stated ramp (`# @ramp`) comes back exactly, or stays unstated */
  if (!(back->ramp == g->ramp || (isnan(back->ramp) && isnan(g->ramp)))) {
    csz_fail("round trip: ramp %.17g became %.17g", g->ramp, back->ramp);
  }
  for (int i = 0; i < g->nrow; i++) {
    if (back->time[i] != g->time[i]) {
      csz_fail("round trip: row %d time %.17g became %.17g", i, g->time[i], back->time[i]);
    }
    for (int l = 1; l <= CSG_NLABEL; l++) {
      double a = csg_gaitPressure(g, i, l), b = csg_gaitPressure(back, i, l);
      if (!(fabs(a - b) <= WRITE_RTOL * fabs(a) + 1e-300)) {
        csz_fail("round trip: row %d label %d pressure %.17g became %.17g", i, l, a, b);
      }
    }
  }
  csg_gaitDestroy(back);
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".csv");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csgGait* g = csg_gaitRead(path, NULL, err);
  csStatus st = g ? CS_OK : err->status;
  csz_checkError(st, g != NULL, err, path, data, size, CSZ_TEXT);
  if (g) {
    csError e2;
    if (g->nrow < 1 || csg_gaitValidate(g, NULL, &e2) != CS_OK) {
      csz_fail("the reader returned a table that fails validation (%d rows): %s", g->nrow,
               g->nrow < 1 ? "no rows" : e2.msg);
    }
    csgGaitSummary s;
    if (csg_gaitComputeSummary(g, &s, &e2) != CS_OK || s.nrow != g->nrow ||
        !(s.t_last >= s.t_first) || s.nused < 0 || s.nused > CSG_NLABEL ||
        !(s.p_max >= 0 && s.p_max <= CSG_DEFAULT_MAX_PRESSURE)) {
      csz_fail("summary of an accepted table is inconsistent");
    }
    if (g->nrow <= ROUNDTRIP_ROWS) {
      roundTrip(g);
    }
  }
  /* tight limits refuse at least what the defaults refuse */
  csgReadOptions tight = csg_defaultReadOptions();
  tight.max_rows = 4;
  tight.max_line_bytes = 64;
  tight.max_pressure = 0.5;
  csError et;
  csgGait* gt = csg_gaitRead(path, &tight, &et);
  csz_checkError(gt ? CS_OK : et.status, gt != NULL, &et, path, data, size, CSZ_TEXT);
  if (gt && !g) {
    csz_fail("tight limits accepted what the defaults refused (%s)", err->msg);
  }
  csg_gaitDestroy(gt);
  csg_gaitDestroy(g);
  return st;
}
