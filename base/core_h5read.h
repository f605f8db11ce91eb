/* core_h5read.h: the HDF5 reader of crawlsim's own data files (serial HDF5 1.10): whole
 * datasets of numbers into doubles, and root attributes (numbers, strings).
 *
 * Owns: csH5Reader (one file open read-only) and its read calls. The files it reads are the
 * writer's (core_h5.h) or the offline tools' (tools/rom_basis.py); every failure is a
 * one-line error naming the file and the dataset or attribute. HDF5's own error stack is
 * silenced (the library never prints). All I/O from one thread. */
#ifndef CS_CORE_H5READ_H
#define CS_CORE_H5READ_H

#include <stddef.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csH5Reader_ csH5Reader;

/* Open `path` read-only; NULL and err (CS_ERR_IO, naming the file) when it is not an HDF5 file. */
csH5Reader* cs_h5ReaderOpen(const char* path, csError* err);
void cs_h5ReaderClose(csH5Reader* r); /* NULL-safe */

/* 1 when the file has a dataset at `name`, else 0. */
int cs_h5ReaderHas(const csH5Reader* r, const char* name);

/* A whole dataset of numbers (rank 1..4, any numeric type, converted) as doubles, row-major,
 * malloc'ed (the caller frees). want (rank entries, 0 = any) fixes its dimensions; dims (may be
 * NULL, 4 entries) gets them, rank (may be NULL) its rank. NULL and err (CS_ERR_IO: missing,
 * wrong rank or dimensions, unreadable; CS_ERR_MEMORY) otherwise. */
double* cs_h5ReaderDoubles(const csH5Reader* r, const char* name, int want_rank,
                           const size_t* want, size_t* dims, int* rank, csError* err);

/* A numeric root attribute into *v; CS_ERR_IO naming it when absent or not a number. */
csStatus cs_h5ReaderAttrDouble(const csH5Reader* r, const char* name, double* v, csError* err);

/* A string root attribute into buf[size] (truncated); CS_ERR_IO when absent or not a string. */
csStatus cs_h5ReaderAttrString(const csH5Reader* r, const char* name, char* buf, size_t size,
                               csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_H5READ_H */
