/* robot_calibration.c: the calibrations behind csrBendMap (robot_calibration.h): the provisional
 * map, the pair-mode FE table, and the FE mode table's model (robot_calibration_model.h) with its
 * adapters for the bend map and the rod level. */
#include "robot_calibration.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "core_math.h"
#include "core_text.h"
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
enum { MAX_LINE = 1023 }; /* bytes per line, line ending excluded (as terrain files) */
/* the reference pressure is a gait pressure: the same 1 MPa ceiling as gaits_csv's reader */
#define MAX_PRESSURE_MPA 1.0
/* rows of a pair table at least this far apart (MPa), as the mode table's (robot_calibration_table.c):
 * rows 1e-317 MPa apart made the analytic reference bend 0 and the FE/analytic ratio infinite
 * (found by fuzz_calib_h5) */
#define MIN_ROW_DP_MPA 1e-9
/* the analytic model under-predicts the FE bend by a modest factor (3.08 for the shipped
 * reference); a factor outside 1/100..100 means the reference numbers are wrong, and using it
 * would make the legs fold instantly or not at all */
#define MIN_SCALE 0.01
#define MAX_SCALE 100.0


csrProvisionalMap* csr_provisionalMapCreate(const char* path, const csrActuator* leg,
                                            csError* err) {
  csuLineReader* r = malloc(sizeof *r); /* an 8 KiB chunk: not on the stack */
  csStatus st = r ? csu_lineOpen(r, path, MAX_LINE, "calibration file", err)
                  : cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  char actname[32] = "";
  int lineno = 0, got = 0;
  unsigned chambers = 0;
  int key_line[NKEY] = {0, 0, 0, 0}; /* line of each key, 0 = not given yet */
  double p_ref = NAN, angle_ref = NAN;
  while (st == CS_OK && (got = csu_lineNext(r, err)) > 0) {
    lineno = (int)r->lineno;
    /* split into words: key, value, and anything after (an error) */
    char* word[3] = {NULL, NULL, NULL};
    int nword = csu_statementWords(r->line, word, 3);
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
      csError cerr;
      if (csu_chamberListParse(val, CSR_NCHAMBER, "chambers", &chambers, &cerr) != CS_OK) {
        st = cs_errorSet(err, cerr.status, "%s:%d: %s", path, lineno, cerr.msg);
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
  if (st == CS_OK && got < 0) {
    st = (csStatus)got;
  }
  if (r) {
    csu_lineClose(r);
    free(r);
  }
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
    p[j] = (chambers & (1u << j)) ? p_ref : 0;
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
  csrBendMap m = {evalThunk, pm, pm->name, INFINITY};
  return m;
}


double csr_provisionalMapScale(const csrProvisionalMap* pm) { return pm->scale; }


/* ---- FE calibration table (robot_calibration.h) ------------------------------------------- */

struct csrFeCalibration_ {
  csrActuator leg;
  int m;         /* table rows */
  double* p;     /* [m] MPa, p[0] = 0, increasing */
  double* ratio; /* [m][3] θ_FE / θ_analytic,pair per segment; row 0 copies row 1 */
  char name[320];
};

/* rows of a table: enough for any sweep a user runs (0.001 MPa steps to 1 MPa is 1001) */
#define FE_TABLE_MAX_ROWS 100000
/* a segment's bend (deg): ten turns is beyond any sweep; a finite 1e308 passed as a factor of
 * 1e306 on the analytic bend (tests/fuzz, fuzz_calib_h5) */
#define FE_TABLE_MAX_ANGLE_DEG 3600.0
/* read a double dataset of rank `rank` with dims[0] rows (and dims[1] = `cols` if rank 2) */
static double* readTable(hid_t f, const char* path, const char* dset, int rank, hsize_t cols,
                         hsize_t* rows, csError* err) {
  int r = -1;
  hsize_t dims[2] = {0, 0};
  H5T_class_t cls;
  size_t size;
  if (H5LTfind_dataset(f, dset + 1) <= 0 || H5LTget_dataset_ndims(f, dset, &r) < 0 ||
      r != rank || H5LTget_dataset_info(f, dset, dims, &cls, &size) < 0 ||
      cls != H5T_FLOAT || (rank == 2 && dims[1] != cols)) {
    cs_errorSet(err, CS_ERR_PARSE, "%s: calibration table needs dataset %s of shape %s", path,
                dset, rank == 1 ? "[M]" : "[M,3]");
    return NULL;
  }
  if (dims[0] < 2 || dims[0] > FE_TABLE_MAX_ROWS) {
    cs_errorSet(err, CS_ERR_RANGE, "%s: %s has %llu rows (need 2..%d)", path, dset,
                (unsigned long long)dims[0], FE_TABLE_MAX_ROWS);
    return NULL;
  }
  double* a = malloc((size_t)dims[0] * (rank == 2 ? (size_t)cols : 1) * sizeof(double));
  if (!a || H5LTread_dataset_double(f, dset, a) < 0) {
    free(a);
    cs_errorSet(err, CS_ERR_IO, "%s: cannot read %s", path, dset);
    return NULL;
  }
  *rows = dims[0];
  return a;
}


csrFeCalibration* csr_feCalibrationCreate(const char* path, const csrActuator* leg,
                                          csError* err) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* errors are reported here, not printed by HDF5 */
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot open as an HDF5 calibration table", path);
    return NULL;
  }
  csrFeCalibration* fc = calloc(1, sizeof *fc);
  double* ang = NULL;
  csStatus st = CS_OK;
  hsize_t m = 0, m2 = 0;
  char chambers[32] = "", model[32] = "";
  if (!fc) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    goto done;
  }
  fc->leg = *leg;
  /* the pair mode, Ω1&Ω2 in every segment (one string each: H5LT's attribute calls wrote an
   * array or a variable-length string past these buffers, fuzz_calib_h5) */
  if (!csr_calAttrString(f, "/", "chambers", chambers, sizeof chambers) ||
      strcmp(chambers, "1,2") != 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: calibration table must be a sweep of chambers "
                     "1,2 (attribute 'chambers' = '%s')", path, chambers);
    goto done;
  }
  if (!csr_calAttrString(f, "/", "model", model, sizeof model)) {
    model[0] = '\0';
  }
  if ((st = csr_calCheckActuator(path, leg, err)) != CS_OK) {
    goto done;
  }
  fc->p = readTable(f, path, "/pressure", 1, 0, &m, err);
  ang = fc->p ? readTable(f, path, "/angle_deg", 2, CSR_NSEG, &m2, err) : NULL;
  if (!fc->p || !ang) {
    st = err ? err->status : CS_ERR_PARSE;
    goto done;
  }
  if (m2 != m) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: /pressure has %llu rows, /angle_deg %llu", path,
                     (unsigned long long)m, (unsigned long long)m2);
    goto done;
  }
  fc->m = (int)m;
  fc->ratio = malloc(m * CSR_NSEG * sizeof(double));
  if (!fc->ratio) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    goto done;
  }
  if (fc->p[0] != 0) {
    st = cs_errorSet(err, CS_ERR_RANGE, "%s: /pressure row 1 is %g MPa, the table must start "
                     "at 0", path, fc->p[0]);
    goto done;
  }
  for (int i = 1; i < fc->m && st == CS_OK; i++) {
    if (!(fc->p[i] >= fc->p[i - 1] + MIN_ROW_DP_MPA) || !(fc->p[i] <= MAX_PRESSURE_MPA)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s: /pressure row %d (%g MPa) must be above row %d "
                       "by at least %g MPa and at most %g MPa", path, i + 1, fc->p[i], i,
                       MIN_ROW_DP_MPA, MAX_PRESSURE_MPA);
      break;
    }
    double P[4] = {fc->p[i], fc->p[i], 0, 0}, bend[2], stretch;
    for (int s = 0; s < CSR_NSEG && st == CS_OK; s++) {
      double th = ang[CSR_NSEG * i + s] * CS_DEG;
      if (!(th > 0) || !(ang[CSR_NSEG * i + s] <= FE_TABLE_MAX_ANGLE_DEG)) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s: /angle_deg row %d segment %d is %g deg: a "
                         "pair-mode sweep bends every segment forward (> 0, at most %g)", path,
                         i + 1, s + 1, ang[CSR_NSEG * i + s], FE_TABLE_MAX_ANGLE_DEG);
      } else if (analyticBend(leg, s, P, bend, &stretch) != 0) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s: the analytic model has no solution at %g MPa "
                         "(row %d)", path, fc->p[i], i + 1);
      } else {
        fc->ratio[CSR_NSEG * i + s] = th / hypot(bend[0], bend[1]);
      }
    }
  }
  if (st != CS_OK) {
    goto done;
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    fc->ratio[s] = fc->ratio[CSR_NSEG + s];
  }
  snprintf(fc->name, sizeof fc->name,
           "%s calibration table (chambers 1,2, 0..%g MPa, %d rows, analytic x %.3f..%.3f): %s",
           model[0] ? model : "unknown-model", fc->p[fc->m - 1], fc->m, fc->ratio[0],
           fc->ratio[CSR_NSEG * (fc->m - 1)], path);
