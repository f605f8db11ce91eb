/* robot_calibration_table.c: reading and checking an FE mode calibration table
 * (robot_calibration_table.h). Every check names the file, the case and the dataset it found
 * wrong, in one line, so that a truncated or foreign table never reaches the legs. */
#include "robot_calibration_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "core_math.h"
#include "robot_bend_io.h"

/* actuator parameters are written as doubles, so file and leg agree exactly; 1e-9 relative
 * only absorbs a hand-edited decimal (as the pair-mode reader, robot_calibration.c) */
#define PARAM_RTOL 1e-9
/* rows of one case: 0.001 MPa steps to 1 MPa are 1001; anything far above is not a sweep */
#define MAX_ROWS 100000
/* ratios are written as doubles (1/3, 5/7 ...): equal patterns compare to round-off */
#define RATIO_TOL 1e-12
/* p_end is the last row's pressure written twice; 1e-12 MPa absorbs nothing but round-off */
#define P_END_TOL 1e-12
/* a sweep's pressures are the writer's load factors (MPa); 1 MPa is the gaits' ceiling */
#define MAX_PRESSURE 1.0
/* kinematic values (rad, mm, -, deg) of any FE result are far below this; a larger finite one
 * (up to 1.8e308) overflows the model's interpolation into NaN (tests/fuzz, fuzz_calib_h5) */
#define MAX_VALUE 1e6
/* MPa: rows closer than this make the interpolation's slopes (value / row spacing) overflow */
#define MIN_ROW_DP 1e-9
/* stiffness probes (N mm^2, N): far above any leg's, far below overflow when averaged */
#define MAX_STIFFNESS 1e12

static const char* const kKindNames[] = {"mode", "holdout", "symmetry", "gravity"};

/* the FE settings a table must name (fem_calibration.h root attributes) */
static const char* const kSettings[] = {"fe_mesh_size_mm", "fe_fibre_size_mm", "fe_fibre_split",
                                        "fe_p_step_MPa", "fe_p_cap_MPa"};


const char* csr_calKindName(csrCalKind kind) {
  return kind >= CSR_CAL_MODE && kind <= CSR_CAL_GRAVITY ? kKindNames[kind] : "?";
}


/* the attribute `name` of `obj` when it holds exactly one element: its id and its type in *type
 * (the caller closes both), or -1. One element only: H5LT's attribute calls write every element
 * and every extent of an attribute into the caller's buffers (an array attribute overflowed
 * them: tests/fuzz, fuzz_calib_h5) */
static hid_t attrOpenOne(hid_t f, const char* obj, const char* name, hid_t* type) {
  if (H5Aexists_by_name(f, obj, name, H5P_DEFAULT) <= 0) {
    return -1;
  }
  hid_t a = H5Aopen_by_name(f, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) {
    return -1;
  }
  hid_t t = H5Aget_type(a), sp = H5Aget_space(a);
  int one = t >= 0 && sp >= 0 && H5Sget_simple_extent_npoints(sp) == 1;
  if (sp >= 0) H5Sclose(sp);
  if (!one) {
    if (t >= 0) H5Tclose(t);
    H5Aclose(a);
    return -1;
  }
  *type = t;
  return a;
}


/* a string attribute of `obj` into buf; 0 if absent, not a string or too long. Fixed-length
 * (this project's writer) and variable-length strings (h5py's default) are both read. */
