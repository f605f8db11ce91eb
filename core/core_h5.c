/* core_h5.c: HDF5 writer (see core_h5.h).
 *
 * Why chunked extendible datasets for series: a run writes samples as it goes and flushes, so
 * a run that diverges or is interrupted still leaves a valid file with the samples so far. The
 * chunk holds 64 rows: small enough for short runs, large enough that a 9 s run at 100 Hz is a
 * handful of chunks. Rows are gathered in memory and written a chunk at a time (and at every
 * cs_h5Flush and at close): one extent change and one write per 64 rows instead of per row
 * (measured on the 9 s rod flat road: a row-by-row append of the 16 series cost ~0.2 ms per
 * sample, 7 % of the run). HDF5's own error stack printing is switched off; failures come back
 * as csStatus with the path named. */
#include "core_h5.h"

#include <hdf5.h>
#include <stdlib.h>
#include <string.h>

enum { SERIES_CHUNK_ROWS = 64 };

typedef struct {
  hid_t dset;
  int rank;        /* full rank = tail rank + 1 */
  hsize_t dims[4]; /* dims written to the file */
  size_t row_len;  /* doubles per row */
  int npend;       /* rows gathered in pend, not yet written */
  double* pend;    /* (SERIES_CHUNK_ROWS x row_len) */
} Series;

struct csH5File_ {
  hid_t file;
  hid_t lcpl; /* link creation property list: create intermediate groups */
  int nseries;
  Series series[CS_H5_MAX_SERIES];
  char path[256];
};


csH5File* cs_h5Create(const char* path, csError* err) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  csH5File* f = calloc(1, sizeof *f);
  if (!f) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  f->file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (f->file < 0) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot create HDF5 file", path);
    free(f);
    return NULL;
  }
  f->lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(f->lcpl, 1);
  snprintf(f->path, sizeof f->path, "%s", path);
  return f;
}


/* write the rows gathered in series s to the file */
static csStatus writePending(csH5File* f, Series* s, csError* err) {
  if (s->npend == 0) {
    return CS_OK;
  }
  hsize_t start[4] = {0}, count[4];
  start[0] = s->dims[0];
  count[0] = (hsize_t)s->npend;
  for (int i = 1; i < s->rank; i++) {
    count[i] = s->dims[i];
  }
  hsize_t dims[4];
  memcpy(dims, s->dims, sizeof dims);
  dims[0] += (hsize_t)s->npend;
  if (H5Dset_extent(s->dset, dims) < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot extend a series", f->path);
  }
  hid_t fspace = H5Dget_space(s->dset);
  H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL);
  hid_t mspace = H5Screate_simple(s->rank, count, NULL);
  herr_t rc = H5Dwrite(s->dset, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, s->pend);
  H5Sclose(mspace);
  H5Sclose(fspace);
  if (rc < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot write series rows", f->path);
  }
  s->dims[0] = dims[0];
  s->npend = 0;
  return CS_OK;
}


csStatus cs_h5Close(csH5File* f) {
  if (!f) {
    return CS_OK;
  }
  csStatus st = CS_OK;
  for (int i = 0; i < f->nseries; i++) {
    if (writePending(f, &f->series[i], NULL) != CS_OK) {
      st = CS_ERR_IO;
    }
    H5Dclose(f->series[i].dset);
    free(f->series[i].pend);
  }
  H5Pclose(f->lcpl);
  if (H5Fclose(f->file) < 0) {
    st = CS_ERR_IO;
  }
  free(f);
  return st;
}


csStatus cs_h5WriteDoubles(csH5File* f, const char* path, int rank, const size_t* dims,
                           const double* data, csError* err) {
  if (!f || rank < 1 || rank > 4) {
    return cs_errorSet(err, CS_ERR_ARG, "h5: bad arguments for dataset %s", path);
  }
  hsize_t d[4];
  for (int i = 0; i < rank; i++) {
    d[i] = dims[i];
  }
  hid_t space = H5Screate_simple(rank, d, NULL);
  hid_t dset = H5Dcreate2(f->file, path, H5T_NATIVE_DOUBLE, space, f->lcpl, H5P_DEFAULT,
                          H5P_DEFAULT);
  csStatus st = CS_OK;
  if (dset < 0 || H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    st = cs_errorSet(err, CS_ERR_IO, "%s: cannot write dataset %s", f->path, path);
  }
  if (dset >= 0) {
    H5Dclose(dset);
  }
  H5Sclose(space);
  return st;
}