done:
  free(ang);
  H5Fclose(f);
  if (st != CS_OK) {
    csr_feCalibrationDestroy(fc);
    return NULL;
  }
  return fc;
}


void csr_feCalibrationDestroy(csrFeCalibration* fc) {
  if (fc) {
    free(fc->p);
    free(fc->ratio);
    free(fc);
  }
}


int csr_feCalibrationEval(const csrFeCalibration* fc, int seg, const double p[4],
                          double bend[2], double* stretch) {
  double pm = fmax(fmax(p[0], p[1]), fmax(p[2], p[3]));
  if (pm > fc->p[fc->m - 1]) {
    return CSR_MAP_OUT_OF_RANGE;
  }
  int rc = analyticBend(&fc->leg, seg, p, bend, stretch);
  /* row interval by bisection: p[lo] <= pm < p[hi] */
  int lo = 0, hi = fc->m - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    (fc->p[mid] <= pm ? (lo = mid) : (hi = mid));
  }
  double w = (pm - fc->p[lo]) / (fc->p[hi] - fc->p[lo]);
  double r = (1 - w) * fc->ratio[CSR_NSEG * lo + seg] + w * fc->ratio[CSR_NSEG * hi + seg];
  bend[0] *= r;
  bend[1] *= r;
  return rc;
}


