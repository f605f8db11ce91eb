/* fuzz_foothold.c: fuzz harness of the .foothold reader (gaits_foothold.h, csg_footholdRead).
 *
 * Per input: read it and check the error contract (fuzz_common.h); a set the reader accepts
 * must hold what it promises: 1..CSG_FOOTHOLD_MAX footholds in increasing lift time, each with
 * 0 <= t <= w0 < w1, a margin >= 0, 1..CSG_FOOTHOLD_MAX_CAND candidates with finite offsets and
 * landings, exactly one nominal, tables covering the window, and no two footholds sharing a
 * leg with overlapping windows; the choice on it with any shift returns a candidate. The
 * candidate table the seeds name (fuzz_foothold_cand.csv) is written beside the input. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_common.h"
#include "gaits_foothold.h"

static const char kCand[] = "time,A_II1_O1,D_II1_O1,H_II1_O1\n0,0,0,0\n1,0.1,0.1,0.1\n"
                            "2,0.2,0.2,0.2\n5,0,0,0\n";


int csz_harnessInit(void) {
  const char* path = csz_tempPath(0, ".foothold");
  if (!path) return 1;
  char cand[1024];
  const char* slash = strrchr(path, '/');
  snprintf(cand, sizeof cand, "%.*sfuzz_foothold_cand.csv", slash ? (int)(slash - path + 1) : 0,
           path);
  return csz_writeFile(cand, (const uint8_t*)kCand, sizeof kCand - 1);
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".foothold");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csgFootholdSet* s = csg_footholdRead(path, NULL, err);
  csStatus st = s ? CS_OK : err->status;
  csz_checkError(st, s != NULL, err, path, data, size, CSZ_TEXT);
  if (s) {
    if (s->n < 1 || s->n > CSG_FOOTHOLD_MAX) csz_fail("%d footholds", s->n);
    for (int k = 0; k < s->n; k++) {
      const csgFoothold* f = &s->fh[k];
      if (!(f->t >= 0 && f->t <= f->w0 && f->w0 < f->w1 && f->margin >= 0) || !f->legs ||
          (k > 0 && !(f->t > s->fh[k - 1].t))) {
        csz_fail("foothold %d: times %g %g %g, margin %g", k, f->t, f->w0, f->w1, f->margin);
      }
      if (f->ncand < 1 || f->ncand > CSG_FOOTHOLD_MAX_CAND || f->nominal < 0 ||
          f->nominal >= f->ncand) {
        csz_fail("foothold %d: %d candidates, nominal %d", k, f->ncand, f->nominal);
      }
      double land[CSG_FOOTHOLD_MAX_CAND], lo[CSG_FOOTHOLD_MAX_CAND], hi[CSG_FOOTHOLD_MAX_CAND];
      for (int i = 0; i < f->ncand; i++) {
        const csgGait* g = f->cand[i].table;
        if (!isfinite(f->cand[i].offset) || !isfinite(f->cand[i].land) || !g ||
            !(g->time[0] <= f->w0 && g->time[g->nrow - 1] >= f->w1)) {
          csz_fail("foothold %d candidate %d", k, i);
        }
        land[i] = f->cand[i].land;
        lo[i] = f->cand[i].lo;
        hi[i] = f->cand[i].hi;
        if (!(lo[i] <= land[i] && land[i] <= hi[i])) csz_fail("candidate %d outside its span", i);
      }
      for (int j = 0; j < k; j++) {
        if ((s->fh[j].legs & f->legs) && f->w0 < s->fh[j].w1) {
          csz_fail("footholds %d and %d overlap on a leg", j, k);
        }
      }
      const double edges[2] = {240, 460};
      for (double delta = -100; delta <= 100; delta += 25) {
        int c = csg_footholdChoose(f->ncand, land, lo, hi, f->nominal, delta, edges, 2, f->margin);
        if (c < 0 || c >= f->ncand) csz_fail("choice %d of %d candidates", c, f->ncand);
      }
    }
  }
  csg_footholdDestroy(s);
  return st;
}