static int attrString(hid_t f, const char* obj, const char* name, char* buf, size_t size) {
  hid_t t = -1;
  hid_t a = attrOpenOne(f, obj, name, &t);
  if (a < 0) {
    return 0;
  }
  int ok = H5Tget_class(t) == H5T_STRING;
  if (ok && H5Tis_variable_str(t) > 0) {
    char* v = NULL;
    hid_t mt = H5Tcopy(H5T_C_S1);
    H5Tset_size(mt, H5T_VARIABLE);
    H5Tset_cset(mt, H5Tget_cset(t)); /* ASCII or UTF-8: no conversion between them */
    ok = H5Aread(a, mt, &v) >= 0 && v && strlen(v) < size;
    if (ok) {
      snprintf(buf, size, "%s", v);
    }
    if (v) {
      H5free_memory(v);
    }
    H5Tclose(mt);
  } else if (ok) {
    const size_t n = H5Tget_size(t);
    ok = n > 0 && n < size;
    if (ok) {
      hid_t mt = H5Tcopy(H5T_C_S1);
      H5Tset_size(mt, n + 1);
      H5Tset_cset(mt, H5Tget_cset(t));
      ok = H5Aread(a, mt, buf) >= 0;
      buf[n] = '\0';
      H5Tclose(mt);
    }
  }
  H5Tclose(t);
  H5Aclose(a);
  return ok;
}


/* a scalar double attribute of `obj`; 0 if absent or not one number */
static int attrDouble(hid_t f, const char* obj, const char* name, double* v) {
  hid_t t = -1;
  hid_t a = attrOpenOne(f, obj, name, &t);
  if (a < 0) {
    return 0;
  }
  const H5T_class_t cls = H5Tget_class(t);
  int ok = (cls == H5T_FLOAT || cls == H5T_INTEGER) && H5Aread(a, H5T_NATIVE_DOUBLE, v) >= 0;
  H5Tclose(t);
  H5Aclose(a);
  return ok;
}


int csr_calAttrString(hid_t f, const char* obj, const char* name, char* buf, size_t size) {
  return attrString(f, obj, name, buf, size);
}


int csr_calIsHdf5(const char* path) {
  static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  unsigned char head[8];
  FILE* fp = fopen(path, "rb");
  if (!fp) {
    return 0;
  }
  size_t n = fread(head, 1, sizeof head, fp);
  fclose(fp);
  return n == sizeof head && memcmp(head, sig, sizeof sig) == 0;
}


int csr_calTableIsModeTable(const char* path) {
  if (!csr_calIsHdf5(path)) {
    return 0;
  }
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return 0;
  }
  char fmt[128] = "";
  int yes = attrString(f, "/", "format", fmt, sizeof fmt) &&
            !strncmp(fmt, CSR_CAL_FORMAT_PREFIX, strlen(CSR_CAL_FORMAT_PREFIX));
  H5Fclose(f);
  return yes;
}


typedef struct {
  hid_t f;
  const char* path;
  csError* err;
  csStatus st;
} ParamCheck;

/* csr_actuatorVisit callback: the table's attribute `name` must equal the leg's value */
static void checkParam(void* user, const char* name, double value) {
  ParamCheck* c = user;
  double v = NAN;
  if (c->st != CS_OK) {
    return;
  }
  if (!attrDouble(c->f, "/", name, &v)) {
    c->st = cs_errorSet(c->err, CS_ERR_PARSE, "%s: calibration table has no attribute '%s' of "
                        "one number (an actuator parameter)", c->path, name);
  } else if (!(fabs(v - value) <= PARAM_RTOL * fabs(value))) {
    c->st = cs_errorSet(c->err, CS_ERR_RANGE, "%s: calibrated for another actuator: %s = %g in "
                        "the table, %g in the leg", c->path, name, v, value);
  }
}


csStatus csr_calCheckActuator(const char* path, const csrActuator* leg, csError* err) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open as an HDF5 calibration table", path);
  }
  ParamCheck pc = {f, path, err, CS_OK};
  csr_actuatorVisit(leg, checkParam, &pc);
  H5Fclose(f);
  return pc.st;
}


/* format the shape of a dataset as "[5,3,2]" */
static void shapeText(const hsize_t* dims, int rank, char* buf, size_t size) {
  size_t n = (size_t)snprintf(buf, size, "[");
  for (int i = 0; i < rank && n < size; i++) {
    n += (size_t)snprintf(buf + n, size - n, i ? ",%llu" : "%llu", (unsigned long long)dims[i]);
  }
  if (n < size) {
    snprintf(buf + n, size - n, "]");
  }
}


