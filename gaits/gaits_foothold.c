/* gaits_foothold.c: the choice of a step's landing from the measured support and the reader
 * of the companion .foothold file (gaits_foothold.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "gaits_foothold.h"

#define MAX_LINE 4096
#define MAX_WORDS 16


/* clearance of landing x from the edges: the distance to the nearest (mm); +inf without edges */
static double clearance(double x, const double* edges, int nedge) {
  double c = INFINITY;
  for (int k = 0; k < nedge; k++) {
    c = fmin(c, fabs(x - edges[k]));
  }
  return c;
}


int csg_footholdChoose(int n, const double* land, const double* lo, const double* hi,
                       int nominal, double delta, const double* edges, int nedge, double margin) {
  if (n < 1 || !land || nominal < 0 || nominal >= n || (nedge > 0 && !edges) || nedge < 0 ||
      !isfinite(delta) || !isfinite(margin)) {
    return -1;
  }
  for (int i = 0; i < n; i++) {
    if (!isfinite(land[i])) return -1;
  }
  for (int k = 0; k < nedge; k++) {
    if (!isfinite(edges[k])) return -1;
  }
  const double target = land[nominal];
  int best = -1, safe_fit = -1, safest = 0;
  double best_d = INFINITY, safe_fit_c = -INFINITY, safest_c = -INFINITY;
  for (int i = 0; i < n; i++) {
    const double x = land[i] + delta;
    const double c = clearance(x, edges, nedge);
    const int fits = (!lo || x >= lo[i]) && (!hi || x <= hi[i]);
    if (c > safest_c) {
      safest_c = c;
      safest = i;
    }
    if (fits && c > safe_fit_c) {
      safe_fit_c = c;
      safe_fit = i;
    }
    if (fits && c >= margin && fabs(x - target) < best_d) {
      best_d = fabs(x - target);
      best = i;
    }
  }
  return best >= 0 ? best : safe_fit >= 0 ? safe_fit : safest;
}


void csg_footholdDestroy(csgFootholdSet* s) {
  if (!s) {
    return;
  }
  for (int k = 0; k < s->n; k++) {
    for (int i = 0; i < s->fh[k].ncand; i++) {
      csg_gaitDestroy(s->fh[k].cand[i].table);
      csg_gaitDestroy(s->fh[k].cand[i].comp);
      csg_gaitDestroy(s->fh[k].cand[i].base);
    }
  }
  free(s);
}


/* ---- the command a candidate stands for (csg_footholdCompose) ---- */

/* the index of g's last row at or before t, -1 if none */
static int lastRowAt(const csgGait* g, double t) {
  int lo = 0, hi = g->nrow; /* the first row past t */
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (g->time[mid] <= t) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo - 1;
}

/* the step command of g's chamber l (0-based) at t: its last row at or before t, vented
 * before its first */
static double stepValue(const csgGait* g, int l, double t) {
  const int r = lastRowAt(g, t);
  return r < 0 ? 0.0 : g->pressure[(size_t)CSG_NLABEL * r + l];
}

static int cmpDouble(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

/* comp and base of foothold k's candidate c (the header's construction); cut[leg]: where the
 * candidate's rows stop on that leg (W1, or a chained later foothold's W0) */
static csStatus composeOne(csgFoothold* f, csgFootholdCand* c, const csgGait* nom,
                           const double* cut, csError* err) {
  const int ra = lastRowAt(nom, f->w0);          /* the nominal's last row at or before W0 */
  int rb = lastRowAt(nom, f->w1) + 1;            /* its first row past W1 */
  rb = rb < nom->nrow ? rb : nom->nrow - 1;
  const int nn = rb - (ra < 0 ? 0 : ra) + 1;
  const size_t cap = (size_t)(nn > 0 ? nn : 0) + (size_t)c->table->nrow + 2 + CSG_NLEG;
  double* t = malloc(sizeof(double) * cap);
  if (!t) {
    return cs_errorSet(err, CS_ERR_MEMORY, "csg_footholdCompose: out of memory");
  }
  size_t n = 0;
  for (int r = ra < 0 ? 0 : ra; r <= rb; r++) {
    t[n++] = nom->time[r];
  }
  for (int r = 0; r < c->table->nrow; r++) {
    if (c->table->time[r] >= f->w0 && c->table->time[r] < f->w1) {
      t[n++] = c->table->time[r];
    }
  }
  t[n++] = f->w0;
  t[n++] = f->w1;
  for (int leg = 0; leg < CSG_NLEG; leg++) {
    if ((f->legs >> leg) & 1u && cut[leg] < f->w1) {
      t[n++] = cut[leg];
    }
  }
  qsort(t, n, sizeof(double), cmpDouble);
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (m == 0 || t[i] > t[m - 1]) {
      t[m++] = t[i];
    }
  }
  csg_gaitDestroy(c->comp);
  csg_gaitDestroy(c->base);
  c->comp = csg_gaitCreate((int)m, err);
  c->base = c->comp ? csg_gaitCreate((int)m, err) : NULL;
  if (!c->base) {
    free(t);
    return err ? err->status : CS_ERR_MEMORY;
  }
  for (size_t i = 0; i < m; i++) {
    c->comp->time[i] = c->base->time[i] = t[i];
    for (int l = 0; l < CSG_NLABEL; l++) {
      const int leg = l / 12;
      const double pn = stepValue(nom, l, t[i]);
      const int chosen = (f->legs >> leg) & 1u && t[i] >= f->w0 && t[i] < cut[leg];
      c->base->pressure[(size_t)CSG_NLABEL * i + l] = pn;
      c->comp->pressure[(size_t)CSG_NLABEL * i + l] = chosen ? stepValue(c->table, l, t[i]) : pn;
    }
  }
  c->comp->ramp = c->base->ramp = nom->ramp;
  f->tail = fmax(f->tail, t[m - 1]);
  free(t);
  return CS_OK;
}


