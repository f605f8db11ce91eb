/* gaits_csv.c: gait table, CSV reader/writer, validation (see gaits_csv.h).
 *
 * Lines come from the shared line reader (core_text.h: one buffer of max_line_bytes + 2, so a
 * huge line or a binary file is refused before anything grows; LF/CRLF, a byte-order mark,
 * NUL bytes and stray CRs handled there); rows grow by doubling up to max_rows. Lines are split
 * in place at ',' and parsed left to right, so the first error in reading order is the one
 * reported. */
#include "gaits_csv.h"

#include "core_text.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* rows allocated by the first growth step of a table being read (then doubled) */
#define INITIAL_ROW_CAP 16
/* smallest line limit accepted in csgReadOptions (the header of one named column is 14 B) */
#define MIN_LINE_BYTES 64
/* longest field or column text quoted in a message (bytes) */
#define QUOTE_MAX 40
/* size of the "(limit ...)" text of a pressure message */
#define LIMIT_TEXT 128
/* significant digits of written pressures (gaits_csv.h); times use 6..17 digits */
#define WRITE_DIGITS 6
#define ROUNDTRIP_DIGITS 17

/* true if the line holds only spaces/tabs or starts (after them) with '#' */
static int isSkippable(const char* line);
/* grow g's arrays to hold at least `need` rows (capacity doubling, limit `max_rows`) */
static csStatus reserveRows(csgGait* g, long need, long max_rows, csError* err);
/* check an options struct */
static csStatus checkOptions(const csgReadOptions* opt, csError* err);
/* check one pressure value against the rules: NULL if fine, else the cause as text
 * (`limit` gets the limit's description, "" when the limit is not the cause) */
static const char* pressureProblem(double p, double max_pressure, char* limit, size_t size);


csgReadOptions csg_defaultReadOptions(void) {
  csgReadOptions o;
  o.max_pressure = CSG_DEFAULT_MAX_PRESSURE;
  o.max_rows = CSG_DEFAULT_MAX_ROWS;
  o.max_line_bytes = CSG_DEFAULT_MAX_LINE_BYTES;
  return o;
}


/* ---- table ---- */

csgGait* csg_gaitCreate(int nrow, csError* err) {
  if (nrow < 0) {
    cs_errorSet(err, CS_ERR_ARG, "csg_gaitCreate: negative row count %d", nrow);
    return NULL;
  }
  csgGait* g = calloc(1, sizeof *g);
  if (!g) {
    cs_errorSet(err, CS_ERR_MEMORY, "csg_gaitCreate: out of memory");
    return NULL;
  }
  g->ramp = NAN; /* states none: the run's ramp applies */
  if (csg_gaitSetRowCount(g, nrow, err) != CS_OK) {
    csg_gaitDestroy(g);
    return NULL;
  }
  return g;
}


void csg_gaitDestroy(csgGait* g) {
  if (g) {
    free(g->time);
    free(g->pressure);
    free(g);
  }
}


static csStatus reserveRows(csgGait* g, long need, long max_rows, csError* err) {
  if (need <= g->cap) {
    return CS_OK;
  }
  /* double, but never past the limit, so the largest block is bounded by max_rows */
  long cap = g->cap > 0 ? g->cap : INITIAL_ROW_CAP;
  while (cap < need) {
    cap = cap > LONG_MAX / 2 ? LONG_MAX : 2 * cap;
  }
  if (cap > max_rows) {
    cap = max_rows;
  }
  if (cap < need || cap > INT_MAX || (size_t)cap > SIZE_MAX / (CSG_NLABEL * sizeof(double))) {
    return cs_errorSet(err, CS_ERR_MEMORY, "gait table of %ld rows is too large", need);
  }
  double* t = realloc(g->time, (size_t)cap * sizeof *t);
  if (!t) {
    return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for %ld gait rows", cap);
  }
  g->time = t;
  double* p = realloc(g->pressure, (size_t)cap * CSG_NLABEL * sizeof *p);
  if (!p) {
    return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for %ld gait rows", cap);
  }
  g->pressure = p;
  g->cap = (int)cap;
  return CS_OK;
}


