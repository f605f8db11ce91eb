/* core_clock.c: the monotonic wall clock (see core_clock.h). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime and CLOCK_MONOTONIC under -std=c17 */
#include "core_clock.h"

#include <time.h>


double csu_wallSeconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}


double csu_timerAdd(csuTimer* t, double t0) {
  double now = csu_wallSeconds();
  t->wall += now - t0;
  t->count++;
  return now;
}