csStatus csg_footholdCompose(csgFootholdSet* s, const csgGait* nominal, csError* err) {
  if (!s || !nominal || nominal->nrow < 1) {
    return cs_errorSet(err, CS_ERR_ARG, "csg_footholdCompose: NULL footholds or empty table");
  }
  for (int k = 0; k < s->n; k++) {
    csgFoothold* f = &s->fh[k];
    /* a chained later foothold's rows hold from its W0 on (the reader's rule) */
    double cut[CSG_NLEG];
    for (int leg = 0; leg < CSG_NLEG; leg++) {
      cut[leg] = f->w1;
      for (int j = k + 1; j < s->n; j++) {
        if ((s->fh[j].legs >> leg) & 1u && s->fh[j].w0 > f->w0 && s->fh[j].w0 < cut[leg]) {
          cut[leg] = s->fh[j].w0;
        }
      }
    }
    f->tail = -INFINITY;
    for (int i = 0; i < f->ncand; i++) {
      csStatus st = composeOne(f, &f->cand[i], nominal, cut, err);
      if (st != CS_OK) {
        return st;
      }
    }
  }
  return CS_OK;
}


static int number(const char* s, double* v) {
  char* end;
  *v = strtod(s, &end);
  return end != s && !*end && isfinite(*v);
}


static csStatus legsParse(const char* s, unsigned* legs, const char* path, int line,
                          csError* err) {
  *legs = 0;
  for (const char* c = s; *c; c++) {
    if (*c < 'A' || *c > 'H' || (*legs & (1u << (*c - 'A')))) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: leg set '%.20s': '%c' is not a leg A..H or "
                         "is named twice", path, line, s, *c);
    }
    *legs |= 1u << (*c - 'A');
  }
  return CS_OK;
}


/* `foothold T LEGS xplan X margin M window W0 W1` */
static csStatus statementFoothold(csgFootholdSet* s, char** w, int nw, const char* path,
                                  int line, csError* err) {
  if (s->n >= CSG_FOOTHOLD_MAX) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d footholds", path, line,
                       CSG_FOOTHOLD_MAX);
  }
  if (nw != 10 || strcmp(w[3], "xplan") || strcmp(w[5], "margin") || strcmp(w[7], "window")) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'foothold' needs T LEGS xplan X margin M "
                       "window W0 W1", path, line);
  }
  csgFoothold* f = &s->fh[s->n];
  memset(f, 0, sizeof *f);
  f->line = line;
  double v[5];
  const int at[5] = {1, 4, 6, 8, 9};
  for (int i = 0; i < 5; i++) {
    if (!number(w[at[i]], &v[i])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%.40s' is not a finite number", path, line,
                         w[at[i]]);
    }
  }
  csStatus st = legsParse(w[2], &f->legs, path, line, err);
  if (st != CS_OK) {
    return st;
  }
  f->t = v[0];
  f->xplan = v[1];
  f->margin = v[2];
  f->w0 = v[3];
  f->w1 = v[4];
  f->nominal = -1;
  if (!(f->t >= 0) || !(f->margin >= 0) || !(f->w0 >= f->t) || !(f->w1 > f->w0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: needs 0 <= T <= W0 < W1 and margin >= 0 (T %g, "
                       "W0 %g, W1 %g s, margin %g mm)", path, line, f->t, f->w0, f->w1,
                       f->margin);
  }
  if (s->n > 0 && !(f->t > s->fh[s->n - 1].t)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: footholds must come in increasing T (%g s "
                       "after %g s)", path, line, f->t, s->fh[s->n - 1].t);
  }
  /* a chain: the next step of the same legs may be a foothold too (its window starts in the
   * swing, while the earlier's rows still run to the lift and two rows past it); the later's
   * columns hold from its W0 on (the player applies footholds in order), so it must start and
   * end after the earlier one, or the earlier's rows would come back after it */
  for (int k = 0; k < s->n; k++) {
    const csgFoothold* o = &s->fh[k];
    if ((o->legs & f->legs) && f->w0 < o->w1 && !(f->w0 > o->w0 && f->w1 > o->w1)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: its window %g..%g s overlaps that of line "
                         "%d (%g..%g s) on a shared leg without following it (a chained "
                         "foothold starts and ends later)", path, line, f->w0, f->w1, o->line,
                         o->w0, o->w1);
    }
  }
  s->n++;
  return CS_OK;
}


