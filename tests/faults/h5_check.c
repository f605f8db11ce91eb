/* h5_check.c: what a reader finds in a crawlsim output file, for the fault-injection suite
 * (tools/fault-suite.py). Opens FILE with the HDF5 C API and prints key=value lines:
 *   open=1|0, kind=run|bend|other, status=<root attribute>, samples=<root attribute or -1>,
 *   rows=<rows of /time (run) or /pressure (bend)>, consistent=1|0 (every series of the kind
 *   that exists has the same number of rows and every value could be read), missing=<series
 *   of the kind that do not exist (a header cut short by a failure)>, monotone=1|0 (/time strictly
 *   increasing, /pressure non-decreasing, all finite), last=<last /time or /pressure value>.
 * Exit status 0 when the file opens, 2 when it does not, 1 on bad usage. */
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char* kRunSeries[] = {"/time", "/support/position", "/support/orientation",
                                   "/pressure", "/support/corners", "/contact/force",
                                   "/contact/max_depth", "/contact/leg_max_depth",
                                   "/legs/A/centerline", "/legs/B/centerline",
                                   "/legs/C/centerline", "/legs/D/centerline",
                                   "/legs/E/centerline", "/legs/F/centerline",
                                   "/legs/G/centerline", "/legs/H/centerline"};
static const char* kBendSeries[] = {"/pressure", "/angle_deg", "/angle_total_deg",
                                    "/tip_position"};

/* rows of a dataset (first dimension), -1 when absent or unreadable; reads it all */
static long rowsOf(hid_t f, const char* path, double** out) {
  if (H5Lexists(f, "/legs", H5P_DEFAULT) < 0 && strncmp(path, "/legs", 5) == 0) {
    return -1;
  }
  if (H5Oexists_by_name(f, path, H5P_DEFAULT) <= 0) {
    return -1;
  }
  hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
  if (d < 0) {
    return -1;
  }
  hid_t sp = H5Dget_space(d);
  hsize_t dims[4] = {0, 1, 1, 1};
  int rank = H5Sget_simple_extent_ndims(sp);
  long rows = -1;
  if (rank >= 1 && rank <= 4 && H5Sget_simple_extent_dims(sp, dims, NULL) >= 0) {
    size_t n = 1;
    for (int i = 0; i < rank; i++) {
      n *= dims[i];
    }
    double* buf = malloc((n ? n : 1) * sizeof(double));
    if (buf && (n == 0 || H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0)) {
      rows = (long)dims[0];
      if (out) {
        *out = buf;
        buf = NULL;
      }
    }
    free(buf);
  }
  H5Sclose(sp);
  H5Dclose(d);
  return rows;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: h5_check FILE\n");
    return 1;
  }
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(argv[1], H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    printf("open=0\n");
    return 2;
  }
  printf("open=1\n");
  /* status: any string attribute */
  char status[1024] = "";
  if (H5Aexists(f, "status") > 0) {
    hid_t a = H5Aopen(f, "status", H5P_DEFAULT);
    hid_t t = H5Aget_type(a);
    if (H5Tis_variable_str(t) > 0) {
      char* v = NULL;
      hid_t mt = H5Tcopy(H5T_C_S1);
      H5Tset_size(mt, H5T_VARIABLE);
      if (H5Aread(a, mt, &v) >= 0 && v) {
        snprintf(status, sizeof status, "%s", v);
        H5free_memory(v);
      }
      H5Tclose(mt);
    } else {
      size_t n = H5Tget_size(t);
      char* v = calloc(n + 1, 1);
      if (v && H5Aread(a, t, v) >= 0) {
        snprintf(status, sizeof status, "%s", v);
      }
      free(v);
    }
    H5Tclose(t);
    H5Aclose(a);
  }
  for (char* c = status; *c; c++) {
    if (*c == '\n') *c = ' ';
  }
  printf("status=%s\n", status);
  double samples = -1;
  if (H5Aexists(f, "samples") > 0) {
    hid_t a = H5Aopen(f, "samples", H5P_DEFAULT);
    H5Aread(a, H5T_NATIVE_DOUBLE, &samples);
    H5Aclose(a);
  }
  printf("samples=%.0f\n", samples);
  int run = H5Lexists(f, "/time", H5P_DEFAULT) > 0;
  int bend = !run && H5Lexists(f, "/angle_total_deg", H5P_DEFAULT) > 0;
  printf("kind=%s\n", run ? "run" : bend ? "bend" : "other");
  const char** list = run ? kRunSeries : kBendSeries;
  size_t nlist = run ? sizeof kRunSeries / sizeof *kRunSeries
                     : sizeof kBendSeries / sizeof *kBendSeries;
  long rows = -1;
  int consistent = 1, monotone = 1, missing = 0;
  double last = NAN;
  if (run || bend) {
    double* x = NULL;
    rows = rowsOf(f, list[0], &x);
    consistent = rows >= 0;
    for (long i = 0; i < rows; i++) {
      if (!isfinite(x[i]) || (i > 0 && (run ? x[i] <= x[i - 1] : x[i] < x[i - 1]))) {
        monotone = 0;
      }
      last = x[i];
    }
    free(x);
    for (size_t k = 1; k < nlist; k++) {
      if (H5Lexists(f, list[k], H5P_DEFAULT) <= 0) {
        missing++;
      } else if (rowsOf(f, list[k], NULL) != rows) {
        consistent = 0;
      }
    }
  }
  printf("rows=%ld\nconsistent=%d\nmissing=%d\nmonotone=%d\nlast=%.9g\n", rows, consistent,
         missing, monotone, last);
  H5Fclose(f);
  return 0;
}