csStatus csg_gaitSetRowCount(csgGait* g, int nrow, csError* err) {
  if (!g || nrow < 0) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetRowCount: %s",
                       g ? "negative row count" : "NULL gait");
  }
  /* exact size when building in code; the reader's doubling happens in csg_gaitRead */
  if (nrow > g->cap) {
    csStatus st = reserveRows(g, nrow, nrow, err);
    if (st != CS_OK) {
      return st;
    }
  }
  for (int i = g->nrow; i < nrow; i++) {
    g->time[i] = 0.0;
    memset(&g->pressure[(size_t)CSG_NLABEL * i], 0, CSG_NLABEL * sizeof(double));
  }
  g->nrow = nrow;
  return CS_OK;
}


csStatus csg_gaitSetTime(csgGait* g, int row, double t, csError* err) {
  if (!g || row < 0 || row >= g->nrow) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetTime: row %d outside 0..%d", row,
                       g ? g->nrow - 1 : -1);
  }
  if (!isfinite(t)) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetTime: row %d: time is not finite", row);
  }
  g->time[row] = t;
  return CS_OK;
}


csStatus csg_gaitSetPressure(csgGait* g, int row, int label, double p, csError* err) {
  if (!g || row < 0 || row >= g->nrow) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetPressure: row %d outside 0..%d", row,
                       g ? g->nrow - 1 : -1);
  }
  if (label < 1 || label > CSG_NLABEL) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetPressure: label %d outside 1..%d", label,
                       CSG_NLABEL);
  }
  if (!isfinite(p)) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitSetPressure: row %d, label %d: not finite", row,
                       label);
  }
  g->pressure[(size_t)CSG_NLABEL * row + (label - 1)] = p;
  return CS_OK;
}


double csg_gaitTime(const csgGait* g, int row) {
  if (!g || row < 0 || row >= g->nrow) {
    return NAN;
  }
  return g->time[row];
}


double csg_gaitPressure(const csgGait* g, int row, int label) {
  if (!g || row < 0 || row >= g->nrow || label < 1 || label > CSG_NLABEL) {
    return NAN;
  }
  return g->pressure[(size_t)CSG_NLABEL * row + (label - 1)];
}


/* ---- validation ---- */

static csStatus checkOptions(const csgReadOptions* opt, csError* err) {
  if (!(opt->max_pressure > 0.0) || !isfinite(opt->max_pressure)) {
    return cs_errorSet(err, CS_ERR_ARG, "gait reader: max_pressure %g MPa must be > 0 and finite",
                       opt->max_pressure);
  }
  if (opt->max_rows < 1 || opt->max_rows > INT_MAX) {
    return cs_errorSet(err, CS_ERR_ARG, "gait reader: max_rows %ld outside 1..%d", opt->max_rows,
                       INT_MAX);
  }
  if (opt->max_line_bytes < MIN_LINE_BYTES || opt->max_line_bytes > SIZE_MAX / 2) {
    return cs_errorSet(err, CS_ERR_ARG,
                       "gait reader: max_line_bytes %zu is below %d or absurdly large",
                       opt->max_line_bytes, MIN_LINE_BYTES);
  }
  return CS_OK;
}


static const char* pressureProblem(double p, double max_pressure, char* limit, size_t size) {
  limit[0] = '\0';
  if (!isfinite(p)) {
    return "pressure is not finite";
  }
  if (p < 0.0) {
    return "negative pressure (gauge pressure: 0 = vented)";
  }
  if (p > max_pressure) {
    snprintf(limit, size, " (limit %g MPa, the reader's max_pressure; kPa or bar typed as MPa?)",
             max_pressure);
    return "pressure above the limit";
  }
  return NULL;
}


