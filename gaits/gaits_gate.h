/* gaits_gate.h: the landing gate, a gait's lifts held until the last pair down is down
 * (issue 33; the design and its runs: docs/studies/obstacle.md, "2026-12-06, fifth session"
 * and "sixth session").
 *
 * Owns: csgGateSet (the model of a companion `.gate` file, constant during a run), its reader,
 * and the test of one gate (csg_gateDown, a pure function of the measured and the designed
 * pressures). The player, which holds the table's clock while a gate waits and plays the held
 * rows (gaits_schedule.h csg_scheduleEvalHeld), is core's (core/sim_gate.c): it reads the
 * chamber pressures, so the run is closed-loop (a sensing controller).
 *
 * The rule. A gate at table time T waits for LEGS (the pair that lifted last before the pair
 * lifting at T). It is down when every chamber c of LEGS is at least as near its valve's
 * command v_c as the design has it at T, within PTOL:
 *     |v_c - p_c| <= |v_c - p_design,c(T)| + PTOL
 * p_design is the table played on time through the design's actuation time (the `ramp`) and
 * pneumatic lag (the `lag`, dp/dt = (p_cmd - p) / lag, sim_model.h), integrated once at load;
 * PTOL is a pressure sensor's accuracy. So the gate waits only when the valves are slower than
 * the design assumed; a run whose valves are as designed never waits and is the open-loop run.
 * A gate releases after `maxwait` at most (one slot of the walk).
 *
 * Units: s, MPa.
 *
 * File format (NAME.gate beside NAME.csv, written by tools/obstacle_gait.py --gate-out;
 * '#' starts a comment, blank lines are skipped; docs/reference/formats.md "Gate files"):
 *   design ramp R lag TAU ptol P maxwait W
 *       once, before any gate: the design's actuation time R (s, >= 0), pneumatic lag TAU
 *       (s, > 0), the tolerance P (MPa, >= 0) and the longest wait W (s, > 0)
 *   gate T LEGS [x XMIN]
 *       a gate at table time T (s, >= 0, not decreasing from one gate to the next) waiting for
 *       LEGS (letters A..H, each once); with `x XMIN` it also waits until the support's
 *       measured displacement along x (mm, the state's) is at least XMIN: a condition on
 *       where the support stands, not on the clock (issue 33, docs/notes/obstacle.md "ramp11":
 *       a landing planned from the hips needs the support near the plan). The same maxwait
 *       releases it.
 *   crawl T0 TPZ N ZEND CARRY
 *       at most once, after the gates (T0 >= every gate's T): the table's lateral crawl ends on
 *       the measured support (issue 33, docs/notes/obstacle.md "crawl10"). The table has N
 *       (>= 3) lateral slots of TPZ s (> 0) from table time T0 (s); the crawl is periodic in
 *       two slots, so at the end of slot j (0-based) with N - 1 - j even the table can jump
 *       to its release (N - 1 - j slots on, the same pose). At each such boundary with j >= 2
 *       the player (core/sim_gate.c) reads the support's measured z (mm) and its advance a over
 *       the last two slots, and ends the crawl there when z + CARRY >= ZEND - a / 2 (stopping
 *       lands nearer ZEND than one more cycle at the measured pace; CARRY (mm, >= 0) the
 *       release's own advance along z, ZEND (mm) the end point's z). Ending skips the table's
 *       clock on by (N - 1 - j) TPZ.
 *   walk T0 TP N XEND CARRY
 *       at most once, after the gates and before the crawl (T0 >= every gate's T; the crawl's
 *       T0 >= T0 + N TP): the walk's length read off the measured support, the crawl's rule on
 *       x (issue 33, docs/notes/obstacle.md "obst13"). The table has N (>= 3) slots of TP s
 *       from table time T0 of a walk periodic in two slots, then its end (the obstacle's turn
 *       to the lateral crawl); at the end of slot j with N - 1 - j even and j >= 2 the player
 *       reads the support's measured x (mm) and its advance a over the last two slots, and
 *       ends the walk there when x + CARRY >= XEND - a / 2 (CARRY, mm >= 0: what the walk's
 *       end and what follows add along x; XEND, mm: the end point's x). Ending skips the
 *       table's clock on by (N - 1 - j) TP; a crawl's boundaries are read on the clock after it.
 * Errors: "<file>:<line>: <cause>" (CS_ERR_PARSE malformed, CS_ERR_RANGE values, CS_ERR_IO a
 * file that cannot be read). */
