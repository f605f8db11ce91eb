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
#include <stdint.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
  MAX_LINE = 1023, /* bytes per line, line ending excluded */
  MAX_WORDS = 72   /* words kept per line (a heightfield row: 64 heights); more are counted */
};

/* coordinates beyond 1 km are a typo, and their box sizes could overflow in ODE */
#define MAX_COORD_MM 1e6
/* a heading is an angle: more than one turn either way is a typo */
#define MAX_HEADING_DEG 360.0
/* the steepest slope: beyond 45 deg the robot's support would rest on its legs' sides */
#define MAX_SLOPE_DEG 45.0
/* friction coefficients beyond 10 are a typo (rubber on rough rock is ~1-2) */
#define MAX_MU 10.0
/* a heightfield's solid depth below its lowest sample: deeper than any foot sinks */
#define CST_HF_THICKNESS_MM 20.0
#define CST_DEG (3.14159265358979323846 / 180.0) /* radians per degree */

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


/* the optional trailing `mu M` of a box statement with n numbers: *mu = M, or -1 without it;
 * checks the word count (n or n + 2 words after the key) */
static csStatus parseBoxValues(Words* w, double* v, int n, const char* what, double* mu,
                               const char* path, int lineno, csError* err) {
  *mu = -1;
  if (w->nword == n + 3 && !strcmp(w->word[n + 1], "mu")) {
    double m;
    int rc = parseFinite(w->word[n + 2], &m);
    if (rc) {
      return cs_errorSet(err, rc == 1 ? CS_ERR_PARSE : CS_ERR_RANGE,
                         "%s:%d: '%s' friction '%.40s' is not a finite number", path, lineno,
                         w->word[0], w->word[n + 2]);
    }
    if (!(m >= 0 && m <= MAX_MU)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: '%s' friction %g must be in 0..%g", path,
                         lineno, w->word[0], m, MAX_MU);
    }
    *mu = m;
    w->nword = n + 1; /* the numbers alone */
  }
  return parseValues(w, v, n, what, path, lineno, err);
}


static csStatus checkCoords(const double* v, int n, const char* path, int lineno,
                            csError* err) {
  for (int i = 0; i < n; i++) {
    if (fabs(v[i]) > MAX_COORD_MM) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: box coordinate %g mm is beyond +-%g mm",
                         path, lineno, v[i], MAX_COORD_MM);
    }
  }
  return CS_OK;
}


int cst_boxOriented(cstBox* b, const double c[3], const double len[3], const double axis[3],
                    double deg, double mu) {
  double an = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(an > 0) || !isfinite(an)) {
    return 0;
  }
  memset(b, 0, sizeof *b);
  double u[3] = {axis[0] / an, axis[1] / an, axis[2] / an};
  double th = deg * CST_DEG, cs = cos(th), sn = sin(th), C = 1 - cs;
  /* Rodrigues: R = cos I + sin [u]x + (1 - cos) u u^T */
  double R[9] = {cs + C * u[0] * u[0],        C * u[0] * u[1] - sn * u[2],
                 C * u[0] * u[2] + sn * u[1], C * u[1] * u[0] + sn * u[2],
                 cs + C * u[1] * u[1],        C * u[1] * u[2] - sn * u[0],
                 C * u[2] * u[0] - sn * u[1], C * u[2] * u[1] + sn * u[0],
                 cs + C * u[2] * u[2]};
  memcpy(b->R, R, sizeof R);
  b->oriented = 1;
  for (int k = 0; k < 3; k++) {
    b->c[k] = c[k];
    b->hi[k] = 0.5 * len[k];
    b->lo[k] = -b->hi[k];
  }
  for (int k = 0; k < 3; k++) {
    double e = 0;
    for (int j = 0; j < 3; j++) e += fabs(R[3 * k + j]) * b->hi[j];
    b->wlo[k] = c[k] - e;
    b->whi[k] = c[k] + e;
  }
  b->own_mu = mu >= 0;
  b->mu = mu >= 0 ? mu : 0;
  return 1;
}