/* shared by csg_gaitValidate and csg_gaitWrite: max_pressure INFINITY = no limit */
static csStatus validateTable(const csgGait* g, double max_pressure, long max_rows, const char* who,
                              csError* err) {
  if (!g) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: NULL gait", who);
  }
  if (g->nrow < 1) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: gait has no rows", who);
  }
  if (g->nrow > max_rows) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: gait has %d rows, more than the limit %ld", who,
                       g->nrow, max_rows);
  }
  if (!isnan(g->ramp) && !(isfinite(g->ramp) && g->ramp >= 0.0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: gait ramp %g s must be >= 0 and finite (or NaN: "
                       "none stated)", who, g->ramp);
  }
  for (int i = 0; i < g->nrow; i++) {
    double t = g->time[i];
    if (!isfinite(t)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s: gait row %d: time is not finite", who, i);
    }
    if (t < 0.0) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s: gait row %d: negative time %g s", who, i, t);
    }
    if (i > 0 && !(t > g->time[i - 1])) {
      return cs_errorSet(
          err, CS_ERR_RANGE,
          "%s: gait row %d: time %.15g s not after row %d's %.15g s (times must increase strictly)",
          who, i, t, i - 1, g->time[i - 1]);
    }
    for (int l = 1; l <= CSG_NLABEL; l++) {
      double p = g->pressure[(size_t)CSG_NLABEL * i + (l - 1)];
      char limit[LIMIT_TEXT];
      const char* why = pressureProblem(p, max_pressure, limit, sizeof limit);
      if (why) {
        char name[CSG_LABEL_NAME_SIZE];
        csg_labelName(l, name, sizeof name);
        return cs_errorSet(err, CS_ERR_RANGE,
                           "%s: gait row %d (t = %g s), chamber %s: %s: %g MPa%s", who, i, t, name,
                           why, p, limit);
      }
    }
  }
  return CS_OK;
}


csStatus csg_gaitValidate(const csgGait* g, const csgReadOptions* opt, csError* err) {
  csgReadOptions o = opt ? *opt : csg_defaultReadOptions();
  csStatus st = checkOptions(&o, err);
  if (st != CS_OK) {
    return st;
  }
  return validateTable(g, o.max_pressure, o.max_rows, "csg_gaitValidate", err);
}


/* ---- reading ---- */

static int isSkippable(const char* line) {
  while (*line == ' ' || *line == '\t') {
    line++;
  }
  return *line == '\0' || *line == '#';
}


/* cut the next ','-separated field off *cursor (in place); NULL when the line is used up */
static char* nextField(char** cursor) {
  char* s = *cursor;
  if (!s) {
    return NULL;
  }
  char* comma = strchr(s, ',');
  if (comma) {
    *comma = '\0';
    *cursor = comma + 1;
  } else {
    *cursor = NULL;
  }
  return s;
}


/* number of ','-separated fields left in a cursor */
static int countFields(const char* s) {
  if (!s) {
    return 0;
  }
  int n = 1;
  for (; *s; s++) {
    n += *s == ',';
  }
  return n;
}


/* what the reader knows about the header: 0-based column c >= 1 holds chamber label[c] */
typedef struct {
  int ncol;                  /* fields per row, time included */
  int label[CSG_NLABEL + 1]; /* (ncol) label of column c; label[0] unused (time) */
  int where[CSG_NLABEL + 1]; /* (97) 1-based column of each label, 0 = not given */
} headerInfo;

/* parse the header line into h; CS_OK or a parse error naming line and column */
static csStatus parseHeader(csuLineReader* r, headerInfo* h, csError* err) {
  memset(h, 0, sizeof *h);
  char* cursor = r->line;
  char* f;
  int col = 0;
  while ((f = nextField(&cursor)) != NULL) {
    col++;
    char* name = csu_trimBlanks(f);
    if (col == 1) {
      if (strcmp(name, "time") != 0) {
        return cs_errorSet(err, CS_ERR_PARSE,
                           "%s:%ld: column 1: header must start with 'time', got '%.*s'%s", r->path,
                           r->lineno, QUOTE_MAX, name,
                           strchr(name, ';') ? " (the separator is ',', not ';')" : "");
      }
      continue;
    }
    if (!name[0]) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: column %d: empty column name", r->path,
                         r->lineno, col);
    }
    int label = csg_labelParse(name);
    if (!label) {
      return cs_errorSet(err, CS_ERR_PARSE,
                         "%s:%ld: column %d: unknown column '%.*s' (expected a chamber name "
                         "A_II1_O1..H_II3_O4 or a label 1..96)",
                         r->path, r->lineno, col, QUOTE_MAX, name);
    }
    if (h->where[label]) {
      char cname[CSG_LABEL_NAME_SIZE];
      csg_labelName(label, cname, sizeof cname);
      return cs_errorSet(
          err, CS_ERR_PARSE,
          "%s:%ld: column %d (%.*s): chamber %s (label %d) given twice, also in column %d", r->path,
          r->lineno, col, QUOTE_MAX, name, cname, label, h->where[label]);
    }
    /* 96 distinct labels at most pass the two checks above, so col <= 97 here */
    h->where[label] = col;
    h->label[col - 1] = label;
  }
  h->ncol = col;
  return CS_OK;
}


