/* robot_levels.c: the measured leg-level table and the `--legs auto` pick (robot_levels.h).
 *
 * The table is a plain CSV without quoting (the benchmark writes no commas inside a field), read
 * line by line through the shared reader (core_text.h) so an overlong line or a NUL byte is
 * refused at its line. Fields are split at every comma, so a row with a missing or an extra
 * field is counted and refused, never shifted into the next column. Numbers go through strtod
 * and are checked finite and in range: strtod alone accepts "nan", "inf" and "1e999". */
#include "robot_levels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "robot_leg.h"

enum {
  MAX_LINE = 1023, /* bytes per line, line ending excluded */
  NCOL = 13,       /* columns of the format (5) */
  NFORMAT = 5
};

/* the columns of format 5, in order; older formats hold a subset (kFormat) */
static const char* const kColumn[NCOL] = {"scene", "level", "links", "macro_steps", "dt_s",
                                          "rod_tol", "step_order", "step_tol_mm", "error_mm",
                                          "whole_run", "cpu_s_per_s", "wall_s_per_s",
                                          "machine"};
enum { COL_ROD_TOL = 5, COL_STEP_ORDER = 6, COL_STEP_TOL = 7, COL_WHOLE = 9 };

/* the formats read: the header line, its column count, and which of format 5's columns it
 * lacks (a missing one reads as its default: rod_tol 1, step_order 0, step_tol_mm 0,
 * whole_run -1) */
static const struct {
  const char* header;
  int ncol;
  unsigned missing; /* bit c: column c of kColumn is absent */
} kFormat[NFORMAT] = {
    {"scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,error_mm,whole_run,"
     "cpu_s_per_s,wall_s_per_s,machine",
     13, 0},
    /* format 4 (tables written before 2026-12-08, fifteenth session): whole runs not judged */
    {"scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,error_mm,cpu_s_per_s,"
     "wall_s_per_s,machine",
     12, 1u << COL_WHOLE},
    /* format 3 (tables written before 2026-12-07 ninth session): every row a fixed step */
    {"scene,level,links,macro_steps,dt_s,rod_tol,step_order,error_mm,cpu_s_per_s,wall_s_per_s,"
     "machine",
     11, 1u << COL_STEP_TOL | 1u << COL_WHOLE},
    /* format 2 (before 2026-12-06): every row at step_order 0 too */
    {"scene,level,links,macro_steps,dt_s,rod_tol,error_mm,cpu_s_per_s,wall_s_per_s,machine", 10,
     1u << COL_STEP_ORDER | 1u << COL_STEP_TOL | 1u << COL_WHOLE},
    /* format 1 (before 2026-12-03): every row at rod_tol 1 too */
    {"scene,level,links,macro_steps,dt_s,error_mm,cpu_s_per_s,wall_s_per_s,machine", 9,
     1u << COL_ROD_TOL | 1u << COL_STEP_ORDER | 1u << COL_STEP_TOL | 1u << COL_WHOLE}};
/* the ranges of the flags the row's settings stand for (tools/cmd_run.c) */
#define MAX_LINKS 64
#define MAX_MACRO 100000
#define MAX_DT_S 0.01
/* an error of a km or a day of CPU per simulated second is a typo */
#define MAX_VALUE 1e6
/* `crawlsim run --rod-tol`'s range */
#define MAX_ROD_TOL 1000
/* `crawlsim run --step-order`'s range (0: the level's default formula) */
#define MAX_STEP_ORDER 2
/* `crawlsim run --step-tol`'s range (mm; 0 here: a fixed step) */
#define MAX_STEP_TOL 100

/* split `line` in place at commas into at most NCOL fields; returns the field count (which
 * may exceed NCOL: the extra ones are counted, not stored) */
static int splitFields(char* line, char** field);

/* parse field `col` of a row as a finite number within [lo, hi] (lo_open: > lo), an integer if
 * `integer`; fills err naming file, line and column on failure */
static csStatus parseField(const char* s, int col, double lo, int lo_open, double hi,
                           int integer, const char* path, long line, double* v, csError* err);

/* parse one data row into *r */
static csStatus parseRow(char** field, const char* path, long line, csrLevelRow* r,
                         csError* err);


static int splitFields(char* line, char** field) {
  int n = 0;
  char* s = line;
  for (;;) {
    char* comma = strchr(s, ',');
    if (comma) {
      *comma = '\0';
    }
    if (n < NCOL) {
      field[n] = csu_trimBlanks(s);
    }
    n++;
    if (!comma) {
      return n;
    }
    s = comma + 1;
  }
}