/* Read dataset `name` of case `c` with the expected shape (rank, want[]); want[0] is the row
 * count, named `rows` ("M" or "K") in the message. Allocates *out. */
static csStatus readDataset(hid_t f, const char* path, const char* cname, const char* name,
                            int rank, const hsize_t* want, const char* rows, double** out,
                            csError* err) {
  char obj[160];
  snprintf(obj, sizeof obj, "/cases/%s/%s", cname, name);
  int r = -1;
  hsize_t dims[4] = {0, 0, 0, 0};
  H5T_class_t cls;
  size_t sz;
  if (H5LTpath_valid(f, obj, 1) <= 0 || H5LTget_dataset_ndims(f, obj, &r) < 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s has no dataset '%s'", path, cname, name);
  }
  int same = r == rank && H5LTget_dataset_info(f, obj, dims, &cls, &sz) >= 0 && cls == H5T_FLOAT;
  for (int i = 0; same && i < rank; i++) {
    same = dims[i] == want[i];
  }
  if (!same) {
    char got[64], exp[64];
    shapeText(dims, r > 0 && r <= 4 ? r : 0, got, sizeof got);
    shapeText(want, rank, exp, sizeof exp);
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s: dataset '%s' has shape %s, expected %s "
                       "(%s = %llu rows): truncated or inconsistent", path, cname, name, got, exp,
                       rows, (unsigned long long)want[0]);
  }
  size_t n = 1;
  for (int i = 0; i < rank; i++) {
    n *= (size_t)want[i];
  }
  *out = malloc((n > 0 ? n : 1) * sizeof(double));
  if (!*out) {
    return cs_errorSet(err, CS_ERR_MEMORY, "%s: case %s: out of memory for '%s' (%zu values)",
                       path, cname, name, n);
  }
  if (H5LTread_dataset_double(f, obj, *out) < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: case %s: cannot read '%s'", path, cname, name);
  }
  return CS_OK;
}


/* every value of a per-row dataset finite: row and part (segment, or component of a point)
 * of the first that is not. `per` values per row in `nseg` parts (per / nseg values each). */
static csStatus checkFinite(const char* path, const char* cname, const char* name,
                            const double* a, int m, int per, int nseg, const char* part,
                            csError* err) {
  for (int i = 0; i < m; i++) {
    for (int q = 0; q < per; q++) {
      const double v = a[(size_t)i * per + q];
      if (!isfinite(v) || fabs(v) > MAX_VALUE) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: %s row %d %s %d is %g (%s)", path,
                           cname, name, i + 1, part, q / (per / nseg) + 1, v,
                           isfinite(v) ? "beyond +-1e6: not an FE result" : "not finite");
      }
    }
  }
  return CS_OK;
}