/* open the object an attribute goes on; the caller closes it with H5Oclose */
static hid_t openObject(csH5File* f, const char* objpath) {
  return H5Oopen(f->file, objpath, H5P_DEFAULT);
}


csStatus cs_h5AttrString(csH5File* f, const char* objpath, const char* name, const char* value,
                         csError* err) {
  hid_t obj = openObject(f, objpath);
  if (obj < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: no object %s for attribute %s", f->path, objpath,
                       name);
  }
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, strlen(value) + 1);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  csStatus st = CS_OK;
  if (attr < 0 || H5Awrite(attr, type, value) < 0) {
    st = cs_errorSet(err, CS_ERR_IO, "%s: cannot write attribute %s", f->path, name);
  }
  if (attr >= 0) {
    H5Aclose(attr);
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Oclose(obj);
  return st;
}


csStatus cs_h5AttrDouble(csH5File* f, const char* objpath, const char* name, double value,
                         csError* err) {
  hid_t obj = openObject(f, objpath);
  if (obj < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: no object %s for attribute %s", f->path, objpath,
                       name);
  }
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  csStatus st = CS_OK;
  if (attr < 0 || H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) < 0) {
    st = cs_errorSet(err, CS_ERR_IO, "%s: cannot write attribute %s", f->path, name);
  }
  if (attr >= 0) {
    H5Aclose(attr);
  }
  H5Sclose(space);
  H5Oclose(obj);
  return st;
}


int cs_h5SeriesCreate(csH5File* f, const char* path, int tail_rank, const size_t* tail_dims,
                      csError* err) {
  if (!f || tail_rank < 0 || tail_rank > 3 || f->nseries >= CS_H5_MAX_SERIES) {
    cs_errorSet(err, CS_ERR_ARG, "h5: cannot create series %s", path);
    return -1;
  }
  Series* s = &f->series[f->nseries];
  memset(s, 0, sizeof *s);
  s->rank = tail_rank + 1;
  s->row_len = 1;
  for (int i = 0; i < tail_rank; i++) {
    s->row_len *= tail_dims[i];
  }
  s->pend = malloc(SERIES_CHUNK_ROWS * s->row_len * sizeof(double));
  if (!s->pend) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory for series %s", f->path, path);
    return -1;
  }
  hsize_t maxdims[4], chunk[4];
  s->dims[0] = 0;
  maxdims[0] = H5S_UNLIMITED;
  chunk[0] = SERIES_CHUNK_ROWS;
  for (int i = 0; i < tail_rank; i++) {
    s->dims[i + 1] = tail_dims[i];
    maxdims[i + 1] = tail_dims[i];
    chunk[i + 1] = tail_dims[i];
  }
  hid_t space = H5Screate_simple(s->rank, s->dims, maxdims);
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, s->rank, chunk);
  s->dset = H5Dcreate2(f->file, path, H5T_NATIVE_DOUBLE, space, f->lcpl, dcpl, H5P_DEFAULT);
  H5Pclose(dcpl);
  H5Sclose(space);
  if (s->dset < 0) {
    free(s->pend);
    s->pend = NULL;
    cs_errorSet(err, CS_ERR_IO, "%s: cannot create dataset %s", f->path, path);
    return -1;
  }
  return f->nseries++;
}


csStatus cs_h5SeriesAppend(csH5File* f, int si, const double* row, csError* err) {
  if (!f || si < 0 || si >= f->nseries) {
    return cs_errorSet(err, CS_ERR_ARG, "h5: bad series index %d", si);
  }
  Series* s = &f->series[si];
  memcpy(s->pend + (size_t)s->npend * s->row_len, row, s->row_len * sizeof(double));
  s->npend++;
  return s->npend == SERIES_CHUNK_ROWS ? writePending(f, s, err) : CS_OK;
}


csStatus cs_h5Flush(csH5File* f, csError* err) {
  if (!f) {
    return CS_OK;
  }
  for (int i = 0; i < f->nseries; i++) {
    csStatus st = writePending(f, &f->series[i], err);
    if (st != CS_OK) {
      return st;
    }
  }
  if (H5Fflush(f->file, H5F_SCOPE_GLOBAL) < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot flush", f->path);
  }
  return CS_OK;
}
