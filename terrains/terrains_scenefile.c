/* terrains_scenefile.c: scene files (see terrains_scenefile.h). Lines come from the shared
 * reader (core_text.h), so an overlong line or a NUL byte is reported at its line; every
 * statement checks its word count and each may appear once. */
#include "terrains_scenefile.h"

#include "core_text.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_LINE = 1023 };

#define MAX_COORD_MM 1e6
#define MAX_HEADING_DEG 360.0
#define MAX_SLOPE_DEG 45.0
#define MAX_T_END_S 1e5

static const char* const kKeys[] = {"scene", "terrain", "gait",  "conditions",
                                    "start", "heading", "slope", "t-end"};
enum { NKEY = sizeof kKeys / sizeof kKeys[0] };


/* a finite number within +-lim (lim > 0), or (positive) 0 < v <= lim */
static csStatus number(const char* s, double lim, int positive, double* v, const char* path,
                       int line, const char* key, csError* err) {
  char* end;
  errno = 0;
  *v = strtod(s, &end);
  if (end == s || *end) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' value '%.40s' is not a number", path,
                       line, key, s);
  }
  if (!isfinite(*v) || (positive ? !(*v > 0 && *v <= lim) : !(fabs(*v) <= lim))) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: '%s' value %.40s must be %s %g", path, line,
                       key, s, positive ? "in (0, ] up to" : "finite and within +-", lim);
  }
  return CS_OK;
}


/* path relative to the scene file's folder unless absolute */
static csStatus resolve(char* out, size_t size, const char* file, const char* rel,
                        const char* path, int line, csError* err) {
  const char* slash = strrchr(file, '/');
  int n = rel[0] == '/' || !slash
              ? snprintf(out, size, "%s", rel)
              : snprintf(out, size, "%.*s/%s", (int)(slash - file), file, rel);
  if (n < 0 || (size_t)n >= size) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: path longer than %d bytes", path, line,
                       (int)size - 1);
  }
  return CS_OK;
}


/* the reader's state between statements (csu_statementFileRead): each key's line, 0 before it */
typedef struct {
  cstSceneFile* s;
  int seen[NKEY];
} sceneReader;

static csStatus sceneStatement(void* ctx, char** w, int nw, const char* path, int line,
                               csError* err) {
  sceneReader* c = ctx;
  cstSceneFile* s = c->s;
  csStatus st = CS_OK;
  int k = 0;
  while (k < NKEY && strcmp(w[0], kKeys[k])) k++;
  if (k == NKEY) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown statement '%.40s' (expected scene, "
                       "terrain, gait, conditions, start, heading, slope, t-end)", path, line,
                       w[0]);
  }
  int want = k == 4 ? 3 : 2; /* start x z */
  if (nw != want) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' needs %d value%s, got %d", path, line,
                       w[0], want - 1, want == 2 ? "" : "s", nw - 1);
  }
  if (c->seen[k]) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second '%s' (the first is on line %d)", path,
                       line, w[0], c->seen[k]);
  }
  c->seen[k] = line;
  const char* v = w[1];
  switch (k) {
    case 0:
      if (strlen(v) >= sizeof s->scene) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: scene name longer than %d characters",
                         path, line, (int)sizeof s->scene - 1);
      } else {
        snprintf(s->scene, sizeof s->scene, "%s", v);
      }
      break;
    case 1:
      st = resolve(s->terrain, sizeof s->terrain, path, v, path, line, err);
      break;
    case 2:
      st = resolve(s->gait, sizeof s->gait, path, v, path, line, err);
      break;
    case 3:
      if (strcmp(v, "earth") && strcmp(v, "paper")) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: conditions '%.40s' (expected earth or "
                         "paper)", path, line, v);
      } else {
        snprintf(s->conditions, sizeof s->conditions, "%s", v);
      }
      break;
    case 4:
      st = number(w[1], MAX_COORD_MM, 0, &s->start[0], path, line, w[0], err);
      if (st == CS_OK) st = number(w[2], MAX_COORD_MM, 0, &s->start[1], path, line, w[0], err);
      s->has_start = st == CS_OK;
      break;
    case 5:
      st = number(v, MAX_HEADING_DEG, 0, &s->heading_deg, path, line, w[0], err);
      s->has_heading = st == CS_OK;
      break;
    case 6:
      st = number(v, MAX_SLOPE_DEG, 0, &s->slope_deg, path, line, w[0], err);
      s->has_slope = st == CS_OK;
      break;
    default:
      st = number(v, MAX_T_END_S, 1, &s->t_end, path, line, w[0], err);
      s->has_t_end = st == CS_OK;
      break;
  }
  return st;
}


csStatus cst_sceneFileLoad(cstSceneFile* s, const char* path, csError* err) {
  memset(s, 0, sizeof *s);
  snprintf(s->source, sizeof s->source, "%s", path);
  sceneReader c;
  memset(&c, 0, sizeof c);
  c.s = s;
  /* the word count is checked per key ("needs N values, got M"): the driver's bound only
   * keeps a runaway line out */
  return csu_statementFileRead(path, MAX_LINE, "scene file", CSU_STATEMENT_MAX_WORDS,
                               sceneStatement, &c, NULL, err);
}