static csStatus parseField(const char* s, int col, double lo, int lo_open, double hi,
                           int integer, const char* path, long line, double* v, csError* err) {
  char* end;
  *v = strtod(s, &end);
  if (!s[0] || end == s || *end) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s '%.40s' is not a number", path, line,
                       kColumn[col], s);
  }
  if (!isfinite(*v)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: %s '%.40s' is not a finite number", path,
                       line, kColumn[col], s);
  }
  if (integer && *v != floor(*v)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: %s %g is not an integer", path, line,
                       kColumn[col], *v);
  }
  if ((lo_open ? !(*v > lo) : !(*v >= lo)) || !(*v <= hi)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: %s %g is outside %s%g, %g]", path, line,
                       kColumn[col], *v, lo_open ? "(" : "[", lo, hi);
  }
  return CS_OK;
}


static csStatus parseRow(char** field, const char* path, long line, csrLevelRow* r,
                         csError* err) {
  memset(r, 0, sizeof *r);
  r->line = (int)line;
  /* scene: one non-empty word that fits */
  if (!field[0][0] || strlen(field[0]) >= sizeof r->scene || strpbrk(field[0], " \t")) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: scene '%.40s' must be one word of 1..%d "
                       "bytes", path, line, field[0], (int)sizeof r->scene - 1);
  }
  strcpy(r->scene, field[0]);
  /* level: a registered leg level */
  int planned = 0;
  if (strlen(field[1]) >= sizeof r->level || !csr_legTypeFind(field[1], &planned)) {
    const char* retired = csr_legRetired(field[1]);
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: level '%.40s' is %s", path, line, field[1],
                       retired   ? retired
                       : planned ? "not available yet"
                                 : "not a leg level (rod, strain)");
  }
  if (csr_legTypeFind(field[1], &planned)->needs_file) {
    /* a level that runs from a file of its own (rom: --rom-file) has no row: --legs auto
     * picks among levels every run has */
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: level '%.40s' runs from a leg file of its "
                       "own (--%s-file), so --legs auto cannot pick it: no rows", path, line,
                       field[1], field[1]);
  }
  strcpy(r->level, field[1]);
  /* links, macro_steps, dt_s, rod_tol, step_order, step_tol_mm, error_mm, whole_run,
   * cpu_s_per_s, wall_s_per_s: ranges (lo open?), integers */
  enum { NNUM = 10 };
  double v[NNUM];
  static const double kLo[NNUM] = {1, 1, 0, 0, 0, 0, 0, -1, 0, 0};
  static const int kOpen[NNUM] = {0, 0, 1, 1, 0, 0, 0, 0, 1, 1};
  static const double kHi[NNUM] = {MAX_LINKS, MAX_MACRO, MAX_DT_S, MAX_ROD_TOL, MAX_STEP_ORDER,
                                   MAX_STEP_TOL, MAX_VALUE, 1, MAX_VALUE, MAX_VALUE};
  static const int kInt[NNUM] = {1, 1, 0, 0, 1, 0, 0, 1, 0, 0};
  for (int c = 2; c < 2 + NNUM; c++) {
    csStatus st = parseField(field[c], c, kLo[c - 2], kOpen[c - 2], kHi[c - 2], kInt[c - 2],
                             path, line, &v[c - 2], err);
    if (st != CS_OK) {
      return st;
    }
  }
  r->links = (int)v[0];
  r->macro_steps = (int)v[1];
  r->dt_s = v[2];
  r->rod_tol = v[3];
  r->step_order = (int)v[4];
  r->step_tol_mm = v[5];
  r->error_mm = v[6];
  r->whole_run = (int)v[7];
  r->cpu_s_per_s = v[8];
  r->wall_s_per_s = v[9];
  /* the adaptive step is the tree step's (core/sim_adaptive.c; either formula): a row the run
   * would refuse is refused here, at its line */
  if (r->step_tol_mm > 0 && !csr_legTypeFind(r->level, NULL)->prepare) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: step_tol_mm %g on level '%s': the adaptive "
                       "step is a tree-stepped level's (strain); 0 for a fixed step", path,
                       line, r->step_tol_mm, r->level);
  }
  snprintf(r->machine, sizeof r->machine, "%s", field[12]);
  return CS_OK;
}