static int feEvalThunk(const void* ctx, int seg, const double p[4], double bend[2],
                       double* stretch) {
  return csr_feCalibrationEval(ctx, seg, p, bend, stretch);
}


csrBendMap csr_feCalibrationGet(const csrFeCalibration* fc) {
  csrBendMap m = {feEvalThunk, fc, fc->name, fc->p[fc->m - 1]};
  return m;
}


/* ---- FE mode table: the model behind the bend map and the rod's actuation --------------- */

/* what the bend map and the rod adapter of a mode table point to */
typedef struct {
  csrCalTable table;
  csrCalModel* model;
  csrRodSection section[CSR_NSEG]; /* the rod's default sections of II1..II3 (GA, GJ kept) */
} ModeCalibration;


static int modeEvalThunk(const void* ctx, int seg, const double p[4], double bend[2],
                         double* stretch) {
  const ModeCalibration* mc = ctx;
  csrCalSegment q;
  int rc = csr_calModelEval(mc->model, seg, p, &q);
  if (rc == 0) {
    bend[0] = q.bend[0], bend[1] = q.bend[1];
    *stretch = q.stretch;
  }
  return rc;
}


/* the rod's actuation: u0 = (-bend[1], bend[0], 0) / S and σ0 = (0, 0, stretch - 1), as the
 * rod's own adapter of a csrBendMap (robot_rod_model.c), plus the probed section */
