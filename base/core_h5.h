/* core_h5.h: the HDF5 writer every crawlsim output goes through (serial HDF5 1.10).
 *
 * Owns: opening/closing an output file, whole datasets of doubles with any rank, extendible
 * "series" datasets that grow by one row per output sample (chunked, flushed, so a run that
 * stops early leaves a readable file), string/double attributes, and keeping the file on disk
 * complete as of its last flush whatever happens to the disk or the process. Intermediate groups in
 * dataset paths ("/legs/A/centerline") are created on demand. All I/O from one thread. */
#ifndef CS_CORE_H5_H
#define CS_CORE_H5_H

#include <stddef.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csH5File_ csH5File;

/* Size (bytes, NUL included) of the root attribute "status": fixed, so that it can be rewritten
 * in place on a full disk. Longer values are truncated. */
#define CS_H5_STATUS_SIZE CS_ERROR_MSG_SIZE

/* Create (truncate) an HDF5 file. The file is built in memory and reaches the disk as a whole
 * at cs_h5Create (empty), at every cs_h5Flush and at close, each time written to "<path>.part"
 * and renamed over <path>: the file at <path> is always complete as of its last flush, even if
 * the process is killed. Its root attribute "status" starts as "running". Returns NULL and fills
 * err on failure (the cause from errno: no space left, read-only file system, ...). */
csH5File* cs_h5Create(const char* path, csError* err);

/* Write the series' gathered rows and the whole file, and close; NULL-safe. CS_ERR_IO when any
 * of it failed: the file on disk then holds its last flushed image, with "status" rewritten in
 * place to the value last set (so set it to say what happened before closing). Every HDF5 id
 * is closed in any case. cs_h5Close is cs_h5CloseChecked without the message. */
csStatus cs_h5CloseChecked(csH5File* f, csError* err);
csStatus cs_h5Close(csH5File* f);

/* Write a whole dataset of doubles: rank 1..4, dims[rank], data row-major (C order). Writing
 * one again replaces it. */
csStatus cs_h5WriteDoubles(csH5File* f, const char* path, int rank, const size_t* dims,
                           const double* data, csError* err);

/* Attributes on the object at `objpath` ("/" for the root); writing one again replaces it. The
 * root's "status" is the fixed-size one (CS_H5_STATUS_SIZE). */
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

/* Write every series' gathered rows and the file image to disk (atomically, see cs_h5Create):
 * the file on disk then holds every row appended so far. Costs a write of the whole file. After
 * one failure later flushes fail at once (the disk is not retried). */
csStatus cs_h5Flush(csH5File* f, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_H5_H */
