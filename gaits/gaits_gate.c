/* gaits_gate.c: the companion .gate file's reader and one gate's test (gaits_gate.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "gaits_gate.h"

#define MAX_LINE 1024
#define MAX_WORDS 12


void csg_gateDestroy(csgGateSet* s) { free(s); }


int csg_gateDown(const csgGate* g, const double* p, const double* v, double ptol) {
  for (int leg = 0; leg < CSG_NLEG; leg++) {
    if (!(g->legs & (1u << leg))) continue;
    for (int c = 12 * leg; c < 12 * leg + 12; c++) {
      if (fabs(v[c] - p[c]) > fabs(v[c] - g->p_design[c]) + ptol) return 0;
    }
  }
  return 1;
}


int csg_gateReady(const csgGate* g, const double* p, const double* v, double ptol, double x) {
  return csg_gateDown(g, p, v, ptol) && x >= g->xmin;
}


void csg_gateLegs(unsigned legs, char* out) {
  int n = 0;
  for (int l = 0; l < CSG_NLEG; l++) {
    if (legs & (1u << l)) out[n++] = (char)('A' + l);
  }
  out[n] = '\0';
}


/* the rule shared by `crawl` (on z) and `walk` (on x): n slots written, v the support's
 * coordinate at the end of slot j, vprev at the end of slot j - 2 (gaits_gate.h) */
static int endSkip(int n, double vend, double carry, int j, double v, double vprev) {
  const int left = n - 1 - j;
  if (n < 3 || j < 2 || left <= 0 || left % 2) {
    return 0;
  }
  return v + carry >= vend - (v - vprev) / 2 ? left : 0;
}


int csg_gateCrawlSkip(const csgGateSet* s, int j, double z, double zprev) {
  return endSkip(s->crawl_n, s->crawl_zend, s->crawl_carry, j, z, zprev);
}


int csg_gateWalkSkip(const csgGateSet* s, int j, double x, double xprev) {
  return endSkip(s->walk_n, s->walk_xend, s->walk_carry, j, x, xprev);
}


static int number(const char* s, double* v) {
  char* end;
  *v = strtod(s, &end);
  return end != s && !*end && isfinite(*v);
}


/* `design ramp R lag TAU ptol P maxwait W` */
static csStatus statementDesign(csgGateSet* s, char** w, int nw, int* seen, const char* path,
                                int line, csError* err) {
  if (*seen) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: a second 'design' line", path, line);
  }
  if (s->n > 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'design' must come before the gates", path,
                       line);
  }
  if (nw != 9 || strcmp(w[1], "ramp") || strcmp(w[3], "lag") || strcmp(w[5], "ptol") ||
      strcmp(w[7], "maxwait")) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'design' needs ramp R lag TAU ptol P maxwait W",
                       path, line);
  }
  double v[4];
  for (int i = 0; i < 4; i++) {
    if (!number(w[2 + 2 * i], &v[i])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%.40s' is not a finite number", path, line,
                         w[2 + 2 * i]);
    }
  }
  if (!(v[0] >= 0 && v[1] > 0 && v[2] >= 0 && v[3] > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: needs ramp >= 0, lag > 0, ptol >= 0 and "
                       "maxwait > 0 (%g s, %g s, %g MPa, %g s)", path, line, v[0], v[1], v[2],
                       v[3]);
  }
  s->ramp = v[0];
  s->lag = v[1];
  s->ptol = v[2];
  s->maxwait = v[3];
  *seen = 1;
  return CS_OK;
}


/* `gate T LEGS [x XMIN]` */
static csStatus statementGate(csgGateSet* s, char** w, int nw, int seen, const char* path,
                              int line, csError* err) {
  if (!seen) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'gate' before the 'design' line", path, line);
  }
  if (nw != 3 && !(nw == 5 && !strcmp(w[3], "x"))) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'gate' needs T LEGS [x XMIN]", path, line);
  }
  if (s->n >= CSG_GATE_MAX) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d gates", path, line, CSG_GATE_MAX);
  }
  csgGate* g = &s->gate[s->n];
  memset(g, 0, sizeof *g);
  g->line = line;
  g->xmin = -INFINITY;
  if (nw == 5 && !number(w[4], &g->xmin)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: x '%.40s' is not a finite number (mm)", path,
                       line, w[4]);
  }
  if (!number(w[1], &g->t)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%.40s' is not a finite number", path, line,
                       w[1]);
  }
  if (!(g->t >= 0) || (s->n > 0 && g->t < s->gate[s->n - 1].t)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: gate times must be >= 0 and not decreasing "
                       "(%g s)", path, line, g->t);
  }
  for (const char* c = w[2]; *c; c++) {
    if (*c < 'A' || *c > 'H' || (g->legs & (1u << (*c - 'A')))) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: leg set '%.20s': '%c' is not a leg A..H or "
                         "is named twice", path, line, w[2], *c);
    }
    g->legs |= 1u << (*c - 'A');
  }
  s->time[s->n] = g->t;
  s->n++;
  return CS_OK;
}