static int modeRodThunk(const void* ctx, int seg, const double p[4],
                        csrRodSegmentActuation* out) {
  const ModeCalibration* mc = ctx;
  csrCalSegment q;
  int rc = csr_calModelEval(mc->model, seg, p, &q);
  if (rc != 0) {
    return rc;
  }
  const double S = mc->model ? csr_calModelLeg(mc->model)->S[seg] : 1.0;
  out->u0[0] = -q.bend[1] / S;
  out->u0[1] = q.bend[0] / S;
  out->u0[2] = 0;
  out->sigma0[2] = q.stretch - 1;
  double EI, EA;
  rc = csr_calModelStiffness(mc->model, seg, p, &EI, &EA);
  if (rc == 2) {
    return 0; /* no probes in the table: the rod keeps its sections */
  }
  if (rc != 0) {
    return rc;
  }
  out->has_section = 1;
  out->section = mc->section[seg];
  out->section.EA = EA;
  out->section.EI[0] = out->section.EI[1] = EI;
  return 0;
}


static void modeFree(ModeCalibration* mc) {
  if (mc) {
    csr_calModelDestroy(mc->model);
    csr_calTableFree(&mc->table);
    free(mc);
  }
}


static ModeCalibration* modeOpen(const char* path, const csrActuator* leg,
                                 const csrCalOptions* opt, csError* err) {
  ModeCalibration* mc = calloc(1, sizeof *mc);
  if (!mc) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  if (csr_calTableRead(path, leg, &mc->table, err) != CS_OK ||
      !(mc->model = csr_calModelCreate(&mc->table, leg, opt, err))) {
    modeFree(mc);
    return NULL;
  }
  csrRodParams par = csr_rodDefaultParams(leg);
  csrRodPiece pieces[CSR_ROD_MAX_PIECES];
  const int n = csr_rodLegPieces(leg, &par, pieces);
  for (int k = 0; k < n; k++) {
    if (pieces[k].segment >= 0 && pieces[k].segment < CSR_NSEG) {
      mc->section[pieces[k].segment] = pieces[k].section;
    }
  }
  return mc;
}


/* ---- any kind ------------------------------------------------------------------------------ */

struct csrCalibration_ {
  csrProvisionalMap* provisional; /* exactly one of the three is set */
  csrFeCalibration* fe;
  ModeCalibration* mode;
};


csrCalibration* csr_calibrationOpen(const char* path, const csrActuator* leg, csError* err) {
  return csr_calibrationOpenWith(path, leg, NULL, err);
}


csrCalibration* csr_calibrationOpenWith(const char* path, const csrActuator* leg,
                                        const csrCalOptions* opt, csError* err) {
  const int is_mode = csr_calTableIsModeTable(path);
  if (opt && !is_mode) {
    cs_errorSet(err, CS_ERR_ARG, "%s: a calibration rule applies only to an FE mode table (this "
                "is %s)", path, csr_calIsHdf5(path) ? "a pair-mode table" :
                "the provisional calibration");
    return NULL;
  }
  csrCalibration* c = calloc(1, sizeof *c);
  if (!c) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  if (is_mode) {
    c->mode = modeOpen(path, leg, opt, err);
  } else if (csr_calIsHdf5(path)) {
    c->fe = csr_feCalibrationCreate(path, leg, err);
  } else {
    c->provisional = csr_provisionalMapCreate(path, leg, err);
  }
  if (!c->fe && !c->provisional && !c->mode) {
    free(c);
    return NULL;
  }
  return c;
}