/* the stiffness probes of a case, if it has any (probe_pressure present) */
static csStatus readProbes(hid_t f, const char* path, csrCalCase* c, csError* err) {
  char obj[160];
  snprintf(obj, sizeof obj, "/cases/%s/probe_pressure", c->name);
  if (H5LTpath_valid(f, obj, 1) <= 0) {
    return CS_OK; /* no probes in this case */
  }
  int r = -1;
  hsize_t dims[4] = {0, 0, 0, 0};
  H5T_class_t cls;
  size_t sz;
  if (H5LTget_dataset_ndims(f, obj, &r) < 0 || r != 1 ||
      H5LTget_dataset_info(f, obj, dims, &cls, &sz) < 0 || dims[0] < 1 ||
      dims[0] > (hsize_t)c->m) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s: probe_pressure must have 1..%d rows",
                       path, c->name, c->m);
  }
  const hsize_t K = dims[0];
  c->k = (int)K;
  const hsize_t dk[1] = {K}, dei[3] = {K, 3, 2}, dea[2] = {K, 3};
  csStatus st = readDataset(f, path, c->name, "probe_pressure", 1, dk, "K", &c->probe_pressure,
                            err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "probe_force", 2, dea, "K", &c->probe_force,
                                    err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "EI", 3, dei, "K", &c->EI, err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "EA", 2, dea, "K", &c->EA, err);
  /* a probe force is >= 0 (0: that probe was not asked for) and of a plausible size */
  for (hsize_t q = 0; q < 3 * K && st == CS_OK; q++) {
    if (!(c->probe_force[q] >= 0 && c->probe_force[q] <= MAX_STIFFNESS)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: probe_force row %d is %g N (must be in "
                       "0..1e12)", path, c->name, (int)(q / 3) + 1, c->probe_force[q]);
    }
  }
  /* the raw probe datasets must be there with the same K (the reduced EI, EA come from them) */
  const hsize_t dpb[4] = {K, 3, 3, 2}, dps[3] = {K, 3, 3};
  const char* raw[3] = {"probe_bend", "probe_stretch", "probe_tip"};
  for (int q = 0; q < 3 && st == CS_OK; q++) {
    double* tmp = NULL;
    st = readDataset(f, path, c->name, raw[q], q == 0 ? 4 : 3, q == 0 ? dpb : dps, "K", &tmp,
                     err);
    free(tmp);
  }
  /* each probe sits on a row of the sweep */
  for (int k = 0; k < c->k && st == CS_OK; k++) {
    int on_row = 0;
    for (int i = 0; i < c->m; i++) {
      on_row |= fabs(c->pressure[i] - c->probe_pressure[k]) <= P_END_TOL;
    }
    if (!on_row) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s: case %s: probe %d at %g MPa is not a row of the "
                       "sweep", path, c->name, k + 1, c->probe_pressure[k]);
    }
  }
  /* a stiffness is NAN (failed probe) or in (0, MAX_STIFFNESS] */
  for (int k = 0; k < c->k && st == CS_OK; k++) {
    for (int s = 0; s < CSR_NSEG && st == CS_OK; s++) {
      const double v[3] = {c->EI[6 * k + 2 * s], c->EI[6 * k + 2 * s + 1], c->EA[3 * k + s]};
      for (int q = 0; q < 3; q++) {
        if (!isnan(v[q]) && !(v[q] > 0 && v[q] <= MAX_STIFFNESS)) {
          st = cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: %s probe %d segment %d is %g (a "
                           "stiffness must be > 0 and at most 1e12, or NaN for a failed probe)",
                           path, c->name, q < 2 ? "EI" : "EA", k + 1, s + 1, v[q]);
          break;
        }
      }
    }
  }
  return st;
}


/* The FE measures a segment's bend as the rotation vector of its end face relative to its base
 * face (fem_measure.c), whose angle is at most pi: a segment bent by theta > pi towards n is
 * written as the same rotation by 2 pi - theta towards -n. Along a sweep the bend grows
 * continuously, so each row takes, of the equivalent vectors v (1 + 2 pi k / |v|), the one
 * nearest the previous row's (k = 0 while the bend stays below pi: the others are 2 pi away). */
static void unwrapBends(csrCalCase* c) {
  for (int s = 0; s < CSR_NSEG; s++) {
    double prev[2] = {c->bend[2 * s], c->bend[2 * s + 1]};
    for (int i = 1; i < c->m; i++) {
      double* v = c->bend + 6 * i + 2 * s;
      const double r = hypot(v[0], v[1]);
      double best[2] = {v[0], v[1]}, dbest = hypot(v[0] - prev[0], v[1] - prev[1]);
      for (int k = -2; k <= 2 && r > 0; k++) {
        const double f = 1 + 2 * CS_PI * k / r;
        const double d = hypot(f * v[0] - prev[0], f * v[1] - prev[1]);
        if (d < dbest) {
          dbest = d, best[0] = f * v[0], best[1] = f * v[1];
        }
      }
      v[0] = best[0], v[1] = best[1];
      prev[0] = v[0], prev[1] = v[1];
    }
  }
}


