/* core_h5.h: the HDF5 writer every crawlsim output goes through (serial HDF5 1.10).
 *
 * Owns: opening/closing an output file, whole datasets of doubles with any rank, extendible
 * "series" datasets that grow by one row per output sample (chunked, flushed, so a run that
 * stops early leaves a readable file), and string/double attributes. Intermediate groups in
 * dataset paths ("/legs/A/centerline") are created on demand. All I/O from one thread. */
#ifndef CS_CORE_H5_H
#define CS_CORE_H5_H

#include <stddef.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csH5File_ csH5File;

/* Create (truncate) an HDF5 file. Returns NULL and fills err on failure. */
csH5File* cs_h5Create(const char* path, csError* err);

/* Write the series' gathered rows, flush and close; NULL-safe. CS_ERR_IO when any of it failed
 * (the file may then lack the last rows). */
csStatus cs_h5Close(csH5File* f);

/* Write a whole dataset of doubles: rank 1..4, dims[rank], data row-major (C order). */
csStatus cs_h5WriteDoubles(csH5File* f, const char* path, int rank, const size_t* dims,
                           const double* data, csError* err);

/* Attributes on the object at `objpath` ("/" for the root). */
csStatus cs_h5AttrString(csH5File* f, const char* objpath, const char* name, const char* value,
                         csError* err);
csStatus cs_h5AttrDouble(csH5File* f, const char* objpath, const char* name, double value,
                         csError* err);

/* An extendible dataset of shape [N, tail...] growing along its first axis. `tail_rank` is 0..3
 * (0 gives a 1-D series of scalars). Returns a series index >= 0, or -1 with err filled. At most
 * CS_H5_MAX_SERIES series per file. */
#define CS_H5_MAX_SERIES 64
int cs_h5SeriesCreate(csH5File* f, const char* path, int tail_rank, const size_t* tail_dims,
                      csError* err);

/* Append one row (prod(tail_dims) doubles) to series `s`. Rows are gathered in memory and
 * written 64 at a time; cs_h5Flush and cs_h5Close write the rest. */
csStatus cs_h5SeriesAppend(csH5File* f, int s, const double* row, csError* err);

/* Write every series' gathered rows and flush all buffers to disk (the file stays readable
 * with every row appended so far if the process stops afterwards). */
csStatus cs_h5Flush(csH5File* f, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_H5_H */
