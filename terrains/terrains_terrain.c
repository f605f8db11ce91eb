/* terrains_terrain.c: terrain description files and their ODE geoms (see terrains_terrain.h).
 *
 * The parser reads one line at a time with the shared line reader (core_text.h, not fgets) so
 * that an overlong line or a NUL byte is reported at its line instead of being split into two
 * statements or cut short; each line is split into whitespace-separated words and every
 * statement checks its word count, so nothing after a statement's values is silently ignored. Numbers are parsed
 * with strtod and then checked to be finite: strtod itself accepts "nan", "inf" and returns
 * HUGE_VAL for "1e999", none of which is a usable coordinate. */
#include "terrains_terrain.h"

#include "core_text.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
  MAX_LINE = 1023, /* bytes per line, line ending excluded */
  MAX_WORDS = 8    /* words kept per line; more are counted, not stored */
};

/* coordinates beyond 1 km are a typo, and their box sizes could overflow in ODE */
#define MAX_COORD_MM 1e6
/* a heading is an angle: more than one turn either way is a typo */
#define MAX_HEADING_DEG 360.0

/* one input line split into words (pointers into the line buffer) */
typedef struct {
  char* word[MAX_WORDS];
  int nword; /* words on the line, may exceed MAX_WORDS */
} Words;

/* parse one finite number: 0 = ok, 1 = not a number, 2 = not finite */
static int parseFinite(const char* s, double* v);

/* parse w->word[1..n] as numbers of statement `key` (checking the count); fills err on failure */
static csStatus parseValues(const Words* w, double* v, int n, const char* what,
                            const char* path, int lineno, csError* err);


static int parseFinite(const char* s, double* v) {
  char* end;
  errno = 0;
  *v = strtod(s, &end);
  if (end == s || *end) {
    return 1;
  }
  /* underflow (ERANGE with a tiny result) is harmless; overflow gives HUGE_VAL */
  return isfinite(*v) ? 0 : 2;
}


static csStatus parseValues(const Words* w, double* v, int n, const char* what,
                            const char* path, int lineno, csError* err) {
  const char* key = w->word[0];
  if (w->nword - 1 != n) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' needs %d number%s %s, got %d value%s",
                       path, lineno, key, n, n == 1 ? "" : "s", what, w->nword - 1,
                       w->nword == 2 ? "" : "s");
  }
  for (int i = 0; i < n; i++) {
    const char* s = w->word[i + 1];
    int rc = parseFinite(s, &v[i]);
    if (rc == 1) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' value %d '%.40s' is not a number", path,
                         lineno, key, i + 1, s);
    }
    if (rc == 2) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "%s:%d: '%s' value %d '%.40s' is not a finite number (nan, inf or "
                         "beyond the double range)",
                         path, lineno, key, i + 1, s);
    }
  }
  return CS_OK;
}


