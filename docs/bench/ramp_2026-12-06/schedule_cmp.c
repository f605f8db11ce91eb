/* bitwise comparison of the new schedule (table's @ramp or 0.2) against the old one (0.2) */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include "gaits_schedule.h"
csgScheduleOptions old_defaultScheduleOptions(void);
csStatus old_scheduleEval(const csgGait*, const csgScheduleOptions*, double, double*);
csStatus old_scheduleEvalRate(const csgGait*, const csgScheduleOptions*, double, double*);
int main(int argc, char** argv) {
  double old_ramp = argc > 2 ? atof(argv[2]) : 0.2;
  csError err;
  csgGait* g = csg_gaitRead(argv[1], NULL, &err);
  if (!g) { printf("%s\n", err.msg); return 1; }
  csgScheduleOptions o = csg_defaultScheduleOptions(), n = o;
  o.ramp = old_ramp;
  n.ramp = isnan(g->ramp) ? old_ramp : g->ramp;
  if (argc > 3) n.ramp = atof(argv[3]);
  double T = g->time[g->nrow - 1] + 1.0;
  long nd = 0, ndr = 0, first = -1, nt = 0; double maxd = 0, tfirst = 0, maxdr = 0;
  for (int pass = 0; pass < 2; pass++) {
    long K = pass == 0 ? (long)(T / 1e-4) : g->nrow * 5L;
    for (long k = 0; k <= K; k++) {
      double t;
      if (pass == 0) t = k * 1e-4;
      else { int i = (int)(k / 5); if (i >= g->nrow) break; double dd[5] = {0, 1e-12, -1e-12, 5e-4, -5e-4}; t = g->time[i] + dd[k % 5]; if (t < 0) continue; }
      double a[96], b[96], ar[96], br[96];
      old_scheduleEval(g, &o, t, a); csg_scheduleEval(g, &n, t, b);
      old_scheduleEvalRate(g, &o, t, ar); csg_scheduleEvalRate(g, &n, t, br);
      nt++;
      int dif = 0, difr = 0;
      for (int l = 0; l < 96; l++) {
        if (a[l] != b[l]) { dif = 1; if (fabs(a[l]-b[l]) > maxd) maxd = fabs(a[l]-b[l]); }
        if (ar[l] != br[l]) { difr = 1; if (fabs(ar[l]-br[l]) > maxdr) maxdr = fabs(ar[l]-br[l]); }
      }
      if (dif && first < 0) { first = k; tfirst = t; }
      nd += dif; ndr += difr;
    }
  }
  printf("%s: old ramp %g, new ramp %g: %ld times, p differs at %ld (max %.3g MPa, first t = %.6f), rate differs at %ld (max %.3g MPa/s)\n",
         argv[1], o.ramp, n.ramp, nt, nd, maxd, first >= 0 ? tfirst : NAN, ndr, maxdr);
  csg_gaitDestroy(g);
  return 0;
}
