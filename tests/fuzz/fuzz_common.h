/* fuzz_common.h: what every fuzz harness of tests/fuzz shares (test code, not a unit).
 *
 * A harness is one .c file that defines csz_harnessInit and csz_harnessRun for one reader of
 * user files. The same file is linked two ways:
 *  - with fuzz_libfuzzer.c and clang's -fsanitize=fuzzer (CS_BUILD_FUZZERS=ON): libFuzzer calls
 *    LLVMFuzzerTestOneInput, which calls csz_harnessRun, under ASan + UBSan + LeakSanitizer;
 *  - with fuzz_replay.c into an ordinary program (every build, ctest): it runs the seeds, the
 *    minimised corpus and every regression input through csz_harnessRun, and compares each
 *    regression input with its .expect file (fuzz_replay.c).
 *
 * The readers take file names, so an input is first written to a file of this process
 * (csz_tempPath: /dev/shm when it exists, so no disk traffic). Checks a harness makes on every
 * input (csz_checkError, csz_fail): the reader returns a status and a filled csError whose
 * status is the same, whose message is one line that starts with the file's name and, when it
 * names a line "<file>:<N>:", a line of the input; a reader that accepts a file hands back an
 * object that is whole (each harness checks its own invariants and uses the result). A broken
 * contract aborts, which libFuzzer records as a crash and ctest as a failed test.
 *
 * The process-wide state (the temp file names, the harness's parsed-once data) is test code's:
 * library code has none (docs/style.md 12). */
#ifndef CS_FUZZ_COMMON_H
#define CS_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- what a harness defines ---- */

/* Once per process, before any input: load what every input needs. 0 = ok. */
int csz_harnessInit(void);

/* One input: write it where the reader reads it, call the reader, check the contract, use the
 * result. Returns the reader's status (CS_OK when it accepted the input) with err filled; an
 * input the harness does not give to the reader (csz_harnessRun's own rule, e.g. HDF5 bytes
 * for the text reader) returns CS_OK with the message "skipped". */
csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err);

/* ---- helpers ---- */

/* A file name private to this process, one per `slot` (0..3), ending in `ext` (".csv"): the
 * same name for the same slot on every call. NULL if no temporary directory is writable. */
const char* csz_tempPath(int slot, const char* ext);

/* Write bytes to `path` (truncating). 0 = ok. */
int csz_writeFile(const char* path, const uint8_t* data, size_t size);

/* Print "fuzz: <harness contract broken>: ..." and the input's size, then abort(). */
void csz_fail(const char* fmt, ...) __attribute__((format(printf, 1, 2), noreturn));

/* How csz_checkError reads a message. */
typedef enum {
  CSZ_TEXT = 0, /* a text file: "<file>:<line>: cause", line within the input */
  CSZ_FILE = 1  /* a binary file: "<file>: cause" (a line number is not checked) */
} cszKind;

/* The error contract of a reader call that returned `st` (and, for loaders, `ok` = it handed
 * back an object): st == CS_OK exactly when ok; on failure err->status == st, st a known
 * negative status, the message non-empty, NUL-terminated, one line (no CR or LF), starting with
 * `path` (except out-of-memory messages), and for CSZ_TEXT a "<path>:<N>:" names a line 1..(the
 * input's lines + 1). Aborts with csz_fail otherwise. */
void csz_checkError(csStatus st, int ok, const csError* err, const char* path,
                    const uint8_t* data, size_t size, cszKind kind);

/* 1 when every value is finite. */
int csz_allFinite(const double* v, size_t n);

/* ---- reading a structured input (the HDF5 harness) ---- */

/* Bytes of an input taken from the front; past the end every read gives 0. */
typedef struct cszBytes_ {
  const uint8_t* data;
  size_t size, pos;
} cszBytes;

unsigned csz_byte(cszBytes* b);
/* a little-endian 16-bit value */
unsigned csz_u16(cszBytes* b);
/* 8 raw bytes as a double (any bit pattern: NaN payloads, denormals, infinities) */
double csz_rawDouble(cszBytes* b);
/* 1 while bytes are left */
int csz_more(const cszBytes* b);

#ifdef __cplusplus
}
#endif
#endif /* CS_FUZZ_COMMON_H */