csStatus cst_terrainLoad(cstTerrain* t, const char* path, csError* err) {
  memset(t, 0, sizeof *t);
  snprintf(t->source, sizeof t->source, "%s", path);
  csuLineReader* r = malloc(sizeof *r); /* an 8 KiB chunk: not on the stack */
  csStatus st = r ? csu_lineOpen(r, path, MAX_LINE, "terrain file", err)
                  : cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  int lineno = 0, got = 0;
  int start_line = 0, name_line = 0, heading_line = 0, slope_line = 0; /* 0 = not yet */
  int hf_line = 0, hf_rows = 0; /* the heightfield's line and rows read */
  while (st == CS_OK && (got = csu_lineNext(r, err)) > 0) {
    lineno = (int)r->lineno;
    Words w;
    w.nword = csu_statementWords(r->line, w.word, MAX_WORDS);
    if (w.nword == 0) {
      continue; /* blank or comment */
    }
    const char* key = w.word[0];
    double v[CST_HF_MAX], mu = -1;
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
    } else if (!strcmp(key, "box") || !strcmp(key, "obox")) {
      int ob = key[0] == 'o', n = ob ? 10 : 6;
      st = parseBoxValues(&w, v, n,
                          ob ? "cx cy cz lx ly lz (mm) ax ay az deg" : "x0 y0 z0 x1 y1 z1 (mm)",
                          &mu, path, lineno, err);
      if (st == CS_OK) {
        st = checkCoords(v, ob ? 6 : 6, path, lineno, err);
      }
      if (st != CS_OK) {
        break;
      }
      if (t->nbox == CST_MAX_BOXES) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d boxes", path, lineno,
                         CST_MAX_BOXES);
        break;
      }
      cstBox* b = &t->box[t->nbox];
      if (ob) {
        if (!(v[3] > 0 && v[4] > 0 && v[5] > 0)) {
          st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: obox edge lengths must be > 0", path,
                           lineno);
          break;
        }
        if (fabs(v[9]) > MAX_HEADING_DEG || fabs(v[6]) > MAX_COORD_MM ||
            fabs(v[7]) > MAX_COORD_MM || fabs(v[8]) > MAX_COORD_MM) {
          st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: obox angle beyond +-%g deg or axis beyond "
                           "+-%g", path, lineno, MAX_HEADING_DEG, MAX_COORD_MM);
          break;
        }
        if (!cst_boxOriented(b, v, v + 3, v + 6, v[9], mu)) {
          st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: obox rotation axis must not be zero", path,
                           lineno);
          break;
        }
      } else {
        if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5])) {
          st = cs_errorSet(err, CS_ERR_RANGE,
                           "%s:%d: box corners must satisfy x0<x1, y0<y1, z0<z1", path, lineno);
          break;
        }
        memset(b, 0, sizeof *b);
        for (int i = 0; i < 3; i++) {
          b->lo[i] = b->wlo[i] = v[i];
          b->hi[i] = b->whi[i] = v[i + 3];
        }
        b->own_mu = mu >= 0;
        b->mu = mu >= 0 ? mu : 0;
      }
      t->has_mu |= b->own_mu;
      t->nbox++;
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
    } else if (!strcmp(key, "heightfield")) {
      st = parseBoxValues(&w, v, 6, "x0 z0 dx dz (mm) nx nz", &mu, path, lineno, err);
      if (st == CS_OK) st = checkCoords(v, 4, path, lineno, err);
      if (st != CS_OK) break;
      if (hf_line) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second 'heightfield' (the first is on line "
                         "%d)", path, lineno, hf_line);
        break;
      }
      if (!(v[2] > 0 && v[3] > 0) || v[4] != floor(v[4]) || v[5] != floor(v[5]) ||
          !(v[4] >= 2 && v[4] <= CST_HF_MAX && v[5] >= 2 && v[5] <= CST_HF_MAX)) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: heightfield spacing must be > 0 and its "
                         "sample counts whole numbers in 2..%d", path, lineno, CST_HF_MAX);
        break;
      }
      cstHeightfield* hf = &t->hf;
      hf->x0 = v[0];
      hf->z0 = v[1];
      hf->dx = v[2];
      hf->dz = v[3];
      hf->nx = (int)v[4];
      hf->nz = (int)v[5];
      hf->thickness = CST_HF_THICKNESS_MM;
      hf->own_mu = mu >= 0;
      hf->mu = mu >= 0 ? mu : 0;
      if (fabs(hf->x0 + hf->dx * (hf->nx - 1)) > MAX_COORD_MM ||
          fabs(hf->z0 + hf->dz * (hf->nz - 1)) > MAX_COORD_MM) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: heightfield reaches beyond +-%g mm", path,
                         lineno, MAX_COORD_MM);
        break;
      }
      t->has_mu |= hf->own_mu;
      hf_line = lineno;
    } else if (!strcmp(key, "row")) {
      if (!hf_line || hf_rows == t->hf.nz) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'row' %s", path, lineno,
                         hf_line ? "beyond the heightfield's nz rows" : "before 'heightfield'");
        break;
      }
      st = parseValues(&w, v, t->hf.nx, "(heights, mm: nx of them)", path, lineno, err);
      if (st == CS_OK) st = checkCoords(v, t->hf.nx, path, lineno, err);
      if (st != CS_OK) break;
      for (int i = 0; i < t->hf.nx; i++) {
        t->hf.h[hf_rows * t->hf.nx + i] = v[i];
      }
      hf_rows++;
      if (hf_rows == t->hf.nz) {
        t->hf.hmin = t->hf.hmax = t->hf.h[0];
        for (int i = 1; i < t->hf.nx * t->hf.nz; i++) {
          t->hf.hmin = fmin(t->hf.hmin, t->hf.h[i]);
          t->hf.hmax = fmax(t->hf.hmax, t->hf.h[i]);
        }
        t->has_hf = 1;
      }
    } else if (!strcmp(key, "slope")) {
      st = parseValues(&w, v, 1, "(degrees)", path, lineno, err);
      if (st == CS_OK && fabs(v[0]) > MAX_SLOPE_DEG) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: slope %g deg is beyond +-%g deg", path,
                         lineno, v[0], MAX_SLOPE_DEG);
      }
      if (st == CS_OK && slope_line) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second 'slope' (the first is on line %d)",
                         path, lineno, slope_line);
      }
      if (st == CS_OK) {
        t->slope_deg = v[0];
        slope_line = lineno;
      }
    } else {
      st = cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: unknown statement '%.40s' (expected name, box, obox, heightfield, "
                       "row, slope, start, heading)",
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
  if (hf_line && !t->has_hf) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: end of file after %d of the heightfield's %d "
                       "rows (line %d)", path, last, hf_rows, t->hf.nz, hf_line);
  }
  if (t->nbox == 0 && !t->has_hf) {
    return cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: end of file without a 'box' or 'heightfield' statement: a terrain "
                       "needs ground", path, last);
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