#ifndef CS_GAITS_GATE_H
#define CS_GAITS_GATE_H

#include "core_status.h"
#include "gaits_labels.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSG_GATE_MAX 128 /* gates per file */

typedef struct csgGate_ {
  double t;     /* s: table time of the lift it holds */
  unsigned legs; /* bit k: leg k (A..H) waited for */
  int line;     /* of its `gate` statement */
  double xmin;  /* mm: the support's x it also waits for (`x XMIN`; -INFINITY: none) */
  double p_design[CSG_NLABEL]; /* MPa: the design's chamber pressures at t (filled by the
                                  player at load, core/sim_gate.c; 0 from the reader) */
} csgGate;

typedef struct csgGateSet_ {
  double ramp;    /* s: the design's actuation time */
  double lag;     /* s: the design's pneumatic lag */
  double ptol;    /* MPa */
  double maxwait; /* s */
  int n;
  csgGate gate[CSG_GATE_MAX]; /* in the file's order (T not decreasing) */
  double time[CSG_GATE_MAX];  /* s: the gates' t, contiguous (csg_scheduleEvalHeld's breaks) */
  /* the `crawl` statement (crawl_n 0: none) */
  int crawl_n;        /* lateral slots written */
  double crawl_t0;    /* s: table time of the first slot's start */
  double crawl_tpz;   /* s: one slot */
  double crawl_zend;  /* mm: the end point's z */
  double crawl_carry; /* mm: the release's own advance along z */
  /* the `walk` statement (walk_n 0: none) */
  int walk_n;        /* walk slots written before its end */
  double walk_t0;    /* s: table time of the first slot's start */
  double walk_tp;    /* s: one slot */
  double walk_xend;  /* mm: the end point's x */
  double walk_carry; /* mm: the walk's end and what follows, along x */
  char source[512];
} csgGateSet;

/* Read a .gate file. Returns a new set (free with csg_gateDestroy) or NULL with err. */
csgGateSet* csg_gateRead(const char* path, csError* err);
/* NULL-safe. */
void csg_gateDestroy(csgGateSet* s);

/* The rule above for one gate (pure): p the measured pressures (96), v the valves' commands
 * (96), g's legs and design pressures, ptol. 1 down, 0 not. */
int csg_gateDown(const csgGate* g, const double* p, const double* v, double ptol);

/* The gate's whole test (pure): csg_gateDown and the support's measured x (mm) >= g->xmin.
 * 1 ready to release, 0 not. */
int csg_gateReady(const csgGate* g, const double* p, const double* v, double ptol, double x);

/* The crawl's rule at one boundary (pure): z the support's measured z (mm) at the end of slot
 * j, zprev at the end of slot j - 2. Returns the slots to skip (N - 1 - j) when the crawl ends
 * there, 0 when it goes on (or j is not a decision boundary). */
int csg_gateCrawlSkip(const csgGateSet* s, int j, double z, double zprev);

/* The walk's rule at one boundary (pure; the crawl's on x, `walk`): x the support's measured x
 * (mm) at the end of slot j, xprev at the end of slot j - 2. Returns the slots to skip
 * (N - 1 - j) when the walk ends there, 0 when it goes on (or j is not a decision boundary). */
int csg_gateWalkSkip(const csgGateSet* s, int j, double x, double xprev);

/* LEGS as letters into out (>= 9 chars). */
void csg_gateLegs(unsigned legs, char* out);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_GATE_H */
