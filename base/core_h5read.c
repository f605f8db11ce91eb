/* core_h5read.c: the HDF5 reader (core_h5read.h), on the high-level H5LT interface. */
#include "core_h5read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

struct csH5Reader_ {
  hid_t f;
  char path[512];
};

csH5Reader* cs_h5ReaderOpen(const char* path, csError* err) {
  hid_t f = -1;
  H5E_BEGIN_TRY { f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT); }
  H5E_END_TRY;
  if (f < 0) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot open as an HDF5 file", path);
    return NULL;
  }
  csH5Reader* r = calloc(1, sizeof *r);
  if (!r) {
    H5Fclose(f);
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  r->f = f;
  snprintf(r->path, sizeof r->path, "%s", path);
  return r;
}

void cs_h5ReaderClose(csH5Reader* r) {
  if (r) {
    H5Fclose(r->f);
    free(r);
  }
}

int cs_h5ReaderHas(const csH5Reader* r, const char* name) {
  int has = 0;
  H5E_BEGIN_TRY { has = H5LTpath_valid(r->f, name, 1) > 0; }
  H5E_END_TRY;
  return has;
}

double* cs_h5ReaderDoubles(const csH5Reader* r, const char* name, int want_rank,
                           const size_t* want, size_t* dims, int* rank, csError* err) {
  if (!cs_h5ReaderHas(r, name)) {
    cs_errorSet(err, CS_ERR_IO, "%s: no dataset %s", r->path, name);
    return NULL;
  }
  int rk = 0;
  hsize_t d[4] = {1, 1, 1, 1};
  H5T_class_t cls;
  size_t sz;
  int ok = 0;
  H5E_BEGIN_TRY {
    ok = H5LTget_dataset_ndims(r->f, name, &rk) >= 0 && rk >= 1 && rk <= 4 &&
         H5LTget_dataset_info(r->f, name, d, &cls, &sz) >= 0 &&
         (cls == H5T_FLOAT || cls == H5T_INTEGER);
  }
  H5E_END_TRY;
  if (!ok) {
    cs_errorSet(err, CS_ERR_IO, "%s: dataset %s is not an array of numbers of rank 1..4", r->path,
                name);
    return NULL;
  }
  if (want_rank > 0) {
    int match = rk == want_rank;
    for (int k = 0; match && k < rk; k++) {
      match = !want || want[k] == 0 || want[k] == (size_t)d[k];
    }
    if (!match) {
      char got[96] = "", exp[96] = "";
      for (int k = 0; k < rk; k++) {
        snprintf(got + strlen(got), sizeof got - strlen(got), "%s%llu", k ? " x " : "",
                 (unsigned long long)d[k]);
      }
      for (int k = 0; k < want_rank; k++) {
        snprintf(exp + strlen(exp), sizeof exp - strlen(exp), "%s%zu", k ? " x " : "",
                 want ? want[k] : 0);
      }
      cs_errorSet(err, CS_ERR_IO, "%s: dataset %s is %s, expected %s", r->path, name, got, exp);
      return NULL;
    }
  }
  size_t count = 1;
  for (int k = 0; k < rk; k++) {
    count *= (size_t)d[k];
    if (dims) {
      dims[k] = (size_t)d[k];
    }
  }
  if (rank) {
    *rank = rk;
  }
  double* v = malloc((count ? count : 1) * sizeof(double));
  if (!v) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory for %s (%zu values)", r->path, name, count);
    return NULL;
  }
  herr_t st = -1;
  H5E_BEGIN_TRY { st = H5LTread_dataset_double(r->f, name, v); }
  H5E_END_TRY;
  if (st < 0) {
    free(v);
    cs_errorSet(err, CS_ERR_IO, "%s: cannot read dataset %s", r->path, name);
    return NULL;
  }
  return v;
}

csStatus cs_h5ReaderAttrDouble(const csH5Reader* r, const char* name, double* v, csError* err) {
  int ok = 0;
  H5E_BEGIN_TRY {
    ok = H5Aexists(r->f, name) > 0 && H5LTget_attribute_double(r->f, "/", name, v) >= 0;
  }
  H5E_END_TRY;
  return ok ? CS_OK
            : cs_errorSet(err, CS_ERR_IO, "%s: no numeric attribute %s", r->path, name);
}

csStatus cs_h5ReaderAttrString(const csH5Reader* r, const char* name, char* buf, size_t size,
                               csError* err) {
  int ok = 0;
  hsize_t d = 0;
  H5T_class_t cls = H5T_NO_CLASS;
  size_t sz = 0;
  H5E_BEGIN_TRY {
    ok = H5Aexists(r->f, name) > 0 &&
         H5LTget_attribute_info(r->f, "/", name, &d, &cls, &sz) >= 0 && cls == H5T_STRING;
  }
  H5E_END_TRY;
  if (!ok) {
    return cs_errorSet(err, CS_ERR_IO, "%s: no string attribute %s", r->path, name);
  }
  char* tmp = calloc(sz + 2, 1);
  if (!tmp) {
    return cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", r->path);
  }
  H5E_BEGIN_TRY { ok = H5LTget_attribute_string(r->f, "/", name, tmp) >= 0; }
  H5E_END_TRY;
  if (ok) {
    snprintf(buf, size, "%s", tmp);
  }
  free(tmp);
  return ok ? CS_OK : cs_errorSet(err, CS_ERR_IO, "%s: cannot read attribute %s", r->path, name);
}
