/* gaits_foothold.h: footholds, a gait's landings chosen during the run from where the support
 * stands (issue 33; the design: docs/studies/obstacle.md, "A foothold that reads the support").
 *
 * Owns: the choice of one step's landing among candidates designed beforehand
 * (csg_footholdChoose, a pure function: candidates' planned landings, the measured shift of the
 * hips against the plan, the terrain's edges, a margin -> index), csgFootholdSet (the model of
 * a companion `.foothold` file, constant during a run) and its reader. The player, which asks
 * the choice at a step's lift and commands the chosen candidate's columns over its window,
 * is core's (core/sim_foothold.c): gaits/ may not see the terrain, so the edges come in as
 * numbers.
 *
 * Units: mm, s, MPa. x is the crawl direction of the terrain's frame (world x).
 *
 * File format (NAME.foothold beside NAME.csv, written by tools/obstacle_gait.py; '#' starts a
 * comment, blank lines are skipped; docs/reference/formats.md "Foothold file"):
 *   foothold T LEGS xplan X margin M window W0 W1
 *       the step of LEGS (letters A..H) lifting at T (s); X (mm) the support's displacement
 *       along x the plan expected at T; M (mm) the clearance from every edge a landing should
 *       keep; the candidates' columns of LEGS replace the nominal table's for W0 <= t < W1 (s,
 *       T <= W0 < W1)
 *   candidate OFFSET land L fits LO HI FILE [nominal]
 *       one candidate of the foothold above it: its landing OFFSET (mm ahead of the hip), the
 *       landing L (mm, terrain x) it makes when the support stands where the plan put it, the
 *       span LO..HI (mm, terrain x, finite, LO <= L <= HI) of landings its stance length suits
 *       (the designer's rule: a road leg's stretched length before the riser, the vented step
 *       length on the plateau and just past it), and its table FILE (a gait CSV, gaits_csv.h,
 *       path relative to the .foothold file's folder) whose LEGS columns hold over the window; `nominal` marks the candidate the nominal
 *       table (NAME.csv) holds: exactly one per foothold
 * Footholds sharing a leg may overlap in their windows only as a chain: the later one starts
 * and ends later (W0 and W1 both greater) and its columns hold from its W0 on (the next step
 * of the same legs, decided while the earlier's rows still run); a candidate table covers its
 * window (first row <= W0, last row >= W1).
 * Errors: "<file>:<line>: <cause>" (CS_ERR_PARSE malformed, CS_ERR_RANGE values, CS_ERR_IO a
 * file that cannot be read, a candidate table's own reader message). */
#ifndef CS_GAITS_FOOTHOLD_H
#define CS_GAITS_FOOTHOLD_H

#include "core_status.h"
#include "gaits_csv.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSG_FOOTHOLD_MAX 16      /* footholds per file */
#define CSG_FOOTHOLD_MAX_CAND 12 /* candidates per foothold */

/* The choice (pure; no allocation). Candidate i lands at x_i = land[i] + delta: land[i] its
 * landing when the hips stand where the plan put them, delta (mm) how far the measured hips
 * stand ahead of the plan. It fits when lo[i] <= x_i <= hi[i] (its stance length suits that
 * landing); its clearance is the distance from x_i to the nearest of the nedge edges (mm,
 * terrain x; +inf without edges). Among the fitting candidates whose clearance is at least
 * margin, the one landing nearest the nominal candidate's planned landing land[nominal] (the
 * plan's foothold, kept where the support lets it); if none, the fitting one of largest
 * clearance; if none fits, the one of largest clearance. Ties go to the lower index. lo, hi
 * NULL: every candidate fits. Returns the index, or -1 for n < 1, a nominal outside 0..n-1,
 * NULL land or edges (with nedge > 0) or a non-finite land, delta, edge or margin. */
int csg_footholdChoose(int n, const double* land, const double* lo, const double* hi,
                       int nominal, double delta, const double* edges, int nedge, double margin);

typedef struct csgFootholdCand_ {
  double offset;      /* mm ahead of the hip (as designed) */
  double land;        /* mm, terrain x: its landing with the support on plan */
  double lo, hi;      /* mm, terrain x: the landings its stance length suits */
  csgGait* table;     /* owned: its rows; the foothold's legs' columns are used */
} csgFootholdCand;

typedef struct csgFoothold_ {
  double t;           /* s: the lift; the choice is made from the state at the start of the
                         first step that reaches t */
  unsigned legs;      /* bit k: leg k (A..H) */
  double xplan;       /* mm: the support's displacement along x the plan expected at t */
  double margin;      /* mm */
  double w0, w1;      /* s: the window of the candidates' columns */
  int ncand;
  int nominal;        /* index of the candidate the nominal table holds */
  csgFootholdCand cand[CSG_FOOTHOLD_MAX_CAND];
  int line;           /* of its `foothold` statement */
} csgFoothold;

typedef struct csgFootholdSet_ {
  int n;
  csgFoothold fh[CSG_FOOTHOLD_MAX];  /* sorted by t */
  char source[512];
} csgFootholdSet;

/* Read a .foothold file and its candidate tables (opt: the gait reader's limits, NULL the
 * defaults). Returns a new set (free with csg_footholdDestroy) or NULL with err. */
csgFootholdSet* csg_footholdRead(const char* path, const csgReadOptions* opt, csError* err);
/* NULL-safe. */
void csg_footholdDestroy(csgFootholdSet* s);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_FOOTHOLD_H */