/* `crawl T0 TPZ N ZEND CARRY` and `walk T0 TP N XEND CARRY`: the same five numbers (an end
 * read off the measured support, gaits_gate.h); after the gates, the walk before the crawl */
#define CRAWL_MAX_SLOTS 1000 /* far beyond any table's crawl or walk (the obstacle's: 3-16) */
static csStatus statementEnd(csgGateSet* s, int walk, char** w, int nw, const char* path,
                             int line, csError* err) {
  const char* kw = walk ? "walk" : "crawl";
  if (walk ? s->walk_n || s->crawl_n : s->crawl_n) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: a second '%s' line%s", path, line, kw,
                       walk && s->crawl_n ? " or one after the 'crawl' line" : "");
  }
  if (nw != 6) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' needs T0 %s N %s CARRY", path, line, kw,
                       walk ? "TP" : "TPZ", walk ? "XEND" : "ZEND");
  }
  double v[5];
  for (int i = 0; i < 5; i++) {
    if (!number(w[1 + i], &v[i])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%.40s' is not a finite number", path, line,
                         w[1 + i]);
    }
  }
  /* a skip never jumps over a gate, nor the walk's over the crawl's first slot */
  const double tlast = s->walk_n && !walk ? s->walk_t0 + s->walk_n * s->walk_tp
                       : s->n > 0 ? s->gate[s->n - 1].t : 0;
  if (!(v[0] >= tlast && v[1] > 0 && v[2] >= 3 && v[2] <= CRAWL_MAX_SLOTS &&
        v[2] == floor(v[2]) && v[4] >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: needs T0 >= the last gate%s (%g s), %s > 0, N "
                       "a whole number 3..%d and CARRY >= 0 (%g s, %g s, %g, %g mm)", path, line,
                       s->walk_n && !walk ? "'s and the walk's end" : "", tlast,
                       walk ? "TP" : "TPZ", CRAWL_MAX_SLOTS, v[0], v[1], v[2], v[4]);
  }
  double* f[4] = {&s->crawl_t0, &s->crawl_tpz, &s->crawl_zend, &s->crawl_carry};
  double* fw[4] = {&s->walk_t0, &s->walk_tp, &s->walk_xend, &s->walk_carry};
  for (int i = 0; i < 4; i++) {
    *(walk ? fw : f)[i] = v[i < 2 ? i : i + 1];
  }
  *(walk ? &s->walk_n : &s->crawl_n) = (int)v[2];
  return CS_OK;
}


/* the reader's state between statements (csu_statementFileRead) */
typedef struct {
  csgGateSet* s;
  int seen; /* the design line's number, 0 before it */
} gateReader;

static csStatus gateStatement(void* ctx, char** w, int nw, const char* path, int line,
                              csError* err) {
  gateReader* g = ctx;
  if (!strcmp(w[0], "design")) {
    return statementDesign(g->s, w, nw, &g->seen, path, line, err);
  }
  if (!strcmp(w[0], "crawl") || !strcmp(w[0], "walk")) {
    return statementEnd(g->s, w[0][0] == 'w', w, nw, path, line, err);
  }
  if (!strcmp(w[0], "gate")) {
    if (g->s->crawl_n || g->s->walk_n) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'gate' after the '%s' line", path, line,
                         g->s->walk_n ? "walk" : "crawl");
    }
    return statementGate(g->s, w, nw, g->seen, path, line, err);
  }
  return cs_errorSet(err, CS_ERR_PARSE,
                     "%s:%d: unknown statement '%.40s' (design, gate, walk, crawl)", path, line,
                     w[0]);
}


csgGateSet* csg_gateRead(const char* path, csError* err) {
  if (!path) {
    cs_errorSet(err, CS_ERR_ARG, "csg_gateRead: NULL path");
    return NULL;
  }
  csgGateSet* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  snprintf(s->source, sizeof s->source, "%s", path);
  gateReader g = {s, 0};
  int line = 0;
  csStatus st = csu_statementFileRead(path, MAX_LINE, "gate file", MAX_WORDS, gateStatement, &g,
                                      &line, err);
  if (st == CS_OK && s->n == 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: no gate", path, line > 0 ? line : 1);
  }
  if (st != CS_OK) {
    csg_gateDestroy(s);
    return NULL;
  }
  return s;
}
