/* robot_calibration.c: the provisional pressure -> bend map (see robot_calibration.h). */
#include "robot_calibration.h"

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


csrProvisionalMap* csr_provisionalMapCreate(const char* path, const csrActuator* leg,
                                            csError* err) {
  FILE* fp = fopen(path, "r");
  if (!fp) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot open calibration file", path);
    return NULL;
  }
  char line[512], actname[32] = "";
  int lineno = 0, chambers[4] = {0, 0, 0, 0}, have_ch = 0;
  double p_ref = NAN, angle_ref = NAN;
  csStatus st = CS_OK;
  while (st == CS_OK && fgets(line, sizeof line, fp)) {
    lineno++;
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char key[32], val[128];
    int n = sscanf(line, " %31s %127s", key, val);
    if (n <= 0) continue;
    if (n != 2) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: expected 'key value'", path, lineno);
    } else if (!strcmp(key, "actuator")) {
      snprintf(actname, sizeof actname, "%.31s", val);
    } else if (!strcmp(key, "chambers")) {
      char* tok = strtok(val, ",");
      while (tok && st == CS_OK) {
        char* end;
        long j = strtol(tok, &end, 10);
        if (*end || j < 1 || j > 4) {
          st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: chamber '%s' not in 1..4", path, lineno,
                           tok);
        } else {
          chambers[j - 1] = 1;
          have_ch = 1;
        }
        tok = strtok(NULL, ",");
      }
    } else if (!strcmp(key, "pressure_MPa") || !strcmp(key, "total_angle_deg")) {
      char* end;
      double v = strtod(val, &end);
      if (*end || !isfinite(v) || v <= 0) {
        st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: %s must be a number > 0", path, lineno, key);
      } else if (key[0] == 'p') {
        p_ref = v;
      } else {
        angle_ref = v;
      }
    } else {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown key '%s'", path, lineno, key);
    }
  }
  fclose(fp);
  if (st != CS_OK) {
    return NULL;
  }
  if (!actname[0] || !have_ch || isnan(p_ref) || isnan(angle_ref)) {
    cs_errorSet(err, CS_ERR_PARSE,
                "%s: needs actuator, chambers, pressure_MPa and total_angle_deg", path);
    return NULL;
  }
  csrActuator ref;
  if (csr_actuatorPreset(&ref, actname, err) != CS_OK) {
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
      cs_errorSet(err, CS_ERR_SOLVER, "%s: analytic model failed at the reference point", path);
      return NULL;
    }
    total += hypot(bend[0], bend[1]);
  }
  if (!(total > 0)) {
    cs_errorSet(err, CS_ERR_RANGE, "%s: the reference chambers do not bend the actuator", path);
    return NULL;
  }
  csrProvisionalMap* pm = calloc(1, sizeof *pm);
  if (!pm) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
    return NULL;
  }
  pm->leg = *leg;
  pm->scale = angle_ref * (3.14159265358979323846 / 180.0) / total;
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