/* `candidate OFFSET land L FILE [nominal]` */
static csStatus statementCandidate(csgFootholdSet* s, char** w, int nw, const char* path,
                                   int line, const csgReadOptions* opt, csError* err) {
  if (s->n == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'candidate' before any 'foothold'", path,
                       line);
  }
  csgFoothold* f = &s->fh[s->n - 1];
  if ((nw != 8 && nw != 9) || strcmp(w[2], "land") || strcmp(w[4], "fits") ||
      (nw == 9 && strcmp(w[8], "nominal"))) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'candidate' needs OFFSET land L fits LO HI "
                       "FILE [nominal]", path, line);
  }
  if (f->ncand >= CSG_FOOTHOLD_MAX_CAND) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d candidates", path, line,
                       CSG_FOOTHOLD_MAX_CAND);
  }
  csgFootholdCand* c = &f->cand[f->ncand];
  if (!number(w[1], &c->offset) || !number(w[3], &c->land) || !number(w[5], &c->lo) ||
      !number(w[6], &c->hi)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: OFFSET, L, LO and HI must be finite numbers "
                       "(mm)", path, line);
  }
  if (!(c->lo <= c->land && c->land <= c->hi)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: the landing %g mm is outside the span it fits, "
                       "%g..%g mm", path, line, c->land, c->lo, c->hi);
  }
  if (nw == 9) {
    if (f->nominal >= 0) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: a second nominal candidate", path, line);
    }
    f->nominal = f->ncand;
  }
  /* the table's path: relative to the .foothold file's folder */
  char file[1024];
  const char* fname = w[7];
  const char* slash = strrchr(path, '/');
  if (fname[0] == '/' || !slash) {
    snprintf(file, sizeof file, "%s", fname);
  } else {
    snprintf(file, sizeof file, "%.*s/%s", (int)(slash - path), path, fname);
  }
  csError e;
  cs_errorClear(&e);
  c->table = csg_gaitRead(file, opt, &e);
  if (!c->table) {
    return cs_errorSet(err, e.status, "%s:%d: candidate table: %.300s", path, line, e.msg);
  }
  f->ncand++;
  const csgGait* g = c->table;
  if (!(g->time[0] <= f->w0 && g->time[g->nrow - 1] >= f->w1)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: candidate table %s holds %g..%g s, not the "
                       "window %g..%g s", path, line, fname, g->time[0], g->time[g->nrow - 1],
                       f->w0, f->w1);
  }
  return CS_OK;
}


/* the reader's state between statements (csu_statementFileRead) */
typedef struct {
  csgFootholdSet* s;
  const csgReadOptions* opt;
} footholdReader;

static csStatus footholdStatement(void* ctx, char** w, int nw, const char* path, int line,
                                  csError* err) {
  footholdReader* f = ctx;
  csgFootholdSet* s = f->s;
  if (!strcmp(w[0], "foothold")) {
    if (s->n > 0 && s->fh[s->n - 1].nominal < 0) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: the foothold of line %d has no nominal "
                         "candidate", path, line, s->fh[s->n - 1].line);
    }
    return statementFoothold(s, w, nw, path, line, err);
  }
  if (!strcmp(w[0], "candidate")) {
    return statementCandidate(s, w, nw, path, line, f->opt, err);
  }
  return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown statement '%.40s' (foothold, "
                     "candidate)", path, line, w[0]);
}


csgFootholdSet* csg_footholdRead(const char* path, const csgReadOptions* opt, csError* err) {
  if (!path) {
    cs_errorSet(err, CS_ERR_ARG, "csg_footholdRead: NULL path");
    return NULL;
  }
  csgFootholdSet* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  snprintf(s->source, sizeof s->source, "%s", path);
  footholdReader f = {s, opt};
  int line = 0;
  csStatus st = csu_statementFileRead(path, MAX_LINE, "foothold file", MAX_WORDS,
                                      footholdStatement, &f, &line, err);
  if (st == CS_OK && s->n == 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: no foothold", path, line > 0 ? line : 1);
  }
  if (st == CS_OK && s->fh[s->n - 1].nominal < 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: the foothold of line %d has no nominal candidate",
                     path, line, s->fh[s->n - 1].line);
  }
  if (st != CS_OK) {
    csg_footholdDestroy(s);
    return NULL;
  }
  return s;
}