csStatus csr_levelTableRead(const char* path, csrLevelTable* t, csError* err) {
  t->nrow = 0;
  snprintf(t->path, sizeof t->path, "%s", path);
  csuLineReader r;
  csStatus st = csu_lineOpen(&r, path, MAX_LINE, "leg-level table", err);
  if (st != CS_OK) {
    return st;
  }
  int have_header = 0, fmt = 0, rc;
  while ((rc = csu_lineNext(&r, err)) == 1) {
    char* line = csu_trimBlanks(r.line);
    if (!line[0] || line[0] == '#') {
      continue;
    }
    if (!have_header) {
      for (fmt = 0; fmt < NFORMAT && strcmp(line, kFormat[fmt].header) != 0; fmt++) {
      }
      if (fmt == NFORMAT) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: the header must be '%s' (got '%.60s')",
                         path, r.lineno, kFormat[0].header, line);
        break;
      }
      have_header = 1;
      continue;
    }
    char* raw[NCOL];
    int n = splitFields(line, raw);
    if (n != kFormat[fmt].ncol) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %d field%s, expected %d (%s)", path,
                       r.lineno, n, n == 1 ? "" : "s", kFormat[fmt].ncol, kFormat[fmt].header);
      break;
    }
    /* an older format's missing columns at their defaults, in their places */
    static char kOne[] = "1", kZero[] = "0", kUnknown[] = "-1";
    char* field[NCOL];
    for (int c = 0, j = 0; c < NCOL; c++) {
      field[c] = !(kFormat[fmt].missing >> c & 1u) ? raw[j++]
                 : c == COL_ROD_TOL                ? kOne
                 : c == COL_WHOLE                  ? kUnknown
                                                   : kZero;
    }
    if (t->nrow == CSR_LEVELS_MAX_ROWS) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: more than %d rows", path, r.lineno,
                       CSR_LEVELS_MAX_ROWS);
      break;
    }
    csrLevelRow* row = &t->row[t->nrow];
    st = parseRow(field, path, r.lineno, row, err);
    if (st != CS_OK) {
      break;
    }
    /* one measurement per configuration: two would leave the pick to the row order */
    for (int i = 0; i < t->nrow; i++) {
      const csrLevelRow* o = &t->row[i];
      if (!strcmp(o->scene, row->scene) && !strcmp(o->level, row->level) &&
          o->links == row->links && o->macro_steps == row->macro_steps && o->dt_s == row->dt_s &&
          o->rod_tol == row->rod_tol && o->step_order == row->step_order &&
          o->step_tol_mm == row->step_tol_mm) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: repeats the configuration of line %d "
                         "(%s, %s, links %d, macro steps %d, dt %g s, rod tol %g, step order "
                         "%d, step tol %g mm)", path, r.lineno, o->line, row->scene, row->level,
                         row->links, row->macro_steps, row->dt_s, row->rod_tol,
                         row->step_order, row->step_tol_mm);
        break;
      }
    }
    if (st != CS_OK) {
      break;
    }
    t->nrow++;
  }
  if (rc < 0) {
    st = (csStatus)rc;
  }
  if (st == CS_OK && !have_header && r.lineno == 0) {
    /* an empty file has no line to name (found by fuzz_levels) */
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: empty file: no header line '%s'", path, kFormat[0].header);
  } else if (st == CS_OK && !have_header) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: no header line '%s'", path, r.lineno, kFormat[0].header);
  } else if (st == CS_OK && t->nrow == 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: no rows after the header", path, r.lineno);
  }
  csu_lineClose(&r);
  if (st != CS_OK) {
    t->nrow = 0;
  }
  return st;
}


int csr_levelTableCount(const csrLevelTable* t, const char* scene) {
  int n = 0;
  for (int i = 0; i < t->nrow; i++) {
    n += !strcmp(t->row[i].scene, scene);
  }
  return n;
}


int csr_levelTableFinest(const csrLevelTable* t, const char* scene) {
  int best = -1;
  for (int i = 0; i < t->nrow; i++) {
    const csrLevelRow* r = &t->row[i];
    if (strcmp(r->scene, scene) || r->whole_run == 0) {
      continue;
    }
    if (best < 0 || r->error_mm < t->row[best].error_mm ||
        (r->error_mm == t->row[best].error_mm && r->cpu_s_per_s < t->row[best].cpu_s_per_s)) {
      best = i;
    }
  }
  return best;
}


int csr_levelTableCostliest(const csrLevelTable* t, const char* scene) {
  int top = -1;
  for (int i = 0; i < t->nrow; i++) {
    if (!strcmp(t->row[i].scene, scene) &&
        (top < 0 || t->row[i].cpu_s_per_s > t->row[top].cpu_s_per_s)) {
      top = i;
    }
  }
  return top;
}


/* is row r of the step kind asked? */
static int ofKind(const csrLevelRow* r, csrStepKind kind) {
  return kind == CSR_STEP_ANY || (kind == CSR_STEP_ADAPTIVE) == (r->step_tol_mm > 0);
}