/* parse a number field (already NUL-terminated); 1 = ok, 0 = not a (whole) number */
static int parseNumber(char* field, double* out) {
  char* s = csu_trimBlanks(field);
  if (!s[0]) {
    return 0;
  }
  char* end = NULL;
  errno = 0;
  double v = strtod(s, &end);
  if (end == s || *end != '\0') {
    return 0;
  }
  *out = v; /* overflow gives +-HUGE_VAL (caught as not finite); underflow a tiny value: ok */
  return 1;
}


/* A comment line that is a directive (`# @name value`, gaits_csv.h) sets it in g; any other
 * comment or blank line is left alone. CS_OK, or an error naming the line. */
static csStatus readDirective(csuLineReader* r, csgGait* g, csError* err) {
  const char* s = r->line;
  s += strspn(s, " \t");
  if (*s != '#') {
    return CS_OK;
  }
  s++;
  s += strspn(s, " \t");
  if (*s != '@') {
    return CS_OK;
  }
  s++;
  size_t n = strcspn(s, " \t");
  if (n != 4 || strncmp(s, "ramp", 4) != 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: unknown directive '@%.*s' (known: @ramp S)",
                       r->path, r->lineno, (int)(n < QUOTE_MAX ? n : QUOTE_MAX), s);
  }
  if (!isnan(g->ramp)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: @ramp stated twice", r->path, r->lineno);
  }
  const char* value = s + n + strspn(s + n, " \t");
  char* end = NULL;
  double v = strtod(value, &end);
  if (end == value || end[strspn(end, " \t")] != '\0') {
    size_t m = strlen(value);
    while (m > 0 && (value[m - 1] == ' ' || value[m - 1] == '\t')) {
      m--;
    }
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: @ramp needs one number (s), got '%.*s'",
                       r->path, r->lineno, (int)(m < QUOTE_MAX ? m : QUOTE_MAX), value);
  }
  if (!isfinite(v) || v < 0.0) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: @ramp %g s must be >= 0 and finite", r->path,
                       r->lineno, v);
  }
  g->ramp = v;
  return CS_OK;
}


