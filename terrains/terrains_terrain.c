/* terrains_terrain.c: terrain description files and their ODE geoms (see terrains_terrain.h). */
#include "terrains_terrain.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_LINE = 1024 };


/* parse `n` doubles from `s`; returns how many were read and sets *trailing if junk follows */
static int parseNumbers(const char* s, double* out, int n, int* trailing) {
  int k = 0;
  char* end;
  *trailing = 0;
  while (k < n) {
    while (isspace((unsigned char)*s)) s++;
    if (!*s) break;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || errno == ERANGE || !isfinite(v)) {
      *trailing = 1;
      return k;
    }
    out[k++] = v;
    s = end;
  }
  while (isspace((unsigned char)*s)) s++;
  if (*s) *trailing = 1;
  return k;
}


csStatus cst_terrainLoad(cstTerrain* t, const char* path, csError* err) {
  memset(t, 0, sizeof *t);
  snprintf(t->source, sizeof t->source, "%s", path);
  FILE* fp = fopen(path, "r");
  if (!fp) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open terrain file", path);
  }
  char line[MAX_LINE];
  int lineno = 0, have_start = 0;
  csStatus st = CS_OK;
  while (fgets(line, sizeof line, fp)) {
    lineno++;
    if (!strchr(line, '\n') && !feof(fp)) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: line longer than %d characters", path, lineno,
                       MAX_LINE - 2);
      break;
    }
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char key[32];
    int used = 0;
    if (sscanf(line, " %31s%n", key, &used) != 1) {
      continue; /* blank or comment */
    }
    const char* rest = line + used;
    double v[6];
    int trailing;
    if (!strcmp(key, "name")) {
      char nm[64];
      if (sscanf(rest, " %63s", nm) != 1) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'name' needs a word", path, lineno);
        break;
      }
      snprintf(t->name, sizeof t->name, "%s", nm);
    } else if (!strcmp(key, "box")) {
      if (parseNumbers(rest, v, 6, &trailing) != 6 || trailing) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'box' needs 6 numbers x0 y0 z0 x1 y1 z1 (mm)",
                         path, lineno);
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
      if (parseNumbers(rest, v, 2, &trailing) != 2 || trailing) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'start' needs 2 numbers x z (mm)", path,
                         lineno);
        break;
      }
      t->start[0] = v[0];
      t->start[1] = v[1];
      have_start = 1;
    } else if (!strcmp(key, "heading")) {
      if (parseNumbers(rest, v, 1, &trailing) != 1 || trailing) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'heading' needs 1 number (degrees)", path,
                         lineno);
        break;
      }
      t->heading_deg = v[0];
    } else {
      st = cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: unknown statement '%s' (expected name, box, start, heading)", path,
                       lineno, key);
      break;
    }
  }
  if (st == CS_OK && ferror(fp)) {
    st = cs_errorSet(err, CS_ERR_IO, "%s: read error", path);
  }
  fclose(fp);
  if (st != CS_OK) {
    return st;
  }
  if (t->nbox == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: no 'box' statement: a terrain needs ground",
                       path, lineno);
  }
  if (!have_start) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: no 'start' statement", path, lineno);
  }
  if (!isfinite(cst_terrainHeightAt(t, t->start[0], t->start[1]))) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: start (%g, %g) is not above any box", path,
                       t->start[0], t->start[1]);
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
