/* core_status.h: status codes and the error record every fallible crawlsim function fills.
 *
 * Owns: csStatus (0 = ok, negative = failure), csError (one-line message naming file, line and
 * cause), and the helpers that format them. The library never exits or prints on failure; it
 * returns a status and fills a csError the caller owns (SUNDIALS/GSL style, docs/style.md 13). */
#ifndef CS_CORE_STATUS_H
#define CS_CORE_STATUS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The functions of the public API (crawlsim.h): the shared library libcrawlsim is built with
 * -fvisibility=hidden and exports these alone (CMakeLists.txt "libcrawlsim"). */
#ifndef CS_API
#define CS_API __attribute__((visibility("default")))
#endif

/* X-macro list: name, value, message. */
#define CS_STATUS_LIST(X)                                   \
  X(CS_OK, 0, "ok")                                         \
  X(CS_ERR_ARG, -1, "invalid argument")                     \
  X(CS_ERR_IO, -2, "file input/output error")               \
  X(CS_ERR_PARSE, -3, "malformed input")                    \
  X(CS_ERR_RANGE, -4, "value out of range")                 \
  X(CS_ERR_MEMORY, -5, "out of memory")                     \
  X(CS_ERR_DIVERGED, -6, "simulation diverged")             \
  X(CS_ERR_SOLVER, -7, "solver failure")                    \
  X(CS_ERR_EXTERNAL, -8, "external program or library failed")           \
  X(CS_ERR_REJECTED, -9, "step rejected (recoverable: a smaller step may pass)")  \
  X(CS_ERR_INTERRUPTED, -10, "interrupted (the caller's cancel flag was set)")

typedef enum csStatus_ {
#define CS_STATUS_ENUM(name, value, msg) name = value,
  CS_STATUS_LIST(CS_STATUS_ENUM)
#undef CS_STATUS_ENUM
} csStatus;

/* Size of the message buffer; messages longer than this are truncated, never overflowed. */
#define CS_ERROR_MSG_SIZE 512

/* One failure: the status and a one-line message ("file:line: cause"). Caller-owned. */
typedef struct csError_ {
  csStatus status;
  char msg[CS_ERROR_MSG_SIZE];
} csError;

/* Human-readable name of a status (static string). */
CS_API const char* cs_statusString(csStatus s);

/* Clear an error record to CS_OK and an empty message. NULL-safe. */
CS_API void cs_errorClear(csError* err);

/* Fill err (if not NULL) with status and a printf-style message; returns status so callers can
 * write `return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: ...", ...)`. Control characters in the
 * result (newlines, tabs, escapes quoted from a file) become '?': the message stays one line. */
csStatus cs_errorSet(csError* err, csStatus status, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_STATUS_H */