csStatus cst_terrainLoad(cstTerrain* t, const char* path, csError* err) {
  memset(t, 0, sizeof *t);
  snprintf(t->source, sizeof t->source, "%s", path);
  csuLineReader* r = malloc(sizeof *r); /* an 8 KiB chunk: not on the stack */
  csStatus st = r ? csu_lineOpen(r, path, MAX_LINE, "terrain file", err)
                  : cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  int lineno = 0, got = 0;
  int start_line = 0, name_line = 0, heading_line = 0; /* where each was given, 0 = not yet */
  while (st == CS_OK && (got = csu_lineNext(r, err)) > 0) {
    lineno = (int)r->lineno;
    char* line = r->line;
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    Words w;
    w.nword = csu_splitWords(line, w.word, MAX_WORDS);
    if (w.nword == 0) {
      continue; /* blank or comment */
    }
    const char* key = w.word[0];
    double v[6];
    if (!strcmp(key, "name")) {
      /* one word that fits the name buffer; never cut short silently */
      if (w.nword != 2) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'name' needs one word, got %d", path, lineno,
                         w.nword - 1);
      } else if (strlen(w.word[1]) >= sizeof t->name) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: name longer than %d characters", path, lineno,
                         (int)sizeof t->name - 1);
      } else if (name_line) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second 'name' (the first is on line %d)",
                         path, lineno, name_line);
      } else {
        snprintf(t->name, sizeof t->name, "%s", w.word[1]);
        name_line = lineno;
      }
    } else if (!strcmp(key, "box")) {
      st = parseValues(&w, v, 6, "x0 y0 z0 x1 y1 z1 (mm)", path, lineno, err);
      if (st != CS_OK) {
        break;
      }
      for (int i = 0; i < 6 && st == CS_OK; i++) {
        if (fabs(v[i]) > MAX_COORD_MM) {
          st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: box coordinate %g mm is beyond +-%g mm",
                           path, lineno, v[i], MAX_COORD_MM);
        }
      }
      if (st != CS_OK) {
        break;
      }
      if (t->nbox == CST_MAX_BOXES) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d boxes", path, lineno,
                         CST_MAX_BOXES);
        break;
      }
      if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5])) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: box corners must satisfy x0<x1, y0<y1, z0<z1",
                         path, lineno);
        break;
      }
      cstBox* b = &t->box[t->nbox++];
      for (int i = 0; i < 3; i++) {
        b->lo[i] = v[i];
        b->hi[i] = v[i + 3];
      }
    } else if (!strcmp(key, "start")) {
      st = parseValues(&w, v, 2, "x z (mm)", path, lineno, err);
      if (st == CS_OK && start_line) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second 'start' (the first is on line %d)",
                         path, lineno, start_line);
      }
      if (st == CS_OK) {
        t->start[0] = v[0];
        t->start[1] = v[1];
        start_line = lineno;
      }
    } else if (!strcmp(key, "heading")) {
      st = parseValues(&w, v, 1, "(degrees)", path, lineno, err);
      if (st == CS_OK && fabs(v[0]) > MAX_HEADING_DEG) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: heading %g deg is beyond +-%g deg", path,
                         lineno, v[0], MAX_HEADING_DEG);
      }
      if (st == CS_OK && heading_line) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second 'heading' (the first is on line %d)",
                         path, lineno, heading_line);
      }
      if (st == CS_OK) {
        t->heading_deg = v[0];
        heading_line = lineno;
      }
    } else {
      st = cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: unknown statement '%.40s' (expected name, box, start, heading)",
                       path, lineno, key);
    }
  }
  if (st == CS_OK && got < 0) {
    st = (csStatus)got;
  }
  if (r) {
    csu_lineClose(r);
    free(r);
  }
  if (st != CS_OK) {
    return st;
  }
  /* whole-file checks name the last line (the end of the file; line 1 if it is empty) */
  int last = lineno > 0 ? lineno : 1;
  if (t->nbox == 0) {
    return cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: end of file without a 'box' statement: a terrain needs ground",
                       path, last);
  }
  if (!start_line) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: end of file without a 'start' statement", path,
                       last);
  }
  if (!isfinite(cst_terrainHeightAt(t, t->start[0], t->start[1]))) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: start (%g, %g) is not above any box", path,
                       start_line, t->start[0], t->start[1]);
  }
  if (!t->name[0]) {
    snprintf(t->name, sizeof t->name, "unnamed");
  }
  return CS_OK;
}


double cst_terrainHeightAt(const cstTerrain* t, double x, double z) {
  double h = -INFINITY;
  for (int i = 0; i < t->nbox; i++) {
    const cstBox* b = &t->box[i];
    if (x >= b->lo[0] && x <= b->hi[0] && z >= b->lo[2] && z <= b->hi[2] && b->hi[1] > h) {
      h = b->hi[1];
    }
  }
  return h;
}


int cst_terrainBuildOde(const cstTerrain* t, dSpaceID space) {
  for (int i = 0; i < t->nbox; i++) {
    const cstBox* b = &t->box[i];
    dGeomID g = dCreateBox(space, b->hi[0] - b->lo[0], b->hi[1] - b->lo[1], b->hi[2] - b->lo[2]);
    dGeomSetPosition(g, 0.5 * (b->lo[0] + b->hi[0]), 0.5 * (b->lo[1] + b->hi[1]),
                     0.5 * (b->lo[2] + b->hi[2]));
  }
  return t->nbox;
}