/* parse one data row into row `i` of g; CS_OK or an error naming line and column */
static csStatus parseRow(csuLineReader* r, const headerInfo* h, csgGait* g, int i,
                         const csgReadOptions* opt, long prev_lineno, csError* err) {
  double* prow = &g->pressure[(size_t)CSG_NLABEL * i];
  memset(prow, 0, CSG_NLABEL * sizeof *prow);
  char* cursor = r->line;
  for (int col = 1; col <= h->ncol; col++) {
    char cname[CSG_LABEL_NAME_SIZE] = "time";
    if (col > 1) {
      csg_labelName(h->label[col - 1], cname, sizeof cname);
    }
    char* f = nextField(&cursor);
    if (!f) {
      return cs_errorSet(err, CS_ERR_PARSE,
                         "%s:%ld: column %d (%s): missing field: row has %d fields, header has %d",
                         r->path, r->lineno, col, cname, col - 1, h->ncol);
    }
    double v;
    if (!parseNumber(f, &v)) {
      const char* s = csu_trimBlanks(f);
      if (!s[0]) {
        return cs_errorSet(err, CS_ERR_PARSE,
                           "%s:%ld: column %d (%s): empty field (expected a number)", r->path,
                           r->lineno, col, cname);
      }
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: column %d (%s): '%.*s' is not a number",
                         r->path, r->lineno, col, cname, QUOTE_MAX, s);
    }
    if (!isfinite(v)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: column %d (%s): value '%.*s' is not finite",
                         r->path, r->lineno, col, cname, QUOTE_MAX, csu_trimBlanks(f));
    }
    if (col == 1) {
      if (v < 0.0) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: column 1 (time): negative time %g s",
                           r->path, r->lineno, v);
      }
      if (i > 0 && !(v > g->time[i - 1])) {
        return cs_errorSet(err, CS_ERR_RANGE,
                           "%s:%ld: column 1 (time): time %.15g s is not after %.15g s on line %ld "
                           "(times must increase strictly)",
                           r->path, r->lineno, v, g->time[i - 1], prev_lineno);
      }
      g->time[i] = v;
      continue;
    }
    char limit[LIMIT_TEXT];
    const char* why = pressureProblem(v, opt->max_pressure, limit, sizeof limit);
    if (why) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: column %d (%s): %s: %g MPa%s", r->path,
                         r->lineno, col, cname, why, v, limit);
    }
    prow[h->label[col - 1] - 1] = v;
  }
  if (cursor) {
    return cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%ld: column %d: extra field: row has %d fields, header has %d", r->path,
                       r->lineno, h->ncol + 1, h->ncol + countFields(cursor), h->ncol);
  }
  return CS_OK;
}


/* the reading proper, on an open reader; fills g */
static csStatus readTable(csuLineReader* r, csgGait* g, const csgReadOptions* opt, csError* err) {
  /* header: the first line that is neither blank nor a comment */
  int got;
  int first = 1;
  while ((got = csu_lineNext(r, err)) > 0) {
    first = 0;
    if (!isSkippable(r->line)) {
      break;
    }
    csStatus dst = readDirective(r, g, err);
    if (dst != CS_OK) {
      return dst;
    }
  }
  if (got < 0) {
    return (csStatus)got;
  }
  if (got == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: expected a header line 'time,<chamber>,...'",
                       r->path, r->lineno > 0 ? r->lineno : 1,
                       first ? "empty file" : "no header (only blank or comment lines)");
  }
  headerInfo h;
  csStatus st = parseHeader(r, &h, err);
  if (st != CS_OK) {
    return st;
  }
  long header_line = r->lineno;

  /* data rows */
  long prev_lineno = 0;
  while ((got = csu_lineNext(r, err)) > 0) {
    if (isSkippable(r->line)) {
      st = readDirective(r, g, err);
      if (st != CS_OK) {
        return st;
      }
      continue;
    }
    if (g->nrow >= opt->max_rows) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "%s:%ld: more than %ld data rows (the reader's max_rows limit)", r->path,
                         r->lineno, opt->max_rows);
    }
    st = reserveRows(g, (long)g->nrow + 1, opt->max_rows, err);
    if (st != CS_OK) {
      return st;
    }
    st = parseRow(r, &h, g, g->nrow, opt, prev_lineno, err);
    if (st != CS_OK) {
      return st;
    }
    g->nrow++;
    prev_lineno = r->lineno;
  }
  if (got < 0) {
    return (csStatus)got;
  }
  if (g->nrow == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: header has no data rows after it", r->path,
                       header_line);
  }
  return CS_OK;
}


csgGait* csg_gaitRead(const char* path, const csgReadOptions* opt, csError* err) {
  if (!path) {
    cs_errorSet(err, CS_ERR_ARG, "csg_gaitRead: NULL path");
    return NULL;
  }
  csgReadOptions o = opt ? *opt : csg_defaultReadOptions();
  if (checkOptions(&o, err) != CS_OK) {
    return NULL;
  }

  csgGait* g = calloc(1, sizeof *g);
  if (!g) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  g->ramp = NAN; /* until a `# @ramp` line states one */
  /* the reader holds one line buffer of max_line_bytes + 2 and an 8 KiB chunk: on the heap */
  csuLineReader* r = malloc(sizeof *r);
  csStatus st = r ? csu_lineOpen(r, path, o.max_line_bytes, "gait CSV", err)
                  : cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  if (st == CS_OK) {
    st = readTable(r, g, &o, err);
  }
  csu_lineClose(r);
  free(r);
  if (st != CS_OK) {
    csg_gaitDestroy(g);
    return NULL;
  }
  return g;
}


