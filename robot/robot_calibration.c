/* robot_calibration.c: the provisional pressure -> bend map (see robot_calibration.h). */
#include "robot_calibration.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robot_analytic.h"

struct csrProvisionalMap_ {
  csrActuator leg;
  double scale;
  char name[160];
};


/* bend vector of one segment from the analytic model: the tip turns towards -kappa by
 * |kappa| S (robot_analytic.h sign convention) */
static int analyticBend(const csrActuator* act, int seg, const double p[4], double bend[2],
                        double* stretch) {
  /* Gauss order 6 instead of the default 12: the section integrals are smooth and the bend
   * changes by < 1e-6 relative (measured, README), while the cost drops by 4x; the map is
   * evaluated for every leg segment whose pressure changes, every step */
  csrAnalyticOptions opt = csr_analyticDefaultOptions();
  opt.nquad = 6;
  csrSegmentStrain s;
  if (csr_analyticSegmentWith(act, seg, p, &opt, &s, NULL) != CS_OK) {
    return 1; /* recoverable: the caller may retry with a smaller step */
  }
  bend[0] = -s.kappa[0] * act->S[seg];
  bend[1] = -s.kappa[1] * act->S[seg];
  *stretch = s.lambda0;
  return 0;
}


int csr_provisionalMapEval(const csrProvisionalMap* pm, int seg, const double p[4],
                           double bend[2], double* stretch) {
  int rc = analyticBend(&pm->leg, seg, p, bend, stretch);
  bend[0] *= pm->scale;
  bend[1] *= pm->scale;
  return rc;
}


static int evalThunk(const void* ctx, int seg, const double p[4], double bend[2],
                     double* stretch) {
  return csr_provisionalMapEval(ctx, seg, p, bend, stretch);
}


/* the reference keys of the file, in the order the "missing" message lists them */
enum { KEY_ACTUATOR, KEY_CHAMBERS, KEY_PRESSURE, KEY_ANGLE, NKEY };
static const char* const kKeys[NKEY] = {"actuator", "chambers", "pressure_MPa",
                                        "total_angle_deg"};
enum { MAX_LINE = 512 }; /* line buffer: at most MAX_LINE - 2 characters and the '\n' */
/* the reference pressure is a gait pressure: the same 1 MPa ceiling as gaits_csv's reader */
#define MAX_PRESSURE_MPA 1.0
/* the analytic model under-predicts the FE bend by a modest factor (3.08 for the shipped
 * reference); a factor outside 1/100..100 means the reference numbers are wrong, and using it
 * would make the legs fold instantly or not at all */
#define MIN_SCALE 0.01
#define MAX_SCALE 100.0


/* parse a chamber list "1,2" (1..4, comma-separated, no repeats) into chambers[4] flags;
 * 0 = ok, else fills `why` */
static int parseChambers(const char* s, int chambers[4], char* why, size_t why_size) {
  const char* p = s;
  memset(chambers, 0, 4 * sizeof *chambers);
  for (;;) {
    char* end;
    long j = strtol(p, &end, 10);
    if (end == p || !isdigit((unsigned char)*p) || (*end != ',' && *end != '\0')) {
      snprintf(why, why_size, "chambers '%.40s': expected chamber numbers 1..4 separated by "
               "commas", s);
      return 1;
    }
    if (j < 1 || j > 4) {
      snprintf(why, why_size, "chambers '%.40s': chamber %.*s is not in 1..4", s,
               (int)(end - p > 12 ? 12 : end - p), p);
      return 1;
    }
    if (chambers[j - 1]) {
      snprintf(why, why_size, "chambers '%.40s': chamber %ld is repeated", s, j);
      return 1;
    }
    chambers[j - 1] = 1;
    if (!*end) {
      return 0;
    }
    p = end + 1; /* past the comma */
  }
}


