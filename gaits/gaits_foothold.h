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
 * and ends later (W0 and W1 both greater) and its rows hold from its W0 on (the next step
 * of the same legs, decided while the earlier's rows still run); a candidate table covers its
 * window (first row <= W0, last row >= W1).
 *
 * What a chosen candidate commands, at any ramp (csg_footholdCompose): the gait table with the
 * foothold's legs' rows replaced over the window, i.e. the step command that is the
 * candidate's (its last row at or before t) for W0 <= t < W1 and the nominal table's outside
 * (a chained later foothold's from its W0 on); the valves then ramp to it as to any table
 * (gaits_schedule.h). So where the ramp outlasts a row (0.5 s against the designer's 0.05 s
 * rows) the choice arrives smeared and late as the table's own rows do, its changes reach up to
 * one ramp past W1, and the rows before W0 stay the nominal's: nothing about the ramp is
 * refused. (Until margin18, 2026-12-07, the player played the candidate's rows alone over the
 * window, which is that command only where the ramp fits the rows, and refused longer ramps.)
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
  csgGait* comp;      /* owned, csg_footholdCompose (NULL before): the command it stands for
                         over the foothold's span (see csg_footholdCompose) */
  csgGait* base;      /* owned: the nominal table's command at comp's row times */
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
  double tail;        /* s, csg_footholdCompose: the last row of its candidates' comp/base (the
                         nominal's first row past W1); their schedules agree from one ramp
                         after it, and before W0 */
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

/* Make every candidate's comp and base against the nominal table (after csg_footholdRead; the
 * run's player calls it at load). comp holds, at the union of the nominal's row times from its
 * last row at or before W0 to its first row past W1 (or its last), the candidate's rows in
 * [W0, W1) and W0, W1 themselves: the command above (on the foothold's legs' columns the
 * candidate's step value for W0 <= tau < W1, cut at a chained later foothold's W0 on a shared
 * leg, the nominal's otherwise; 0 before the nominal's first row); base the nominal's step
 * value at the same times. The schedule is linear in the rows and a row's ramp depends only on
 * the row times (gaits_schedule.h), so on the legs' columns
 *   S(nominal)(t) + S(comp)(t) - S(base)(t) = S(the nominal with the chosen rows)(t)
 * for every ramp, shape and gate's hold, up to rounding: comp and base start from vented alike
 * and share every row time, so that start cancels; the difference is exactly 0 before W0
 * (equal rows) and from tail + ramp on (both at their equal last row). Rebuilds what a
 * previous call made. Returns CS_OK, CS_ERR_ARG (NULL s or nominal), CS_ERR_MEMORY. */
csStatus csg_footholdCompose(csgFootholdSet* s, const csgGait* nominal, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_FOOTHOLD_H */