/* the user-facing rule names (csr_calRuleParse) */
static const struct {
  const char* name;
  csrCalRule rule;
} kRuleNames[] = {{"prism", CSR_CAL_RULE_SUPERPOSITION},
                  {"rbf", CSR_CAL_RULE_RBF},
                  {"rbf-pair", CSR_CAL_RULE_RBF_PAIR}};


int csr_calRuleParse(const char* name, csrCalRule* rule) {
  for (size_t k = 0; name && k < sizeof kRuleNames / sizeof kRuleNames[0]; k++) {
    if (!strcmp(name, kRuleNames[k].name)) {
      *rule = kRuleNames[k].rule;
      return 1;
    }
  }
  return 0;
}


int csr_calDropParse(const char* text, unsigned* drop) {
  if (!text || !*text) {
    return 0;
  }
  if (!strcmp(text, "none")) {
    *drop = 0;
    return 1;
  }
  unsigned d = 0;
  const char* s = text;
  for (;;) {
    size_t n = strcspn(s, ",");
    unsigned bit = n == 7 && !strncmp(s, "stretch", 7)     ? CSR_CAL_DROP_STRETCH
                   : n == 9 && !strncmp(s, "stiffness", 9) ? CSR_CAL_DROP_STIFFNESS
                                                           : 0;
    if (!bit || (d & bit)) {
      return 0; /* an unknown or repeated word */
    }
    d |= bit;
    if (!s[n]) {
      break;
    }
    s += n + 1;
  }
  *drop = d;
  return 1;
}


void csr_calDropFormat(unsigned drop, char* buf, size_t size) {
  const int st = (drop & CSR_CAL_DROP_STRETCH) != 0, sf = (drop & CSR_CAL_DROP_STIFFNESS) != 0;
  snprintf(buf, size, "%s%s%s", st ? "stretch" : sf ? "" : "none", st && sf ? "," : "",
           sf ? "stiffness" : "");
}


const char* csr_calRuleName(csrCalRule rule) {
  for (size_t k = 0; k < sizeof kRuleNames / sizeof kRuleNames[0]; k++) {
    if (kRuleNames[k].rule == rule) {
      return kRuleNames[k].name;
    }
  }
  return "?";
}


const char* csr_calibrationRuleName(const csrCalibration* c) {
  const csrCalModel* m = csr_calibrationModel(c);
  return m ? csr_calRuleName(csr_calModelOptions(m)->rule) : "none";
}


void csr_calibrationClose(csrCalibration* c) {
  if (c) {
    csr_feCalibrationDestroy(c->fe);
    csr_provisionalMapDestroy(c->provisional);
    modeFree(c->mode);
    free(c);
  }
}


csrBendMap csr_calibrationMap(const csrCalibration* c) {
  if (c->mode) {
    csrBendMap m = {modeEvalThunk, c->mode, csr_calModelName(c->mode->model),
                    csr_calModelPMax(c->mode->model)};
    return m;
  }
  return c->fe ? csr_feCalibrationGet(c->fe) : csr_provisionalMapGet(c->provisional);
}


const csrCalModel* csr_calibrationModel(const csrCalibration* c) {
  return c && c->mode ? c->mode->model : NULL;
}


const csrCalTable* csr_calibrationTable(const csrCalibration* c) {
  return c && c->mode ? &c->mode->table : NULL;
}


static int rodFromMode(const ModeCalibration* mc, csrRodCalibration* out) {
  out->eval = modeRodThunk;
  out->ctx = mc;
  out->name = csr_calModelName(mc->model);
  return 1;
}


int csr_calibrationRod(const csrCalibration* c, csrRodCalibration* out) {
  return c && c->mode ? rodFromMode(c->mode, out) : 0;
}


int csr_calibrationRodFromMap(const csrBendMap* map, csrRodCalibration* out) {
  return map && map->eval == modeEvalThunk && map->ctx ? rodFromMode(map->ctx, out) : 0;
}