csrProvisionalMap* csr_provisionalMapCreate(const char* path, const csrActuator* leg,
                                            csError* err) {
  errno = 0;
  FILE* fp = fopen(path, "r");
  if (!fp) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot open calibration file: %s", path, strerror(errno));
    return NULL;
  }
  char line[MAX_LINE], actname[32] = "";
  int lineno = 0, chambers[4] = {0, 0, 0, 0};
  int key_line[NKEY] = {0, 0, 0, 0}; /* line of each key, 0 = not given yet */
  double p_ref = NAN, angle_ref = NAN;
  csStatus st = CS_OK;
  while (st == CS_OK && fgets(line, sizeof line, fp)) {
    lineno++;
    size_t len = strlen(line);
    if (len == sizeof line - 1 && line[len - 1] != '\n' && !feof(fp)) {
      /* a line that does not fit: reading on would parse its tail as another line */
      int c = getc(fp);
      if (c != EOF) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: line longer than %d characters", path,
                         lineno, MAX_LINE - 2);
        break;
      }
    }
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    /* split into words: key, value, and anything after (an error) */
    char* word[3] = {NULL, NULL, NULL};
    int nword = 0;
    for (char* c = line; *c;) {
      while (isspace((unsigned char)*c)) *c++ = '\0';
      if (!*c) {
        break;
      }
      if (nword < 3) {
        word[nword] = c;
      }
      nword++;
      while (*c && !isspace((unsigned char)*c)) c++;
    }
    if (nword == 0) {
      continue; /* blank or comment */
    }
    int key = 0;
    while (key < NKEY && strcmp(word[0], kKeys[key])) key++;
    if (key == NKEY) {
      st = cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%d: unknown key '%.40s' (expected actuator, chambers, pressure_MPa, "
                       "total_angle_deg)",
                       path, lineno, word[0]);
      break;
    }
    if (nword != 2) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' needs exactly one value, got %d", path,
                       lineno, kKeys[key], nword - 1);
      break;
    }
    if (key_line[key]) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: second '%s' (the first is on line %d)", path,
                       lineno, kKeys[key], key_line[key]);
      break;
    }
    key_line[key] = lineno;
    const char* val = word[1];
    if (key == KEY_ACTUATOR) {
      if (strlen(val) >= sizeof actname) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown actuator '%.40s...' (expected fig1, "
                         "baseline or leg)", path, lineno, val);
      } else {
        snprintf(actname, sizeof actname, "%s", val);
      }
    } else if (key == KEY_CHAMBERS) {
      char why[160];
      if (parseChambers(val, chambers, why, sizeof why)) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: %s", path, lineno, why);
      }
    } else {
      char* end;
      double v = strtod(val, &end);
      if (end == val || *end || !isfinite(v) || v <= 0) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: %s '%.40s' must be a finite number > 0",
                         path, lineno, kKeys[key], val);
      } else if (key == KEY_PRESSURE && v > MAX_PRESSURE_MPA) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pressure_MPa %g is above the %g MPa limit of "
                         "gait pressures", path, lineno, v, MAX_PRESSURE_MPA);
      } else if (key == KEY_PRESSURE) {
        p_ref = v;
      } else {
        angle_ref = v;
      }
    }
  }
  if (st == CS_OK && ferror(fp)) {
    st = cs_errorSet(err, CS_ERR_IO, "%s:%d: read error: %s", path, lineno + 1, strerror(errno));
  }
  fclose(fp);
  if (st != CS_OK) {
    return NULL;
  }
  /* every key is needed: name the missing ones at the end of the file */
  char missing[128] = "";
  for (int key = 0; key < NKEY; key++) {
    if (!key_line[key]) {
      size_t n = strlen(missing);
      snprintf(missing + n, sizeof missing - n, "%s'%s'", n ? ", " : "", kKeys[key]);
    }
  }
  if (missing[0]) {
    cs_errorSet(err, CS_ERR_PARSE, "%s:%d: end of file: missing %s (needs actuator, chambers, "
                "pressure_MPa and total_angle_deg)", path, lineno > 0 ? lineno : 1, missing);
    return NULL;
  }
  csrActuator ref;
  if (csr_actuatorPreset(&ref, actname, err) != CS_OK) {
    /* the preset's message names the cause; put the file and line in front */
    char why[CS_ERROR_MSG_SIZE];
    snprintf(why, sizeof why, "%s", err ? err->msg : "unknown actuator");
    cs_errorSet(err, err ? err->status : CS_ERR_ARG, "%s:%d: %s", path,
                key_line[KEY_ACTUATOR], why);
    return NULL;
  }
  double p[4];
  for (int j = 0; j < 4; j++) {
    p[j] = chambers[j] ? p_ref : 0;
  }
  double total = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2], stretch;
    if (analyticBend(&ref, s, p, bend, &stretch) != 0) {
      cs_errorSet(err, CS_ERR_SOLVER, "%s:%d: analytic model failed at the reference pressure "
                  "%g MPa", path, key_line[KEY_PRESSURE], p_ref);
      return NULL;
    }
    total += hypot(bend[0], bend[1]);
  }
  if (!(total > 0) || !isfinite(total)) {
    cs_errorSet(err, CS_ERR_RANGE, "%s:%d: the reference chambers do not bend the actuator",
                path, key_line[KEY_CHAMBERS]);
    return NULL;
  }
  double scale = angle_ref * (3.14159265358979323846 / 180.0) / total;
  if (!(scale >= MIN_SCALE && scale <= MAX_SCALE)) {
    cs_errorSet(err, CS_ERR_RANGE, "%s:%d: total_angle_deg %g at %g MPa needs a factor %.3g on "
                "the analytic bend, outside %g..%g: check pressure_MPa and total_angle_deg",
                path, key_line[KEY_ANGLE], angle_ref, p_ref, scale, MIN_SCALE, MAX_SCALE);
    return NULL;
  }
  csrProvisionalMap* pm = calloc(1, sizeof *pm);
  if (!pm) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
    return NULL;
  }
  pm->leg = *leg;
  pm->scale = scale;
  snprintf(pm->name, sizeof pm->name,
           "PROVISIONAL: analytic model x %.4f (%s reaches %g deg at %g MPa), %s", pm->scale,
           actname, angle_ref, p_ref, path);
  return pm;
}


void csr_provisionalMapDestroy(csrProvisionalMap* pm) { free(pm); }


csrBendMap csr_provisionalMapGet(const csrProvisionalMap* pm) {
  csrBendMap m = {evalThunk, pm, pm->name};
  return m;
}


double csr_provisionalMapScale(const csrProvisionalMap* pm) { return pm->scale; }