/* ---- writing ---- */

/* shortest %.<d>g (d = 6..17) of t that reads back exactly, so written times keep their order */
static void formatTime(double t, char* buf, size_t size) {
  for (int d = WRITE_DIGITS; d <= ROUNDTRIP_DIGITS; d++) {
    snprintf(buf, size, "%.*g", d, t);
    if (strtod(buf, NULL) == t) {
      return;
    }
  }
}


csStatus csg_gaitWrite(const csgGait* g, const char* path, const char* comment, csError* err) {
  if (!path) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitWrite: NULL path");
  }
  csStatus st = validateTable(g, INFINITY, INT_MAX, "csg_gaitWrite", err);
  if (st != CS_OK) {
    return st;
  }
  FILE* f = fopen(path, "wb");
  if (!f) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open for writing: %s", path, strerror(errno));
  }
  int bad = 0;

  /* comment lines: one '#' line per '\n'-separated line of the comment */
  for (const char* c = comment; c && *c;) {
    size_t n = strcspn(c, "\n");
    bad |= fprintf(f, "# %.*s\n", (int)n, c) < 0;
    c += n + (c[n] == '\n');
  }

  /* the stated ramp, read back exactly */
  if (!isnan(g->ramp)) {
    char rbuf[64];
    formatTime(g->ramp, rbuf, sizeof rbuf);
    bad |= fprintf(f, "# @ramp %s\n", rbuf) < 0;
  }

  /* header: all 96 chambers by name, in label order */
  bad |= fputs("time", f) < 0;
  for (int l = 1; l <= CSG_NLABEL; l++) {
    char name[CSG_LABEL_NAME_SIZE];
    csg_labelName(l, name, sizeof name);
    bad |= fprintf(f, ",%s", name) < 0;
  }
  bad |= fputc('\n', f) == EOF;

  /* rows */
  for (int i = 0; i < g->nrow && !bad; i++) {
    char tbuf[64];
    formatTime(g->time[i], tbuf, sizeof tbuf);
    bad |= fputs(tbuf, f) < 0;
    const double* prow = &g->pressure[(size_t)CSG_NLABEL * i];
    for (int l = 0; l < CSG_NLABEL; l++) {
      /* +0.0 turns a -0.0 into 0 so the file never shows "-0" */
      bad |= fprintf(f, ",%.*g", WRITE_DIGITS, prow[l] + 0.0) < 0;
    }
    bad |= fputc('\n', f) == EOF;
  }
  int close_failed = fclose(f) != 0;
  if (bad || close_failed) {
    return cs_errorSet(err, CS_ERR_IO, "%s: write error: %s", path, strerror(errno));
  }
  return CS_OK;
}


/* ---- summary ---- */

csStatus csg_gaitComputeSummary(const csgGait* g, csgGaitSummary* s, csError* err) {
  if (!g || !s || g->nrow < 1) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_gaitComputeSummary: %s",
                       !g || !s ? "NULL argument" : "gait has no rows");
  }
  memset(s, 0, sizeof *s);
  s->nrow = g->nrow;
  s->t_first = g->time[0];
  s->t_last = g->time[g->nrow - 1];
  s->p_max_row = -1;
  for (int l = 1; l <= CSG_NLABEL; l++) {
    int used = 0;
    for (int i = 0; i < g->nrow; i++) {
      double p = g->pressure[(size_t)CSG_NLABEL * i + (l - 1)];
      used |= p > 0.0;
      /* first occurrence in (row, label) order wins ties */
      if (p > s->p_max || (p == s->p_max && p > 0.0 && i < s->p_max_row)) {
        s->p_max = p;
        s->p_max_label = l;
        s->p_max_row = i;
      }
    }
    s->nused += used;
  }
  return CS_OK;
}
