/* fuzz_gate.c: fuzz harness of the .gate reader (gaits_gate.h, csg_gateRead).
 *
 * Per input: read it and check the error contract (fuzz_common.h); a set the reader accepts
 * must hold what it promises: a design line (ramp >= 0, lag > 0, ptol >= 0, maxwait > 0, all
 * finite) and 1..CSG_GATE_MAX gates with finite times >= 0, not decreasing, each waiting for
 * at least one leg, the contiguous times equal to the gates'. */
#include <math.h>

#include "fuzz_common.h"
#include "gaits_gate.h"


int csz_harnessInit(void) { return 0; }


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".gate");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csgGateSet* s = csg_gateRead(path, err);
  csStatus st = s ? CS_OK : err->status;
  csz_checkError(st, s != NULL, err, path, data, size, CSZ_TEXT);
  if (s) {
    if (!(isfinite(s->ramp) && s->ramp >= 0 && isfinite(s->lag) && s->lag > 0 &&
          isfinite(s->ptol) && s->ptol >= 0 && isfinite(s->maxwait) && s->maxwait > 0)) {
      csz_fail("design ramp %g lag %g ptol %g maxwait %g", s->ramp, s->lag, s->ptol, s->maxwait);
    }
    if (s->n < 1 || s->n > CSG_GATE_MAX) csz_fail("%d gates", s->n);
    for (int k = 0; k < s->n; k++) {
      const csgGate* g = &s->gate[k];
      if (!(isfinite(g->t) && g->t >= 0) || !g->legs || g->legs > 0xffu || s->time[k] != g->t ||
          (k > 0 && g->t < s->gate[k - 1].t)) {
        csz_fail("gate %d: t %g, legs %u", k, g->t, g->legs);
      }
    }
  }
  csg_gateDestroy(s);
  return st;
}