/* attributes, datasets and their consistency for one case */
static csStatus readCase(hid_t f, const char* path, csrCalCase* c, csError* err) {
  char obj[128], kind[32] = "";
  snprintf(obj, sizeof obj, "/cases/%s", c->name);
  if (!attrString(f, obj, "kind", kind, sizeof kind)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s has no 'kind' attribute", path, c->name);
  }
  int kd = 0;
  while (kd < 4 && strcmp(kind, kKindNames[kd])) kd++;
  if (kd == 4) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s: unknown kind '%s' (expected mode, "
                       "holdout, symmetry or gravity)", path, c->name, kind);
  }
  c->kind = (csrCalKind)kd;
  /* the status is written last: without it the case did not finish */
  if (!attrString(f, obj, "status", c->status, sizeof c->status)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s is unfinished (no status attribute)",
                       path, c->name);
  }
  c->complete = !strcmp(c->status, "complete");
  if (!c->complete && strncmp(c->status, "ended at ", 9) != 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s is unfinished (status '%.200s')", path,
                       c->name, c->status);
  }
  double rmax = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    char nm[16];
    snprintf(nm, sizeof nm, "ratio%d", j + 1);
    if (!attrDouble(f, obj, nm, &c->ratio[j])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s has no attribute '%s' of one number",
                         path, c->name, nm);
    }
    if (!(c->ratio[j] >= 0 && c->ratio[j] <= 1)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: %s is %g (chamber ratios are in [0, "
                         "1])", path, c->name, nm, c->ratio[j]);
    }
    rmax = fmax(rmax, c->ratio[j]);
  }
  if (c->kind != CSR_CAL_GRAVITY && rmax != 1) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: the largest chamber ratio is %g (the "
                       "load factor p is the highest chamber's pressure: 1)", path, c->name, rmax);
  }
  if (!attrDouble(f, obj, "wall_time_s", &c->wall_time)) {
    c->wall_time = NAN; /* informative only */
  }
  if (!attrDouble(f, obj, "p_end", &c->p_end) || !attrDouble(f, obj, "p_limit", &c->p_limit)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s needs attributes p_end and p_limit", path,
                       c->name);
  }
  /* the row count from the pressure; every other dataset must have as many rows */
  snprintf(obj, sizeof obj, "/cases/%s/pressure", c->name);
  int r = -1;
  hsize_t dims[4] = {0, 0, 0, 0};
  H5T_class_t cls;
  size_t sz;
  if (H5LTpath_valid(f, obj, 1) <= 0 || H5LTget_dataset_ndims(f, obj, &r) < 0 || r != 1 ||
      H5LTget_dataset_info(f, obj, dims, &cls, &sz) < 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s needs a dataset 'pressure' of shape [M]",
                       path, c->name);
  }
  if (dims[0] < 2 || dims[0] > MAX_ROWS) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s has %llu rows (need 2..%d)", path, c->name,
                       (unsigned long long)dims[0], MAX_ROWS);
  }
  const hsize_t M = dims[0];
  c->m = (int)M;
  const hsize_t d1[1] = {M}, d2[2] = {M, 3}, d3[3] = {M, 3, 2};
  csStatus st = readDataset(f, path, c->name, "pressure", 1, d1, "M", &c->pressure, err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "bend", 3, d3, "M", &c->bend, err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "twist", 2, d2, "M", &c->twist, err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "stretch", 2, d2, "M", &c->stretch, err);
  if (st == CS_OK) st = readDataset(f, path, c->name, "radial", 2, d2, "M", &c->radial, err);
  if (st == CS_OK) {
    st = readDataset(f, path, c->name, "radial_max", 2, d2, "M", &c->radial_max, err);
  }
  if (st == CS_OK) st = readDataset(f, path, c->name, "tip", 2, d2, "M", &c->tip, err);
  if (st == CS_OK) {
    st = readDataset(f, path, c->name, "angle_total_deg", 1, d1, "M", &c->angle_total, err);
  }
  if (st != CS_OK) {
    return st;
  }
  /* pressures: 0 first, strictly increasing, within the gaits' range; p_end the last row */
  if (c->pressure[0] != 0) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: pressure row 1 is %g MPa (a sweep starts "
                       "at 0)", path, c->name, c->pressure[0]);
  }
  for (int i = 1; i < c->m; i++) {
    if (!(c->pressure[i] >= c->pressure[i - 1] + MIN_ROW_DP) ||
        !(c->pressure[i] <= MAX_PRESSURE)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: pressure row %d (%g MPa) must be above "
                         "row %d (%g MPa) by %g MPa at least and at most %g MPa", path, c->name,
                         i + 1, c->pressure[i], i, c->pressure[i - 1], MIN_ROW_DP, MAX_PRESSURE);
    }
  }
  if (!(fabs(c->p_end - c->pressure[c->m - 1]) <= P_END_TOL)) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s: case %s: p_end is %g MPa but the last row is at "
                       "%g MPa (truncated or inconsistent)", path, c->name, c->p_end,
                       c->pressure[c->m - 1]);
  }
  if (!isnan(c->p_limit) && !(c->p_limit > 0 && isfinite(c->p_limit))) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: p_limit is %g (a pressure > 0, or NaN for "
                       "none)", path, c->name, c->p_limit);
  }
  const struct {
    const char* name;
    const double* a;
    int per;
  } fin[] = {{"bend", c->bend, 6},           {"twist", c->twist, 3},
             {"stretch", c->stretch, 3},     {"radial", c->radial, 3},
             {"radial_max", c->radial_max, 3}, {"tip", c->tip, 3}};
  for (size_t q = 0; q < sizeof fin / sizeof fin[0] && st == CS_OK; q++) {
    /* the tip is one point per row: its parts are the components x, y, z */
    st = checkFinite(path, c->name, fin[q].name, fin[q].a, c->m, fin[q].per, 3,
                     fin[q].a == c->tip ? "component" : "segment", err);
  }
  if (st == CS_OK) {
    st = checkFinite(path, c->name, "angle_total_deg", c->angle_total, c->m, 1, 1, "value",
                     err);
  }
  for (int i = 0; i < c->m && st == CS_OK; i++) {
    for (int s = 0; s < CSR_NSEG; s++) {
      if (!(c->stretch[3 * i + s] > 0)) {
        st = cs_errorSet(err, CS_ERR_RANGE, "%s: case %s: stretch row %d segment %d is %g (must "
                         "be > 0)", path, c->name, i + 1, s + 1, c->stretch[3 * i + s]);
        break;
      }
    }
  }
  if (st == CS_OK) {
    unwrapBends(c);
  }
  return st == CS_OK ? readProbes(f, path, c, err) : st;
}