int csr_levelTablePick(const csrLevelTable* t, const char* scene, double tol_mm, csError* err) {
  return csr_levelTablePickStep(t, scene, tol_mm, CSR_STEP_ANY, err);
}


int csr_levelTablePickStep(const csrLevelTable* t, const char* scene, double tol_mm,
                           csrStepKind kind, csError* err) {
  if (!(tol_mm >= 0) || !isfinite(tol_mm)) {
    cs_errorSet(err, CS_ERR_RANGE, "--tol %g mm must be finite and >= 0", tol_mm);
    return -1;
  }
  int best = -1, fin = -1, n = 0, failed = -1, nfailed = 0;
  for (int i = 0; i < t->nrow; i++) {
    const csrLevelRow* r = &t->row[i];
    if (strcmp(r->scene, scene) || !ofKind(r, kind)) {
      continue;
    }
    n++;
    /* a row whose whole run misses the scene's goal (falls later than its measured window,
     * say) is never picked; within tol it is counted for the message */
    if (r->whole_run == 0) {
      if (r->error_mm <= tol_mm) {
        nfailed++;
        if (failed < 0 || r->cpu_s_per_s < t->row[failed].cpu_s_per_s) {
          failed = i;
        }
      }
      continue;
    }
    /* the most accurate of the kind, for the message when none is within tol */
    if (fin < 0 || r->error_mm < t->row[fin].error_mm ||
        (r->error_mm == t->row[fin].error_mm && r->cpu_s_per_s < t->row[fin].cpu_s_per_s)) {
      fin = i;
    }
    if (!(r->error_mm <= tol_mm)) {
      continue;
    }
    if (best < 0 || r->cpu_s_per_s < t->row[best].cpu_s_per_s ||
        (r->cpu_s_per_s == t->row[best].cpu_s_per_s && r->error_mm < t->row[best].error_mm)) {
      best = i;
    }
  }
  if (best >= 0) {
    return best;
  }
  const char* what = kind == CSR_STEP_FIXED ? " with a fixed step (--strain-step fixed)"
                     : kind == CSR_STEP_ADAPTIVE
                         ? " with the adaptive step (--strain-step adaptive; a row with "
                           "step_tol_mm > 0)"
                         : "";
  if (n == 0 && csr_levelTableCount(t, scene) > 0) {
    cs_errorSet(err, CS_ERR_ARG, "%s: no row for scene '%.31s'%s (rerun tools/bench_levels.py "
                "with such configurations)", t->path, scene, what);
  } else if (n == 0) {
    cs_errorSet(err, CS_ERR_ARG, "%s: no row for scene '%.31s' (the table measures another "
                "scene; rerun tools/bench_levels.py with --scenes)", t->path, scene);
  } else if (nfailed > 0) {
    const csrLevelRow* r = &t->row[failed];
    cs_errorSet(err, CS_ERR_RANGE, "%s: no level meets --tol %g mm on %s%s with a whole run "
                "that reaches the scene's goal: %d row%s within it fail%s (whole_run 0; "
                "the cheapest %s, links %d, macro steps %d, dt %g s, line %d)", t->path, tol_mm,
                scene, what, nfailed, nfailed == 1 ? "" : "s",
                nfailed == 1 ? "s its own" : " theirs",
                r->level, r->links, r->macro_steps, r->dt_s, r->line);
  } else if (fin < 0) {
    cs_errorSet(err, CS_ERR_RANGE, "%s: every row for scene '%.31s'%s fails the scene's whole "
                "run (whole_run 0): no configuration to pick", t->path, scene, what);
  } else {
    const csrLevelRow* r = &t->row[fin];
    char steptol[48] = "";
    if (r->step_tol_mm > 0) {
      snprintf(steptol, sizeof steptol, ", adaptive step at %g mm", r->step_tol_mm);
    }
    cs_errorSet(err, CS_ERR_RANGE, "%s: no level meets --tol %g mm on %s%s: the best "
                "achievable is %.3g mm (%s, links %d, macro steps %d, dt %g s%s, line %d)",
                t->path, tol_mm, scene, what, r->error_mm, r->level, r->links, r->macro_steps,
                r->dt_s, steptol, r->line);
  }
  return -1;
}


int csr_levelTableFailing(const csrLevelTable* t, const char* scene, double tol_mm,
                          csrStepKind kind, double cpu_below) {
  int n = 0;
  for (int i = 0; i < t->nrow; i++) {
    const csrLevelRow* r = &t->row[i];
    n += !strcmp(r->scene, scene) && ofKind(r, kind) && r->error_mm <= tol_mm &&
         r->whole_run == 0 && r->cpu_s_per_s < cpu_below;
  }
  return n;
}
