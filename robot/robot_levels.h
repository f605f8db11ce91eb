/* robot_levels.h: the measured leg-level table behind `crawlsim run --legs auto --tol MM`.
 *
 * Owns: reading the table (robot/levels.csv, written by tools/bench_levels.py) and picking,
 * for one scene, the cheapest configuration whose measured error stays within a tolerance.
 *
 * File format (text, LF or CRLF, '#' comment lines and blank lines skipped): one header line,
 * exactly
 *   scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,error_mm,whole_run,
 *   cpu_s_per_s,wall_s_per_s,machine
 * (format 5; format 4, without whole_run, format 3, without step_tol_mm either, format 2,
 * without step_order either, and format 1, without rod_tol either, are still read, every row
 * a fixed step at step_order 0 and rod_tol 1 with its whole run not judged where the column
 * is missing)
 * then one row per measured configuration:
 *   scene        a scene name (a word, at most 31 bytes: flat-road, obstacle, ...)
 *   level        a registered leg level (csr_legTypeFind: rod, strain; a retired one, prb, is
 *                refused naming why, csr_legRetired)
 *   links        elements (rod) or bending modes (strain) per segment, integer
 *                1..64 (`--links`)
 *   macro_steps  ODE steps per exchange, integer 1..100000 (`--macro-steps`)
 *   dt_s         ODE step (s), 0 < dt <= 0.01 (`--dt`); with step_tol_mm > 0 the adaptive
 *                step's longest
 *   rod_tol      the rod legs' CVODE tolerances' factor, 0 < K <= 1000 (`--rod-tol`; strain: 1)
 *   step_order   the tree step's formula, integer 0..2 (`--step-order`: 1 backward Euler, 2 BDF2;
 *                0 the level's default; rod: 0)
 *   step_tol_mm  0: a fixed step of dt_s; > 0 (<= 100): the adaptive tree step at this local
 *                error per step (mm; `--strain-step adaptive --step-tol`), only on a
 *                tree-stepped level (strain), either formula (core/sim_adaptive.c estimates
 *                backward Euler's or BDF2's error)
 *   error_mm     the scene's track error against the benchmark's reference (mm), finite, >= 0
 *   whole_run    the scene's whole default run in this configuration (no --t-end: the track
 *                may be measured on a shorter window, the obstacle's first 4 s): 1 it reaches
 *                the scene's goal, 0 it does not (it falls, tips over, stops, or ends away from
 *                the goal; tools/bench_levels.py says which goal), -1 not judged
 *   cpu_s_per_s  CPU seconds of the whole process per simulated second, finite, > 0
 *   wall_s_per_s wall seconds per simulated second on the benchmark's machine, finite, > 0
 *   machine      free text without commas (where it was measured)
 * A repeated (scene, level, links, macro_steps, dt_s, rod_tol, step_order, step_tol_mm) is
 * refused. Every refusal is one line
 * "<file>:<line>: <cause>" in err (CS_ERR_PARSE or CS_ERR_RANGE; CS_ERR_IO when unreadable).
 *
 * The pick: among the scene's rows with error_mm <= tol whose whole run does not fail
 * (whole_run 1 or -1; and of the step kind asked, if one is: csr_levelTablePickStep), the
 * smallest cpu_s_per_s (a tie: the smaller error, then the earlier row). A row accurate on its
 * window whose whole run fails is never picked: a configuration within 1 mm over the
 * obstacle's first 4 s can still fall off the step at 12 s. Cost is CPU time, less sensitive than wall time to the
 * load of a shared machine. */
#ifndef CS_ROBOT_LEVELS_H
#define CS_ROBOT_LEVELS_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* rows a table may hold: a benchmark writes a handful per scene */
#define CSR_LEVELS_MAX_ROWS 256

/* one measured configuration */
typedef struct csrLevelRow_ {
  char scene[32];
  char level[16];       /* a registered leg level's name */
  int links;            /* links / elements per segment */
  int macro_steps;      /* ODE steps per exchange */
  double dt_s;          /* s: ODE step */
  double rod_tol;       /* the rod's CVODE tolerance factor (`--rod-tol`) */
  int step_order;       /* the tree step's formula (`--step-order`; 0: the level's default) */
  double step_tol_mm;   /* mm: the adaptive step's local error per step; 0: a fixed step */
  double error_mm;      /* mm: track error against the reference */
  int whole_run;        /* the whole run: 1 reaches the scene's goal, 0 fails, -1 not judged */
  double cpu_s_per_s;   /* CPU s per simulated s */
  double wall_s_per_s;  /* wall s per simulated s */
  char machine[64];
  int line;             /* line of the file it came from */
} csrLevelRow;

/* a table as read */
typedef struct csrLevelTable_ {
  int nrow;
  csrLevelRow row[CSR_LEVELS_MAX_ROWS];
  char path[512];       /* the file it came from, for messages */
} csrLevelTable;

/* Read `path` into *t. On failure t->nrow is 0 and err says file, line and cause. */
csStatus csr_levelTableRead(const char* path, csrLevelTable* t, csError* err);

/* The row index to run for `scene` within `tol_mm` (finite, >= 0), or -1 with err: the table
 * has no row for the scene (CS_ERR_ARG), or no row meets the tolerance (CS_ERR_RANGE, naming
 * the best achievable error and its configuration). */
int csr_levelTablePick(const csrLevelTable* t, const char* scene, double tol_mm, csError* err);
/* (a scene whose every row within tol fails its whole run: -1, CS_ERR_RANGE naming them) */

/* which rows a pick may take: any, fixed steps only (step_tol_mm 0), adaptive only (> 0) */
typedef enum { CSR_STEP_ANY = 0, CSR_STEP_FIXED = 1, CSR_STEP_ADAPTIVE = 2 } csrStepKind;

/* csr_levelTablePick among the rows of one step kind (`--strain-step fixed|adaptive` beside
 * `--legs auto`); with no row of the scene of that kind: -1, CS_ERR_ARG naming the kind */
int csr_levelTablePickStep(const csrLevelTable* t, const char* scene, double tol_mm,
                           csrStepKind kind, csError* err);

/* Rows of `scene` and `kind` within `tol_mm` whose whole run fails (whole_run 0) and that
 * cost less than `cpu_below` CPU s per simulated s: what a pick passed over, for its note. */
int csr_levelTableFailing(const csrLevelTable* t, const char* scene, double tol_mm,
                          csrStepKind kind, double cpu_below);

/* The scene's most accurate row whose whole run does not fail (smallest error; a tie: the
 * cheaper), or -1 if it has none. */
int csr_levelTableFinest(const csrLevelTable* t, const char* scene);

/* The scene's costliest row (most CPU s per simulated s), or -1 if it has none. */
int csr_levelTableCostliest(const csrLevelTable* t, const char* scene);

/* Rows of `scene` in the table. */
int csr_levelTableCount(const csrLevelTable* t, const char* scene);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_LEVELS_H */