csStatus csr_calTableRead(const char* path, const csrActuator* leg, csrCalTable* t,
                          csError* err) {
  memset(t, 0, sizeof *t);
  snprintf(t->path, sizeof t->path, "%s", path);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* errors are reported here, not printed by HDF5 */
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open as an HDF5 calibration table", path);
  }
  csStatus st = CS_OK;
  char fmt[128] = "";
  hid_t g = -1;
  if (!attrString(f, "/", "format", fmt, sizeof fmt)) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: not a crawlsim FE calibration table (no root "
                     "attribute 'format')", path);
    goto done;
  }
  if (strcmp(fmt, CSR_CAL_FORMAT) != 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: calibration table format '%.60s' is not supported "
                     "(this build reads '%s')", path, fmt, CSR_CAL_FORMAT);
    goto done;
  }
  ParamCheck pc = {f, path, err, CS_OK};
  csr_actuatorVisit(leg, checkParam, &pc); /* the file is open here: no second open */
  if ((st = pc.st) != CS_OK) {
    goto done;
  }
  double set[5];
  for (int q = 0; q < 5; q++) {
    if (!attrDouble(f, "/", kSettings[q], &set[q])) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s: no FE setting '%s' (a table names the FE settings "
                       "it came from)", path, kSettings[q]);
      goto done;
    }
  }
  t->fe_mesh_size = set[0], t->fe_fibre_size = set[1], t->fe_p_step = set[3];
  t->fe_p_cap = set[4];
  double sym = 0;
  if (H5Aexists_by_name(f, "/", "fe_mesh_symmetric", H5P_DEFAULT) > 0 &&
      (!attrDouble(f, "/", "fe_mesh_symmetric", &sym) || (sym != 0 && sym != 1))) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: fe_mesh_symmetric must be 0 or 1", path);
    goto done;
  }
  t->fe_mesh_symmetric = (int)sym;
  snprintf(t->fe_fibre_law, sizeof t->fe_fibre_law, "linear");
  if (H5Aexists_by_name(f, "/", "fe_fibre_law", H5P_DEFAULT) > 0 &&
      (!attrString(f, "/", "fe_fibre_law", t->fe_fibre_law, sizeof t->fe_fibre_law) ||
       csr_fibreLawParse(t->fe_fibre_law) < 0)) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: fe_fibre_law must be \"linear\" or "
                     "\"tension-only\"", path);
    goto done;
  }
  if (!attrString(f, "/", "fe_solver", t->fe_solver, sizeof t->fe_solver)) {
    snprintf(t->fe_solver, sizeof t->fe_solver, "?");
  }
  if (!attrString(f, "/", "version", t->version, sizeof t->version)) {
    snprintf(t->version, sizeof t->version, "?");
  }
  H5G_info_t gi;
  g = H5Lexists(f, "/cases", H5P_DEFAULT) > 0 ? H5Gopen2(f, "/cases", H5P_DEFAULT) : -1;
  if (g < 0 || H5Gget_info(g, &gi) < 0 || gi.nlinks == 0) {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s: calibration table has no cases (group /cases)",
                     path);
    goto done;
  }
  t->cases = calloc((size_t)gi.nlinks, sizeof *t->cases);
  if (!t->cases) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    goto done;
  }
  for (hsize_t i = 0; i < gi.nlinks && st == CS_OK; i++) {
    csrCalCase* c = t->cases + t->ncase++;
    ssize_t n = H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, c->name, sizeof c->name,
                                   H5P_DEFAULT);
    if (n <= 0 || (size_t)n >= sizeof c->name) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s: case %llu of /cases has no usable name", path,
                       (unsigned long long)i + 1);
    } else {
      st = readCase(f, path, c, err);
    }
  }
done:
  if (g >= 0) {
    H5Gclose(g);
  }
  H5Fclose(f);
  return st;
}


void csr_calTableFree(csrCalTable* t) {
  if (!t) {
    return;
  }
  for (int i = 0; i < t->ncase; i++) {
    csrCalCase* c = t->cases + i;
    double* arrays[] = {c->pressure, c->bend, c->twist,          c->stretch, c->radial,
                        c->radial_max, c->tip, c->angle_total, c->probe_pressure, c->probe_force,
                        c->EI, c->EA};
    for (size_t q = 0; q < sizeof arrays / sizeof arrays[0]; q++) {
      free(arrays[q]);
    }
  }
  free(t->cases);
  t->cases = NULL;
  t->ncase = 0;
}


const csrCalCase* csr_calTableFind(const csrCalTable* t, csrCalKind kind,
                                   const double ratio[CSR_NCHAMBER]) {
  for (int i = 0; i < t->ncase; i++) {
    const csrCalCase* c = t->cases + i;
    int same = c->kind == kind;
    for (int j = 0; j < CSR_NCHAMBER && same; j++) {
      same = fabs(c->ratio[j] - ratio[j]) <= RATIO_TOL;
    }
    if (same) {
      return c;
    }
  }
  return NULL;
}