/* top of box b on the vertical through (x, z): -INFINITY if the vertical misses it */
static double boxTopAt(const cstBox* b, double x, double z) {
  if (!b->oriented) {
    int in = x >= b->lo[0] && x <= b->hi[0] && z >= b->lo[2] && z <= b->hi[2];
    return in ? b->hi[1] : -INFINITY;
  }
  /* the line (x, y, z) in the box frame: q(y) = q0 + y d with q0 = R^T ((x, 0, z) - c) and
   * d = R^T e_y; clip y against the three slabs (Kay & Kajiya) */
  double p[3] = {x - b->c[0], -b->c[1], z - b->c[2]}, ylo = -INFINITY, yhi = INFINITY;
  for (int k = 0; k < 3; k++) {
    double q0 = b->R[k] * p[0] + b->R[3 + k] * p[1] + b->R[6 + k] * p[2], d = b->R[3 + k];
    if (d == 0) {
      if (q0 < b->lo[k] || q0 > b->hi[k]) return -INFINITY;
      continue;
    }
    double y0 = (b->lo[k] - q0) / d, y1 = (b->hi[k] - q0) / d;
    ylo = fmax(ylo, fmin(y0, y1));
    yhi = fmin(yhi, fmax(y0, y1));
  }
  return ylo <= yhi ? yhi : -INFINITY;
}


double cst_terrainHeightAt(const cstTerrain* t, double x, double z) {
  double h = -INFINITY;
  for (int i = 0; i < t->nbox; i++) {
    h = fmax(h, boxTopAt(&t->box[i], x, z));
  }
  return t->has_hf ? fmax(h, cst_hfHeightAt(&t->hf, x, z)) : h;
}


void cst_terrainGravityDir(const cstTerrain* t, double g[3]) {
  double a = t->slope_deg * CST_DEG;
  g[0] = t->slope_deg != 0 ? -sin(a) : 0.0;
  g[1] = t->slope_deg != 0 ? -cos(a) : -1.0;
  g[2] = 0;
}


double cst_terrainBoxMu(const cstTerrain* t, int i, double mu_default) {
  return i >= 0 && i < t->nbox && t->box[i].own_mu ? t->box[i].mu : mu_default;
}


int cst_terrainBuildOde(const cstTerrain* t, dSpaceID space) {
  for (int i = 0; i < t->nbox; i++) {
    const cstBox* b = &t->box[i];
    dGeomID g = dCreateBox(space, b->hi[0] - b->lo[0], b->hi[1] - b->lo[1], b->hi[2] - b->lo[2]);
    if (b->oriented) {
      dMatrix3 R; /* ODE's 3 x 4 row-major */
      for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) R[4 * r + k] = b->R[3 * r + k];
        R[4 * r + 3] = 0;
      }
      dGeomSetPosition(g, b->c[0], b->c[1], b->c[2]);
      dGeomSetRotation(g, R);
    } else {
      dGeomSetPosition(g, 0.5 * (b->lo[0] + b->hi[0]), 0.5 * (b->lo[1] + b->hi[1]),
                       0.5 * (b->lo[2] + b->hi[2]));
    }
    /* the support's contacts read the surface's friction here (contact_ode.c); the geom
     * never writes through it */
    dGeomSetData(g, b->own_mu ? (void*)(uintptr_t)&b->mu : NULL);
  }
  if (t->has_hf) {
    cst_hfBuildOde(&t->hf, space);
  }
  return t->nbox + t->has_hf;
}
