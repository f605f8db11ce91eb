/* fuzz_common.c: temp files, the error contract and byte reading of the fuzz harnesses (see
 * fuzz_common.h). */
#define _POSIX_C_SOURCE 200809L /* getpid, access */

#include "fuzz_common.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { NSLOT = 4, PATH_SIZE = 256 };

/* the temp file names of this process (test code: process-wide by design) */
static char g_path[NSLOT][PATH_SIZE];
static int g_cleanup_registered;

static void removeTempFiles(void) {
  for (int i = 0; i < NSLOT; i++) {
    if (g_path[i][0]) {
      remove(g_path[i]);
    }
  }
}


const char* csz_tempPath(int slot, const char* ext) {
  if (slot < 0 || slot >= NSLOT) {
    return NULL;
  }
  if (!g_path[slot][0]) {
    /* tmpfs first: every input is written once, and the disk need not see it */
    const char* env = getenv("TMPDIR");
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm"
                      : env && env[0] && access(env, W_OK) == 0 ? env
                                                                : "/tmp";
    snprintf(g_path[slot], PATH_SIZE, "%s/crawlsim-fuzz-%ld-%d%s", dir, (long)getpid(), slot,
             ext ? ext : "");
    if (!g_cleanup_registered) {
      g_cleanup_registered = 1;
      atexit(removeTempFiles);
    }
  }
  return g_path[slot];
}


int csz_writeFile(const char* path, const uint8_t* data, size_t size) {
  FILE* f = path ? fopen(path, "wb") : NULL;
  if (!f) {
    return -1;
  }
  size_t n = size ? fwrite(data, 1, size, f) : 0;
  int bad = fclose(f) != 0;
  return n == size && !bad ? 0 : -1;
}


void csz_fail(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fputs("fuzz: harness contract broken: ", stderr);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  fflush(stderr);
  abort();
}


void csz_checkError(csStatus st, int ok, const csError* err, const char* path,
                    const uint8_t* data, size_t size, cszKind kind) {
  if (ok != (st == CS_OK)) {
    csz_fail("status %d (%s) but the reader %s an object", (int)st, cs_statusString(st),
             ok ? "returned" : "did not return");
  }
  if (st == CS_OK) {
    return;
  }
  if (!err) {
    csz_fail("no error record");
  }
  const char* msg = err->msg;
  if (!memchr(msg, '\0', sizeof err->msg)) {
    csz_fail("message is not NUL-terminated");
  }
  if (err->status != st) {
    csz_fail("returned status %d, error record says %d (%s)", (int)st, (int)err->status, msg);
  }
  if (!(st <= CS_ERR_ARG && st >= CS_ERR_REJECTED)) {
    csz_fail("unknown status %d (%s)", (int)st, msg);
  }
  if (!msg[0]) {
    csz_fail("status %s with an empty message", cs_statusString(st));
  }
  if (strpbrk(msg, "\r\n")) {
    csz_fail("message is more than one line: '%s'", msg);
  }
  if (st == CS_ERR_MEMORY) {
    return; /* an allocation failure may not know the file */
  }
  size_t plen = strlen(path);
  if (strncmp(msg, path, plen) != 0) {
    csz_fail("message does not name the file: '%s'", msg);
  }
  if (kind != CSZ_TEXT || msg[plen] != ':' || !isdigit((unsigned char)msg[plen + 1])) {
    return;
  }
  /* "<path>:<N>:": N must be a line of the input (or the one after its last newline) */
  char* end = NULL;
  long line = strtol(msg + plen + 1, &end, 10);
  if (*end != ':') {
    return; /* not a line reference */
  }
  long nlines = 1;
  for (size_t i = 0; i < size; i++) {
    nlines += data[i] == '\n';
  }
  if (line < 1 || line > nlines) {
    csz_fail("message names line %ld of an input of %ld lines: '%s'", line, nlines, msg);
  }
}


int csz_allFinite(const double* v, size_t n) {
  for (size_t i = 0; i < n; i++) {
    if (!isfinite(v[i])) {
      return 0;
    }
  }
  return 1;
}


/* ---- bytes ---- */

unsigned csz_byte(cszBytes* b) { return b->pos < b->size ? b->data[b->pos++] : 0u; }


unsigned csz_u16(cszBytes* b) {
  unsigned lo = csz_byte(b);
  return lo | (csz_byte(b) << 8);
}


double csz_rawDouble(cszBytes* b) {
  unsigned char raw[sizeof(double)];
  for (size_t i = 0; i < sizeof raw; i++) {
    raw[i] = (unsigned char)csz_byte(b);
  }
  double v;
  memcpy(&v, raw, sizeof v);
  return v;
}


int csz_more(const cszBytes* b) { return b->pos < b->size; }
