/* core_status.c: status strings and error-record formatting (see core_status.h). */
#include "core_status.h"

#include <stdarg.h>
#include <stdio.h>


const char* cs_statusString(csStatus s) {
  switch (s) {
#define CS_STATUS_CASE(name, value, msg) \
  case name:                             \
    return msg;
    CS_STATUS_LIST(CS_STATUS_CASE)
#undef CS_STATUS_CASE
  }
  return "unknown status";
}


void cs_errorClear(csError* err) {
  if (err) {
    err->status = CS_OK;
    err->msg[0] = '\0';
  }
}


csStatus cs_errorSet(csError* err, csStatus status, const char* fmt, ...) {
  if (err) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    /* one line, whatever a file put into the quoted text (a newline in an HDF5 string
     * attribute, a terminal escape in a word): control characters become '?' */
    for (char* c = err->msg; *c; c++) {
      if ((unsigned char)*c < 0x20 || *c == 0x7f) {
        *c = '?';
      }
    }
    err->status = status;
  }
  return status;
}
